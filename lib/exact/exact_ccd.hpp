// The exact path: GMP rationals for the polynomials of the contact rule, CGAL's
// Algebraic_kernel_d_1 for their real roots in [0, 1] and for exact signs at those roots.
// Never wrong, never gives up; slow (tens of microseconds per query). The filters of later
// stages defer to it whenever a sign is uncertain.
#pragma once

#include <optional>

#include "exactccd/rational.hpp"
#include "exactccd/types.hpp"

namespace exactccd::exact {

/// Exact vertex-face CCD: true iff p(t) is in the closed triangle for some t in [0, 1].
bool ccd(const RationalVertexFaceQuery& q);

/// Exact edge-edge CCD: true iff the closed segments meet for some t in [0, 1].
bool ccd(const RationalEdgeEdgeQuery& q);

/// Earliest contact time of a vertex-face query, enclosed in the tightest double interval.
std::optional<TimeInterval> toi(const RationalVertexFaceQuery& q);

/// Earliest contact time of an edge-edge query, enclosed in the tightest double interval.
std::optional<TimeInterval> toi(const RationalEdgeEdgeQuery& q);

}  // namespace exactccd::exact
