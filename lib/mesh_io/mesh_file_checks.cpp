#include "lib/mesh_io/mesh_file_checks.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <system_error>

#include "topology/indexed_mesh.hpp"

namespace tissu {
namespace {

/// How much of a file the header checks read: headers longer than this are refused (PLY) or not
/// checked (the others).
constexpr std::size_t kHeaderBytes = 1 << 20;

[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& why) {
  throw MeshError(file.string() + ": cannot read mesh: " + why);
}

std::string lowercase_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

/// What a file that is not regular is, in words.
std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string head_of(const std::filesystem::path& file, std::uintmax_t size) {
  std::ifstream in(file, std::ios::binary);
  std::string head(static_cast<std::size_t>(std::min<std::uintmax_t>(size, kHeaderBytes)), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return head;
}

/// Refuses a header that declares `count` items of at least `item_bytes` each when they cannot
/// fit in `available` bytes. Compares in floating point, so that no count overflows.
void check_fits(const std::filesystem::path& file, double count, const std::string& what,
                double item_bytes, double available) {
  if (count * item_bytes > available) {
    std::ostringstream message;
    message.precision(15);
    message << "its header declares " << count << " " << what << ", which need at least "
            << count * item_bytes << " bytes, but the file has only " << available
            << ": the header is damaged or the file truncated";
    refuse(file, message.str());
  }
}

/// A whole number of items as a header states it, or refuses naming `what`.
double parse_count(const std::filesystem::path& file, const std::string& text,
                   const std::string& what) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) {
    refuse(file, "its header gives \"" + text + "\" as the number of " + what +
                     ", expected a whole number");
  }
  return std::stod(text);
}

/// Bytes of one binary PLY scalar of `type`, or 0 for a type tissu does not know.
double ply_scalar_bytes(const std::string& type) {
  static const std::map<std::string, double> sizes{
      {"char", 1},   {"int8", 1},    {"uchar", 1},  {"uint8", 1},  {"short", 2}, {"int16", 2},
      {"ushort", 2}, {"uint16", 2},  {"int", 4},    {"int32", 4},  {"uint", 4},  {"uint32", 4},
      {"float", 4},  {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

/// PLY: "element NAME COUNT" lines, each followed by its properties, up to "end_header". An
/// element takes at least the sizes of its binary scalar types, or two characters per value
/// ("0 ") in ASCII; a list holds at least its count.
void check_ply_header(const std::filesystem::path& file, const std::string& head,
                      std::uintmax_t size) {
  std::istringstream lines(head);
  std::string line;
  bool ascii = true;
  double required = 0.0, element_count = 0.0, element_bytes = 0.0;
  std::string element;
  std::streamoff header_end = 0;
  const auto available = [&] {
    return static_cast<double>(size) - static_cast<double>(header_end);
  };
  // the last ASCII value may end the file without a separator
  const auto close_element = [&] {
    if (element_count == 0.0) return;
    check_fits(file, element_count, "elements \"" + element + "\"", element_bytes,
               available() + (ascii ? 1.0 : 0.0));
    required += element_count * element_bytes;
  };
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      std::string format;
      words >> format;
      ascii = format == "ascii";
    } else if (keyword == "element") {
      close_element();
      std::string count;
      words >> element >> count;
      element_count = parse_count(file, count, "elements \"" + element + "\"");
      element_bytes = 0.0;
    } else if (keyword == "property") {
      std::string type;
      words >> type;
      if (type == "list") words >> type;  // a list holds at least its count
      element_bytes += ascii ? 2.0 : ply_scalar_bytes(type);
    } else if (keyword == "end_header") {
      header_end = lines.tellg();
      close_element();
      check_fits(file, required, "bytes of elements in all", 1.0,
                 available() + (ascii ? 1.0 : 0.0));
      return;
    }
  }
  refuse(file, "it is a PLY file without an \"end_header\" line in its first " +
                   std::to_string(std::min<std::uintmax_t>(size, kHeaderBytes)) + " bytes");
}

/// OFF: the keyword, then "vertices faces [edges]" (comments start with #). A vertex takes at
/// least "0 0 0\n" (6 bytes), a face "3 0 1 2\n" (8 bytes).
void check_off_header(const std::filesystem::path& file, const std::string& head,
                      std::uintmax_t size) {
  std::istringstream lines(head);
  std::string text, line;
  for (int read = 0; read < 64 && std::getline(lines, line); ++read) {
    text += line.substr(0, line.find('#')) + "\n";
  }
  std::istringstream words(text);
  std::string keyword, vertices, faces;
  words >> keyword;
  if (keyword.find("OFF") == std::string::npos || text.find("BINARY") != std::string::npos) {
    return;  // not an ASCII OFF: the importer decides
  }
  if (!(words >> vertices >> faces)) return;
  check_fits(file, parse_count(file, vertices, "vertices"), "vertices of at least 6 bytes (0 0 0)",
             6.0, static_cast<double>(size));
  check_fits(file, parse_count(file, faces, "faces"), "faces of at least 8 bytes (3 0 1 2)", 8.0,
             static_cast<double>(size));
}

std::uint32_t little_endian_u32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
  return value;
}

/// Binary STL: an 80-byte header, a triangle count, 50 bytes per triangle. A file that starts
/// with "solid" and does not have that exact size is ASCII (assimp's rule too).
void check_stl_header(const std::filesystem::path& file, const std::string& head,
                      std::uintmax_t size) {
  if (head.size() < 84) return;
  const double triangles = little_endian_u32(head, 80);
  const bool exact = 84.0 + 50.0 * triangles == static_cast<double>(size);
  if (head.compare(0, 5, "solid") == 0 && !exact) return;
  check_fits(file, triangles, "triangles of 50 bytes", 50.0, static_cast<double>(size) - 84.0);
}

/// GLB: "glTF", version, total length, then chunks of (length, type, data).
void check_glb_header(const std::filesystem::path& file, const std::string& head,
                      std::uintmax_t size) {
  if (head.size() < 20 || head.compare(0, 4, "glTF") != 0) return;
  const std::uint32_t length = little_endian_u32(head, 8);
  if (length != size) {
    refuse(file, "its GLB header gives a length of " + std::to_string(length) +
                     " bytes, but the file has " + std::to_string(size) +
                     " bytes: the header is damaged or the file truncated");
  }
  check_fits(file, little_endian_u32(head, 12), "bytes in its first chunk", 1.0,
             static_cast<double>(size) - 20.0);
}

}  // namespace

std::uintmax_t check_mesh_file(const std::filesystem::path& file, std::uintmax_t max_bytes) {
  if (file.empty()) refuse(file, "the file name is empty");
  struct stat info {};
  if (::stat(file.c_str(), &info) != 0) {
    refuse(file, errno == ENOENT ? "no such file" : std::strerror(errno));
  }
  if (!S_ISREG(info.st_mode)) refuse(file, "it is " + kind_of(info.st_mode) + ", not a file");
  const auto size = static_cast<std::uintmax_t>(info.st_size);
  if (size == 0) refuse(file, "the file is empty");
  if (size > max_bytes) {
    refuse(file, "the file has " + std::to_string(size) + " bytes, more than the limit of " +
                     std::to_string(max_bytes) + " bytes for a mesh file");
  }
  const std::string extension = lowercase_extension(file);
  if (extension != ".ply" && extension != ".off" && extension != ".stl" && extension != ".glb") {
    return size;
  }
  const std::string head = head_of(file, size);
  if (extension == ".ply" && head.compare(0, 3, "ply") == 0) check_ply_header(file, head, size);
  if (extension == ".off") check_off_header(file, head, size);
  if (extension == ".stl") check_stl_header(file, head, size);
  if (extension == ".glb") check_glb_header(file, head, size);
  return size;
}

}  // namespace tissu
