// Stage 3 of the filtered method: exact integer arithmetic (GMP) on the contact polynomials
// of a double query scaled to integers, with a small exact kernel for degree <= 4
// (exact/integer_poly.hpp) instead of CGAL's general algebraic kernel. It decides what the
// interval stage could not: contact exactly at t = 0 or 1, signs that vanish at a root
// (contact through a vertex or an edge), double roots, coplanar-for-all-t motion.
#pragma once

#include "exactccd/types.hpp"
#include "filter/interval_stage.hpp"

namespace exactccd::filter {

/// Stage 3 for vertex-face: exact; the verdict is never `uncertain` unless an internal limit is
/// hit (then the CGAL path decides). With want_toi, a collision carries its tightest TOI.
StageResult integer_stage(const VertexFaceQuery& q, bool want_toi);

/// Stage 3 for edge-edge; see integer_stage(const VertexFaceQuery&, bool).
StageResult integer_stage(const EdgeEdgeQuery& q, bool want_toi);

}  // namespace exactccd::filter
