#include "rigid/swept_box.hpp"

#include <algorithm>

#include "rigid/quaternion.hpp"

namespace exactccd::rigid {
namespace {

using I = SweptBody::I;

/// R(q) = M(q) / |q|^2 in intervals, row-major (column k is M(q) e_k / |q|^2).
std::array<I, 9> rotation(const Quaternion& q) {
  const QuaternionT<I> qi{I(q.w), I(q.x), I(q.y), I(q.z)};
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
  rotation_ = {rotation(t0.q), rotation(t1.q)};
  const double c0[3] = {t0.c.x, t0.c.y, t0.c.z}, c1[3] = {t1.c.x, t1.c.y, t1.c.z};
  for (int k = 0; k < 3; ++k) c_lo_[k] = I(std::min(c0[k], c1[k])), c_hi_[k] = I(std::max(c0[k], c1[k]));
  const QuaternionT<I> a{I(t0.q.w), I(t0.q.x), I(t0.q.y), I(t0.q.z)}, b{I(t1.q.w), I(t1.q.x), I(t1.q.y), I(t1.q.z)};
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
