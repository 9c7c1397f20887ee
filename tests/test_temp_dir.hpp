#pragma once
// A scratch folder of this test process: test programs may run side by side (ctest -j, or two
// checkouts on one machine), so no two processes share one.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace tissu::test {

/// An empty folder named after `name` under the test temp dir, unique to this process.
inline std::filesystem::path fresh_temp_dir(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / ("tissu_" + std::to_string(getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// An empty folder `group`/<the running test's name>, as fresh_temp_dir makes it.
inline std::filesystem::path fresh_dir_for_this_test(const std::string& group) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return fresh_temp_dir(group + "/" + info->name());
}

}  // namespace tissu::test
