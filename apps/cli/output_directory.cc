#include "apps/cli/output_directory.h"

#include "apps/cli/input_error.h"

#include <deal.II/base/mpi.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <system_error>

namespace compax::cli
{
  namespace fs = std::filesystem;

  namespace
  {
    /// Under mpirun only rank 0 creates, publishes and removes the folder;
    /// every rank writes its pieces into the same staging path.
    bool
    is_root()
    {
      return !dealii::Utilities::MPI::job_supports_mpi()
             || dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    }

    bool
    with_mpi()
    {
      return dealii::Utilities::MPI::job_supports_mpi()
             && dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1;
    }

    void
    barrier()
    {
      if (dealii::Utilities::MPI::job_supports_mpi())
        MPI_Barrier(MPI_COMM_WORLD);
    }

    /// Rank 0's text on every rank.
    std::string
    from_root(const std::string &text)
    {
      if (!with_mpi())
        return text;
      return dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, text, 0);
    }

    /// The absolute, normalised path with symbolic links of its existing
    /// part resolved.
    fs::path
    resolved(const fs::path &path)
    {
      std::error_code error;
      fs::path        p = fs::weakly_canonical(fs::absolute(path), error);
      if (error)
        p = fs::absolute(path).lexically_normal();
      // "a/b/" names the folder a/b.
      if (p.has_parent_path() && p.filename().empty())
        p = p.parent_path();
      return p;
    }

    /// Whether @p inner is @p outer or lies inside it.
    bool
    inside(const fs::path &inner, const fs::path &outer)
    {
      auto i = inner.begin();
      for (auto o = outer.begin(); o != outer.end(); ++o, ++i)
        if (i == inner.end() || *i != *o)
          return false;
      return true;
    }

    [[noreturn]] void
    refuse(const fs::path &path, const std::string &why)
    {
      throw InputError("output folder (-o) '" + path.string() + "' " + why);
    }

    /// The files an earlier compax run listed in its marker; false if
    /// @p folder has no readable marker.
    bool
    read_manifest(const fs::path &folder, std::set<std::string> &files)
    {
      std::ifstream in(folder / output_marker);
      std::string   line;
      if (!in || !std::getline(in, line) || line.rfind("compax-output", 0) != 0)
        return false;
      bool listed = false;
      while (std::getline(in, line))
        if (listed)
          files.insert(line);
        else if (line == "files:")
          listed = true;
      return listed;
    }

    /// The first entry below @p folder that is not in @p files (or a
    /// folder of them); empty if there is none.
    std::string
    foreign_entry(const fs::path &folder, const std::set<std::string> &files)
    {
      std::set<std::string> folders;
      for (const std::string &f : files)
        for (fs::path p = fs::path(f).parent_path(); !p.empty();
             p          = p.parent_path())
          folders.insert(p.generic_string());
      std::error_code error;
      for (fs::recursive_directory_iterator
             it(folder, fs::directory_options::none, error),
           end;
           !error && it != end;
           it.increment(error))
        {
          const std::string name
            = it->path().lexically_relative(folder).generic_string();
          if (name == output_marker)
            continue;
          const bool is_folder
            = it->is_directory(error) && !it->is_symlink(error);
          if (is_folder ? folders.count(name) == 0 : files.count(name) == 0)
            return name;
        }
      if (error)
        return "(unreadable: " + error.message() + ")";
      return {};
    }

    /// Every file below @p folder (relative, '/'-separated, sorted).
    std::vector<std::string>
    list_files(const fs::path &folder)
    {
      std::vector<std::string> files;
      for (const auto &e : fs::recursive_directory_iterator(folder))
        if (!e.is_directory())
          {
            const std::string name
              = e.path().lexically_relative(folder).generic_string();
            if (name != output_marker)
              files.push_back(name);
          }
      std::sort(files.begin(), files.end());
      return files;
    }

    /// Whether an existing OUTDIR may be replaced; throws if not.
    void
    check_existing(const fs::path    &shown,
                   const fs::path    &path,
                   const OutputRules &rules)
    {
      std::error_code error;
      const auto      status = fs::symlink_status(path, error);
      if (error || !fs::exists(status))
        return;
      if (fs::is_symlink(status))
        refuse(shown, "is a symbolic link; compax does not replace it");
      if (!fs::is_directory(status))
        refuse(shown,
               "is an existing file, not a folder; compax never replaces "
               "it (choose another OUTDIR)");
      if (fs::is_empty(path, error) && !error)
        return;
      std::set<std::string> files;
      if (!read_manifest(path, files))
        refuse(shown,
               "exists and holds files that compax did not write; compax "
               "never deletes them (choose a new or empty OUTDIR)");
      const std::string foreign = foreign_entry(path, files);
      if (!foreign.empty())
        refuse(shown,
               "holds an earlier compax output and '" + foreign
                 + "', which compax did not write; move it away or choose "
                   "another OUTDIR (compax never deletes it)");
      if (!rules.overwrite)
        refuse(shown,
               "holds the output of an earlier compax run; add --overwrite "
               "to replace it, or choose another OUTDIR");
    }
  } // namespace

  void
  check_output_directory(const fs::path &path, const OutputRules &rules)
  {
    if (path.empty())
      throw InputError("option '-o' needs a folder name; got an empty one");
    const fs::path target = resolved(path);
    if (target == target.root_path())
      refuse(path, "is the root folder; OUTDIR must be a new folder");
    if (const char *home = std::getenv("HOME"); home && *home)
      if (target == resolved(home))
        refuse(path, "is the home folder; OUTDIR must be a new folder");
    if (inside(resolved(fs::current_path()), target))
      refuse(path,
             target == resolved(fs::current_path())
               ? "is the working folder; OUTDIR must be a new folder"
               : "holds the working folder; OUTDIR must be a new folder");
    for (const fs::path &input : rules.inputs)
      if (inside(resolved(input), target))
        refuse(path,
               "holds the input file '" + input.string()
                 + "'; OUTDIR must be a new folder");
    std::error_code error;
    for (fs::path p = target.parent_path(); !p.empty() && p != p.parent_path();
         p          = p.parent_path())
      if (fs::exists(p, error))
        {
                   if (!fs::is_directory(p, error))
            refuse(path, "lies below '" + p.string() + "', which is a file");
          break;
        }
    check_existing(path, target, rules);
  }

  OutputDirectory::OutputDirectory(fs::path path, OutputRules rules_)
      : rules(std::move(rules_))
  {
    std::string error_text;
    if (is_root())
      {
        try
          {
            check_output_directory(path, rules);
            final_path               = resolved(path);
            const fs::path    shown  = path;
            const fs::path    parent = final_path.parent_path();
            const std::string name   = final_path.filename().string();

            // Parent folders are created (and removed again on failure).
            std::vector<fs::path> missing;
            for (fs::path p = parent; !fs::exists(p); p = p.parent_path())
              missing.push_back(p);
            for (auto it = missing.rbegin(); it != missing.rend(); ++it)
              {
                std::error_code error;
                if (!fs::create_directory(*it, error) && error)
                  refuse(shown,
                         "cannot be created (" + it->string() + ": "
                           + error.message() + ")");
                created_parents.push_back(*it);
              }

            // The lock: one run per OUTDIR. A lock file whose holder died
            // is taken over; the holder removes it when it is done, and a
            // run that locked a file removed meanwhile tries again.
            lock_path = parent / ("." + name + ".lock");
            for (int attempt = 0; attempt < 100 && lock_fd < 0; ++attempt)
              {
                const int fd = ::open(lock_path.c_str(),
                                      O_RDWR | O_CREAT | O_CLOEXEC,
                                      0644);
                if (fd < 0)
                  refuse(shown,
                         "cannot be locked (" + lock_path.string() + ": "
                           + std::strerror(errno) + ")");
                if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
                  {
                    std::string holder;
                    char        buffer[32] = {};
                    if (::pread(fd, buffer, sizeof(buffer) - 1, 0) > 0)
                      holder = std::string(buffer);
                    ::close(fd);
                    while (!holder.empty()
                           && std::isspace(
                             static_cast<unsigned char>(holder.back())))
                      holder.pop_back();
                    refuse(shown,
                           "is in use by another compax run"
                             + (holder.empty() ? std::string()
                                               : " (process " + holder + ")")
                             + "; wait for it to end or choose another "
                               "OUTDIR");
                  }
                struct stat held, named;
                if (::fstat(fd, &held) == 0
                    && ::stat(lock_path.c_str(), &named) == 0
                    && held.st_ino == named.st_ino
                    && held.st_dev == named.st_dev)
                  lock_fd = fd;
                else
                  ::close(fd);
              }
            if (lock_fd < 0)
              refuse(shown, "cannot be locked (" + lock_path.string() + ")");
            const std::string pid = std::to_string(::getpid()) + "\n";
            if (::ftruncate(lock_fd, 0) != 0
                || ::pwrite(lock_fd, pid.data(), pid.size(), 0) < 0)
              { // the pid is information only
              }

            // Under the lock: the folder may have changed since the check.
            check_existing(shown, final_path, rules);
            staging_path
              = parent
                / ("." + name + ".partial-" + std::to_string(::getpid()));
            std::error_code error;
            fs::remove_all(staging_path, error);
            if (!fs::create_directory(staging_path, error) || error)
              refuse(shown,
                     "cannot be created (" + staging_path.string() + ": "
                       + error.message() + ")");
          }
        catch (const InputError &e)
          {
            error_text = e.what();
          }
      }
    error_text = from_root(error_text);
    if (!error_text.empty())
      {
        release_lock();
        for (auto it = created_parents.rbegin(); it != created_parents.rend();
             ++it)
          {
            std::error_code ignored;
            fs::remove(*it, ignored); // only if still empty
          }
        throw InputError(error_text);
      }
    final_path   = from_root(final_path.string());
    staging_path = from_root(staging_path.string());
  }

  void
  OutputDirectory::release_lock()
  {
    if (lock_fd >= 0)
      {
        std::error_code ignored;
        fs::remove(lock_path, ignored);
        ::close(lock_fd);
        lock_fd = -1;
      }
  }

  OutputDirectory::~OutputDirectory()
  {
    if (!published && is_root())
      {
        std::error_code ignored;
        fs::remove_all(staging_path, ignored);
        for (auto it = created_parents.rbegin(); it != created_parents.rend();
             ++it)
          fs::remove(*it, ignored); // only if still empty
      }
    release_lock();
  }

  void
  OutputDirectory::publish()
  {
    barrier();
    std::string error_text;
    if (is_root())
      {
        try
          {
            {
              std::ofstream marker(staging_path / output_marker);
              marker << "compax-output 1\ncommand " << rules.command
                     << "\nversion " << rules.version << "\nfiles:\n";
              for (const std::string &f : list_files(staging_path))
                marker << f << '\n';
              if (!marker)
                throw InputError("cannot write the marker file in '"
                                 + staging_path.string() + "'");
            }
            try
              {
                check_existing(final_path, final_path, rules);
              }
            catch (const InputError &e)
              {
                published = true; // the results stay where they are
                throw InputError(
                  std::string(e.what())
                  + " (it changed during the run); the results are in '"
                  + staging_path.string() + "'");
              }
            std::error_code error;
            fs::path        old;
            if (fs::exists(final_path, error))
              {
                if (fs::is_empty(final_path, error))
                  fs::remove(final_path, error);
                else
                  {
                    old = final_path.parent_path()
                          / ("." + final_path.filename().string() + ".replaced-"
                             + std::to_string(::getpid()));
                    fs::rename(final_path, old, error);
                  }
                if (error)
                  {
                    published = true;
                    throw InputError("output folder '" + final_path.string()
                                     + "' cannot be replaced ("
                                     + error.message() + "); the results are "
                                     + "in '" + staging_path.string() + "'");
                  }
              }
            fs::rename(staging_path, final_path, error);
            if (error)
              {
                published = true;
                throw InputError("output folder '" + final_path.string()
                                 + "' cannot be created (" + error.message()
                                 + "); the results are in '"
                                 + staging_path.string() + "'");
              }
            // The earlier compax output it replaced (checked above to
            // hold only files compax wrote).
            if (!old.empty())
              fs::remove_all(old, error);
          }
        catch (const InputError &e)
          {
            error_text = e.what();
          }
      }
    published  = true;
    error_text = from_root(error_text);
    release_lock();
    if (!error_text.empty())
      throw InputError(error_text);
  }
} // namespace compax::cli
