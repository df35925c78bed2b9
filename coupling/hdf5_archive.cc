#include "coupling/hdf5_archive.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numeric>
#include <sstream>
#include <system_error>
#include <utility>

namespace compax::coupling
{
  namespace
  {
    using Entry = archive_detail::Entry;

    /// The user block that holds the compax header (a power of 2, >= 512).
    constexpr std::size_t header_size = 512;

    constexpr char hdf5_signature[8]
      = {'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};

    /// Root attributes the writer writes itself.
    const char *const reserved[] = {"format",
                                    "format_version",
                                    "kind",
                                    "parameters",
                                    "parameters_hash",
                                    "checksum"};

    /// HDF5 prints nothing: every error is turned into an exception.
    void
    quiet_hdf5()
    {
      static const bool done = [] {
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
        return true;
      }();
      (void)done;
    }

    /// An HDF5 identifier closed when it goes out of scope.
    class Handle
    {
    public:
      Handle(hid_t id, herr_t (*close)(hid_t))
          : id(id)
          , close(close)
      {
      }
      ~Handle()
      {
        if (id >= 0)
          close(id);
      }
      Handle(const Handle &) = delete;
      Handle &
      operator=(const Handle &)
        = delete;

      operator hid_t() const
      {
        return id;
      }
      bool
      valid() const
      {
        return id >= 0;
      }

    private:
      hid_t id;
      herr_t (*close)(hid_t);
    };

    /// The text of the first header line that starts with @p key + ' '.
    std::string
    header_field(const std::string &header, const std::string &key)
    {
      std::istringstream lines(header);
      for (std::string line; std::getline(lines, line);)
        if (line.rfind(key + " ", 0) == 0)
          return line.substr(key.size() + 1);
      return {};
    }

    /// What the header's hash covers besides the bytes after the header.
    std::string
    header_fields(const std::string &kind, std::uint64_t bytes)
    {
      return std::string(archive_format) + "\nversion "
             + std::to_string(archive_format_version) + "\nkind " + kind
             + "\nbytes " + std::to_string(bytes) + "\n";
    }

    std::string
    as_bytes(const std::vector<double> &values)
    {
      return std::string(reinterpret_cast<const char *>(values.data()),
                         values.size() * sizeof(double));
    }

    std::vector<double>
    as_doubles(const std::string &bytes)
    {
      std::vector<double> values(bytes.size() / sizeof(double));
      if (!values.empty())
        std::memcpy(values.data(),
                    bytes.data(),
                    values.size() * sizeof(double));
      return values;
    }

    /// Parses "key = value" lines into (key, value) pairs in order.
    std::vector<std::pair<std::string, std::string>>
    parameter_lines(const std::string &text)
    {
      std::vector<std::pair<std::string, std::string>> entries;
      std::istringstream                               lines(text);
      for (std::string line; std::getline(lines, line);)
        {
          const auto eq = line.find(" = ");
          if (eq == std::string::npos)
            entries.emplace_back(line, "");
          else
            entries.emplace_back(line.substr(0, eq), line.substr(eq + 3));
        }
      return entries;
    }

    /// Shortens a value for a one-line message.
    std::string
    shown(const std::string &value)
    {
      if (value.empty())
        return "(empty)";
      return value.size() <= 80 ? value : value.substr(0, 77) + "...";
    }
  } // namespace

  std::string
  describe_archive_kind(const std::string &kind)
  {
    static const std::map<std::string, std::string> names{
      {archive_kind::die_compaction, "die compaction checkpoint"},
      {archive_kind::die_branch, "die branch checkpoint"},
      {archive_kind::die_state, "die bed state"},
      {archive_kind::rve, "RVE checkpoint"},
      {archive_kind::rve_state, "RVE state"},
      {archive_kind::rve_database, "RVE response database"},
      {archive_kind::database_checkpoint, "database checkpoint"},
      {archive_kind::tablet, "tablet checkpoint"},
      {archive_kind::fe2_rve_states, "FE2 RVE states"}};
    const auto it = names.find(kind);
    return it == names.end() ? "'" + kind + "' archive" : it->second;
  }

  std::string
  parameter_fingerprint(const std::string &parameters)
  {
    return to_hex(hash64(parameters.data(), parameters.size()));
  }

  std::string
  first_parameter_difference(const std::string &archived,
                             const std::string &expected)
  {
    const auto                         a = parameter_lines(archived);
    const auto                         e = parameter_lines(expected);
    std::map<std::string, std::string> in_archive(a.begin(), a.end());
    std::map<std::string, std::string> here(e.begin(), e.end());
    for (const auto &[key, value] : e)
      {
        const auto it = in_archive.find(key);
        if (it == in_archive.end())
          return key + " = " + shown(value)
                 + " here is not among the archive's parameters";
        if (it->second != value)
          return key + " = " + shown(it->second) + " in the archive, "
                 + shown(value) + " here";
      }
    for (const auto &[key, value] : a)
      if (here.find(key) == here.end())
        return key + " = " + shown(value)
               + " in the archive is not among this run's parameters";
    return {};
  }

  namespace archive_detail
  {
    std::uint64_t
    content_checksum(const std::map<std::string, Entry> &datasets,
                     const std::map<std::string, Entry> &attributes)
    {
      std::uint64_t h = hash64(nullptr, 0);
      const auto    add
        = [&h](const char tag, const std::string &name, const Entry &e) {
            h                        = hash64(&tag, 1, h);
            h                        = hash64(name.c_str(), name.size() + 1, h);
            h                        = hash64(&e.type, 1, h);
            const std::uint64_t rank = e.shape.size();
            h                        = hash64(&rank, sizeof(rank), h);
            for (const hsize_t d : e.shape)
              {
                const std::uint64_t extent = d;
                h                          = hash64(&extent, sizeof(extent), h);
              }
            const std::uint64_t n = e.bytes.size();
            h                     = hash64(&n, sizeof(n), h);
            h                     = hash64(e.bytes.data(), e.bytes.size(), h);
          };
      for (const auto &[name, e] : datasets)
        add('D', name, e);
      for (const auto &[name, e] : attributes)
        if (name != "checksum")
          add('A', name, e);
      return h;
    }
  } // namespace archive_detail

  Hdf5ArchiveError::Hdf5ArchiveError(const std::string &file,
                                     const std::string &reason)
      : io::FileError("archive", file, reason)
  {
  }

  namespace
  {
    /// Flushes @p path (a file or a directory) to stable storage.
    void
    sync_path(const std::string &path, bool directory)
    {
      const int fd
        = ::open(path.c_str(), directory ? O_RDONLY | O_DIRECTORY : O_RDONLY);
      if (fd < 0 && directory) // best effort: the rename is already done
        return;
      if (fd < 0)
        throw Hdf5ArchiveError(path, "cannot open to sync");
      const int rc = ::fsync(fd);
      ::close(fd);
      if (rc != 0 && !directory) // some file systems refuse directory fsync
        throw Hdf5ArchiveError(path, "fsync failed");
    }

    Entry
    text_entry(const std::string &text)
    {
      return {'t', {static_cast<hsize_t>(text.size())}, text};
    }
  } // namespace

  Hdf5ArchiveWriter::Hdf5ArchiveWriter(std::string     path_,
                                       ArchiveIdentity identity)
      : target(std::move(path_))
      , temporary(target + ".tmp")
  {
    quiet_hdf5();
    if (target.empty())
      throw Hdf5ArchiveError(target, "empty file name");
    if (identity.kind.empty())
      throw Hdf5ArchiveError(target, "an archive needs a kind");
    const std::filesystem::path parent
      = std::filesystem::path(target).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent))
      throw Hdf5ArchiveError(target,
                             "directory '" + parent.string()
                               + "' does not exist");
    const Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
    if (!fcpl.valid() || H5Pset_userblock(fcpl, header_size) < 0)
      throw Hdf5ArchiveError(temporary, "cannot set up the HDF5 file");
    file = H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, fcpl, H5P_DEFAULT);
    if (file < 0)
      throw Hdf5ArchiveError(temporary, "cannot create");
    const std::string &params = identity.parameters;
    put_attribute("format", text_entry(archive_format));
    put_attribute("format_version",
                  {'f', {}, as_bytes({double(archive_format_version)})});
    put_attribute("kind", text_entry(identity.kind));
    put_attribute("parameters", text_entry(params));
    put_attribute("parameters_hash", text_entry(parameter_fingerprint(params)));
  }

  Hdf5ArchiveWriter::~Hdf5ArchiveWriter()
  {
    if (file >= 0)
      {
        H5Fclose(file);
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
      }
  }

  void
  Hdf5ArchiveWriter::check_name(const std::string &name,
                                const bool         attribute) const
  {
    if (file < 0)
      throw Hdf5ArchiveError(target, "write of '" + name + "' after commit()");
    if (name.empty() || name.front() == '/' || name.back() == '/'
        || name.find("//") != std::string::npos
        || name.find('\0') != std::string::npos)
      throw Hdf5ArchiveError(target, "invalid entry name '" + name + "'");
    if (attribute)
      {
        if (name.find('/') != std::string::npos)
          throw Hdf5ArchiveError(target,
                                 "attribute '" + name
                                   + "' of the root has a '/' in its name");
        if (attributes.count(name) > 0)
          throw Hdf5ArchiveError(target,
                                 "attribute '" + name + "' written twice");
        return;
      }
    if (datasets.count(name) > 0)
      throw Hdf5ArchiveError(target, "entry '" + name + "' written twice");
    // No group may be a dataset, and the name may not be a group.
    for (std::size_t slash = name.find('/'); slash != std::string::npos;
         slash             = name.find('/', slash + 1))
      if (datasets.count(name.substr(0, slash)) > 0)
        throw Hdf5ArchiveError(target,
                               "'" + name.substr(0, slash)
                                 + "' is an array, not a group");
    const auto after = datasets.lower_bound(name + "/");
    if (after != datasets.end() && after->first.rfind(name + "/", 0) == 0)
      throw Hdf5ArchiveError(target, "'" + name + "' is a group");
  }

  void
  Hdf5ArchiveWriter::write_dataset(const std::string &name, Entry entry)
  {
    check_name(name, false);
    const auto fail = [&](const std::string &what) {
      throw Hdf5ArchiveError(target, "cannot write '" + name + "': " + what);
    };
    const bool   text = entry.type == 't';
    const int    rank = static_cast<int>(entry.shape.size());
    const Handle space(H5Screate_simple(rank, entry.shape.data(), nullptr),
                       H5Sclose);
    const Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    if (!space.valid() || !dcpl.valid() || H5Pset_obj_track_times(dcpl, 0) < 0)
      fail("property lists");
    // The groups on the way, without time stamps (the same data gives the
    // same bytes).
    for (std::size_t slash = name.find('/'); slash != std::string::npos;
         slash             = name.find('/', slash + 1))
      {
                    const std::string group = name.substr(0, slash);
                    if (!groups.insert(group).second)
          continue;
        const Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
                    if (!gcpl.valid() || H5Pset_obj_track_times(gcpl, 0) < 0)
          fail("property lists");
        const Handle created(
          H5Gcreate2(file, group.c_str(), H5P_DEFAULT, gcpl, H5P_DEFAULT),
          H5Gclose);
                    if (!created.valid())
          fail("cannot create group '" + group + "'");
      }
    const std::size_t element = text ? 1 : sizeof(double);
    const hsize_t     n       = entry.bytes.size() / element;
    if (n > 0)
      {
        // Chunks of at most ~1M elements along the first index, each
        // checked by Fletcher-32.
        std::vector<hsize_t> chunk = entry.shape;
        hsize_t              row   = 1;
        for (int k = 1; k < rank; ++k)
          row *= chunk[k];
        chunk[0]
          = std::max<hsize_t>(1,
                              std::min<hsize_t>(chunk[0],
                                                (hsize_t(1) << 20)
                                                  / std::max<hsize_t>(row, 1)));
        if (H5Pset_chunk(dcpl, rank, chunk.data()) < 0
            || H5Pset_fletcher32(dcpl) < 0)
          fail("chunking");
      }
    const hid_t  file_type = text ? H5T_STD_U8LE : H5T_IEEE_F64LE;
    const hid_t  mem_type  = text ? H5T_NATIVE_UCHAR : H5T_NATIVE_DOUBLE;
    const Handle dataset(
      H5Dcreate2(
        file, name.c_str(), file_type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
      H5Dclose);
    if (!dataset.valid())
      fail("cannot create the dataset");
    if (n > 0
        && H5Dwrite(dataset,
                    mem_type,
                    H5S_ALL,
                    H5S_ALL,
                    H5P_DEFAULT,
                    entry.bytes.data())
             < 0)
      fail("write failed");
    datasets.emplace(name, std::move(entry));
  }

  void
  Hdf5ArchiveWriter::put_attribute(const std::string &name, Entry entry)
  {
    check_name(name, true);
    const auto fail = [&](const std::string &what) {
      throw Hdf5ArchiveError(target,
                             "cannot write attribute '" + name + "': " + what);
    };
    const bool text = entry.type == 't';
    if (text && entry.bytes.size() > 60000)
      fail("text longer than 60000 bytes (write it with write_text)");
    const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    const Handle type(text ? H5Tcopy(H5T_C_S1) : H5Tcopy(H5T_IEEE_F64LE),
                      H5Tclose);
    if (!space.valid() || !type.valid())
      fail("types");
    // Fixed-length text, padded with NULs (an empty text is one NUL).
    if (text
        && (H5Tset_size(type, std::max<std::size_t>(1, entry.bytes.size())) < 0
            || H5Tset_strpad(type, H5T_STR_NULLPAD) < 0))
      fail("types");
    const Handle attribute(
      H5Acreate2(file, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose);
    if (!attribute.valid())
      fail("cannot create");
    std::string data = entry.bytes;
    if (text && data.empty())
      data.push_back('\0');
    if (H5Awrite(attribute, text ? hid_t(type) : H5T_NATIVE_DOUBLE, data.data())
        < 0)
      fail("write failed");
    attributes.emplace(name, std::move(entry));
  }

  void
  Hdf5ArchiveWriter::write_array(const std::string         &name,
                                 const std::vector<double> &values)
  {
    write_array(name, values, {static_cast<hsize_t>(values.size())});
  }

  void
  Hdf5ArchiveWriter::write_array(const std::string          &name,
                                 const std::vector<double>  &values,
                                 const std::vector<hsize_t> &shape)
  {
    const hsize_t n = std::accumulate(shape.begin(),
                                      shape.end(),
                                      hsize_t(1),
                                      std::multiplies<hsize_t>());
    if (shape.empty() || n != values.size())
      throw Hdf5ArchiveError(target,
                             "array '" + name + "' has "
                               + std::to_string(values.size())
                               + " values, which its shape does not hold");
    write_dataset(name, {'f', shape, as_bytes(values)});
  }

  void
  Hdf5ArchiveWriter::write_text(const std::string &name,
                                const std::string &text)
  {
    write_dataset(name, text_entry(text));
  }

  void
  Hdf5ArchiveWriter::write_attribute(const std::string &name,
                                     const double       value)
  {
    for (const char *r : reserved)
      if (name == r)
        throw Hdf5ArchiveError(target, "attribute '" + name + "' is reserved");
    put_attribute(name, {'f', {}, as_bytes({value})});
  }

  void
  Hdf5ArchiveWriter::write_attribute(const std::string &name,
                                     const std::string &value)
  {
    for (const char *r : reserved)
      if (name == r)
        throw Hdf5ArchiveError(target, "attribute '" + name + "' is reserved");
    put_attribute(name, text_entry(value));
  }

  void
  Hdf5ArchiveWriter::commit()
  {
    if (file < 0)
      throw Hdf5ArchiveError(target, "commit() called twice");
    put_attribute("checksum",
                  text_entry(to_hex(
                    archive_detail::content_checksum(datasets, attributes))));
    const std::string kind = attributes.at("kind").bytes;
    const hid_t       f    = file;
    file                   = -1;
    if (H5Fclose(f) < 0)
      {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw Hdf5ArchiveError(temporary, "closing the HDF5 file failed");
      }

    // The header: the hash of its fields and of every byte after it.
    const auto fail = [&](const std::string &what) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw Hdf5ArchiveError(temporary, what);
    };
    const int fd = ::open(temporary.c_str(), O_RDWR);
    if (fd < 0)
      fail("cannot reopen to write the header");
    struct stat st;
    if (::fstat(fd, &st) != 0
        || static_cast<std::size_t>(st.st_size) < header_size)
      {
        ::close(fd);
        fail("HDF5 wrote no user block");
      }
    const auto        bytes  = static_cast<std::uint64_t>(st.st_size);
    const std::string fields = header_fields(kind, bytes);
    std::uint64_t     h      = hash64(fields.data(), fields.size());
    std::vector<char> buffer(1 << 16);
    for (off_t offset = header_size; offset < st.st_size;)
      {
        const ssize_t got = ::pread(fd, buffer.data(), buffer.size(), offset);
        if (got <= 0)
          {
            ::close(fd);
            fail("cannot read back");
          }
        h = hash64(buffer.data(), static_cast<std::size_t>(got), h);
        offset += got;
      }
    std::string header = fields + "hash " + to_hex(h) + "\n";
    if (header.size() > header_size)
      {
        ::close(fd);
        fail("kind too long for the header");
      }
    header.resize(header_size, '\0');
    const bool written = ::pwrite(fd, header.data(), header.size(), 0)
                           == static_cast<ssize_t>(header.size())
                         && ::fsync(fd) == 0;
    ::close(fd);
    if (!written)
      fail("cannot write the header");
    std::error_code error;
    std::filesystem::rename(temporary, target, error);
    if (error)
      fail("cannot rename the temporary onto '" + target
           + "': " + error.message());
    const std::filesystem::path parent
      = std::filesystem::path(target).parent_path();
    sync_path(parent.empty() ? std::string(".") : parent.string(), true);
  }

  Hdf5ArchiveReader::Hdf5ArchiveReader(std::string path_)
      : path(std::move(path_))
  {
    load("", std::nullopt);
  }

  Hdf5ArchiveReader::Hdf5ArchiveReader(
    std::string                       path_,
    const std::string                &expected_kind,
    const std::optional<std::string> &expected_parameters)
      : path(std::move(path_))
  {
    if (expected_kind.empty())
      fail("no kind of archive asked for");
    load(expected_kind, expected_parameters);
  }

  Hdf5ArchiveReader
  open_archive(const std::string                &path,
               const std::string                &kind,
               const std::optional<std::string> &parameters)
  {
    return Hdf5ArchiveReader(path, kind, parameters);
  }

  void
  Hdf5ArchiveReader::fail(const std::string &reason) const
  {
    throw Hdf5ArchiveError(path, reason);
  }

  namespace
  {
    /// Everything below the root: datasets by full name.
    struct Visit
    {
      std::vector<std::string> datasets;
      bool                     other = false;
    };

    herr_t
    visit_link(hid_t group, const char *name, const H5L_info_t *, void *data)
    {
      auto        &v = *static_cast<Visit *>(data);
      const Handle object(H5Oopen(group, name, H5P_DEFAULT), H5Oclose);
      if (!object.valid())
        return -1;
      const H5I_type_t type = H5Iget_type(object);
      if (type == H5I_DATASET)
        v.datasets.emplace_back(name);
      else if (type != H5I_GROUP)
        v.other = true;
      return 0;
    }

    herr_t
    visit_attribute(hid_t, const char *name, const H5A_info_t *, void *data)
    {
      static_cast<std::vector<std::string> *>(data)->emplace_back(name);
      return 0;
    }
  } // namespace

  void
  Hdf5ArchiveReader::load(const std::string                &expected_kind,
                          const std::optional<std::string> &expected_parameters)
  {
    quiet_hdf5();
    namespace fs = std::filesystem;
    std::error_code error;
    const auto      status = fs::status(path, error);
    if (error || !fs::exists(status))
      fail("no such file");
    if (fs::is_directory(status))
      fail("is a folder, not an archive file");
    if (!fs::is_regular_file(status))
      fail("is not a regular file");

    // 1. The header, before HDF5 sees a byte of the file.
    std::ifstream in(path, std::ios::binary);
    if (!in)
      fail("cannot be read (" + std::string(std::strerror(errno)) + ")");
    std::string head(header_size, '\0');
    in.read(head.data(), header_size);
    const auto got = static_cast<std::size_t>(in.gcount());
    head.resize(got);
    if (got == 0)
      fail("is empty (0 bytes)");
    if (head.compare(0, sizeof(hdf5_signature), hdf5_signature, 8) == 0)
      fail("is an HDF5 file without the compax archive header (written by "
           "a compax older than archive format "
           + std::to_string(archive_format_version)
           + ", or by another program): rerun the study that wrote it");
    const std::string tag = std::string(archive_format) + "\n";
    if (head.compare(0, tag.size(), tag) != 0)
      fail("is not a compax archive (no '" + std::string(archive_format)
           + "' header)");
    if (got < header_size)
      fail("is truncated (" + std::to_string(got)
           + " bytes, less than its header)");
    const std::string version = header_field(head, "version");
    if (version != std::to_string(archive_format_version))
      fail("has archive format version '" + shown(version)
           + "'; this compax reads version "
           + std::to_string(archive_format_version)
           + " (rerun the study that wrote it)");
    const std::string        kind       = header_field(head, "kind");
    const std::string        bytes_text = header_field(head, "bytes");
    const std::string        hash_text  = header_field(head, "hash");
    char                    *end        = nullptr;
    const unsigned long long bytes
      = std::strtoull(bytes_text.c_str(), &end, 10);
    // Nothing but NULs after the header's text (every byte is checked).
    const std::string text_part
      = header_fields(kind, std::strtoull(bytes_text.c_str(), nullptr, 10))
        + "hash " + hash_text + "\n";
    const bool padded
      = head.compare(0, text_part.size(), text_part) == 0
        && head.find_first_not_of('\0', text_part.size()) == std::string::npos;
    if (kind.empty() || bytes_text.empty() || *end != '\0'
        || hash_text.size() != 16 || !padded)
      fail("has a damaged compax archive header");
    in.seekg(0, std::ios::end);
    const auto size = static_cast<unsigned long long>(in.tellg());
    if (size < bytes)
      fail("is truncated (" + std::to_string(size) + " of "
           + std::to_string(bytes) + " bytes)");
    if (size > bytes)
      fail("has " + std::to_string(size - bytes)
           + " bytes more than it was written with (damaged)");
    {
      const std::string fields = header_fields(kind, bytes);
      std::uint64_t     h      = hash64(fields.data(), fields.size());
      in.seekg(header_size);
      std::vector<char> buffer(1 << 16);
      while (in)
        {
          in.read(buffer.data(), buffer.size());
          h = hash64(buffer.data(), static_cast<std::size_t>(in.gcount()), h);
        }
      if (to_hex(h) != hash_text)
        fail("fails its checksum (the file is damaged)");
    }
    in.close();
    if (!expected_kind.empty() && kind != expected_kind)
      fail("is of kind '" + kind + "' (" + describe_archive_kind(kind)
           + "), not '" + expected_kind + "' ("
           + describe_archive_kind(expected_kind) + ")");

    // 2. Everything in it, read into memory; the file is closed on return.
    {
      const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT),
                        H5Fclose);
      if (!file.valid())
        fail("cannot be opened by HDF5 (damaged)");
      Visit visit;
      if (H5Lvisit(file, H5_INDEX_NAME, H5_ITER_INC, visit_link, &visit) < 0
          || visit.other)
        fail("has an unreadable structure (damaged)");
      for (const std::string &name : visit.datasets)
        {
          const Handle dataset(H5Dopen2(file, name.c_str(), H5P_DEFAULT),
                               H5Dclose);
          const Handle space(dataset.valid() ? H5Dget_space(dataset) : -1,
                             H5Sclose);
          const Handle type(dataset.valid() ? H5Dget_type(dataset) : -1,
                            H5Tclose);
          if (!space.valid() || !type.valid())
            fail("dataset '" + name + "' cannot be opened (damaged)");
          const int rank = H5Sget_simple_extent_ndims(space);
          if (rank < 1 || rank > 8)
            fail("dataset '" + name + "' has an unexpected shape");
          Entry e;
          e.shape.resize(rank);
          if (H5Sget_simple_extent_dims(space, e.shape.data(), nullptr) != rank)
            fail("dataset '" + name + "' has an unreadable shape (damaged)");
          const H5T_class_t type_class = H5Tget_class(type);
          const std::size_t type_size  = H5Tget_size(type);
          hid_t             mem_type   = -1;
          std::size_t       element    = 0;
          if (type_class == H5T_FLOAT && type_size == 8)
            {
              e.type   = 'f';
              mem_type = H5T_NATIVE_DOUBLE;
              element  = 8;
            }
          else if (type_class == H5T_INTEGER && type_size == 1)
            {
              e.type   = 't';
              mem_type = H5T_NATIVE_UCHAR;
              element  = 1;
            }
          else
            fail("dataset '" + name + "' has an unexpected type");
          const hssize_t n = H5Sget_simple_extent_npoints(space);
          if (n < 0 || static_cast<unsigned long long>(n) * element > size)
            fail("dataset '" + name + "' is larger than the file (damaged)");
          e.bytes.resize(static_cast<std::size_t>(n) * element);
          if (n > 0
              && H5Dread(dataset,
                         mem_type,
                         H5S_ALL,
                         H5S_ALL,
                         H5P_DEFAULT,
                         e.bytes.data())
                   < 0)
            fail("dataset '" + name
                 + "' cannot be read (Fletcher-32 checksum mismatch or "
                   "damaged data)");
          datasets.emplace(name, std::move(e));
        }
      std::vector<std::string> names;
      hsize_t                  index = 0;
      if (H5Aiterate2(
            file, H5_INDEX_NAME, H5_ITER_INC, &index, visit_attribute, &names)
          < 0)
        fail("has unreadable attributes (damaged)");
      for (const std::string &name : names)
        {
          const Handle attribute(H5Aopen(file, name.c_str(), H5P_DEFAULT),
                                 H5Aclose);
          const Handle type(attribute.valid() ? H5Aget_type(attribute) : -1,
                            H5Tclose);
          const Handle space(attribute.valid() ? H5Aget_space(attribute) : -1,
                             H5Sclose);
          if (!type.valid() || !space.valid()
              || H5Sget_simple_extent_type(space) != H5S_SCALAR)
            fail("attribute '" + name + "' cannot be read (damaged)");
          Entry             e;
          const H5T_class_t type_class = H5Tget_class(type);
          const std::size_t type_size  = H5Tget_size(type);
          if (type_class == H5T_FLOAT && type_size == 8)
            {
              double value = 0.0;
              if (H5Aread(attribute, H5T_NATIVE_DOUBLE, &value) < 0)
                fail("attribute '" + name + "' cannot be read (damaged)");
              e = {'f', {}, as_bytes({value})};
            }
          else if (type_class == H5T_STRING && !H5Tis_variable_str(type)
                   && type_size > 0 && type_size <= size)
            {
              std::string value(type_size, '\0');
              if (H5Aread(attribute, type, value.data()) < 0)
                fail("attribute '" + name + "' cannot be read (damaged)");
              value.erase(value.find_last_not_of('\0') + 1);
              e = text_entry(value);
            }
          else
            fail("attribute '" + name + "' has an unexpected type");
          attributes.emplace(name, std::move(e));
        }
    }

    // 3. The convention's attributes and the checksum of the content.
    const auto text = [&](const char *name) -> std::string {
      const auto it = attributes.find(name);
      if (it == attributes.end() || it->second.type != 't')
        fail("has no '" + std::string(name) + "' attribute (damaged)");
      return it->second.bytes;
    };
    if (text("format") != archive_format)
      fail("is not a compax archive (format '" + shown(text("format")) + "')");
    const auto v = attributes.find("format_version");
    if (v == attributes.end() || v->second.type != 'f'
        || as_doubles(v->second.bytes).at(0) != archive_format_version)
      fail("has another archive format version than its header (damaged)");
    if (text("kind") != kind)
      fail("has another kind than its header (damaged)");
    if (text("checksum")
        != to_hex(archive_detail::content_checksum(datasets, attributes)))
      fail("fails the checksum of its datasets and attributes (damaged)");
    archive_kind_  = kind;
    parameter_text = text("parameters");
    if (text("parameters_hash") != parameter_fingerprint(parameter_text))
      fail("fails the checksum of its parameters (damaged)");
    if (expected_parameters
        && parameter_fingerprint(*expected_parameters)
             != parameter_fingerprint(parameter_text))
      {
        std::string difference
          = first_parameter_difference(parameter_text, *expected_parameters);
        if (difference.empty())
          difference = "the parameter lists differ in order";
        fail("was written with other parameters: " + difference
             + " (resume with the parameters of the run that wrote it)");
      }
  }

  bool
  Hdf5ArchiveReader::has_array(const std::string &name) const
  {
    const auto it = datasets.find(name);
    return it != datasets.end() && it->second.type == 'f';
  }

  bool
  Hdf5ArchiveReader::has_text(const std::string &name) const
  {
    const auto it = datasets.find(name);
    return it != datasets.end() && it->second.type == 't';
  }

  bool
  Hdf5ArchiveReader::has_attribute(const std::string &name) const
  {
    return attributes.count(name) > 0;
  }

  const archive_detail::Entry &
  Hdf5ArchiveReader::dataset(const std::string &name, const char type) const
  {
    const auto it = datasets.find(name);
    if (it == datasets.end())
      fail(std::string("has no ") + (type == 'f' ? "array" : "text") + " '"
           + name + "'");
    if (it->second.type != type)
      fail("entry '" + name + "' is not "
           + (type == 'f' ? "an array" : "text"));
    return it->second;
  }

  const archive_detail::Entry &
  Hdf5ArchiveReader::attribute(const std::string &name, const char type) const
  {
    const auto it = attributes.find(name);
    if (it == attributes.end())
      fail("has no attribute '" + name + "'");
    if (it->second.type != type)
      fail("attribute '" + name + "' is not "
           + (type == 'f' ? "a number" : "text"));
    return it->second;
  }

  std::vector<hsize_t>
  Hdf5ArchiveReader::array_shape(const std::string &name) const
  {
    return dataset(name, 'f').shape;
  }

  std::vector<double>
  Hdf5ArchiveReader::read_array(const std::string &name) const
  {
    return as_doubles(dataset(name, 'f').bytes);
  }

  std::string
  Hdf5ArchiveReader::read_text(const std::string &name) const
  {
    return dataset(name, 't').bytes;
  }

  double
  Hdf5ArchiveReader::read_attribute(const std::string &name) const
  {
    return as_doubles(attribute(name, 'f').bytes).at(0);
  }

  std::string
  Hdf5ArchiveReader::read_text_attribute(const std::string &name) const
  {
    return attribute(name, 't').bytes;
  }
} // namespace compax::coupling
