#pragma once

#include "io/content_hash.h"
#include "io/file_error.h"

#include <hdf5.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace compax::coupling
{
  /**
   * @name The compax archive convention
   *
   * Every checkpoint and database compax writes is one HDF5 file of this
   * form, written by Hdf5ArchiveWriter and read by Hdf5ArchiveReader only:
   *
   * - a 512-byte header in HDF5's user block: "compax-archive", the format
   *   version, the kind of study, the file's length and a 64-bit hash of
   *   the header fields and every byte after the header; a reader checks
   *   it before HDF5 parses anything, so a truncated, damaged or foreign
   *   file never reaches the HDF5 library;
   * - root attributes `format` ("compax-archive"), `format_version`,
   *   `kind`, `parameters` (the canonical parameter text: one line
   *   "Subsection/Entry = value" per entry that must match on resume),
   *   `parameters_hash` (its fingerprint) and `checksum`, a 64-bit hash of
   *   every dataset and attribute in name order;
   * - datasets of doubles (and bytes, for long text), chunked with HDF5's
   *   Fletcher-32 filter.
   *
   * A reader refuses another kind, another version, another fingerprint
   * (naming the first differing entry), a checksum mismatch and a
   * truncated file with one Hdf5ArchiveError whose reason() is one line.
   * It reads the whole file into memory and closes it before it returns,
   * so nothing can unwind through an open HDF5 file.
   */
  ///@{

  /// The format tag of the header and of the `format` attribute.
  inline constexpr const char *archive_format = "compax-archive";

  /// The format version this compax writes and reads.
  inline constexpr int archive_format_version = 2;

  /// The kinds of study an archive holds.
  namespace archive_kind
  {
    /// checkpoints/compaction.h5 of `compax die`.
    inline constexpr const char *die_compaction = "die-compaction";
    /// checkpoints/branch-<k>.h5 of `compax die` (Rerun branch from).
    inline constexpr const char *die_branch = "die-branch";
    /// last_converged.h5 of a `compax die` run that stopped.
    inline constexpr const char *die_state = "die-state";
    /// checkpoints/rve.h5 of `compax rve`.
    inline constexpr const char *rve = "rve";
    /// One RVE state (last_converged.h5 of `compax rve`).
    inline constexpr const char *rve_state = "rve-state";
    /// database.h5 of `compax database`.
    inline constexpr const char *rve_database = "rve-database";
    /// checkpoints/database.h5 of `compax database`.
    inline constexpr const char *database_checkpoint = "database-checkpoint";
    /// checkpoint/tablet.h5 of `compax tablet`.
    inline constexpr const char *tablet = "tablet";
    /// checkpoint/rve.<rank>.h5 of a multiscale-fe2 tablet.
    inline constexpr const char *fe2_rve_states = "fe2-rve-states";
  } // namespace archive_kind

  /// What a kind of archive is, in words ("die compaction checkpoint").
  std::string
  describe_archive_kind(const std::string &kind);

  using io::file_hash;
  using io::hash64;
  using io::to_hex;

  /// hash64 of canonical parameter text in hex (the fingerprint).
  std::string
  parameter_fingerprint(const std::string &parameters);

  /**
   * The first entry in which two canonical parameter texts differ, as
   * "Material/Radius = 0.0002 in the archive, 0.00022 here"; empty if they
   * hold the same entries and values.
   */
  std::string
  first_parameter_difference(const std::string &archived,
                             const std::string &expected);
  ///@}

  /// Thrown for any archive problem (missing file, foreign or damaged file,
  /// missing or mis-sized entry). what() names the file; reason() is the
  /// problem alone, one line, for messages that name the file themselves.
  class Hdf5ArchiveError : public io::FileError
  {
  public:
    Hdf5ArchiveError(const std::string &file, const std::string &reason);
  };

  namespace archive_detail
  {
    /// One dataset or attribute as its bytes (what the checksum covers).
    struct Entry
    {
      char                 type = 'f'; // 'f' doubles, 't' text
      std::vector<hsize_t> shape;
      std::string          bytes;
    };

    /// The checksum of an archive's datasets and root attributes (all but
    /// `checksum`), in name order.
    std::uint64_t
    content_checksum(const std::map<std::string, Entry> &datasets,
                     const std::map<std::string, Entry> &attributes);
  } // namespace archive_detail

  /// What an archive holds: its kind and the canonical text of the
  /// parameters that must match when it is read (empty if none do).
  struct ArchiveIdentity
  {
    std::string kind;
    std::string parameters;
  };

  /**
   * Writes one archive: named arrays of doubles of any shape (row-major),
   * long text, and named scalar attributes of the root. Names may contain
   * '/' to place entries in groups. The root attributes of the convention
   * are written by the writer itself (their names are reserved).
   *
   * Everything goes to "<path>.tmp"; commit() computes the checksums,
   * closes the file, writes its header, flushes it to disk and renames it
   * onto @p path. A crash or an exception before commit() leaves any
   * previous archive at @p path untouched; the destructor of an
   * uncommitted writer removes the temporary. Written serially: in an MPI
   * run, gather the data or write one file per rank.
   */
  class Hdf5ArchiveWriter
  {
  public:
    /// Creates (truncates) "<path>.tmp".
    Hdf5ArchiveWriter(std::string path, ArchiveIdentity identity);
    ~Hdf5ArchiveWriter();

    Hdf5ArchiveWriter(const Hdf5ArchiveWriter &) = delete;
    Hdf5ArchiveWriter &
    operator=(const Hdf5ArchiveWriter &)
      = delete;

    /// Writes a 1-D array.
    void
    write_array(const std::string &name, const std::vector<double> &values);

    /// Writes an array of the given @p shape; values.size() must equal the
    /// product of the extents (row-major, last index fastest).
    void
    write_array(const std::string          &name,
                const std::vector<double>  &values,
                const std::vector<hsize_t> &shape);

    /// Writes text of any length as a dataset of bytes.
    void
    write_text(const std::string &name, const std::string &text);

    /// Writes a scalar attribute of the root.
    void
    write_attribute(const std::string &name, double value);

    /// Writes a (short) text attribute of the root.
    void
    write_attribute(const std::string &name, const std::string &value);

    /// Writes a text attribute; a string literal is text, not a bool.
    void
    write_attribute(const std::string &name, const char *value)
    {
      write_attribute(name, std::string(value));
    }

    /// Closes the temporary and atomically renames it onto the target path.
    /// No more writes afterwards.
    void
    commit();

    const std::string &
    path() const
    {
      return target;
    }

  private:
    using Entry = archive_detail::Entry;

    void
    check_name(const std::string &name, bool attribute) const;

    void
    write_dataset(const std::string &name, Entry entry);

    void
    put_attribute(const std::string &name, Entry entry);

    std::string                  target;
    std::string                  temporary;
    hid_t                        file = -1;
    std::map<std::string, Entry> datasets;
    std::map<std::string, Entry> attributes;
    std::set<std::string>        groups;
  };

  /**
   * Writes the archive @p path of @p identity atomically: @p fill writes
   * its entries through the Hdf5ArchiveWriter it is given, then the archive
   * is committed. If @p fill throws, nothing is committed and any previous
   * archive at @p path stays as it was.
   */
  template <typename Fill>
  void
  write_archive(const std::string &path, ArchiveIdentity identity, Fill &&fill)
  {
    Hdf5ArchiveWriter archive(path, std::move(identity));
    fill(archive);
    archive.commit();
  }

  /**
   * Reads an archive written by Hdf5ArchiveWriter. The constructor checks
   * the header (format, version, length, hash), the kind, the checksum of
   * the datasets and attributes and, if given, the parameters, reads
   * everything and closes the file; every failure is one
   * Hdf5ArchiveError. Lookups of missing entries throw it too.
   */
  class Hdf5ArchiveReader
  {
  public:
    /// Opens @p path and checks its integrity; any kind and parameters.
    explicit Hdf5ArchiveReader(std::string path);

    /// Opens @p path and checks that it is an intact archive of
    /// @p expected_kind whose parameters, if @p expected_parameters is
    /// given, equal it.
    Hdf5ArchiveReader(std::string                       path,
                      const std::string                &expected_kind,
                      const std::optional<std::string> &expected_parameters
                      = std::nullopt);

    Hdf5ArchiveReader(Hdf5ArchiveReader &&) = default;
    Hdf5ArchiveReader &
    operator=(Hdf5ArchiveReader &&)
      = default;

    const std::string &
    kind() const
    {
      return archive_kind_;
    }

    const std::string &
    parameters() const
    {
      return parameter_text;
    }

    bool
    has_array(const std::string &name) const;

    bool
    has_text(const std::string &name) const;

    bool
    has_attribute(const std::string &name) const;

    /// The array's values, flattened row-major.
    std::vector<double>
    read_array(const std::string &name) const;

    /// The array's extents.
    std::vector<hsize_t>
    array_shape(const std::string &name) const;

    std::string
    read_text(const std::string &name) const;

    double
    read_attribute(const std::string &name) const;

    std::string
    read_text_attribute(const std::string &name) const;

    const std::string &
    file() const
    {
      return path;
    }

  private:
    using Entry = archive_detail::Entry;

    void
    load(const std::string                &expected_kind,
         const std::optional<std::string> &expected_parameters);

    [[noreturn]] void
    fail(const std::string &reason) const;

    const Entry &
    dataset(const std::string &name, char type) const;

    const Entry &
    attribute(const std::string &name, char type) const;

    std::string                  path;
    std::string                  archive_kind_;
    std::string                  parameter_text;
    std::map<std::string, Entry> datasets;
    std::map<std::string, Entry> attributes;
  };

  /// Opens an archive of @p kind (see Hdf5ArchiveReader).
  Hdf5ArchiveReader
  open_archive(const std::string                &path,
               const std::string                &kind,
               const std::optional<std::string> &parameters = std::nullopt);
} // namespace compax::coupling
