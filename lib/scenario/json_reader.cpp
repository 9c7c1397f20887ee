#include "lib/scenario/json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <type_traits>

#include "lib/scenario/printable_text.hpp"

namespace tissu {
namespace {

/// The value as JSON text, cut to about 60 bytes (at a character boundary).
std::string describe(const nlohmann::json& value) {
  // replace: a string set by --set or built in code may hold bytes that are not UTF-8
  std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (text.size() > 60) {
    std::size_t cut = 57;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    text = text.substr(0, cut) + "...";
  }
  return text;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// Largest edit distance at which a key is taken for a misspelling of another.
std::size_t suggestion_distance(std::string_view key) {
  return std::max<std::size_t>(3, key.size() / 3);
}

/// Whether `value` is an integer in [min, max]; an unsigned one above INT64_MAX is not read as a
/// negative long long.
bool integer_within(const nlohmann::json& value, int min, int max) {
  if (!value.is_number_integer()) return false;
  if (value.is_number_unsigned() &&
      value.get<std::uint64_t>() > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
    return false;
  }
  const auto x = value.get<long long>();
  return x >= min && x <= max;
}

std::string number_text(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

/// The copy of `key` of the object a reader reads in the resolved scenario, or null.
nlohmann::json* resolved_child(nlohmann::json* resolved, std::string_view key) {
  return resolved ? &(*resolved)[std::string(key)] : nullptr;
}

}  // namespace

NumberRule positive(std::string unit) {
  return {0.0, std::numeric_limits<double>::infinity(), true, "a positive number" + unit};
}
NumberRule non_negative(std::string unit) {
  return {0.0, std::numeric_limits<double>::infinity(), false, "a number >= 0" + unit};
}
NumberRule between(double min, double max, std::string unit) {
  return {min, max, false,
          "a number between " + number_text(min) + " and " + number_text(max) + unit};
}

JsonObjectReader::JsonObjectReader(const nlohmann::json& object, std::string file, std::string path,
                                   nlohmann::json* resolved)
    : m_object(object), m_file(std::move(file)), m_path(std::move(path)), m_resolved(resolved) {}

JsonObjectReader object_reader(const ArrayElement& element, const std::string& file) {
  return object_reader(*element.value, file, element.path, element.resolved);
}

JsonObjectReader object_reader(const nlohmann::json& value, const std::string& file,
                               const std::string& path, nlohmann::json* resolved) {
  if (!value.is_object()) {
    throw ScenarioError(file + ": " + (path.empty() ? "top level" : path) +
                        ": expected an object {...}, got " + describe(value));
  }
  return JsonObjectReader(value, file, path, resolved);
}

void JsonObjectReader::resolve(std::string_view key, nlohmann::json value) {
  if (m_resolved) (*m_resolved)[std::string(key)] = std::move(value);
}

template <class T>
T JsonObjectReader::fall_back(std::string_view key, T fallback) {
  if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
    resolve(key, {fallback.x(), fallback.y(), fallback.z()});
  } else {
    resolve(key, fallback);
  }
  return fallback;
}

std::string JsonObjectReader::key_path(std::string_view key) const {
  // a user's key may hold control characters or be very long: printed on one line, cut
  const std::string printable = printable_text(key, 100);
  return m_path.empty() ? printable : m_path + "." + printable;
}

void JsonObjectReader::fail(std::string_view key, const std::string& expected) const {
  std::string message = m_file + ": " + key_path(key) + ": expected " + expected;
  if (auto it = m_object.find(key); it != m_object.end()) message += ", got " + describe(*it);
  throw ScenarioError(message);
}

bool JsonObjectReader::has(std::string_view key) const {
  m_known.emplace(key);
  return m_object.contains(key);
}

const nlohmann::json& JsonObjectReader::get(std::string_view key, const std::string& expected) {
  if (!has(key)) {
    // a misspelling of a required key is reported as such rather than as a missing key
    for (const auto& [present, value] : m_object.items()) {
      if (!m_read.count(present) && edit_distance(present, key) <= suggestion_distance(present)) {
        throw ScenarioError(m_file + ": " + key_path(present) + ": unknown key; did you mean '" +
                            std::string(key) + "'?");
      }
    }
    throw ScenarioError(m_file + ": " + key_path(key) + ": missing; expected " + expected);
  }
  m_read.emplace(key);
  return m_object.find(key).value();
}

double JsonObjectReader::checked_number(std::string_view key, const nlohmann::json& value,
                                        const NumberRule& rule) const {
  if (!value.is_number()) fail(key, rule.what);
  const double x = value.get<double>();
  const bool below = rule.min_exclusive ? !(x > rule.min) : !(x >= rule.min);
  if (!std::isfinite(x) || below || !(x <= rule.max)) fail(key, rule.what);
  return x;
}

double JsonObjectReader::number(std::string_view key, const NumberRule& rule) {
  return checked_number(key, get(key, rule.what), rule);
}

double JsonObjectReader::number_or(std::string_view key, double fallback, const NumberRule& rule) {
  return has(key) ? number(key, rule) : fall_back(key, fallback);
}

int JsonObjectReader::integer(std::string_view key, int min, int max) {
  const std::string expected =
      "an integer from " + std::to_string(min) +
      (max == std::numeric_limits<int>::max() ? " up" : " to " + std::to_string(max));
  const nlohmann::json& value = get(key, expected);
  if (!integer_within(value, min, max)) fail(key, expected);
  return value.get<int>();
}

int JsonObjectReader::integer_or(std::string_view key, int fallback, int min, int max) {
  return has(key) ? integer(key, min, max) : fall_back(key, fallback);
}

bool JsonObjectReader::boolean_or(std::string_view key, bool fallback) {
  if (!has(key)) return fall_back(key, fallback);
  const nlohmann::json& value = get(key, "true or false");
  if (!value.is_boolean()) fail(key, "true or false");
  return value.get<bool>();
}

std::string JsonObjectReader::string(std::string_view key) {
  const nlohmann::json& value = get(key, "a string");
  if (!value.is_string()) fail(key, "a string");
  return value.get<std::string>();
}

std::string JsonObjectReader::choice(std::string_view key,
                                     const std::vector<std::string>& allowed) {
  std::string expected = "one of";
  for (std::size_t k = 0; k < allowed.size(); ++k) {
    expected += (k == 0 ? " \"" : ", \"") + allowed[k] + "\"";
  }
  const nlohmann::json& value = get(key, expected);
  if (!value.is_string()) fail(key, expected);
  const auto text = value.get<std::string>();
  if (std::find(allowed.begin(), allowed.end(), text) == allowed.end()) fail(key, expected);
  return text;
}

std::string JsonObjectReader::choice_or(std::string_view key, std::string fallback,
                                        const std::vector<std::string>& allowed) {
  return has(key) ? choice(key, allowed) : fall_back(key, std::move(fallback));
}

Eigen::Vector3d JsonObjectReader::vector3(std::string_view key) {
  const std::string expected = "an array of 3 finite numbers [x, y, z]";
  const nlohmann::json& value = get(key, expected);
  if (!value.is_array() || value.size() != 3) fail(key, expected);
  Eigen::Vector3d out;
  for (int k = 0; k < 3; ++k) {
    if (!value[k].is_number() || !std::isfinite(value[k].get<double>())) fail(key, expected);
    out[k] = value[k].get<double>();
  }
  return out;
}

Eigen::Vector3d JsonObjectReader::vector3_or(std::string_view key,
                                             const Eigen::Vector3d& fallback) {
  return has(key) ? vector3(key) : fall_back(key, fallback);
}

Eigen::Vector3d JsonObjectReader::direction_or(std::string_view key,
                                               const Eigen::Vector3d& fallback) {
  const Eigen::Vector3d d = vector3_or(key, fallback);
  if (!(d.norm() > 0.0)) fail(key, "a non-zero direction [x, y, z]");
  return d.normalized();
}

JsonObjectReader JsonObjectReader::object(std::string_view key) {
  return object_reader(get(key, "an object {...}"), m_file, key_path(key),
                       resolved_child(m_resolved, key));
}

const nlohmann::json& empty_json_object() {
  static const nlohmann::json empty = nlohmann::json::object();
  return empty;
}

JsonObjectReader JsonObjectReader::optional_object(std::string_view key,
                                                   const nlohmann::json& when_absent) {
  if (has(key)) return object(key);
  resolve(key, when_absent);
  return JsonObjectReader(when_absent, m_file, key_path(key), resolved_child(m_resolved, key));
}

std::vector<ArrayElement> JsonObjectReader::array(std::string_view key) {
  const nlohmann::json& value = get(key, "an array [...]");
  if (!value.is_array()) fail(key, "an array [...]");
  nlohmann::json* resolved = resolved_child(m_resolved, key);
  std::vector<ArrayElement> out;
  for (std::size_t k = 0; k < value.size(); ++k) {
    out.push_back({&value[k], key_path(key) + "[" + std::to_string(k) + "]",
                   resolved ? &(*resolved)[k] : nullptr});
  }
  return out;
}

std::vector<int> JsonObjectReader::integers(std::string_view key, int min) {
  const std::string expected = "a non-empty array of integers >= " + std::to_string(min);
  const nlohmann::json& value = get(key, expected);
  if (!value.is_array() || value.empty()) fail(key, expected);
  std::vector<int> out;
  for (const auto& element : value) {
    if (!integer_within(element, min, std::numeric_limits<int>::max())) fail(key, expected);
    out.push_back(element.get<int>());
  }
  return out;
}

std::vector<double> JsonObjectReader::numbers(std::string_view key, std::size_t count,
                                              const NumberRule& rule) {
  const std::string expected =
      "an array of " + std::to_string(count) + " numbers, each " + rule.what;
  const nlohmann::json& value = get(key, expected);
  if (!value.is_array() || value.size() != count) fail(key, expected);
  std::vector<double> out;
  for (const auto& element : value) {
    if (!element.is_number()) fail(key, expected);
    const double x = element.get<double>();
    const bool below = rule.min_exclusive ? !(x > rule.min) : !(x >= rule.min);
    if (!std::isfinite(x) || below || !(x <= rule.max)) fail(key, expected);
    out.push_back(x);
  }
  return out;
}

Eigen::AlignedBox3d JsonObjectReader::box(std::string_view key) {
  JsonObjectReader corners = object(key);
  const Eigen::AlignedBox3d box(corners.vector3("min"), corners.vector3("max"));
  if ((box.min().array() > box.max().array()).any())
    corners.fail("max", "max >= min on every axis");
  corners.finish();
  return box;
}

std::vector<Eigen::Vector3d> JsonObjectReader::points(std::string_view key, std::size_t min_count) {
  const std::string expected = "an array of at least " + std::to_string(min_count) +
                               " points, each an array of 3 finite numbers [x, y, z]";
  const nlohmann::json& value = get(key, expected);
  if (!value.is_array() || value.size() < min_count) fail(key, expected);
  std::vector<Eigen::Vector3d> out;
  for (const auto& point : value) {
    if (!point.is_array() || point.size() != 3) fail(key, expected);
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k) {
      if (!point[k].is_number() || !std::isfinite(point[k].get<double>())) fail(key, expected);
      p[k] = point[k].get<double>();
    }
    out.push_back(p);
  }
  return out;
}

void JsonObjectReader::finish() const {
  for (const auto& [key, value] : m_object.items()) {
    if (m_read.count(key)) continue;
    std::string message = m_file + ": " + key_path(key) + ": unknown key";
    std::string_view best;
    std::size_t best_distance = suggestion_distance(key) + 1;
    for (const std::string& known : m_known) {
      if (const std::size_t d = edit_distance(key, known); d < best_distance) {
        best_distance = d;
        best = known;
      }
    }
    if (!best.empty()) {
      message += "; did you mean '" + std::string(best) + "'?";
    } else if (!m_known.empty()) {
      message += "; known keys here:";
      for (const std::string& known : m_known) message += " " + known;
    }
    throw ScenarioError(message);
  }
}

}  // namespace tissu
