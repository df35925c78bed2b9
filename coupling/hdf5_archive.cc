#include "coupling/hdf5_archive.h"

#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <numeric>
#include <system_error>
#include <utility>

namespace compax::coupling
{
  /**
   * deal.II's HDF5::File plus access to its raw handle, for the existence
   * queries (H5Lexists, H5Aexists) and the flush that the wrappers lack.
   * The handle is the protected member of the wrapper's base class.
   */
  class Hdf5ArchiveWriter::File : public dealii::HDF5::File
  {
  public:
    using dealii::HDF5::File::File;

    hid_t
    id() const
    {
      return *hdf5_reference;
    }

    /// Whether the '/'-separated @p path names a link below the root. Each
    /// leading component is checked to be an existing group first, so that
    /// HDF5 never reports (and prints) an error.
    bool
    has_link(const std::string &path) const
    {
      if (path.empty())
        return false;
      std::size_t slash = path.find('/');
      while (slash != std::string::npos)
        {
          if (object_type(path.substr(0, slash)) != H5I_GROUP)
            return false;
          slash = path.find('/', slash + 1);
        }
      return H5Lexists(id(), path.c_str(), H5P_DEFAULT) > 0;
    }

    /// H5I_GROUP, H5I_DATASET, ... of the object at @p path, whose parent
    /// groups must exist; H5I_BADID if there is none.
    H5I_type_t
    object_type(const std::string &path) const
    {
      if (path.empty() || H5Lexists(id(), path.c_str(), H5P_DEFAULT) <= 0)
        return H5I_BADID;
      const hid_t object = H5Oopen(id(), path.c_str(), H5P_DEFAULT);
      if (object < 0)
        return H5I_BADID;
      const H5I_type_t type = H5Iget_type(object);
      H5Oclose(object);
      return type;
    }

    bool
    is_dataset(const std::string &path) const
    {
      return has_link(path) && object_type(path) == H5I_DATASET;
    }

    /// The HDF5 type class (H5T_FLOAT, H5T_STRING, ...) of the root
    /// attribute @p name, which must exist.
    H5T_class_t
    root_attribute_class(const std::string &name) const
    {
      const hid_t       attribute = H5Aopen(id(), name.c_str(), H5P_DEFAULT);
      const hid_t       type      = H5Aget_type(attribute);
      const H5T_class_t result    = H5Tget_class(type);
      H5Tclose(type);
      H5Aclose(attribute);
      return result;
    }

    bool
    has_root_attribute(const std::string &name) const
    {
      return !name.empty() && H5Aexists(id(), name.c_str()) > 0;
    }
  };

  namespace
  {
    [[noreturn]] void
    fail(const std::string &file, const std::string &what)
    {
      throw Hdf5ArchiveError("HDF5 archive '" + file + "': " + what);
    }

    /// Flushes @p path (a file or a directory) to stable storage.
    void
    sync_path(const std::string &path, bool directory)
    {
      const int fd
        = ::open(path.c_str(), directory ? O_RDONLY | O_DIRECTORY : O_RDONLY);
      if (fd < 0 && directory) // best effort: the rename is already done
        return;
      if (fd < 0)
        fail(path, "cannot open to sync");
      const int rc = ::fsync(fd);
      ::close(fd);
      if (rc != 0 && !directory) // some file systems refuse directory fsync
        fail(path, "fsync failed");
    }
  } // namespace

  Hdf5ArchiveWriter::Hdf5ArchiveWriter(std::string path_)
      : target(std::move(path_))
      , temporary(target + ".tmp")
  {
    if (target.empty())
      throw Hdf5ArchiveError("HDF5 archive: empty file name");
    const std::filesystem::path parent
      = std::filesystem::path(target).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent))
      fail(target, "directory '" + parent.string() + "' does not exist");
    file = std::make_unique<File>(temporary,
                                  dealii::HDF5::File::FileAccessMode::create);
    if (file->id() < 0)
      fail(temporary, "cannot create");
  }

  Hdf5ArchiveWriter::~Hdf5ArchiveWriter()
  {
    if (file)
      {
        file.reset();
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
      }
  }

  void
  Hdf5ArchiveWriter::check_open(const std::string &name) const
  {
    if (!file)
      fail(target, "write of '" + name + "' after commit()");
    if (name.empty() || name.front() == '/' || name.back() == '/')
      fail(target, "invalid entry name '" + name + "'");
  }

  void
  Hdf5ArchiveWriter::create_parent_groups(const std::string &name)
  {
    std::size_t slash = name.find('/');
    while (slash != std::string::npos)
      {
        const std::string group = name.substr(0, slash);
        const H5I_type_t  type  = file->object_type(group);
        if (type == H5I_BADID)
          file->create_group(group);
        else if (type != H5I_GROUP)
          fail(target, "'" + group + "' is an array, not a group");
        slash = name.find('/', slash + 1);
      }
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
    check_open(name);
    const hsize_t n = std::accumulate(shape.begin(),
                                      shape.end(),
                                      hsize_t(1),
                                      std::multiplies<hsize_t>());
    if (shape.empty() || n != values.size())
      fail(target,
           "array '" + name + "' has " + std::to_string(values.size())
             + " values, which its shape does not hold");
    if (file->has_link(name))
      fail(target, "entry '" + name + "' written twice");
    create_parent_groups(name);
    auto dataset = file->create_dataset<double>(name, shape);
    if (n > 0)
      dataset.write(values);
  }

  void
  Hdf5ArchiveWriter::write_attribute(const std::string &name,
                                     const double       value)
  {
    check_open(name);
    if (file->has_root_attribute(name))
      fail(target, "attribute '" + name + "' written twice");
    file->set_attribute(name, value);
  }

  void
  Hdf5ArchiveWriter::write_attribute(const std::string &name,
                                     const std::string &value)
  {
    check_open(name);
    if (file->has_root_attribute(name))
      fail(target, "attribute '" + name + "' written twice");
    file->set_attribute(name, value);
  }

  void
  Hdf5ArchiveWriter::commit()
  {
    if (!file)
      fail(target, "commit() called twice");
    if (H5Fflush(file->id(), H5F_SCOPE_GLOBAL) < 0)
      fail(temporary, "flush failed");
    file.reset(); // closes the file
    sync_path(temporary, false);
    std::error_code error;
    std::filesystem::rename(temporary, target, error);
    if (error)
      fail(target, "cannot rename the temporary onto it: " + error.message());
    const std::filesystem::path parent
      = std::filesystem::path(target).parent_path();
    sync_path(parent.empty() ? std::string(".") : parent.string(), true);
  }

  Hdf5ArchiveReader::Hdf5ArchiveReader(std::string path_)
      : path(std::move(path_))
  {
    if (!std::filesystem::is_regular_file(path))
      fail(path, "no such file");
    if (H5Fis_hdf5(path.c_str()) <= 0)
      fail(path, "not an HDF5 file");
    file = std::make_unique<Hdf5ArchiveWriter::File>(
      path, dealii::HDF5::File::FileAccessMode::open);
    if (file->id() < 0)
      fail(path, "cannot open");
  }

  Hdf5ArchiveReader::~Hdf5ArchiveReader() = default;

  bool
  Hdf5ArchiveReader::has_array(const std::string &name) const
  {
    return file->is_dataset(name);
  }

  bool
  Hdf5ArchiveReader::has_attribute(const std::string &name) const
  {
    return file->has_root_attribute(name);
  }

  void
  Hdf5ArchiveReader::require_array(const std::string &name) const
  {
    if (!has_array(name))
      fail(path, "no array '" + name + "'");
  }

  void
  Hdf5ArchiveReader::require_attribute(const std::string &name) const
  {
    if (!has_attribute(name))
      fail(path, "no attribute '" + name + "'");
  }

  std::vector<hsize_t>
  Hdf5ArchiveReader::array_shape(const std::string &name) const
  {
    require_array(name);
    return file->open_dataset(name).get_dimensions();
  }

  std::vector<double>
  Hdf5ArchiveReader::read_array(const std::string &name) const
  {
    require_array(name);
    auto dataset = file->open_dataset(name);
    if (dataset.get_size() == 0)
      return {};
    return dataset.read<std::vector<double>>();
  }

  double
  Hdf5ArchiveReader::read_attribute(const std::string &name) const
  {
    require_attribute(name);
    if (file->root_attribute_class(name) != H5T_FLOAT)
      fail(path, "attribute '" + name + "' is not a number");
    return file->get_attribute<double>(name);
  }

  std::string
  Hdf5ArchiveReader::read_text_attribute(const std::string &name) const
  {
    require_attribute(name);
    if (file->root_attribute_class(name) != H5T_STRING)
      fail(path, "attribute '" + name + "' is not text");
    return file->get_attribute<std::string>(name);
  }
} // namespace compax::coupling
