#include "lib/mesh_io/sandboxed_call.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <new>

namespace tissu {
namespace {

/// The first byte of what the child writes: what follows is `work`'s result or its error text.
constexpr char kResultTag = 'R';
constexpr char kErrorTag = 'E';

std::string describe_bytes(std::size_t bytes) {
  const double gib = static_cast<double>(bytes) / static_cast<double>(std::size_t{1} << 30);
  if (gib >= 1.0) return std::to_string(static_cast<long long>(gib + 0.5)) + " GiB";
  return std::to_string(bytes >> 20) + " MiB";
}

std::string describe_seconds(std::chrono::milliseconds time) {
  const long long ms = time.count();
  return ms % 1000 == 0 ? std::to_string(ms / 1000) + " s" : std::to_string(ms) + " ms";
}

/// The second field of /proc/PID/statm (resident pages) in bytes, or 0 if it cannot be read
/// (the process has just exited).
std::size_t resident_bytes(pid_t pid) {
  std::ifstream statm("/proc/" + std::to_string(pid) + "/statm");
  std::size_t size_pages = 0, resident_pages = 0;
  if (!(statm >> size_pages >> resident_pages)) return 0;
  return resident_pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

/// Our own address space size (bytes), from the first field of /proc/self/statm; 0 if unknown.
std::size_t own_address_space_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::size_t size_pages = 0;
  if (!(statm >> size_pages)) return 0;
  return size_pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

bool write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t written = ::write(fd, data, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

void send(int fd, char tag, const std::string& payload) {
  write_all(fd, &tag, 1);
  write_all(fd, payload.data(), payload.size());
}

/// The child's side: limits, quiet output, the work, its result on `fd`, _exit.
[[noreturn]] void run_child(int fd, const std::function<std::string()>& work,
                            const SandboxLimits& limits) {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  const int null = ::open("/dev/null", O_WRONLY);
  if (null >= 0) {
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
  }
  const rlimit no_core{0, 0};
  ::setrlimit(RLIMIT_CORE, &no_core);
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
  // sanitizers reserve terabytes of address space up front: capping it would fail every
  // allocation, so under them only the resident-memory watch applies
  if (const std::size_t now = own_address_space_bytes(); now > 0) {
    const rlimit address_space{now + limits.memory_bytes, now + limits.memory_bytes};
    ::setrlimit(RLIMIT_AS, &address_space);
  }
#endif
  try {
    send(fd, kResultTag, work());
  } catch (const std::bad_alloc&) {
    send(fd, kErrorTag,
         "ran out of memory (the limit is " + describe_bytes(limits.memory_bytes) + ")");
  } catch (const std::exception& e) {
    send(fd, kErrorTag, e.what());
  } catch (...) {
    send(fd, kErrorTag, "failed with an exception that is not a std::exception");
  }
  ::close(fd);
  ::_exit(0);
}

/// Waits for `pid` and returns its status; kills it first if `kill_first`.
int reap(pid_t pid, bool kill_first) {
  if (kill_first) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

/// Closes a file descriptor when it goes out of scope.
struct FdCloser {
  int fd;
  ~FdCloser() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string sandboxed_call(const std::function<std::string()>& work, const SandboxLimits& limits) {
  int ends[2];
  if (::pipe2(ends, O_CLOEXEC) != 0) {
    throw SandboxFailure(
        SandboxFailure::Kind::not_started,
        std::string("could not start a child process: pipe: ") + std::strerror(errno));
  }
  // the child starts with the caller's pages: it is charged only for what it adds
  const std::size_t resident_at_fork = resident_bytes(::getpid());
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int error = errno;
    ::close(ends[0]);
    ::close(ends[1]);
    throw SandboxFailure(
        SandboxFailure::Kind::not_started,
        std::string("could not start a child process: fork: ") + std::strerror(error));
  }
  if (pid == 0) {
    ::close(ends[0]);
    run_child(ends[1], work, limits);
  }
  ::close(ends[1]);
  const FdCloser reader{ends[0]};

  const auto start = std::chrono::steady_clock::now();
  std::string received;
  char chunk[1 << 16];
  for (;;) {
    pollfd watched{reader.fd, POLLIN, 0};
    const int ready = ::poll(&watched, 1, 20);
    if (ready < 0 && errno != EINTR) {
      reap(pid, true);
      throw SandboxFailure(SandboxFailure::Kind::not_started,
                           std::string("lost its child process: poll: ") + std::strerror(errno));
    }
    if (ready > 0) {
      const ssize_t got = ::read(reader.fd, chunk, sizeof chunk);
      if (got == 0) break;  // the child closed its end: it is done
      if (got > 0) received.append(chunk, static_cast<std::size_t>(got));
    }
    if (std::chrono::steady_clock::now() - start > limits.wall_time) {
      reap(pid, true);
      throw SandboxFailure(
          SandboxFailure::Kind::over_a_limit,
          "did not finish within " + describe_seconds(limits.wall_time) + " (the time limit)");
    }
    if (resident_bytes(pid) > resident_at_fork + limits.memory_bytes ||
        received.size() > limits.memory_bytes) {
      reap(pid, true);
      throw SandboxFailure(SandboxFailure::Kind::over_a_limit,
                           "used more than " + describe_bytes(limits.memory_bytes) +
                               " of memory (the memory limit)");
    }
  }

  const int status = reap(pid, false);
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    const char* name = strsignal(signal);
    throw SandboxFailure(
        SandboxFailure::Kind::crashed,
        "crashed (signal " + std::to_string(signal) + ", " + (name ? name : "unknown") + ")");
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw SandboxFailure(SandboxFailure::Kind::crashed,
                         "crashed (exit status " + std::to_string(WEXITSTATUS(status)) + ")");
  }
  if (received.empty())
    throw SandboxFailure(SandboxFailure::Kind::crashed, "exited without a result");
  const std::string payload = received.substr(1);
  if (received[0] == kErrorTag) throw std::runtime_error(payload);
  if (received[0] != kResultTag)
    throw SandboxFailure(SandboxFailure::Kind::crashed, "returned a malformed result");
  return payload;
}

}  // namespace tissu
