#pragma once
/// \file
/// Running untrusted work (a third-party file importer) in a child process with time and memory
/// limits, so that whatever it does on a hostile file (crash, endless loop, allocation storm,
/// heap corruption) becomes an error the caller can report, and the caller's process is never
/// harmed. POSIX only (fork, pipe, waitpid).

#include <chrono>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>

namespace tissu {

/// Bounds on the work run by sandboxed_call.
struct SandboxLimits {
  std::chrono::milliseconds wall_time{60'000};  ///< the child is killed after this
  /// memory the child may add to what it shares with the caller at the fork (resident bytes)
  std::size_t memory_bytes = std::size_t{4} << 30;
};

/// Why sandboxed work produced no result: it crashed, was killed at a limit, or failed to start.
/// what() says it in words ("crashed (signal 11, segmentation fault)", "did not finish within
/// 60 s", ...), to be prefixed by the caller with what the work was.
class SandboxFailure : public std::runtime_error {
 public:
  enum class Kind {
    crashed,       ///< died on a signal, exited without a result or returned a malformed one
    over_a_limit,  ///< killed at the time or memory limit
    not_started,   ///< no child process could be made
  };
  SandboxFailure(Kind kind, const std::string& what) : std::runtime_error(what), m_kind(kind) {}
  Kind kind() const { return m_kind; }

 private:
  Kind m_kind;
};

/// Runs `work` in a forked child process and returns the bytes it returned.
///
/// The child shares nothing with the caller after the fork: it must not rely on threads of the
/// parent (only the calling thread exists in it), and its stdout and stderr go to /dev/null. It
/// exits with _exit, so no atexit handler, static destructor or stdio buffer of the parent runs
/// twice. An exception thrown by `work` is passed back and rethrown here as std::runtime_error
/// with the same message.
///
/// The caller watches the child while reading its result: it is killed (SIGKILL) when its wall
/// time exceeds `limits.wall_time` or its resident memory (/proc/PID/statm) exceeds the caller's
/// at the fork by more than `limits.memory_bytes`. Where no sanitizer reserves the address space,
/// the child's address space is also capped (RLIMIT_AS) at what it had at the fork plus
/// `limits.memory_bytes`, so an allocation beyond the limit fails at once instead of being killed
/// at the next check.
///
/// Throws SandboxFailure when the child crashes, is killed at a limit, or returns a malformed
/// result; std::runtime_error with the child's message when `work` threw.
std::string sandboxed_call(const std::function<std::string()>& work, const SandboxLimits& limits);

}  // namespace tissu
