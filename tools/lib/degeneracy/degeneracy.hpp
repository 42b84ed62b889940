// Degeneracy categories of a query, decided exactly: what makes it hard for floating-point
// CCD. Used by `exactccd compare` to label other codes' false positives and negatives.
#pragma once

#include <string>
#include <vector>

#include "exactccd/rational.hpp"
#include "exactccd/types.hpp"

namespace exactccd::exact {

/// Labels, in a fixed order, among: coplanar_for_all_t (V identically zero), root_at_t0,
/// root_at_t1 (V vanishes at an end of the step), multiple_root (V has a multiple root in
/// [0, 1]: grazing), degenerate_triangle (collinear or coincident vertices at t0 or t1),
/// parallel_edges / zero_length_edge (edge-edge, at t0 or t1), static (nothing moves). A query
/// with none of them is labelled "generic".
std::vector<std::string> degeneracy_categories(const RationalVertexFaceQuery& q);
std::vector<std::string> degeneracy_categories(const RationalEdgeEdgeQuery& q);

/// The labels joined by '+'.
std::string join_categories(const std::vector<std::string>& labels);

}  // namespace exactccd::exact
