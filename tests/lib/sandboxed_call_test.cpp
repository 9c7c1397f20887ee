#include "lib/mesh_io/sandboxed_call.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <csignal>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace tissu {
namespace {

using ::testing::HasSubstr;

/// The message of what `call` throws as `Exception`, or "" if it throws nothing.
template <class Exception, class Call>
std::string message_of(Call call) {
  try {
    call();
  } catch (const Exception& e) {
    return e.what();
  }
  return "";
}

TEST(SandboxedCall, ReturnsTheBytesTheWorkReturns) {
  const std::string small("a\0b", 3);
  EXPECT_EQ(sandboxed_call([&] { return small; }, {}), small);
  // larger than a pipe's buffer: the caller reads while the child writes
  std::string large(10 << 20, '\0');
  for (std::size_t i = 0; i < large.size(); ++i) large[i] = static_cast<char>(i * 7919 % 251);
  EXPECT_EQ(sandboxed_call([&] { return large; }, {}), large);
}

TEST(SandboxedCall, PassesBackTheMessageOfAnException) {
  const std::string message = message_of<std::runtime_error>([] {
    sandboxed_call([]() -> std::string { throw std::invalid_argument("bad header on line 3"); },
                   {});
  });
  EXPECT_EQ(message, "bad header on line 3");
}

TEST(SandboxedCall, ACrashBecomesAFailureAndTheCallerGoesOn) {
  const std::string message = message_of<SandboxFailure>([] {
    sandboxed_call(
        []() -> std::string {
          std::raise(SIGSEGV);
          return "not reached";
        },
        {});
  });
  // a plain build reports the signal; under AddressSanitizer its handler exits with status 1
  EXPECT_THAT(message, HasSubstr("crashed ("));
  EXPECT_EQ(sandboxed_call([] { return std::string("after"); }, {}), "after");
}

TEST(SandboxedCall, AnEndlessLoopIsKilledAtTheTimeLimit) {
  SandboxLimits limits;
  limits.wall_time = std::chrono::milliseconds(300);
  const std::string message = message_of<SandboxFailure>([&] {
    sandboxed_call(
        []() -> std::string {
          volatile long spins = 0;
          for (;;) spins = spins + 1;
        },
        limits);
  });
  EXPECT_EQ(message, "did not finish within 300 ms (the time limit)");
}

TEST(SandboxedCall, AnAllocationStormStopsAtTheMemoryLimit) {
  SandboxLimits limits;
  limits.memory_bytes = std::size_t{64} << 20;
  // allocates and touches memory in 1 MiB blocks until 4 GiB: either an allocation fails
  // (address-space cap) or the watch kills the child; both name the limit
  const auto storm = []() -> std::string {
    std::vector<std::vector<char>> blocks;
    for (int i = 0; i < 4096; ++i) blocks.emplace_back(1 << 20, static_cast<char>(i));
    return "not reached";
  };
  std::string message;
  try {
    sandboxed_call(storm, limits);
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  EXPECT_THAT(message, HasSubstr("64 MiB"));
}

}  // namespace
}  // namespace tissu
