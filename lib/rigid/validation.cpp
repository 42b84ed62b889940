#include "rigid/validation.hpp"

#include <gmpxx.h>

#include <array>
#include <cmath>

namespace exactccd::rigid {

bool quaternion_path_vanishes(const Quaternion& q0, const Quaternion& q1) {
  const std::array<double, 4> a{q0.w, q0.x, q0.y, q0.z}, b{q1.w, q1.x, q1.y, q1.z};
  const auto zero = [](const std::array<double, 4>& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0 && v[3] == 0; };
  if (zero(a) || zero(b)) return true;
  // q1 = -s q0 (s > 0) needs q0 . q1 < 0. The computed dot product s~ of the four products errs
  // by less than 5 u S + 2^-1072 (u = 2^-53, S = sum |a_i b_i| <= S~ (1 + u) + 2^-1073 with S~ the
  // computed sum of the computed |products|: each product rounds by u relative and 2^-1075
  // absolute, each of the three sums by u relative, subnormal sums exactly), and the threshold
  // fl(fl(S~ 2^-50) + 2^-1060) exceeds that. So s~ > threshold proves q0 . q1 > 0: the path does
  // not vanish. Overflow makes S~ infinite and the comparison false: the exact test decides.
  double dot = 0, magnitude = 0;
  for (int i = 0; i < 4; ++i) {
    const double p = a[i] * b[i];
    dot += p;
    magnitude += std::fabs(p);
  }
  if (dot > magnitude * 0x1p-50 + 0x1p-1060) return false;
  // Exactly: q1 = -s q0 with s > 0 iff every 2x2 minor a_i b_j - a_j b_i vanishes (parallel, both
  // nonzero) and a . b < 0.
  std::array<mpq_class, 4> x, y;
  for (int i = 0; i < 4; ++i) x[i] = a[i], y[i] = b[i];
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (x[i] * y[j] != x[j] * y[i]) return false;
  mpq_class exact_dot = 0;
  for (int i = 0; i < 4; ++i) exact_dot += x[i] * y[i];
  return exact_dot < 0;
}

const char* invalid_motion(const RigidPose& t0, const RigidPose& t1) {
  for (const RigidPose* p : {&t0, &t1}) {
    for (const double v : {p->c.x, p->c.y, p->c.z, p->q.w, p->q.x, p->q.y, p->q.z})
      if (!std::isfinite(v)) return "non-finite pose component (NaN or infinity)";
  }
  if (t0.q.w == 0 && t0.q.x == 0 && t0.q.y == 0 && t0.q.z == 0) return "zero quaternion at t = 0";
  if (t1.q.w == 0 && t1.q.x == 0 && t1.q.y == 0 && t1.q.z == 0) return "zero quaternion at t = 1";
  if (quaternion_path_vanishes(t0.q, t1.q))
    return "the quaternion path (1 - t) q0 + t q1 passes through 0 (q1 is a negative multiple of q0)";
  return nullptr;
}

}  // namespace exactccd::rigid
