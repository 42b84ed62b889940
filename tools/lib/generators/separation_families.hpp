// Minimum-separation query families: for every kind of lib/kinds and a question (d, tmax),
// queries whose exact minimum distance over [0, tmax] is d itself, or moves toward or away from
// it by a known amount (perturbations of 2^-k relative, at least one ulp). `exactccd
// fuzz-against --min-distance D --tmax T` draws from them; tests/datasets/
// test_separation_families.cpp checks every claim below with an independent exact distance.
// A library (no I/O, no global mutable state).
//
// One construction serves every feature pair (docs/fuzzing.md, "The families at d > 0"): in a
// local frame with a normal axis n (z, or y in the plane), the points of primitive A marked
// `near` lie on the plane n = g and the others strictly above it; B's near points lie on n = 0
// and the others strictly below. Then at every t, dist(A(t), B(t)) >= g, with equality exactly
// when the projections (along n) of A's near feature and B's near feature meet: a point, an
// edge or a triangle on either side gives the point-point, point-edge, point-triangle and
// edge-edge pairs (parallel, crossing, end to end) at distance exactly g. The motions:
//   pass      A moves in the plane (along the first in-plane axis); the near features'
//             projections first meet at a contact time t_c: dist >= g, = g at t_c, > g before;
//   approach  the gap g(t) = h0 + (h1 - h0) t falls through d; projections overlap throughout:
//             dist(t) = g(t) exactly;
//   leave     g(t) rises from h0 = d (the pair separates from distance d at t = 0);
//   slide     constant gap, both primitives drifting together: dist(t) = g.
// The placement (random axis permutation and reflections, power-of-two scales of the in-plane
// axes and of the whole construction, translations and a common velocity, each applied only
// where every coordinate stays exactly a double) keeps every claim: distances along n are
// untouched, and the in-plane maps keep where projections meet and when.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "exactccd/rational.hpp"
#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd::separation_families {

/// A query of any kind in its row order: the first 2 * Kind::points rows are used (the rest
/// are zero); the plane's kinds have z = 0.
using Rows = std::array<Vec3, 8>;

/// How a construction moves (see the top of this file).
enum class Motion : std::uint8_t { pass, approach, leave, slide };

/// The name of a motion: "pass", "approach", "leave", "slide".
const char* motion_name(Motion m);

/// One construction of a kind, in the local frame.
struct Construction {
  const char* name;  ///< the family's name ("vf_sep_edge_cross", ...)
  Motion motion;
  /// Bit i set: point i of the kind is on its primitive's near plane (A's points first).
  std::uint8_t near;
  /// In-plane coordinates of each point at the contact configuration, in units of the scale
  /// (the first dimension - 1 used). For `pass`, A's near points have a first coordinate of 0
  /// and B's near feature lies at first coordinate >= 0, touching 0: A moves toward +.
  std::array<std::array<std::int8_t, 2>, 4> at_contact;
};

/// What a construction knows of an instance, exactly (in its own coordinates: the placement
/// keeps all of it).
struct Claim {
  Motion motion = Motion::pass;
  /// pass: h0 == h1 == the gap g: dist(t) >= g at every t, dist(contact) == g and
  /// dist(t) > g for t < contact. approach, leave, slide: dist(t) == h0 + (h1 - h0) t for every
  /// t in [0, 1].
  mpq_class h0, h1;
  /// pass: the first time the near features' projections meet (it may be past 1); approach:
  /// the time the gap reaches d (0 when it starts within d); leave and slide: 0 when h0 <= d.
  std::optional<mpq_class> contact;
  /// The answer to (d, tmax) when the construction decides it (always, but for a pass whose
  /// gap is below d with its contact after tmax).
  std::optional<bool> expected;
  /// The exact minimum distance over [0, tmax] is d itself.
  bool minimum_is_d = false;
};

/// One generated query and what is known of it.
struct Instance {
  Rows rows{};
  Claim claim;
};

/// A family: one construction of one kind.
struct Family {
  std::string name;
  std::string_view kind;  ///< the kind's name (kinds::VertexFace::name, ...)
  int points = 0;         ///< the kind's points (Kind::points)
  int first_points = 0;   ///< points 0 .. first_points - 1 are primitive A
  int dimension = 3;      ///< coordinates per point
  const Construction* construction = nullptr;
};

/// Every family of every kind, in the order of kinds::for_each_kind.
const std::vector<Family>& all_families();

/// The families of the kind Kind (a description of lib/kinds), in all_families() order.
template <class Kind>
std::vector<const Family*> families_of_kind() {
  std::vector<const Family*> out;
  for (const Family& f : all_families())
    if (f.kind == Kind::name) out.push_back(&f);
  return out;
}

/// The family of that name, or nullptr.
const Family* find_family(const std::string& name);

/// k meaning "no perturbation": the minimum distance over [0, tmax] is d (up to the contact
/// time's rounding when it is placed at tmax: the claim then says which).
constexpr int kUnperturbed = -1;

/// The family's instance for the question `params` at perturbation 2^-k (relative to d for
/// the gap, to tmax for the contact time; at least one ulp), toward the question's answer
/// "collides" or away from it. Everything but k and the direction (the scale, the speed, the
/// contact time, what is perturbed, the placement) is drawn from placement_seed, so the same
/// seed at another k is the same configuration perturbed by another amount.
Instance make(const Family& family, const CcdParams& params, int k, bool toward, std::uint64_t placement_seed);

/// A random instance of a random family of `pool` (k uniform in -1..60, a random direction
/// and placement seed).
Instance random_instance(const std::vector<const Family*>& pool, const CcdParams& params, std::mt19937_64& rng);

/// A random query of `points` points in `dimension` coordinates near the distance d: integer
/// coordinates in [-4, 4] times a power of two within 2^-3..2^3 of d (of 1 when d = 0), a
/// random half of the points static, and one random degenerate edit (a repeated point, a
/// coordinate flattened, a point copied from the other time).
Rows random_near(int points, int dimension, const CcdParams& params, std::mt19937_64& rng);

}  // namespace exactccd::separation_families
