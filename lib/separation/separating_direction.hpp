// The filtered method's stage for minimum separation: a certified separating direction.
//
// Every point of A(t), t in [0, 1], is a convex combination of A's vertices at t, and each of
// those of the vertex's positions at t0 and t1 (linear motion). So for any vector n != 0,
// n.a <= max over A's rows of n.x and n.b >= min over B's rows of n.x, and if
// gap = min_B n.x - max_A n.x > d |n| then n.(b - a) > d |n| and, by Cauchy-Schwarz,
// |b - a| > d for every a in A(t), b in B(t), t in [0, 1]: no collision (likewise with A and
// B exchanged). The direction n is any double vector (it need not be accurate, only finite);
// the products and the comparison gap^2 > d^2 (n.n) with gap > 0 are evaluated in interval
// arithmetic (CGAL::Interval_nt under upward rounding), so the conclusion is certified whatever
// the rounding of n, including overflow (an infinite bound never certifies) and gradual
// underflow (intervals stay inclusive with subnormals; the caller's DefaultFpEnvironment has
// cleared flush-to-zero). Directions tried, cheapest first: the coordinate axes, then for each
// of the kind's feature pairs its natural direction at t0 and at t1 (point-point: y - x;
// point-edge: e x (r x e), the perpendicular from the line to the point; point-triangle: the
// normal; edge-edge: da x db).
#pragma once

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "contact/vec3_ops.hpp"
#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"
#include "separation/separation_terms.hpp"

namespace exactccd::separation {

/// Which set a point belongs to in points_separated: neither, the first or the second.
enum class Side { none, first, second };

/// True when a direction certifies that the points of `side` first, moving linearly over
/// [0, 1], stay farther than d from the hull of the second ones (so from every convex
/// combination of them) at every t; directions: the axes, then those of `features` at t0 and t1
/// (the header's argument). `x`: a query's points3 rows in doubles. False: only "not certified".
template <class Kind, std::size_t N, std::size_t F>
bool points_separated(const std::array<Vec3, N>& x, const std::array<Side, Kind::points>& side, double d,
                      const std::array<kinds::Feature, F>& features, std::size_t feature_count) {
  using I = CGAL::Interval_nt<false>;
  constexpr int P = Kind::points;
  const CGAL::Protect_FPU_rounding<true> upward;  // Interval_nt<false> needs it
  const I d2 = I(d) * I(d);
  // Certifies the gap along n, given the projection of every row (an interval each).
  const auto certifies = [&](auto&& project, const I& nn) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    double a_lo = inf, a_hi = -inf, b_lo = inf, b_hi = -inf;
    for (int i = 0; i < 2 * P; ++i) {
      if (side[i % P] == Side::none) continue;
      const I v = project(x[i]);
      if (std::isnan(v.inf()) || std::isnan(v.sup())) return false;  // (cannot happen: bounds
      // of finite products are never +inf below or -inf above, so no inf - inf)
      const bool in_a = side[i % P] == Side::first;
      double& lo = in_a ? a_lo : b_lo;
      double& hi = in_a ? a_hi : b_hi;
      lo = std::min(lo, v.inf());
      hi = std::max(hi, v.sup());
    }
    const auto clears = [&](double low, double high) {  // low - high > d |n|, certified
      const I gap = I(low) - I(high);
      return gap.inf() > 0 && (gap * gap).inf() > (d2 * nn).sup();
    };
    return clears(b_lo, a_hi) || clears(a_lo, b_hi);
  };
  for (int axis = 0; axis < Kind::dimension; ++axis) {
    const auto coordinate = [&](const Vec3& v) { return I(axis == 0 ? v.x : axis == 1 ? v.y : v.z); };
    if (certifies(coordinate, I(1))) return true;
  }
  const auto along = [&](const Vec3& n) {
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) return false;
    const auto project = [&](const Vec3& v) { return I(n.x) * I(v.x) + I(n.y) * I(v.y) + I(n.z) * I(v.z); };
    return certifies(project, project(n));
  };
  for (std::size_t k = 0; k < feature_count; ++k) {
    const kinds::Feature& f = features[k];
    if (Kind::dimension == 2 && f.pair == kinds::FeaturePair::edge_edge) continue;  // n = z axis
    for (int at = 0; at < 2 * P; at += P) {
      using contact::cross;
      const auto p = [&](int j) { return x[f.points[j] + at]; };
      Vec3 n{};
      switch (f.pair) {
        case kinds::FeaturePair::point_point: n = contact::operator-(p(1), p(0)); break;
        case kinds::FeaturePair::point_edge: {
          const Vec3 e = contact::operator-(p(2), p(1)), r = contact::operator-(p(0), p(1));
          n = cross(e, cross(r, e));
          break;
        }
        case kinds::FeaturePair::point_triangle:
          n = cross(contact::operator-(p(2), p(1)), contact::operator-(p(3), p(1)));
          break;
        case kinds::FeaturePair::edge_edge:
          n = cross(contact::operator-(p(1), p(0)), contact::operator-(p(3), p(2)));
          break;
      }
      if (along(n)) return true;
    }
  }
  return false;
}

/// True when a direction certifies dist(A(t), B(t)) > d for every t in [0, 1] (then no t in
/// [0, tmax] collides). False means only "not certified".
template <class Query>
bool separated_beyond(const Query& q, double d) {
  using Kind = kinds::kind_of<Query>;
  std::array<Side, Kind::points> side;
  for (int i = 0; i < Kind::points; ++i) side[i] = i < Kind::first_points ? Side::first : Side::second;
  return points_separated<Kind>(points3<double>(q), side, d, Kind::features, Kind::features.size());
}

/// True when a direction certifies that feature pair f's two parts (its first point, or first
/// edge for edge-edge, against the rest) stay farther than d apart over [0, 1]: then its term
/// holds nowhere (the term's distance is that of the two parts' hulls, or more).
template <class Kind, std::size_t N>
bool feature_separated(const std::array<Vec3, N>& x, const kinds::Feature& f, double d) {
  std::array<Side, Kind::points> side;
  side.fill(Side::none);
  const int first = f.pair == kinds::FeaturePair::edge_edge ? 2 : 1;
  const int count = f.pair == kinds::FeaturePair::point_point ? 2
                    : f.pair == kinds::FeaturePair::point_edge ? 3
                                                               : 4;
  for (int k = 0; k < count; ++k) side[f.points[k]] = k < first ? Side::first : Side::second;
  return points_separated<Kind>(x, side, d, std::array<kinds::Feature, 1>{f}, 1);
}

}  // namespace exactccd::separation
