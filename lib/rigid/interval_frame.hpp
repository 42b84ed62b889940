// The rigid query's scaled positions as polynomials with interval coefficients (docs/design.md,
// 9.4): built once per query (rigid_frame.hpp's scaled_frame on CGAL::Interval_nt), then
// evaluated at a time (thin intervals) or over a time cell: the value enclosure is Horner's
// scheme over the cell intersected with the mean-value form P(m) + P'(T) (T - m), and the
// derivative's enclosure is Horner's scheme of P' over the cell; both contain every exact value
// (inclusion property). Also the volume V as a polynomial of degree 5 whose sign on [0, 1] is
// V's: vertex-face n.(N - a D) with n = (b - a) x (c - a) (B's constant normal, 9.2), edge-edge
// the world-frame numerator of 9.2,
//   V D = det[M(qA) eA, cB - cA, M(qB) eB] + (M(qA) eA).(M(qB)(b0 x eB)) - (M(qA)(eA x a0)).(M(qB) eB)
// (eA = a1 - a0, eB = b1 - b0 in body coordinates; R = M / |q|^2, and a rotation common to three
// vectors changes no determinant, R u x R v = R (u x v)).
// Everything here needs upward rounding (CGAL::Protect_FPU_rounding<true>) held by the caller.
#pragma once

#include <boost/optional.hpp>

#include <algorithm>
#include <array>
#include <optional>
#include <type_traits>

#include "contact/polynomial.hpp"
#include "exactccd/rigid.hpp"
#include "numeric/interval.hpp"
#include "rigid/quaternion.hpp"
#include "rigid/rigid_frame.hpp"

namespace exactccd::rigid {

using numeric::Interval;

/// A value and its derivative (forward differentiation), both enclosures over a time cell.
struct Dual {
  Interval value;
  Interval slope;
};
inline Dual operator+(const Dual& a, const Dual& b) { return {a.value + b.value, a.slope + b.slope}; }
inline Dual operator-(const Dual& a, const Dual& b) { return {a.value - b.value, a.slope - b.slope}; }
inline Dual operator*(const Dual& a, const Dual& b) { return {a.value * b.value, a.slope * b.value + a.value * b.slope}; }

/// p(t) by Horner's scheme.
template <int D>
Interval horner(const contact::Poly<Interval, D>& p, const Interval& t) {
  Interval r = p.c[D];
  for (int k = D - 1; k >= 0; --k) r = r * t + p.c[k];
  return r;
}

/// p'.
template <int D>
contact::Poly<Interval, (D > 0 ? D - 1 : 0)> derivative(const contact::Poly<Interval, D>& p) {
  auto r = contact::Poly<Interval, (D > 0 ? D - 1 : 0)>::zero();
  for (int k = 1; k <= D; ++k) r.c[k - 1] = p.c[k] * Interval(k);
  return r;
}

/// The intersection of two enclosures of the same value (both hold it, so they meet).
inline Interval meet(const Interval& a, const Interval& b) {
  return Interval(std::max(a.inf(), b.inf()), std::min(a.sup(), b.sup()));
}

/// A polynomial with its derivative, evaluated over cells.
template <int D>
struct SlopedPoly {
  contact::Poly<Interval, D> p;
  contact::Poly<Interval, (D > 0 ? D - 1 : 0)> dp;
  explicit SlopedPoly(const contact::Poly<Interval, D>& poly = contact::Poly<Interval, D>::zero())
      : p(poly), dp(derivative(poly)) {}
  /// At a double t (a thin interval).
  Interval at(double t) const { return horner(p, Interval(t)); }
  /// Over [a, b]: the value (Horner over the cell met with the mean-value form) and the slope.
  Dual over(double a, double b) const {
    const Interval cell(a, b);
    const double m = a + (b - a) / 2;
    const Interval slope = horner(dp, cell);
    return {meet(horner(p, cell), horner(p, Interval(m)) + slope * (cell - Interval(m))), slope};
  }
};

/// A normalized rigid query's positions (scaled by D) and volume as interval polynomials. The
/// volume is built at construction; the positions on first use (most queries that reach the
/// interval stage are decided by the volume's roots alone).
template <class Query>
class IntervalFrame {
 public:
  using Kind = kinds::kind_of<Query>;
  using IQuery = std::conditional_t<std::is_same_v<Kind, kinds::VertexFace>, RigidVertexFaceQueryT<Interval>,
                                    RigidEdgeEdgeQueryT<Interval>>;

  explicit IntervalFrame(const Query& q) : iq_(to_intervals(q)), parts_(iq_) {
    volume_ = SlopedPoly<5>(volume_polynomial(iq_));
  }

  /// The positions at the double t.
  std::array<Vec3T<Interval>, 4> at(double t) const {
    const auto& position = positions();
    std::array<Vec3T<Interval>, 4> out;
    for (int i = 0; i < 4; ++i) out[i] = {position[i].x.at(t), position[i].y.at(t), position[i].z.at(t)};
    return out;
  }
  /// The positions over [a, b], with slopes.
  std::array<Vec3T<Dual>, 4> over(double a, double b) const {
    const auto& position = positions();
    std::array<Vec3T<Dual>, 4> out;
    for (int i = 0; i < 4; ++i) out[i] = {position[i].x.over(a, b), position[i].y.over(a, b), position[i].z.over(a, b)};
    return out;
  }
  /// The value enclosures alone over [a, b].
  std::array<Vec3T<Interval>, 4> boxes(double a, double b) const {
    const auto& position = positions();
    std::array<Vec3T<Interval>, 4> out;
    for (int i = 0; i < 4; ++i)
      out[i] = {position[i].x.over(a, b).value, position[i].y.over(a, b).value, position[i].z.over(a, b).value};
    return out;
  }
  /// D at t, and over [a, b].
  Interval D_at(double t) const { return D().at(t); }
  Dual D_over(double a, double b) const { return D().over(a, b); }
  /// The volume polynomial of degree 5 (file comment).
  const SlopedPoly<5>& volume() const { return volume_; }

 private:
  using P0 = contact::Poly<Interval, 0>;
  using Positions = std::array<Vec3T<SlopedPoly<5>>, 4>;

  static IQuery to_intervals(const Query& q) {
    IQuery iq;
    const auto pose = [](const RigidPose& p) {
      return RigidPoseT<Interval>{{Interval(p.c.x), Interval(p.c.y), Interval(p.c.z)},
                                  {Interval(p.q.w), Interval(p.q.x), Interval(p.q.y), Interval(p.q.z)}};
    };
    iq.a_t0 = pose(q.a_t0), iq.a_t1 = pose(q.a_t1), iq.b_t0 = pose(q.b_t0), iq.b_t1 = pose(q.b_t1);
    const auto points = body_points(q);
    int k = 0;
    set_interval_points(iq, [&](Vec3T<Interval>& v) {
      v = {Interval(points[k].x), Interval(points[k].y), Interval(points[k].z)};
      ++k;
    });
    return iq;
  }
  template <class F>
  static void set_interval_points(RigidVertexFaceQueryT<Interval>& q, F&& f) {
    f(q.p), f(q.a), f(q.b), f(q.c);
  }
  template <class F>
  static void set_interval_points(RigidEdgeEdgeQueryT<Interval>& q, F&& f) {
    f(q.a0), f(q.a1), f(q.b0), f(q.b1);
  }

  const Positions& positions() const {
    if (!positions_) {
      Positions p;
      const auto points = body_points(iq_);
      for (int i = 0; i < 4; ++i) {
        const auto x = parts_.position(points[i], i < Kind::first_points);
        p[i] = {SlopedPoly<5>(x.x), SlopedPoly<5>(x.y), SlopedPoly<5>(x.z)};
      }
      positions_.emplace(p);
    }
    return *positions_;
  }
  const SlopedPoly<4>& D() const {
    if (!D_) D_.emplace(parts_.D);
    return *D_;
  }

  static Vec3T<P0> constant(const Vec3T<Interval>& v) { return {P0{{v.x}}, P0{{v.y}}, P0{{v.z}}}; }

  /// Vertex-face: n.(N - a D), n = (b - a) x (c - a) (B's constant normal).
  contact::Poly<Interval, 5> volume_polynomial(const RigidVertexFaceQueryT<Interval>& q) const {
    using contact::cross;
    const Vec3T<Interval> ab{q.b.x - q.a.x, q.b.y - q.a.y, q.b.z - q.a.z}, ac{q.c.x - q.a.x, q.c.y - q.a.y, q.c.z - q.a.z};
    const Vec3T<Interval> n = cross(ab, ac);
    const auto N = parts_.position(q.p, true);
    const auto component = [&](const contact::Poly<Interval, 5>& Nk, const Interval& ak, const Interval& nk) {
      return P0{{nk}} * (Nk - P0{{ak}} * parts_.D);
    };
    return component(N.x, q.a.x, n.x) + component(N.y, q.a.y, n.y) + component(N.z, q.a.z, n.z);
  }

  /// Edge-edge: the world-frame numerator of the file comment.
  contact::Poly<Interval, 5> volume_polynomial(const RigidEdgeEdgeQueryT<Interval>& q) const {
    using contact::cross;
    using contact::dot;
    const auto qa = linear_path(q.a_t0.q, q.a_t1.q), qb = linear_path(q.b_t0.q, q.b_t1.q);
    const Vec3T<Interval> ea{q.a1.x - q.a0.x, q.a1.y - q.a0.y, q.a1.z - q.a0.z};
    const Vec3T<Interval> eb{q.b1.x - q.b0.x, q.b1.y - q.b0.y, q.b1.z - q.b0.z};
    using contact::operator-;
    const auto delta = linear_path(q.b_t0.c, q.b_t1.c) - linear_path(q.a_t0.c, q.a_t1.c);  // cB - cA
    const auto ma_ea = rotate_scaled(qa, constant(ea)), mb_eb = rotate_scaled(qb, constant(eb));
    const auto mb_b0eb = rotate_scaled(qb, constant(cross(q.b0, eb)));
    const auto ma_eaa0 = rotate_scaled(qa, constant(cross(ea, q.a0)));
    const auto first = dot(ma_ea, cross(delta, mb_eb));
    return first + widen<5>(dot(ma_ea, mb_b0eb)) - widen<5>(dot(ma_eaa0, mb_eb));
  }

  IQuery iq_;
  ScaledFrameParts<IQuery> parts_;
  SlopedPoly<5> volume_;
  mutable std::optional<Positions> positions_;
  mutable std::optional<SlopedPoly<4>> D_;
};

/// The interval frame of one normalized query, shared by the stages of its list that read it
/// (the contact walk, the contact probe's, the separation walk: contact_walk.hpp,
/// rigid_separation_walk.hpp): built once, on first use, so that splitting the walks into stages
/// computes nothing twice. Every query of the rigid lists creates one, most never build the frame
/// (the direction stage decides them): boost::optional, whose empty storage is left
/// uninitialised, where GCC 12's std::optional zero-fills the frame's 3.7 kB for each query
/// (a `rep stos` of 460 words: +6.7% instructions on the tumbling-body sets, callgrind).
template <class Query>
class SharedIntervalFrame {
 public:
  /// The frame of `normalized_query` (the same query at every call: the Work's after the unit
  /// scaling stage), built under the caller's upward rounding on first use.
  const IntervalFrame<Query>& of(const Query& normalized_query) {
    if (!frame_) frame_.emplace(normalized_query);
    return *frame_;
  }

 private:
  boost::optional<IntervalFrame<Query>> frame_;
};

}  // namespace exactccd::rigid
