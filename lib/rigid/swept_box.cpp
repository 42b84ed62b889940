#include "rigid/swept_box.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rigid/quaternion.hpp"

namespace exactccd::rigid {
namespace {

using I = SweptBody::I;

/// q times the power of two first * second (two normal doubles), enclosed (R(s q) = R(q); near
/// 1, no square of it overflows or vanishes).
QuaternionT<I> scaled(const Quaternion& q, const std::array<double, 2>& factor) {
  const auto s = [&](double v) { return (I(v) * I(factor[0])) * I(factor[1]); };
  return {s(q.w), s(q.x), s(q.y), s(q.z)};
}

/// R(q) = M(q) / |q|^2 in intervals, row-major (column k is M(q) e_k / |q|^2).
std::array<I, 9> rotation(const QuaternionT<I>& qi) {
  const I n2 = squared_norm(qi);
  std::array<I, 9> r;
  for (int k = 0; k < 3; ++k) {
    const Vec3T<I> e{I(k == 0 ? 1 : 0), I(k == 1 ? 1 : 0), I(k == 2 ? 1 : 0)};
    const Vec3T<I> m = rotate_scaled(qi, e);
    r[0 * 3 + k] = m.x / n2, r[1 * 3 + k] = m.y / n2, r[2 * 3 + k] = m.z / n2;
  }
  return r;
}

I hull(const I& a, const I& b) { return I(std::min(a.inf(), b.inf()), std::max(a.sup(), b.sup())); }

}  // namespace

SweptBody::SweptBody(const RigidPose& t0, const RigidPose& t1) {
  double largest = 0;
  for (const Quaternion* q : {&t0.q, &t1.q})
    largest = std::max({largest, std::fabs(q->w), std::fabs(q->x), std::fabs(q->y), std::fabs(q->z)});
  // 2^-e with largest 2^-e in [1, 2), as two normal double factors (|e| <= 1074).
  const int e = std::ilogb(largest);
  const std::array<double, 2> factor{std::ldexp(1.0, -e / 2), std::ldexp(1.0, -(e - e / 2))};
  const QuaternionT<I> a = scaled(t0.q, factor), b = scaled(t1.q, factor);
  rotation_ = {rotation(a), rotation(b)};
  const double c0[3] = {t0.c.x, t0.c.y, t0.c.z}, c1[3] = {t1.c.x, t1.c.y, t1.c.z};
  for (int k = 0; k < 3; ++k) c_lo_[k] = I(std::min(c0[k], c1[k])), c_hi_[k] = I(std::max(c0[k], c1[k]));
  const I dot = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
  short_arc_ = dot.inf() > 0;
  if (short_arc_) one_minus_cos_ = I(1) - dot / CGAL::sqrt(squared_norm(a) * squared_norm(b));
}

Box SweptBody::box(const Vec3& p, double margin) const {
  const I x(p.x), y(p.y), z(p.z);
  const I length = CGAL::sqrt(x * x + y * y + z * z);
  const I sagitta = short_arc_ ? length * one_minus_cos_ : length;  // the long arc: the ball alone
  std::array<double, 3> lo, hi;
  for (int k = 0; k < 3; ++k) {
    const I r0 = rotation_[0][3 * k] * x + rotation_[0][3 * k + 1] * y + rotation_[0][3 * k + 2] * z;
    const I r1 = rotation_[1][3 * k] * x + rotation_[1][3 * k + 1] * y + rotation_[1][3 * k + 2] * z;
    const I chord = hull(r0, r1);
    // Grown by the sagitta (interval operations: rounded outward), then clamped to |p|.
    const I arc(std::max((I(chord.inf()) - sagitta).inf(), -length.sup()),
                std::min((I(chord.sup()) + sagitta).sup(), length.sup()));
    const I lo_k = c_lo_[k] + arc - I(margin), hi_k = c_hi_[k] + arc + I(margin);
    lo[k] = lo_k.inf(), hi[k] = hi_k.sup();
    // An overflow may leave a NaN bound (0 times infinity): the whole line then, which holds
    // every curve.
    if (std::isnan(lo[k])) lo[k] = -std::numeric_limits<double>::infinity();
    if (std::isnan(hi[k])) hi[k] = std::numeric_limits<double>::infinity();
  }
  return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
}

Box swept_box(const RigidPose& t0, const RigidPose& t1, const Vec3& p, double margin) {
  const CGAL::Protect_FPU_rounding<true> upward;
  return SweptBody(t0, t1).box(p, margin);
}

std::vector<Box> swept_boxes(const RigidPose& t0, const RigidPose& t1, const std::vector<Vec3>& points,
                             double margin) {
  const CGAL::Protect_FPU_rounding<true> upward;
  const SweptBody body(t0, t1);
  std::vector<Box> out;
  out.reserve(points.size());
  for (const Vec3& p : points) out.push_back(body.box(p, margin));
  return out;
}

}  // namespace exactccd::rigid
