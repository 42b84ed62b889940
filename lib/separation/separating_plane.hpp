// The contact question's stage between stage 1 and the interval stage: a plane of fixed normal
// n that separates the two primitives at t0 and at t1, with each on the same side at both
// ends, separates them at every t in between (separation/separating_direction.hpp,
// gap_certified_at_each_end: n.(x_j(t) - x_i(t)) is affine in t for every pair of points), so
// they never touch. Certified in plain doubles with the static error bound proved there (any
// rounding mode; no rounding-mode switch, no allocation).
//
// What it is for: stage 1 passes on every query whose four points become coplanar at some t
// in [0, 1] (V changes sign), which in a resting or sliding cloth is most pairs of neighbouring
// elements (nearly in one plane, moving alike) though they stay apart in that plane; the
// interval stage then isolates V's roots and evaluates the in-plane rule there, about 10^4
// instructions each. Directions tried, each n any double vector (its accuracy only decides
// whether it certifies): the difference of the two primitives' centroids at t0, the same at
// t1, and at t0 the part of the first difference perpendicular to each edge of the query (the
// edges' outward directions in a flat neighbourhood). Measured on the cloth-ball step's
// candidates that stage 1 passes on and that do not collide (every 200th candidate; the method
// and counts are in the message of commit 0a53300, which added this stage): 84% decided. On
// data/sim/*.csv (exactccd check --stats, d = 0, tmax 1 or 0.5): 374 queries decided here that
// the interval stage (373) or the fixed-width integer stage (1) decided before.
//
// Floating point. The directions need no error bound: any finite double vector is a valid n
// (its accuracy only decides whether it certifies), and every bound is in the certification
// (gap_certified_at_each_end: the header of separating_direction.hpp, steps 1-4, applied to
// the rows of each end; step 2 normalises n exactly as there). Overflow: the frame's rows are
// below 2^402 in magnitude, so a centroid difference (at most 3 + 3 rows times the point
// counts) is below 2^406, an edge e below 2^403, e.e below 2^808 and m.e below 2^811; a
// quotient me / ee may still overflow (ee tiny: underflowed products, even 0, which is
// skipped), and then the direction has an infinite or NaN component and normalised_direction
// rejects it (never certified). Underflow only makes a direction less accurate.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <utility>

#include "kinds/primitive_kinds.hpp"
#include "pipeline/outcome.hpp"
#include "separation/separating_direction.hpp"
#include "contact/separation_terms.hpp"

namespace exactccd::separation {

/// The edges of a contact kind's points at t0 whose perpendicular directions are tried: the
/// triangle's three (vertex-face), the two edges (edge-edge).
template <class Kind>
constexpr auto plane_edges() {
  if constexpr (Kind::first_points == 1)
    return std::array<std::pair<int, int>, 3>{{{1, 2}, {2, 3}, {3, 1}}};
  else
    return std::array<std::pair<int, int>, 2>{{{0, 1}, {2, 3}}};
}

/// True when a plane of fixed normal separates the query's two primitives at t0 and at t1 on
/// the same side (the file comment's directions): then they never touch in [0, 1]. False
/// means only "not certified".
template <class Query>
bool separated_by_plane(const Query& q) {
  using Kind = kinds::kind_of<Query>;
  constexpr std::size_t P = Kind::points;
  const separation::ProjectionFrame frame(contact::points3<double>(q), 0.0);
  if (!frame.usable) return false;
  std::array<separation::Side, P> side;
  for (std::size_t i = 0; i < P; ++i) side[i] = static_cast<int>(i) < Kind::first_points ? separation::Side::first : separation::Side::second;
  const separation::SideRows<2 * P> rows(side);
  const auto& y = frame.y;
  // The centroid difference at `end`, times the two point counts (a positive factor).
  const auto centroids = [&](std::size_t end) {
    Vec3 a{0, 0, 0}, b{0, 0, 0};
    for (std::size_t i = 0; i < P; ++i) {
      Vec3& s = static_cast<int>(i) < Kind::first_points ? a : b;
      s = {s.x + y[i + end].x, s.y + y[i + end].y, s.z + y[i + end].z};
    }
    const double na = Kind::first_points, nb = static_cast<double>(P) - na;
    return Vec3{na * b.x - nb * a.x, na * b.y - nb * a.y, na * b.z - nb * a.z};
  };
  const auto certifies = [&](const Vec3& n) {
    const std::optional<Vec3> u = separation::normalised_direction(n);
    return u && separation::gap_certified_at_each_end(frame, rows, *u);
  };
  const Vec3 m = centroids(0);
  if (certifies(m) || certifies(centroids(P))) return true;
  for (const auto& [u, v] : plane_edges<Kind>()) {
    const Vec3 e{y[v].x - y[u].x, y[v].y - y[u].y, y[v].z - y[u].z};
    const double ee = e.x * e.x + e.y * e.y + e.z * e.z, me = m.x * e.x + m.y * e.y + m.z * e.z;
    if (!(ee > 0)) continue;
    const double k = me / ee;
    if (certifies(Vec3{m.x - k * e.x, m.y - k * e.y, m.z - k * e.z})) return true;
  }
  return false;
}

/// The contact question's stage before the interval stage: separate when a plane certifies it
/// (separated_by_plane), else undecided. Counted as a separating direction.
struct SeparatingPlaneStage {
  static constexpr pipeline::Counter counter = &StageCounters::separating_direction;  ///< counted as
  /// Separate when a plane of fixed normal separates the primitives at both ends; else undecided.
  template <class Query, class Findings>
  pipeline::Outcome operator()(const pipeline::Work<Query, Findings>& work) const {
    if (separated_by_plane(work.query())) return pipeline::Outcome::separate();
    return pipeline::Outcome::undecided();
  }
};

}  // namespace exactccd::separation
