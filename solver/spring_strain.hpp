#pragma once
/// \file
/// How stretched the springs are: a cheap test, on the flat model, of whether tearing has anything
/// to look at.

#include "solver/spring_model.hpp"

namespace tissu {

/// The largest engineering strain |x_i - x_j| / l0 - 1 over the springs of `kind` at positions
/// `x` (3#P, m); -1 when there is none. Independent of the thread count (a max is exact).
double max_spring_strain(const SpringModel& model, const Eigen::VectorXd& x, SpringKind kind);

}  // namespace tissu
