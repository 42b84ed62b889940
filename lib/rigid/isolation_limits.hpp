// The rigid walks' root isolation (numeric/bernstein_isolation.hpp) and its limits: the rigid
// polynomials (the volume, degree 5; the coplanar walk's orientations, degree 10) are isolated
// down to cells of 2^-40 and at most 4096 cells each, before the walk hands the query on.
#pragma once

#include <boost/container/small_vector.hpp>

#include "numeric/bernstein_isolation.hpp"

namespace exactccd::rigid {

using numeric::classify;
using numeric::Isolation;
using numeric::RootCell;
using numeric::sign_class;
using numeric::SignClass;

/// Cells of width 2^-40 at the finest, at most 4096 examined per polynomial (a polynomial
/// within rounding of zero over a long stretch would otherwise split every cell down to the
/// depth limit, 2^40 cells).
inline constexpr numeric::IsolationLimits kIsolationLimits{40, 4096};

/// The root cells of one rigid polynomial.
using RootCells = boost::container::small_vector<RootCell, 8>;

}  // namespace exactccd::rigid
