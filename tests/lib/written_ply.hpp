#pragma once
// A small reader of the binary PLY files write_mesh writes (double vertex properties, faces as
// uchar-counted int lists), independent of the library's read path, which goes through assimp
// in single precision and joins coincident vertices.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace tissu::test {

struct WrittenPly {
  std::vector<std::string> comments;
  std::vector<std::string> vertex_properties;  ///< in file order, all double
  /// property name -> #V values
  std::map<std::string, std::vector<double>> vertex_values;
  std::vector<std::vector<int>> faces;
  /// #F lists of u v per corner when the file has the face property texcoord, else empty
  std::vector<std::vector<double>> face_texcoords;
};

/// Reads `file`; fails the test (and returns what it read so far) if it is not laid out as
/// write_mesh writes it.
inline WrittenPly read_written_ply(const std::filesystem::path& file) {
  WrittenPly out;
  std::ifstream in(file, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::size_t end = bytes.find("end_header\n");
  if (end == std::string::npos) {
    ADD_FAILURE() << file << ": no end_header";
    return out;
  }
  std::istringstream header(bytes.substr(0, end));
  std::string line;
  std::size_t vertices = 0, faces = 0;
  std::string element;
  bool with_texcoords = false;
  while (std::getline(header, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "comment") {
      out.comments.push_back(line.substr(8));
    } else if (keyword == "format") {
      std::string format;
      words >> format;
      EXPECT_EQ(format, "binary_little_endian");
    } else if (keyword == "element") {
      std::size_t count = 0;
      words >> element >> count;
      (element == "vertex" ? vertices : faces) = count;
    } else if (keyword == "property" && element == "vertex") {
      std::string type, name;
      words >> type >> name;
      EXPECT_EQ(type, "double") << name;
      out.vertex_properties.push_back(name);
    } else if (keyword == "property" && line == "property list uchar double texcoord") {
      with_texcoords = true;
    } else if (keyword == "property") {
      EXPECT_EQ(line, "property list uchar int vertex_indices");
      EXPECT_FALSE(with_texcoords) << "texcoord before vertex_indices";
    }
  }
  std::size_t at = end + std::strlen("end_header\n");
  const auto take = [&](void* data, std::size_t size) {
    if (at + size > bytes.size()) {
      ADD_FAILURE() << file << ": truncated";
      return false;
    }
    std::memcpy(data, bytes.data() + at, size);  // the test machines are little-endian
    at += size;
    return true;
  };
  for (std::size_t v = 0; v < vertices; ++v) {
    for (const std::string& name : out.vertex_properties) {
      double value = 0.0;
      if (!take(&value, sizeof value)) return out;
      out.vertex_values[name].push_back(value);
    }
  }
  for (std::size_t f = 0; f < faces; ++f) {
    std::uint8_t count = 0;
    if (!take(&count, 1)) return out;
    std::vector<int>& face = out.faces.emplace_back(count);
    for (int& id : face) {
      std::int32_t value = 0;
      if (!take(&value, sizeof value)) return out;
      id = value;
    }
    if (!with_texcoords) continue;
    if (!take(&count, 1)) return out;
    std::vector<double>& uvs = out.face_texcoords.emplace_back(count);
    for (double& value : uvs) {
      if (!take(&value, sizeof value)) return out;
    }
  }
  EXPECT_EQ(at, bytes.size()) << file << ": bytes after the faces";
  return out;
}

}  // namespace tissu::test
