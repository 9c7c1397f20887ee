#pragma once
// A file size limit for the test process (RLIMIT_FSIZE, what `ulimit -f` sets): writes past it fail
// with EFBIG, as writes to a full disk fail with ENOSPC, which makes "the disk refused a write"
// testable without a small file system.

#include <sys/resource.h>

#include <csignal>

namespace tissu::test {

/// While alive, no file of this process can grow past `bytes` (SIGXFSZ, which would end the
/// process, is ignored meanwhile).
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &m_old);
    m_old_handler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = m_old;
    limited.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limited);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &m_old);
    std::signal(SIGXFSZ, m_old_handler);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit m_old{};
  void (*m_old_handler)(int) = SIG_DFL;
};

}  // namespace tissu::test
