#include "lib/scenario/read_scenario_text.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "lib/scenario/scenario_error.hpp"
#include "lib/scenario/scenario_limits.hpp"

namespace tissu {
namespace {

/// "a directory", "a FIFO (named pipe)"...: what a file that is not a regular one is.
std::string file_kind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

[[noreturn]] void fail_kind(const std::string& name, mode_t mode) {
  throw ScenarioError(name + ": cannot read the scenario: it is " + file_kind(mode) +
                      "; expected a regular file of JSON text");
}

/// `at_least`: the file was read up to the bound and had more.
[[noreturn]] void fail_size(const std::string& name, unsigned long long bytes, bool at_least) {
  throw ScenarioError(name + ": cannot read the scenario: it has " + (at_least ? "at least " : "") +
                      std::to_string(bytes) + " bytes, more than the " +
                      std::to_string(max_scenario_bytes) + " (16 MiB) a scenario file may have");
}

/// Closes a file descriptor on every way out.
struct FileDescriptor {
  int fd;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_scenario_text(const std::filesystem::path& file, const std::string& name) {
  if (file.empty()) {
    throw ScenarioError("(empty path): cannot read the scenario: the path is empty");
  }
  struct stat status {};
  if (::stat(file.c_str(), &status) != 0) {
    throw ScenarioError(name + ": cannot open the scenario file: " + std::strerror(errno));
  }
  if (!S_ISREG(status.st_mode)) fail_kind(name, status.st_mode);
  if (static_cast<unsigned long long>(status.st_size) > max_scenario_bytes) {
    fail_size(name, status.st_size, false);
  }
  // O_NONBLOCK: should the file be replaced by a FIFO after stat(), open() still returns
  const FileDescriptor in{::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
  if (in.fd < 0) {
    throw ScenarioError(name + ": cannot open the scenario file: " + std::strerror(errno));
  }
  if (::fstat(in.fd, &status) != 0 || !S_ISREG(status.st_mode)) fail_kind(name, status.st_mode);
  // read at most one byte more than the bound: the file may have grown since stat()
  std::string text;
  char chunk[65536];
  while (text.size() <= max_scenario_bytes) {
    const ssize_t got = ::read(in.fd, chunk, sizeof chunk);
    if (got == 0) break;
    if (got < 0) {
      if (errno == EINTR) continue;
      throw ScenarioError(name + ": cannot read the scenario file: " + std::strerror(errno));
    }
    text.append(chunk, static_cast<std::size_t>(got));
  }
  if (text.size() > max_scenario_bytes) fail_size(name, text.size(), true);
  return text;
}

}  // namespace tissu
