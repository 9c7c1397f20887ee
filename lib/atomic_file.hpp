#pragma once
/// \file
/// Output files that are complete or absent, never half written, whatever the disk does (full,
/// a file size limit) and whenever the process is stopped. Two kinds:
/// - a file written whole (a frame mesh, a PNG, a report): its bytes go to a temporary name in
///   the same folder, which is renamed over the target once every byte is written and the file is
///   closed. rename(2) replaces the target atomically within one file system (POSIX), so a reader
///   sees the old file or the new one; on failure the temporary is removed.
/// - a file that grows by records (stats.csv, AppendFile): each record is written with one
///   write(2) where possible and, if the disk refuses part of it, the file is cut back to its last
///   complete record.
/// No fsync: this guards against full disks and killed processes, not against power loss.
/// Every failure throws a FileWriteError naming the target (not the temporary) and the cause
/// (strerror: "No space left on device", "File too large"). CGAL-free, POSIX.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace tissu {

/// A file that could not be written: "<file>: cannot write <what>: <cause>".
class FileWriteError : public std::runtime_error {
 public:
  FileWriteError(const std::filesystem::path& file, const std::string& what,
                 const std::string& cause);
  const std::filesystem::path& file() const { return m_file; }

 private:
  std::filesystem::path m_file;
};

/// A fresh name for a temporary file beside `file`, in the same folder (so that renaming it over
/// `file` stays within one file system): ".<file name>.tmp<pid>_<n>", hidden, unique to this
/// process and call. After a SIGKILL or a power loss such a file may be left over; it can be
/// deleted.
std::filesystem::path temporary_path_beside(const std::filesystem::path& file);

/// Writes `contents` to `file`, replacing it, through a temporary file beside it (see the file
/// comment): on return `file` holds exactly `contents`; on failure it is as before (absent, or
/// the previous file) and no temporary is left. `what` names the contents for the message
/// ("mesh", "PNG image"). Throws FileWriteError.
void write_file_atomically(const std::filesystem::path& file, std::string_view contents,
                           const std::string& what);

/// A file that another program writes (ffmpeg, gnuplot), made to appear whole or not at all: the
/// program writes temporary(), commit() renames it to the target; a PendingFile destroyed without
/// commit() removes the temporary.
class PendingFile {
 public:
  PendingFile(std::filesystem::path target, std::string what);
  ~PendingFile();
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;

  const std::filesystem::path& target() const { return m_target; }
  const std::filesystem::path& temporary() const { return m_temporary; }
  /// Renames temporary() to target(). Throws FileWriteError if the temporary is not a regular
  /// file or cannot be renamed (the temporary is then removed).
  void commit();

 private:
  std::filesystem::path m_target;
  std::filesystem::path m_temporary;
  std::string m_what;
  bool m_committed = false;
};

/// A file written record by record (stats.csv), created empty (replacing any file of its name).
/// After every append the file ends with a whole record: append() writes the record to the
/// operating system at once (nothing is buffered in the process, so a killed process loses no
/// written record), and when the disk refuses part of it, the file is cut back to its length
/// before that record and FileWriteError is thrown.
class AppendFile {
 public:
  /// Throws FileWriteError if `file` cannot be created. `what` names the contents for messages.
  AppendFile(std::filesystem::path file, std::string what);
  ~AppendFile();
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;

  /// Appends `record` whole, or throws FileWriteError and leaves the file as it was.
  void append(std::string_view record);
  /// Rewrites bytes already written at `offset` (a header's record count) in place; throws
  /// FileWriteError. Needs no new space, so a full disk does not refuse it.
  void overwrite(long long offset, std::string_view bytes);
  const std::filesystem::path& file() const { return m_file; }

 private:
  std::filesystem::path m_file;
  std::string m_what;
  int m_fd = -1;
  long long m_size = 0;  ///< bytes of complete records written (bytes)
};

}  // namespace tissu
