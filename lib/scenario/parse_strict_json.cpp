#include "lib/scenario/parse_strict_json.hpp"

#include <utility>
#include <vector>

#include "lib/scenario/printable_text.hpp"
#include "lib/scenario/scenario_error.hpp"
#include "lib/scenario/scenario_limits.hpp"

namespace tissu {
namespace {

using json = nlohmann::json;

/// Builds the tree from the parser's events, like nlohmann's own DOM builder, and knows the key
/// path of every value it adds, for messages.
class StrictTreeBuilder final : public nlohmann::json_sax<json> {
 public:
  StrictTreeBuilder(json& root, const std::string& file, std::string base_path, int base_depth)
      : m_root(root), m_file(file), m_base_path(std::move(base_path)), m_base_depth(base_depth) {}

  bool null() override { return add(nullptr), true; }
  bool boolean(bool value) override { return add(value), true; }
  bool number_integer(number_integer_t value) override { return add(value), true; }
  bool number_unsigned(number_unsigned_t value) override { return add(value), true; }
  bool number_float(number_float_t value, const string_t&) override { return add(value), true; }
  bool string(string_t& value) override { return add(std::move(value)), true; }
  bool binary(binary_t& value) override { return add(json::binary(value)), true; }
  bool start_object(std::size_t) override { return open(json::object()), true; }
  bool start_array(std::size_t) override { return open(json::array()), true; }
  bool end_object() override { return m_open.pop_back(), true; }
  bool end_array() override { return m_open.pop_back(), true; }

  bool key(string_t& key) override {
    json& object = *m_open.back().node;
    const std::string path = join(m_open.back().path, key);
    if (object.contains(key)) {
      fail(path,
           "duplicate key: it appears twice in the same object, and one of the two would be "
           "silently ignored; keep one");
    }
    m_key_path = path;
    m_element = &object[key];
    return true;
  }

  bool parse_error(std::size_t, const std::string& last_token,
                   const nlohmann::detail::exception& e) override {
    if (e.id == 406) {  // number overflow: "1e999"
      fail(next_path(), "the number " + printable_text(last_token, 40) +
                            " is beyond the range of a double (about 1.8e308); expected a finite "
                            "number");
    }
    std::string what = e.what();  // "[json.exception.parse_error.101] parse error at ..."
    if (const auto cut = what.find("] "); cut != std::string::npos) what.erase(0, cut + 2);
    m_syntax_error = printable_text(what, 300);
    return false;
  }

  const std::string& syntax_error() const { return m_syntax_error; }

 private:
  struct OpenContainer {
    json* node;        ///< an array or object being filled
    std::string path;  ///< its key path
  };

  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? printable_text(key, 100) : path + "." + printable_text(key, 100);
  }

  /// Key path of the value the parser reads next.
  std::string next_path() const {
    if (m_open.empty()) return m_base_path;
    const OpenContainer& top = m_open.back();
    if (top.node->is_array()) return top.path + "[" + std::to_string(top.node->size()) + "]";
    return m_key_path;
  }

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw ScenarioError(m_file + ": " + (path.empty() ? "top level" : path) + ": " + what);
  }

  json* add(json value) {
    if (m_open.empty()) {
      m_root = std::move(value);
      return &m_root;
    }
    json& top = *m_open.back().node;
    if (top.is_array()) {
      top.push_back(std::move(value));
      return &top.back();  // stable: nothing is added to `top` while this child is open
    }
    *m_element = std::move(value);
    return m_element;
  }

  void open(json container) {
    std::string path = next_path();
    if (m_base_depth + static_cast<int>(m_open.size()) + 1 > max_json_depth) {
      fail(path, "arrays and objects nested more than " + std::to_string(max_json_depth) +
                     " levels deep (the limit; a scenario needs about 6)");
    }
    json* node = add(std::move(container));
    m_open.push_back({node, std::move(path)});
  }

  json& m_root;
  const std::string& m_file;
  std::string m_base_path;
  int m_base_depth;
  std::vector<OpenContainer> m_open;
  std::string m_key_path;     ///< key path of the value after the last key
  json* m_element = nullptr;  ///< where the value after the last key goes
  std::string m_syntax_error;
};

/// Line and column (from 1) of text[offset].
std::string line_and_column(std::string_view text, std::size_t offset) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

}  // namespace

StrictJsonResult parse_strict_json(std::string_view text, const std::string& file,
                                   const std::string& base_path, int base_depth) {
  // nlohmann's lexer takes a NUL byte for the end of the text and ignores whatever follows
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
    throw ScenarioError(file + ": " + (base_path.empty() ? "" : base_path + ": ") +
                        "invalid JSON: a NUL byte at " + line_and_column(text, nul) +
                        "; expected text only, and nothing after the JSON value");
  }
  StrictJsonResult result;
  StrictTreeBuilder builder(result.value, file, base_path, base_depth);
  json::sax_parse(text.begin(), text.end(), &builder, nlohmann::json::input_format_t::json,
                  /*strict=*/true, /*ignore_comments=*/true);
  result.syntax_error = builder.syntax_error();
  if (!result.syntax_error.empty()) result.value = nullptr;
  return result;
}

}  // namespace tissu
