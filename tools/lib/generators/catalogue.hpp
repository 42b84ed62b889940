// The degenerate catalogue: hand-made vertex-face and edge-edge queries whose answers were
// derived by hand (the derivations are comments in catalogue.cpp), plus their scaled and
// translated copies. Used by the tests, by `exactccd generate catalogue` (the bundled CSV sets
// the demo runs on) and as fuzzing seeds.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "exactccd/rational.hpp"
#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd::catalogue {

/// One hand-derived query. Every coordinate is exactly a double.
template <class Query>
struct Entry {
  std::string name;        ///< unique snake_case id
  std::string category;    ///< what degeneracy it exercises, e.g. "grazing"
  Query query;             ///< rational coordinates (mpq_class)
  bool collides = false;   ///< the exact answer, derived by hand
  std::optional<mpq_class> toi;  ///< the exact earliest time when it collides and is rational
  /// For an irrational TOI: a polynomial (coefficients c0..c3) with the TOI as its only root
  /// in the returned interval's neighbourhood (tests check the enclosure by its signs).
  std::vector<mpq_class> toi_polynomial;
};

using VertexFaceEntry = Entry<RationalVertexFaceQuery>;
using EdgeEdgeEntry = Entry<RationalEdgeEdgeQuery>;

/// The hand-made vertex-face cases, then their copies scaled by 2^996 (coordinates near 1e300),
/// by 2^-1060 (subnormal coordinates; only cases that stay exact) and translated by 2^20 and
/// 2^40 (only cases that stay exact). Scaling and translation keep every answer and TOI.
std::vector<VertexFaceEntry> vertex_face_cases();

/// The hand-made edge-edge cases and their scaled and translated copies (as above).
std::vector<EdgeEdgeEntry> edge_edge_cases();

/// The hand-made cases only, without the scaled and translated copies.
std::vector<VertexFaceEntry> vertex_face_base_cases();
std::vector<EdgeEdgeEntry> edge_edge_base_cases();

/// The cases of a kind, by its description (lib/kinds): vertex_face_cases() or
/// edge_edge_cases(), for code that handles every kind alike.
inline std::vector<VertexFaceEntry> cases(kinds::VertexFace) { return vertex_face_cases(); }
inline std::vector<EdgeEdgeEntry> cases(kinds::EdgeEdge) { return edge_edge_cases(); }
/// The hand-made cases of a kind (base_cases(kinds::VertexFace{}), ...).
inline std::vector<VertexFaceEntry> base_cases(kinds::VertexFace) { return vertex_face_base_cases(); }
inline std::vector<EdgeEdgeEntry> base_cases(kinds::EdgeEdge) { return edge_edge_base_cases(); }

}  // namespace exactccd::catalogue
