// Mesh files are untrusted input (issue 18): whatever a file holds, reading it throws one clear
// MeshError naming the file, within bounded time and memory, and never harms the caller.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "lib/mesh_io/read_mesh.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::filesystem::path kCorpus = std::filesystem::path(TISSU_TESTS_DIR) / "corpus/meshes";

/// Limits small enough that a hang or an allocation storm ends the test quickly.
MeshImportLimits test_limits() {
  MeshImportLimits limits;
  limits.importer = SandboxLimits{std::chrono::milliseconds(5000), std::size_t{512} << 20};
  return limits;
}

/// What reading `file` as a cloth (`as_cloth`) or an obstacle did: the message of the MeshError it
/// threw, or "read" if it succeeded. Fails the test if it threw another exception.
std::string outcome(const std::filesystem::path& file, bool as_cloth,
                    const MeshImportLimits& limits = test_limits()) {
  try {
    if (as_cloth) {
      read_numbered_mesh(file, limits);
    } else {
      read_polygons(file, limits);
    }
  } catch (const MeshError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << file << ": threw an exception that is not a MeshError: " << e.what();
    return "";
  }
  return "read";
}

void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

/// A line of expected_errors.txt.
struct ExpectedError {
  std::vector<std::string> texts;  ///< the message must contain one of these
  bool cloth_only = false;         ///< an obstacle may read the file
};

/// expected_errors.txt by file name.
std::map<std::string, ExpectedError> expected_errors() {
  std::ifstream in(kCorpus / "expected_errors.txt");
  std::map<std::string, ExpectedError> out;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string name, text, scope;
    std::getline(fields, name, '\t');
    std::getline(fields, text, '\t');
    std::getline(fields, scope, '\t');
    // alternatives, " | " between them: what assimp does with a damaged file may depend on the
    // allocator (a heap overrun aborts under glibc's, and garbles the mesh under ASan's)
    std::vector<std::string> texts;
    for (std::size_t begin = 0;;) {
      const std::size_t bar = text.find(" | ", begin);
      texts.push_back(text.substr(begin, bar - begin));
      if (bar == std::string::npos) break;
      begin = bar + 3;
    }
    out[name] = {texts, scope == "cloth only"};
  }
  return out;
}

TEST(HostileMeshCorpus, EveryFileIsRefusedWithOneLineNamingIt) {
  const std::map<std::string, ExpectedError> expected = expected_errors();
  ASSERT_GE(expected.size(), 10u);
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kCorpus)) {
    const std::string name = entry.path().filename().string();
    if (name == "expected_errors.txt" || name == "README.md") continue;
    ++files;
    const auto listed = expected.find(name);
    for (const bool as_cloth : {true, false}) {
      SCOPED_TRACE(name + (as_cloth ? " as a cloth" : " as an obstacle"));
      const std::string message = outcome(entry.path(), as_cloth);
      const bool may_be_read = listed == expected.end() || (listed->second.cloth_only && !as_cloth);
      if (message == "read" && may_be_read) continue;
      EXPECT_THAT(message, StartsWith(entry.path().string() + ": "));
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      if (listed != expected.end()) {
        const std::vector<std::string>& texts = listed->second.texts;
        EXPECT_TRUE(std::any_of(texts.begin(), texts.end(), [&](const std::string& text) {
          return message.find(text) != std::string::npos;
        })) << message;
      }
    }
  }
  EXPECT_GE(files, static_cast<int>(expected.size()));
}

TEST(HostileMeshFile, OnlyRegularFilesAreOpened) {
  const std::filesystem::path dir = test::fresh_dir_for_this_test("hostile_mesh");
  const std::filesystem::path fifo = dir / "sheet.ply";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // opening a FIFO would block until a writer comes: the test would hang
  EXPECT_THAT(outcome(fifo, true), HasSubstr("it is a FIFO (named pipe), not a file"));
  EXPECT_THAT(outcome(dir, true), HasSubstr("it is a directory, not a file"));
  EXPECT_THAT(outcome("/dev/zero", false), HasSubstr("it is a device, not a file"));
  EXPECT_THAT(outcome(dir / "missing.obj", true), HasSubstr("no such file"));
  EXPECT_EQ(outcome("", true), ": cannot read mesh: the file name is empty");
}

TEST(HostileMeshFile, FilesOverTheSizeLimitAreNotRead) {
  const std::filesystem::path file = test::fresh_dir_for_this_test("hostile_mesh") / "big.obj";
  write_text(file, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# padding padding padding\n");
  MeshImportLimits limits = test_limits();
  limits.max_file_bytes = 16;
  EXPECT_THAT(outcome(file, true, limits),
              HasSubstr("more than the limit of 16 bytes for a mesh file"));
}

TEST(HostileMeshFile, AnImporterThatRunsPastTheTimeLimitIsStopped) {
  // a PLY whose face claims 2^31 indices: assimp 5.2.5 reads it for a very long time, or fails
  MeshImportLimits limits = test_limits();
  limits.importer->wall_time = std::chrono::milliseconds(1500);
  const auto start = std::chrono::steady_clock::now();
  const std::string message = outcome(kCorpus / "ply_face_list_count_2_31.ply", true, limits);
  EXPECT_THAT(message, HasSubstr("cannot read mesh"));
  // bounded by the limit (plus the fork and the watch's period), however the importer behaves
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
}

TEST(HostileMeshFile, ValidFilesReadInTheChildProcessAreUnchanged) {
  const std::filesystem::path file = test::fresh_dir_for_this_test("hostile_mesh") / "quad.ply";
  write_text(file,
             "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
             "property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
             "end_header\n0 0 0\n0.5 0 0\n0.5 0.375 0\n0 0.375 -0.125\n4 0 1 2 3\n");
  const NumberedMesh read = read_numbered_mesh(file, test_limits());
  ASSERT_EQ(read.mesh.vertices.size(), 4u);
  EXPECT_EQ(read.mesh.vertices[2], Eigen::Vector3d(0.5, 0.375, 0));
  EXPECT_EQ(read.mesh.vertices[3], Eigen::Vector3d(0, 0.375, -0.125));
  ASSERT_EQ(read.mesh.faces.size(), 1u);
  EXPECT_EQ(read.mesh.faces[0], (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(read.mesh_vertex_of_file_vertex, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_TRUE(read.has_vertex_numbering());
}

}  // namespace
}  // namespace tissu
