#pragma once
/// \file
/// Strict reading of one JSON object of a scenario: every key read is checked for type and range,
/// and finish() rejects the keys nobody read, suggesting the nearest known one.

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

class JsonObjectReader {
 public:
  /// `path` is the key path of `object` in the file ("" at the top level).
  JsonObjectReader(const nlohmann::json& object, std::string file, std::string path);

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
  /// The elements of an array, each with its key path ("pins[2]").
  std::vector<std::pair<const nlohmann::json*, std::string>> array(std::string_view key);
  std::vector<int> integers(std::string_view key, int min);
  /// Exactly `count` numbers, each obeying `rule`.
  std::vector<double> numbers(std::string_view key, std::size_t count, const NumberRule& rule);

  /// An object { "min": [x, y, z], "max": [x, y, z] } with max >= min on every axis.
  Eigen::AlignedBox3d box(std::string_view key);
  /// An array of at least `min_count` points [x, y, z] of finite numbers (a polyline).
  std::vector<Eigen::Vector3d> points(std::string_view key, std::size_t min_count);
  /// Rejects any key that was not read.
  void finish() const;

  /// Fails at `key` of this object: "FILE: PATH.KEY: expected EXPECTED, got VALUE".
  [[noreturn]] void fail(std::string_view key, const std::string& expected) const;
  std::string key_path(std::string_view key) const;
  const std::string& file() const { return m_file; }
  const std::string& path() const { return m_path; }

 private:
  const nlohmann::json& get(std::string_view key, const std::string& expected);
  double checked_number(std::string_view key, const nlohmann::json& value,
                        const NumberRule& rule) const;

  const nlohmann::json& m_object;
  std::string m_file;
  std::string m_path;
  std::set<std::string, std::less<>> m_read;           ///< keys present and read
  mutable std::set<std::string, std::less<>> m_known;  ///< every key asked for, for suggestions
};

/// Reads a JSON object standing at `path` of `file`, failing if it is not an object.
JsonObjectReader object_reader(const nlohmann::json& value, const std::string& file,
                               const std::string& path);

}  // namespace tissu
