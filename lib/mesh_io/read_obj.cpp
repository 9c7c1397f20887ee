#include "lib/mesh_io/read_obj.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>

#include "topology/indexed_mesh.hpp"

namespace tissu {
namespace {

/// Whether `word` can be a statement keyword: a letter, then letters, digits or underscores.
/// Writers add their own statements (e.g. ARCSim's `ny`, `nv`, `e`), which are skipped; a line
/// that starts otherwise is not OBJ.
bool is_keyword(std::string_view word) {
  const auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  return !word.empty() && letter(word.front()) &&
         std::all_of(word.begin(), word.end(),
                     [&](char c) { return letter(c) || digit(c) || c == '_'; });
}

/// The blank-separated words of `text`, up to a `#` that starts a comment.
std::vector<std::string_view> words_of(std::string_view text) {
  std::vector<std::string_view> words;
  std::size_t at = 0;
  while (true) {
    at = text.find_first_not_of(" \t\r\f\v", at);
    if (at == std::string_view::npos || text[at] == '#') break;
    const std::size_t end = std::min(text.find_first_of(" \t\r\f\v#", at), text.size());
    words.push_back(text.substr(at, end - at));
    at = end;
  }
  return words;
}

/// `word` in quotes for a message: at most 32 characters, unprintable ones shown as '?'.
std::string quoted(std::string_view word) {
  std::string out = "\"";
  for (char c : word.substr(0, 32)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  return out + (word.size() > 32 ? "...\"" : "\"");
}

std::string shortest(double value) {
  std::array<char, 32> text{};
  const auto [end, error] = std::to_chars(text.data(), text.data() + text.size(), value);
  return std::string(text.data(), error == std::errc() ? end : text.data());
}

/// A face corner's index as written: 1-based, or negative counting back from the last element.
struct RawIndex {
  long long value = 0;  ///< 0 when the corner does not give this index
  bool given() const { return value != 0; }
};

/// Reads statements one by one; ids are checked against the counts when the file ends, since a
/// positive index may refer to an element defined after the face.
class ObjParser {
 public:
  explicit ObjParser(std::string file) : m_file(std::move(file)) {}

  void statement(std::string_view text, int line) {
    const std::vector<std::string_view> words = words_of(text);
    if (words.empty()) return;
    const std::string_view keyword = words.front();
    if (keyword == "v") {
      vertex(words, line);
    } else if (keyword == "vt") {
      texture_coordinate(words, line);
    } else if (keyword == "vn") {
      ++m_normals;
    } else if (keyword == "f") {
      face(words, line);
    } else if (!is_keyword(keyword)) {
      fail(line, "expected an OBJ statement (v, vt, f, ...), got " + quoted(keyword));
    }
  }

  ObjPolygons finish() {
    for (std::size_t f = 0; f < m_out.faces.size(); ++f) {
      check_range(m_out.faces[f], m_out.positions.size(), "vertex", "vertices",
                  m_out.face_lines[f]);
      check_range(m_out.face_texture_coordinates[f], m_out.texture_coordinates.size(),
                  "texture coordinate", "texture coordinates", m_out.face_lines[f]);
    }
    for (const auto& [index, line] : m_normal_indices) {
      if (static_cast<std::size_t>(index) >= m_normals) {
        fail(line, "normal index " + std::to_string(index + 1) + " is out of range: the file has " +
                       std::to_string(m_normals) + " normals");
      }
    }
    return std::move(m_out);
  }

  [[noreturn]] void fail(int line, const std::string& what) const {
    throw MeshError(m_file + ": line " + std::to_string(line) + ": " + what);
  }

 private:
  double number(const std::vector<std::string_view>& words, std::size_t k, const char* what,
                int line) const {
    if (k >= words.size()) fail(line, std::string("expected ") + what + ", got nothing");
    std::string_view word = words[k];
    if (word.size() > 1 && word.front() == '+' && word[1] != '-') word.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error == std::errc::result_out_of_range) {
      fail(line, std::string(what) + " " + quoted(words[k]) + " is out of the range of a double");
    }
    if (error != std::errc() || end != word.data() + word.size()) {
      fail(line, std::string("expected ") + what + ", got " + quoted(words[k]));
    }
    return value;
  }

  void vertex(const std::vector<std::string_view>& words, int line) {
    // a w weight or a colour may follow: only x, y, z are read
    const Eigen::Vector3d p(number(words, 1, "the x coordinate of a vertex", line),
                            number(words, 2, "the y coordinate of a vertex", line),
                            number(words, 3, "the z coordinate of a vertex", line));
    if (!p.allFinite()) {
      fail(line, "the vertex has a non-finite coordinate (" + shortest(p.x()) + ", " +
                     shortest(p.y()) + ", " + shortest(p.z()) + ")");
    }
    m_out.positions.push_back(p);
  }

  void texture_coordinate(const std::vector<std::string_view>& words, int line) {
    Eigen::Vector3d uvw(number(words, 1, "the u of a texture coordinate", line), 0.0, 0.0);
    if (words.size() > 2) uvw.y() = number(words, 2, "the v of a texture coordinate", line);
    if (words.size() > 3) uvw.z() = number(words, 3, "the w of a texture coordinate", line);
    if (!uvw.allFinite()) fail(line, "a texture coordinate is not finite");
    m_out.texture_coordinates.push_back(uvw);
  }

  [[noreturn]] void bad_corner(std::string_view corner, int line) const {
    fail(line,
         "expected a face corner v, v/vt, v//vn or v/vt/vn of indices from 1 (or negative, "
         "counting back), got " +
             quoted(corner));
  }

  /// `word` as an index, or 0 if it is empty (an index the corner leaves out).
  RawIndex index(std::string_view word, std::string_view corner, int line) const {
    RawIndex out;
    if (word.empty()) return out;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), out.value);
    if (error != std::errc() || end != word.data() + word.size() || out.value == 0) {
      bad_corner(corner, line);
    }
    return out;
  }

  /// The 0-based id of `raw`; a negative one is resolved against the `count` defined so far.
  long long resolve(RawIndex raw, std::size_t count, const char* what, int line) const {
    if (raw.value > 0) return raw.value - 1;
    const long long id = static_cast<long long>(count) + raw.value;
    if (id < 0) {
      fail(line, std::string(what) + " index " + std::to_string(raw.value) +
                     " is out of range: only " + std::to_string(count) +
                     " are defined before this line");
    }
    return id;
  }

  void face(const std::vector<std::string_view>& words, int line) {
    if (words.size() < 4) {
      fail(line, "a face needs at least 3 corners, got " + std::to_string(words.size() - 1));
    }
    std::vector<int>& vertices = m_out.faces.emplace_back();
    std::vector<int>& uvs = m_out.face_texture_coordinates.emplace_back();
    m_out.face_lines.push_back(line);
    bool with_uvs = false;  // whether the first corner gives a texture coordinate
    for (std::size_t k = 1; k < words.size(); ++k) {
      const std::string_view corner = words[k];
      const std::size_t slash = std::min(corner.find('/'), corner.size());
      const std::size_t slash2 = std::min(corner.find('/', slash + 1), corner.size());
      if (slash2 < corner.size() && corner.find('/', slash2 + 1) != std::string_view::npos) {
        bad_corner(corner, line);  // more than three parts
      }
      const RawIndex v = index(corner.substr(0, slash), corner, line);
      const RawIndex vt = slash < corner.size()
                              ? index(corner.substr(slash + 1, slash2 - slash - 1), corner, line)
                              : RawIndex{};
      const RawIndex vn =
          slash2 < corner.size() ? index(corner.substr(slash2 + 1), corner, line) : RawIndex{};
      if (!v.given()) bad_corner(corner, line);
      if (k == 1) with_uvs = vt.given();
      if (vt.given() != with_uvs) {
        fail(line, "the face gives texture coordinates at some corners and not at others");
      }
      vertices.push_back(to_id(resolve(v, m_out.positions.size(), "vertex", line), line));
      if (vt.given()) {
        uvs.push_back(
            to_id(resolve(vt, m_out.texture_coordinates.size(), "texture coordinate", line), line));
      }
      if (vn.given()) m_normal_indices.emplace_back(resolve(vn, m_normals, "normal", line), line);
    }
  }

  int to_id(long long id, int line) const {
    if (id > std::numeric_limits<int>::max()) fail(line, "an index is too large");
    return static_cast<int>(id);
  }

  void check_range(const std::vector<int>& ids, std::size_t count, const char* what,
                   const char* plural, int line) const {
    for (int id : ids) {
      if (static_cast<std::size_t>(id) >= count) {
        fail(line, std::string(what) + " index " + std::to_string(id + 1LL) +
                       " is out of range: the file has " + std::to_string(count) + " " + plural);
      }
    }
  }

  std::string m_file;
  ObjPolygons m_out;
  std::size_t m_normals = 0;
  std::vector<std::pair<long long, int>> m_normal_indices;  ///< (0-based id, line)
};

}  // namespace

ObjPolygons read_obj(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw MeshError(file.string() + ": cannot read mesh: cannot open the file");
  ObjParser parser(file.string());
  std::string line, statement;
  int number = 0, first_line = 0;
  while (std::getline(in, line)) {
    ++number;
    if (statement.empty()) first_line = number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty() && line.back() == '\\') {  // continues on the next line
      line.back() = ' ';
      statement += line;
      continue;
    }
    statement += line;
    parser.statement(statement, first_line);
    statement.clear();
  }
  if (in.bad()) throw MeshError(file.string() + ": cannot read mesh: reading the file failed");
  parser.statement(statement, first_line);
  return parser.finish();
}

}  // namespace tissu
