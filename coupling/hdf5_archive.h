#pragma once

#include <deal.II/base/hdf5.h>

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace compax::coupling
{
  /// Thrown for any archive problem (missing file, not HDF5, missing or
  /// mis-sized entry); what() names the file and the entry.
  class Hdf5ArchiveError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * Writes one HDF5 archive (the RVE and die checkpoint store): named
   * arrays of doubles of any shape (row-major) and named scalar attributes
   * on the file root. Names may contain '/' to place entries in groups,
   * which are created on the way.
   *
   * Everything goes to "<path>.tmp"; commit() closes it, flushes it to disk
   * and renames it onto @p path. A crash or an exception before commit()
   * leaves any previous archive at @p path untouched, never a half-written
   * one; the destructor of an uncommitted writer removes the temporary.
   *
   * The file is written serially: in an MPI run, gather the data and write
   * from one rank.
   */
  class Hdf5ArchiveWriter
  {
  public:
    /// Creates (truncates) "<path>.tmp".
    explicit Hdf5ArchiveWriter(std::string path);
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

    /// Writes a scalar attribute of the root.
    void
    write_attribute(const std::string &name, double value);

    /// Writes a text attribute of the root (format tags, units, versions).
    void
    write_attribute(const std::string &name, const std::string &value);

    /// Closes the temporary and atomically renames it onto the target path.
    /// No more writes afterwards.
    void
    commit();

    const std::string &
    path() const
    {
      return target;
    }

    /// Implementation detail (defined in the .cc): deal.II's HDF5::File
    /// with access to its raw handle for existence queries and flushing.
    class File;

  private:
    /// Creates the groups named by the '/'-separated prefix of @p name.
    void
    create_parent_groups(const std::string &name);

    void
    check_open(const std::string &name) const;

    std::string           target;
    std::string           temporary;
    std::unique_ptr<File> file;
  };

  /**
   * Reads an archive written by Hdf5ArchiveWriter. Every lookup checks that
   * the entry exists first and throws Hdf5ArchiveError otherwise.
   */
  class Hdf5ArchiveReader
  {
  public:
    /// Opens @p path read-only; throws Hdf5ArchiveError if it does not exist
    /// or is not an HDF5 file.
    explicit Hdf5ArchiveReader(std::string path);
    ~Hdf5ArchiveReader();

    Hdf5ArchiveReader(const Hdf5ArchiveReader &) = delete;
    Hdf5ArchiveReader &
    operator=(const Hdf5ArchiveReader &)
      = delete;

    bool
    has_array(const std::string &name) const;

    bool
    has_attribute(const std::string &name) const;

    /// The array's values, flattened row-major.
    std::vector<double>
    read_array(const std::string &name) const;

    /// The array's extents.
    std::vector<hsize_t>
    array_shape(const std::string &name) const;

    double
    read_attribute(const std::string &name) const;

    std::string
    read_text_attribute(const std::string &name) const;

  private:
    void
    require_array(const std::string &name) const;

    void
    require_attribute(const std::string &name) const;

    std::string                              path;
    std::unique_ptr<Hdf5ArchiveWriter::File> file;
  };
} // namespace compax::coupling
