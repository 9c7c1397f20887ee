#pragma once
/// \file
/// Strict reading of one JSON object of a scenario: every key read is checked for type and range,
/// and finish() rejects the keys nobody read, suggesting the nearest known one. A reader may also
/// fill in the resolved scenario: a copy of the JSON in which every default it falls back on is
/// written at its key, so that the copy says all a run used (the run folder's scenario.json).

#include <Eigen/Geometry>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "lib/scenario/scenario_error.hpp"

namespace tissu {

/// Accepted interval of a number; `what` completes "expected ..." in messages.
struct NumberRule {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;
  std::string what = "a finite number";
};
NumberRule positive(std::string unit);
NumberRule non_negative(std::string unit);
NumberRule between(double min, double max, std::string unit);

/// {}, for the life of the program.
const nlohmann::json& empty_json_object();

/// One element of an array read by JsonObjectReader::array().
struct ArrayElement {
  const nlohmann::json* value;
  std::string path;          ///< its key path, "pins[2]"
  nlohmann::json* resolved;  ///< its copy in the resolved scenario, or null
};

class JsonObjectReader {
 public:
  /// `path` is the key path of `object` in the file ("" at the top level). `resolved`, when not
  /// null, is the copy of `object` in the resolved scenario, into which the defaults go.
  JsonObjectReader(const nlohmann::json& object, std::string file, std::string path,
                   nlohmann::json* resolved = nullptr);

  bool has(std::string_view key) const;
  double number(std::string_view key, const NumberRule& rule);
  double number_or(std::string_view key, double fallback, const NumberRule& rule);
  int integer(std::string_view key, int min, int max);
  int integer_or(std::string_view key, int fallback, int min, int max);
  bool boolean_or(std::string_view key, bool fallback);
  std::string string(std::string_view key);
  /// One of `allowed`.
  std::string choice(std::string_view key, const std::vector<std::string>& allowed);
  std::string choice_or(std::string_view key, std::string fallback,
                        const std::vector<std::string>& allowed);
  Eigen::Vector3d vector3(std::string_view key);
  Eigen::Vector3d vector3_or(std::string_view key, const Eigen::Vector3d& fallback);
  /// A non-zero vector3, normalised.
  Eigen::Vector3d direction_or(std::string_view key, const Eigen::Vector3d& fallback);
  JsonObjectReader object(std::string_view key);
  /// The object at `key`, or `when_absent` (an object that outlives the reader) when there is
  /// none: an empty one gives only defaults, {"enabled": false} a section switched off.
  JsonObjectReader optional_object(std::string_view key,
                                   const nlohmann::json& when_absent = empty_json_object());
  /// The reader would keep a reference to a temporary: pass a static object instead.
  JsonObjectReader optional_object(std::string_view key,
                                   const nlohmann::json&& when_absent) = delete;
  std::vector<ArrayElement> array(std::string_view key);
  std::vector<int> integers(std::string_view key, int min);
  /// Exactly `count` numbers, each obeying `rule`.
  std::vector<double> numbers(std::string_view key, std::size_t count, const NumberRule& rule);

  /// An object { "min": [x, y, z], "max": [x, y, z] } with max >= min on every axis.
  Eigen::AlignedBox3d box(std::string_view key);
  /// An array of at least `min_count` points [x, y, z] of finite numbers (a polyline).
  std::vector<Eigen::Vector3d> points(std::string_view key, std::size_t min_count);
  /// Rejects any key that was not read.
  void finish() const;
  /// Writes `value` at `key` of the resolved scenario: a path made absolute, or a default the
  /// caller decides, such as {"enabled": false} for a section that is absent.
  void resolve(std::string_view key, nlohmann::json value);

  /// Fails at `key` of this object: "FILE: PATH.KEY: expected EXPECTED, got VALUE".
  [[noreturn]] void fail(std::string_view key, const std::string& expected) const;
  std::string key_path(std::string_view key) const;
  const std::string& file() const { return m_file; }
  const std::string& path() const { return m_path; }

 private:
  const nlohmann::json& get(std::string_view key, const std::string& expected);
  /// Records `fallback` at `key` in the resolved scenario and returns it.
  template <class T>
  T fall_back(std::string_view key, T fallback);
  double checked_number(std::string_view key, const nlohmann::json& value,
                        const NumberRule& rule) const;

  const nlohmann::json& m_object;
  std::string m_file;
  std::string m_path;
  nlohmann::json* m_resolved;
  std::set<std::string, std::less<>> m_read;           ///< keys present and read
  mutable std::set<std::string, std::less<>> m_known;  ///< every key asked for, for suggestions
};

/// Reads a JSON object standing at `path` of `file`, failing if it is not an object; `resolved`
/// as for JsonObjectReader.
JsonObjectReader object_reader(const nlohmann::json& value, const std::string& file,
                               const std::string& path, nlohmann::json* resolved = nullptr);
/// Reads an array element that must be an object.
JsonObjectReader object_reader(const ArrayElement& element, const std::string& file);

}  // namespace tissu
