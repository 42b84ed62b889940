// Degenerate rigid query families (issue 24): exactly degenerate configurations of turning
// bodies (a turning edge sweeping exactly through an edge's end, a vertex turning exactly onto a
// triangle's edge, a vertex's circle tangent to a face, contacts at t = 0, 1 and 3/4, edges
// collinear at contact, motion in one plane) perturbed by 2^-k towards or away from contact,
// with the answer and time of impact known by construction (derivations in rigid_families.cpp),
// then placed by an exact random change of frame common to both bodies: a rotation of the cube
// group (a signed permutation of the coordinates, quaternion with entries in {0, +-1}), a
// power-of-two scale and a translation, kept only where every number stays exact. Distances
// do not change under a rigid map and scale with the scale (d scaled alike), so the answer and
// the time of impact are the construction's (docs/design.md, 9.6).
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "exactccd/rigid.hpp"
#include "generators/families.hpp"  // KnownToi, is_tightest_enclosure

namespace exactccd::rigid_families {

/// A rigid query of either kind.
using AnyRigidQuery = std::variant<RigidVertexFaceQuery, RigidEdgeEdgeQuery>;

/// One generated instance: the query, the minimum separation d it is asked with, and the answer
/// and TOI known by construction (set when known).
struct Instance {
  AnyRigidQuery query;
  double min_distance = 0;
  std::optional<bool> expected;
  std::optional<families::KnownToi> toi;  ///< set when expected is true and the time is known
};

/// A family: its name and its generator for the perturbation exponent k (k < 0: unperturbed)
/// and direction.
struct Family {
  std::string name;
  bool vertex_face = true;
  /// The instance before placement.
  Instance (*make)(int k, bool toward);
};

/// Every family.
const std::vector<Family>& all_families();

/// The instance placed by a random exact change of frame (the file comment); nullopt when a
/// number would not stay exact (then draw again).
std::optional<Instance> placed(const Instance& instance, std::mt19937_64& rng);

/// An instance of `family` at k, placed (redrawn until the placement is exact; unplaced after
/// 100 failures).
Instance make(const Family& family, int k, bool toward, std::mt19937_64& rng);

}  // namespace exactccd::rigid_families
