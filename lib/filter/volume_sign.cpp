#include "filter/volume_sign.hpp"

#include <array>
#include <cmath>

#include "contact/contact_rule.hpp"
#include "filter/double_word.hpp"

namespace exactccd::filter {
namespace {

// Double-double arithmetic with error bounds: filter/double_word.hpp (its proofs).
using namespace double_word;

using Rows = std::array<Vec3, 8>;

/// The vector from row `from` to row `to` at time t (t1 rows are four rows later).
std::array<Approx, 3> vector_at(const Rows& r, int from, int to, double t) {
  const Vec3 &u0 = r[from], &u1 = r[from + 4], &v0 = r[to], &v1 = r[to + 4];
  return {difference_at(u0.x, v0.x, u1.x, v1.x, t), difference_at(u0.y, v0.y, u1.y, v1.y, t),
          difference_at(u0.z, v0.z, u1.z, v1.z, t)};
}

/// sign(A . (B x C)) at time t for the vectors from row `o` to rows `a`, `b`, `c`.
int volume_sign(const Rows& r, int o, int a, int b, int c, double t) {
  if (!(t >= 0 && t <= 1)) return contact::kUnknownSign;
  // No overflow: with |coordinates| <= 2^300 every difference and its value at t is below
  // 2^302 and every product of three, and sum of such, below 2^910 (errors likewise).
  // Underflow is covered by kAbsolute.
  for (const Vec3& p : r)
    for (double x : {p.x, p.y, p.z})
      if (!(std::fabs(x) <= 0x1p300)) return contact::kUnknownSign;
  const auto A = vector_at(r, o, a, t), B = vector_at(r, o, b, t), C = vector_at(r, o, c, t);
  const Approx v = A[0] * (B[1] * C[2] - B[2] * C[1]) + A[1] * (B[2] * C[0] - B[0] * C[2]) +
                   A[2] * (B[0] * C[1] - B[1] * C[0]);
  const int s = certain_sign(v);
  return s != 0 ? s : contact::kUnknownSign;  // including V(t) = 0 exactly: the caller decides exactly
}

}  // namespace

// V = (b - a) . ((c - a) x (p - a)): rows p = 0, a = 1, b = 2, c = 3.
int certified_volume_sign(const VertexFaceQuery& q, double t) { return volume_sign(rows(q), 1, 2, 3, 0, t); }

// V = (a1 - a0) . ((b0 - a0) x (b1 - a0)): rows a0 = 0, a1 = 1, b0 = 2, b1 = 3.
int certified_volume_sign(const EdgeEdgeQuery& q, double t) { return volume_sign(rows(q), 0, 1, 2, 3, t); }

}  // namespace exactccd::filter
