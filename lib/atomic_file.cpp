#include "lib/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

namespace tissu {
namespace {

namespace fs = std::filesystem;

std::string errno_text(int error) {
  return std::strerror(error);
}

/// Writes all of `data` to `fd`, retrying short writes and interruptions; 0, or the errno of the
/// write that failed.
int write_all(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = ::write(fd, data.data(), data.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return EIO;  // no progress and no error: give up rather than spin
    data.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

}  // namespace

FileWriteError::FileWriteError(const fs::path& file, const std::string& what,
                               const std::string& cause)
    : std::runtime_error(file.string() + ": cannot write " + what + ": " + cause), m_file(file) {}

fs::path temporary_path_beside(const fs::path& file) {
  static std::atomic<unsigned long> made{0};  // one name per call of this process
  // appended piece by piece: GCC 12 warns (-Wrestrict, falsely) about "." + std::string
  std::string name(".");
  name += file.filename().string();
  name += ".tmp";
  name += std::to_string(::getpid());
  name += '_';
  name += std::to_string(made++);
  return file.parent_path() / name;
}

void write_file_atomically(const fs::path& file, std::string_view contents,
                           const std::string& what) {
  const fs::path temporary = temporary_path_beside(file);
  // a name of this process's (its pid), so no other process is writing it: truncate what a dead
  // process of the same pid may have left
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw FileWriteError(file, what, errno_text(errno));
  int error = write_all(fd, contents);
  // close reports what some file systems (NFS) only learn then
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error == 0 && ::rename(temporary.c_str(), file.c_str()) != 0) error = errno;
  if (error != 0) {
    ::unlink(temporary.c_str());
    throw FileWriteError(file, what, errno_text(error));
  }
}

PendingFile::PendingFile(fs::path target, std::string what)
    : m_target(std::move(target)),
      m_temporary(temporary_path_beside(m_target)),
      m_what(std::move(what)) {}

PendingFile::~PendingFile() {
  if (!m_committed) ::unlink(m_temporary.c_str());
}

void PendingFile::commit() {
  struct stat info {};
  int error = 0;
  if (::stat(m_temporary.c_str(), &info) != 0)
    error = errno;
  else if (!S_ISREG(info.st_mode))
    error = EINVAL;
  if (error == 0 && ::rename(m_temporary.c_str(), m_target.c_str()) != 0) error = errno;
  if (error != 0) {
    ::unlink(m_temporary.c_str());
    m_committed = true;  // nothing left to remove
    throw FileWriteError(m_target, m_what, errno_text(error));
  }
  m_committed = true;
}

AppendFile::AppendFile(fs::path file, std::string what)
    : m_file(std::move(file)), m_what(std::move(what)) {
  m_fd = ::open(m_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0666);
  if (m_fd < 0) throw FileWriteError(m_file, m_what, errno_text(errno));
}

AppendFile::~AppendFile() {
  if (m_fd >= 0) ::close(m_fd);
}

void AppendFile::append(std::string_view record) {
  const int error = write_all(m_fd, record);
  if (error != 0) {
    // cut back to the last whole record: shrinking needs no space (a failure here leaves a
    // partial record, and the message says why the run stopped all the same)
    while (::ftruncate(m_fd, static_cast<off_t>(m_size)) != 0 && errno == EINTR) {
    }
    throw FileWriteError(m_file, m_what, errno_text(error));
  }
  m_size += static_cast<long long>(record.size());
}

void AppendFile::overwrite(long long offset, std::string_view bytes) {
  // through a descriptor of its own: on Linux, pwrite(2) on an O_APPEND one appends all the same
  const int fd = ::open(m_file.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) throw FileWriteError(m_file, m_what, errno_text(errno));
  int error = 0;
  for (std::size_t done = 0; done < bytes.size() && error == 0;) {
    const ssize_t n = ::pwrite(fd, bytes.data() + done, bytes.size() - done,
                               static_cast<off_t>(offset + static_cast<long long>(done)));
    if (n > 0)
      done += static_cast<std::size_t>(n);
    else if (n == 0 || errno != EINTR)
      error = n == 0 ? EIO : errno;
  }
  ::close(fd);
  if (error != 0) throw FileWriteError(m_file, m_what, errno_text(error));
}

}  // namespace tissu
