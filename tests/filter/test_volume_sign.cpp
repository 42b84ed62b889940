// filter::certified_volume_sign (double-double, certified): every
// certified sign equals the exact sign of V(t) (GMP rationals), and the filter is decisive at
// the doubles next to a root, which is what it is for (narrowing a TOI to adjacent doubles).
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "contact/contact_rule.hpp"
#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"
#include "filter/volume_sign.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd {
namespace {

using Rows = std::array<Vec3, 8>;

/// The exact sign of V(t) = A . (B x C), A, B, C the vectors from row o to rows a, b, c at t.
int exact_volume_sign(const Rows& r, int o, int a, int b, int c, double t) {
  const mpq_class T(t);
  const auto at = [&](int i) {
    const Vec3 &p0 = r[static_cast<std::size_t>(i)], &p1 = r[static_cast<std::size_t>(i + 4)];
    return std::array<mpq_class, 3>{mpq_class(p0.x) + T * (mpq_class(p1.x) - mpq_class(p0.x)),
                                    mpq_class(p0.y) + T * (mpq_class(p1.y) - mpq_class(p0.y)),
                                    mpq_class(p0.z) + T * (mpq_class(p1.z) - mpq_class(p0.z))};
  };
  const auto O = at(o), P = at(a), Q = at(b), R = at(c);
  std::array<mpq_class, 3> A, B, C;
  for (int k = 0; k < 3; ++k) A[k] = P[k] - O[k], B[k] = Q[k] - O[k], C[k] = R[k] - O[k];
  const mpq_class v = A[0] * (B[1] * C[2] - B[2] * C[1]) + A[1] * (B[2] * C[0] - B[0] * C[2]) +
                      A[2] * (B[0] * C[1] - B[1] * C[0]);
  return sgn(v);
}

struct Counts {
  int checked = 0, decided = 0, near_root = 0, decided_near_root = 0;
};

/// The certified sign of V(t) of a query against the exact one (V's rows from the kind's
/// description).
template <class Query>
void check(const Query& q, double t, Counts& counts, bool near_root) {
  using Kind = kinds::kind_of<Query>;
  const int fast = filter::certified_volume_sign(q, t);
  const auto& v = Kind::volume_rows;
  const int exact = exact_volume_sign(rows(q), v[0], v[1], v[2], v[3], t);
  ++counts.checked;
  // Next to a root the filter is meant to decide, except where V(t) is exactly zero (never
  // certified) or t is subnormal (next to a root at 0: |V(t)| ~ 2^-1074, below the bound).
  const bool counted = near_root && exact != 0 && t >= 0x1p-900;
  counts.near_root += counted;
  if (fast == 0) return;
  ++counts.decided;
  counts.decided_near_root += counted;
  ASSERT_EQ(fast, exact) << Kind::name << " at t = " << std::hexfloat << t;
}

TEST(VolumeSign, CertifiedSignsAreExactAndDecisiveNextToRoots) {
  std::mt19937_64 rng(0x5eedULL);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Counts counts;
  int collisions = 0;
  for (int i = 0; i < 3000; ++i) {
    const bool vertex_face = i % 2 == 0;
    Rows r;
    // Points near an offset (as a mesh far from the origin), moving a little: many cross.
    const double offset = (i % 3 == 0) ? 0.0 : std::ldexp(1.0, static_cast<int>(i % 7) * 3);
    for (std::size_t k = 0; k < 4; ++k) {
      r[k] = {offset + unit(rng), offset + unit(rng), unit(rng)};
      r[k + 4] = {r[k].x + 0.5 * unit(rng), r[k].y + 0.5 * unit(rng), r[k].z + 0.5 * unit(rng)};
    }
    if (i % 5 == 0) r[6] = r[2], r[2] = r[1];  // shared and static points
    const auto run = [&](const auto& q) {
      for (int j = 0; j < 4; ++j) check(q, std::ldexp(static_cast<double>(rng() >> 11), -53), counts, false);
      check(q, 0.0, counts, false);
      check(q, 1.0, counts, false);
      // Next to the exact TOI (an exact root of V): the doubles just below and above it.
      const auto toi = exactccd::toi(q, Method::exact);
      if (!toi) return;
      ++collisions;
      for (double t : {toi->lo, toi->hi, std::nextafter(toi->lo, -1.0), std::nextafter(toi->hi, 2.0)})
        if (t >= 0 && t <= 1) check(q, t, counts, true);
    };
    if (vertex_face) run(from_rows<VertexFaceQuery>(r)); else run(from_rows<EdgeEdgeQuery>(r));
  }
  ASSERT_GT(collisions, 300);
  // Decisive almost everywhere (the point of the filter); measured: see the output.
  EXPECT_GT(counts.decided, counts.checked * 9 / 10);
  EXPECT_GT(counts.decided_near_root, counts.near_root * 95 / 100);
  std::cout << "[ volume   ] " << counts.decided << " of " << counts.checked << " signs certified, "
            << counts.decided_near_root << " of " << counts.near_root << " at normal doubles next to a root where V != 0; "
            << collisions << " collisions\n";
}

TEST(VolumeSign, ExactZerosAndHugeCoordinatesAreLeftToTheExactPath) {
  // Coplanar for all t (z = 0 everywhere): V = 0 exactly, never certified as nonzero.
  Rows flat{};
  for (std::size_t k = 0; k < 8; ++k) flat[k] = {static_cast<double>(k % 3), static_cast<double>(k % 2), 0.0};
  EXPECT_EQ(filter::certified_volume_sign(from_rows<VertexFaceQuery>(flat), 0.5), 0);
  EXPECT_EQ(filter::certified_volume_sign(from_rows<EdgeEdgeQuery>(flat), 0.25), 0);
  // Huge and tiny coordinates are scaled by a power of two first (numeric/certified_sign.hpp):
  // the sign is still the exact one, not an overflowed or underflowed guess.
  for (const double scale : {0x1p400, 0x1p1000, 0x1p-1000}) {
    Rows far = flat;
    for (Vec3& p : far) p = {p.x * scale, p.y * scale, p.z * scale};
    far[3] = {0, 0, scale};
    far[7] = {0, 0, scale};
    const int sign = filter::certified_volume_sign(from_rows<VertexFaceQuery>(far), 0.5);
    EXPECT_EQ(sign, exact_volume_sign(far, 1, 2, 3, 0, 0.5)) << "coordinates of magnitude " << scale;
    EXPECT_NE(sign, 0) << "coordinates of magnitude " << scale;
  }
  // A plain positive and negative volume.
  Rows unit{};
  unit[0] = unit[4] = {0.25, 0.25, 1};   // p above the triangle
  unit[1] = unit[5] = {0, 0, 0};
  unit[2] = unit[6] = {1, 0, 0};
  unit[3] = unit[7] = {0, 1, 0};
  const int above = filter::certified_volume_sign(from_rows<VertexFaceQuery>(unit), 0.5);
  EXPECT_EQ(above, exact_volume_sign(unit, 1, 2, 3, 0, 0.5));
  unit[0].z = unit[4].z = -1;
  EXPECT_EQ(filter::certified_volume_sign(from_rows<VertexFaceQuery>(unit), 0.5), -above);
}

}  // namespace
}  // namespace exactccd
