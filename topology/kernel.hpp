#pragma once
/// \file
/// The CGAL kernel of the cloth complex, for code that needs its points and vectors without the
/// complex itself (lighter than topology/cloth_complex.hpp; topology/ and lib/ sources only).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace tissu {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;    ///< a position (m)
using Vector3 = Kernel::Vector_3;  ///< a displacement or velocity (m, m/s)

}  // namespace tissu
