#pragma once
/// \file
/// The error every bad scenario gives: one line naming the file, the key path and what was
/// expected.

#include <stdexcept>
#include <string>

namespace tissu {

class ScenarioError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tissu
