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
StageResult vertex_face_integer_stage(const VertexFaceQuery& q, bool want_toi);

/// Stage 3 for edge-edge; see vertex_face_integer_stage.
StageResult edge_edge_integer_stage(const EdgeEdgeQuery& q, bool want_toi);

/// The tightest double interval around the root of V in `cell` (a cell from the interval stage:
/// see VolumeRootCell), by exact signs of V at dyadic points; nullopt when the exact signs at
/// the cell's ends contradict the cell (then the caller runs the whole stage).
std::optional<TimeInterval> toi_in_cell(const VertexFaceQuery& q, const VolumeRootCell& cell);

/// See toi_in_cell(const VertexFaceQuery&, const VolumeRootCell&).
std::optional<TimeInterval> toi_in_cell(const EdgeEdgeQuery& q, const VolumeRootCell& cell);

}  // namespace exactccd::filter
