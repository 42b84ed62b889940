// The contact rule's terms as intervals over a time interval T, without their polynomials
// (docs/design.md, 5.2, "Signs at a root": the values over the cell).
//
// The interval stage decides the in-plane rule over a root cell T of V from certified signs of
// the rule's terms over T. Building a term's polynomial in interval arithmetic (a degree-4
// parameter is two cross products and a dot product of polynomials) and evaluating it over T
// costs several times more than evaluating the same formula on the points' relative positions
// over T: MotionOver gives the relative motion of two points as the interval
// d0 + (d1 - d0) T (d0, d1 the differences at t = 0 and t = 1, as relative_motion), and the
// term classes of contact_polynomials.hpp (VertexFaceTerms, EdgeEdgeTerms: the same formulas)
// combine them. By the inclusion property of interval arithmetic (every operation's result
// contains the exact result for every choice of exact values in its operands), each term's
// interval contains the polynomial's exact value at every t in T: a certain sign is the sign
// at every t in T, and an exact [0, 0] is zero at every t in T. The enclosure is wider than the
// polynomial's over a wide T (the dependency problem), which is why the stage also keeps the
// polynomial path (in_plane_over_cell.hpp, in_plane_verdict). Runs under the stage's upward
// rounding, like everything in Interval_nt<false>.
#pragma once

#include <array>
#include <optional>
#include <utility>

#include "contact/contact_polynomials.hpp"
#include "contact/contact_rule.hpp"
#include "filter/interval/isolation.hpp"

namespace exactccd::filter::interval {

/// The relative motions of a query's points evaluated over the time interval t (cached: a rule
/// asks for the same pair several times). Refers to the rows: they must outlive it.
class MotionOver {
 public:
  /// `rows`: the query's rows in intervals (t0 rows, then t1 rows).
  MotionOver(const std::array<Vec3T<Interval>, 8>& rows, Interval t) : rows_(&rows), t_(t) {}
  /// Not from a temporary: the motion keeps a pointer to the rows.
  MotionOver(std::array<Vec3T<Interval>, 8>&&, Interval) = delete;

  /// The vector from row `from` to row `to` over t: d0 + (d1 - d0) t per coordinate.
  const Vec3T<Interval>& rel(int from, int to) const {
    return contact::cached(rel_[static_cast<std::size_t>(from * 4 + to)], [&] {
      const auto& r = *rows_;
      const auto over = [&](const Interval& u0, const Interval& u1, const Interval& v0, const Interval& v1) {
        const Interval d0 = v0 - u0, d1 = v1 - u1;
        return d0 + (d1 - d0) * t_;
      };
      const Vec3T<Interval>&u0 = r[from], &u1 = r[from + 4], &v0 = r[to], &v1 = r[to + 4];
      return Vec3T<Interval>{over(u0.x, u1.x, v0.x, v1.x), over(u0.y, u1.y, v0.y, v1.y),
                             over(u0.z, u1.z, v0.z, v1.z)};
    });
  }

 private:
  const std::array<Vec3T<Interval>, 8>* rows_;
  Interval t_;
  mutable std::array<std::optional<Vec3T<Interval>>, 16> rel_;
};

/// Certified signs of term values (contact_rule.hpp's oracle protocol): numeric::interval_sign.
struct ValueSignOracle {
  /// The sign the value certifies, or kUnknownSign.
  int operator()(const Interval& value) const { return numeric::interval_sign(value); }
};

/// The in-plane rule over the cell, from the values of the terms of P's query over it (a
/// certain answer holds at every t of the cell).
template <class Polys>
contact::Truth in_plane_rule_over(const Polys& P, const RootCell& cell) {
  const Interval t(cell.lo, cell.hi);
  const auto& rows = P.motion().rows();
  if constexpr (contact::is_vertex_face_polys<Polys>::value)
    return contact::in_plane_contact(contact::VertexFaceTerms<MotionOver>(std::in_place, rows, t), ValueSignOracle{});
  else
    return contact::in_plane_contact(contact::EdgeEdgeTerms<MotionOver>(std::in_place, rows, t), ValueSignOracle{});
}

}  // namespace exactccd::filter::interval
