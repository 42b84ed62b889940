// separation::certified_distance_sign (double-double, certified, separation/distance_sign.hpp):
// every sign it certifies equals the exact sign of the feature's distance polynomial f at that
// double time, computed independently in GMP rationals from the power-basis polynomial of the
// exact path (contact::terms on mpq_class, evaluated by Horner's scheme); it is decisive at
// the doubles next to f's roots (what the interval stage's narrowing needs), also with
// subnormal and huge coordinates and d; and it never certifies an exact zero.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <random>
#include <string>

#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"
#include "separation/distance_sign.hpp"
#include "contact/separation_terms.hpp"

namespace exactccd {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Term `feature`'s distance polynomial, exactly (the exact path's polynomials).
template <class Kind, std::size_t N>
contact::Poly6<mpq_class> exact_distance(const std::array<Vec3, N>& x, double d, std::size_t feature) {
  std::array<Vec3T<mpq_class>, N> q;
  for (std::size_t i = 0; i < N; ++i) q[i] = {mpq_class(x[i].x), mpq_class(x[i].y), mpq_class(x[i].z)};
  const mpq_class D(d);
  return contact::terms<Kind>(q, mpq_class(D * D)).at(feature).distance;
}

/// The exact sign of p at t.
int exact_sign(const contact::Poly6<mpq_class>& p, double t) {
  const mpq_class T(t);
  mpq_class v = p.c[6];
  for (int k = 5; k >= 0; --k) v = v * T + p.c[k];
  return sgn(v);
}

struct Counts {
  int checked = 0, certified = 0, near_root = 0, certified_near_root = 0, roots = 0;
};

/// Certified sign against the exact one at t; `near_root`: t is next to a root (counted for
/// decisiveness where the exact value is nonzero).
template <class Kind, std::size_t N>
void check(const std::array<Vec3, N>& x, double d, std::size_t feature, const contact::Poly6<mpq_class>& p,
           double t, bool near_root, Counts& c, const std::string& what) {
  const int fast = separation::certified_distance_sign(Kind::features[feature], x, d, t);
  const int exact = exact_sign(p, t);
  ++c.checked;
  const bool counted = near_root && exact != 0;
  c.near_root += counted;
  if (fast == 0) return;
  ++c.certified;
  c.certified_near_root += counted;
  ASSERT_EQ(fast, exact) << what << " " << Kind::name << " feature " << feature << " d = " << std::hexfloat << d
                         << " t = " << t;
}

/// The doubles around each root of f in [0, 1]: sign changes of the exact f on a grid, each
/// narrowed by bisection over the doubles with exact signs to consecutive doubles lo < hi
/// (or an exact root); then lo, hi and their neighbours are checked.
template <class Kind, std::size_t N>
void check_near_roots(const std::array<Vec3, N>& x, double d, std::size_t feature, const contact::Poly6<mpq_class>& p,
                      Counts& c, const std::string& what) {
  constexpr int kGrid = 16;
  double a = 0;
  int sa = exact_sign(p, a);
  for (int k = 1; k <= kGrid; ++k) {
    const double b = static_cast<double>(k) / kGrid;
    const int sb = exact_sign(p, b);
    if (sa != 0 && sb != 0 && sa != sb) {
      double lo = a, hi = b;
      bool exact_root = false;
      while (std::nextafter(lo, kInf) < hi) {
        double m = lo + (hi - lo) / 2;
        if (!(lo < m && m < hi)) m = std::nextafter(lo, kInf);
        const int s = exact_sign(p, m);
        if (s == 0) {
          lo = hi = m;
          exact_root = true;
          break;
        }
        (s == sa ? lo : hi) = m;
      }
      ++c.roots;
      for (double t : {lo, hi, std::nextafter(lo, -kInf), std::nextafter(hi, kInf), std::nextafter(lo, kInf),
                       std::nextafter(hi, -kInf)})
        if (t >= 0 && t <= 1) check<Kind>(x, d, feature, p, t, !exact_root || t != lo, c, what);
    }
    a = b;
    sa = sb;
  }
}

/// Random queries of a kind (2D kinds: z = 0), points near an offset moving a little so that
/// distances cross d, every input multiplied by `scale` (a power of two: subnormal or huge
/// coordinates and d) or d replaced by `fixed_d` when nonzero.
template <class Kind>
Counts run(std::uint64_t seed, int queries, double scale, double fixed_d, const std::string& what) {
  constexpr std::size_t N = 2 * Kind::points;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Counts c;
  for (int i = 0; i < queries; ++i) {
    std::array<Vec3, N> x;
    const double offset = i % 3 == 0 ? 0.0 : std::ldexp(1.0, static_cast<int>(i % 7) * 3);
    for (std::size_t k = 0; k < N / 2; ++k) {
      x[k] = {offset + unit(rng), offset + unit(rng), Kind::dimension == 2 ? 0.0 : unit(rng)};
      x[k + N / 2] = {x[k].x + unit(rng), x[k].y + unit(rng), Kind::dimension == 2 ? 0.0 : x[k].z + unit(rng)};
    }
    if (i % 5 == 1) x[N / 2 + 1] = x[1];  // a static point
    double d = fixed_d != 0 ? fixed_d : std::ldexp(std::abs(unit(rng)), -static_cast<int>(i % 4) * 4);
    for (Vec3& p : x) p = {p.x * scale, p.y * scale, p.z * scale};
    if (fixed_d == 0) d *= scale;
    for (std::size_t f = 0; f < Kind::features.size(); ++f) {
      const auto p = exact_distance<Kind>(x, d, f);
      for (int j = 0; j < 3; ++j) check<Kind>(x, d, f, p, std::ldexp(static_cast<double>(rng() >> 11), -53), false, c, what);
      check<Kind>(x, d, f, p, 0.0, false, c, what);
      check<Kind>(x, d, f, p, 1.0, false, c, what);
      check_near_roots<Kind>(x, d, f, p, c, what);
      if (::testing::Test::HasFatalFailure()) return c;
    }
  }
  std::cout << "[ distance ] " << what << " " << Kind::name << ": " << c.certified << " of " << c.checked
            << " signs certified, " << c.certified_near_root << " of " << c.near_root
            << " next to a root where f != 0 (" << c.roots << " roots)\n";
  return c;
}

/// Every kind: certified signs exact; decisive next to roots (the filter's purpose) with at
/// least `share` percent of the nonzero values there, per kind; at least 30 roots in all (the
/// check is not vacuous).
void run_all_kinds(std::uint64_t seed, int queries, double scale, const std::string& what, int share) {
  int roots = 0;
  const auto expect_decisive = [&](const Counts& c) {
    roots += c.roots;
    EXPECT_GE(c.certified_near_root * 100, c.near_root * share) << what;
  };
  expect_decisive(run<kinds::VertexFace>(seed, queries, scale, 0.0, what));
  expect_decisive(run<kinds::EdgeEdge>(seed + 1, queries, scale, 0.0, what));
  expect_decisive(run<kinds::PointEdge>(seed + 2, queries, scale, 0.0, what));
  expect_decisive(run<kinds::PointPoint>(seed + 3, queries, scale, 0.0, what));
  expect_decisive(run<kinds::EdgeEdge2d>(seed + 4, queries, scale, 0.0, what));
  expect_decisive(run<kinds::PointEdge2d>(seed + 5, queries, scale, 0.0, what));
  expect_decisive(run<kinds::PointPoint2d>(seed + 6, queries, scale, 0.0, what));
  EXPECT_GE(roots, 30) << what;
}

TEST(SeparationDistanceSign, CertifiedSignsAreExactAndDecisiveNextToRoots) {
  run_all_kinds(0x5eed, 40, 1.0, "unit", 95);
}

TEST(SeparationDistanceSign, SubnormalCoordinatesAndDistance) {
  // Every input times 2^-1070: subnormal coordinates and d (their low bits lost: a different,
  // valid query). Scaled up exactly before evaluation, so still decisive.
  run_all_kinds(0xabc, 15, 0x1p-1070, "subnormal", 90);
}

TEST(SeparationDistanceSign, HugeCoordinatesAndDistance) {
  // Every input times 2^1000 (coordinates up to about 2^1019 in magnitude).
  run_all_kinds(0xdef, 15, 0x1p1000, "huge", 95);
}

TEST(SeparationDistanceSign, SubnormalOrHugeDistanceAloneIsExact) {
  // d subnormal or tiny (its square underflows: bounded, not formed) against unit-size
  // coordinates: f is then about the squared distance, nonzero at random times, so nearly every
  // sign is certified; d huge (beyond 2^400 of the coordinates' scale: not certified, or
  // coordinates scaled far down): whatever is certified is exact.
  for (double d : {0x1p-1074, 0x1.8p-1050, 0x1p-540, 0x1p500, 0x1p1000}) {
    for (const Counts& c : {run<kinds::VertexFace>(0x11, 10, 1.0, d, "fixed d"), run<kinds::EdgeEdge>(0x12, 10, 1.0, d, "fixed d"),
                            run<kinds::PointEdge>(0x13, 10, 1.0, d, "fixed d")}) {
      if (d < 1) {
        EXPECT_GE(c.certified * 100, c.checked * 95) << std::hexfloat << d;
      }
    }
  }
}

TEST(SeparationDistanceSign, ExactZerosAreNeverCertifiedAndNeighboursAre) {
  // Point-point, x(t) = (t, 0, 0), y = (0.5, 0, 0), d = 0.25: f = (0.5 - t)^2 - 1/16, roots
  // 0.25 and 0.75 (doubles); f > 0 just below 0.25, < 0 just above (hand derivation).
  const std::array<Vec3, 4> x{Vec3{0, 0, 0}, Vec3{0.5, 0, 0}, Vec3{1, 0, 0}, Vec3{0.5, 0, 0}};
  const kinds::Feature pp = kinds::PointPoint::features[0];
  EXPECT_EQ(separation::certified_distance_sign(pp, x, 0.25, 0.25), 0);
  EXPECT_EQ(separation::certified_distance_sign(pp, x, 0.25, 0.75), 0);
  EXPECT_EQ(separation::certified_distance_sign(pp, x, 0.25, std::nextafter(0.25, 0.0)), 1);
  EXPECT_EQ(separation::certified_distance_sign(pp, x, 0.25, std::nextafter(0.25, 1.0)), -1);
  EXPECT_EQ(separation::certified_distance_sign(pp, x, 0.25, std::nextafter(0.75, 0.0)), -1);
  EXPECT_EQ(separation::certified_distance_sign(pp, x, 0.25, std::nextafter(0.75, 1.0)), 1);
  EXPECT_EQ(separation::certified_distance_sign(pp, x, 0.25, 0.5), -1);
  // Everything zero: f = 0 identically; a point on an edge's line with d = 0: f = 0.
  const std::array<Vec3, 4> zero{};
  EXPECT_EQ(separation::certified_distance_sign(pp, zero, 0.0, 0.5), 0);
  const std::array<Vec3, 6> on_line{Vec3{0.5, 0.5, 0.5}, Vec3{0, 0, 0}, Vec3{1, 1, 1},
                                    Vec3{0.5, 0.5, 0.5}, Vec3{0, 0, 0}, Vec3{1, 1, 1}};
  EXPECT_EQ(separation::certified_distance_sign(kinds::PointEdge::features[0], on_line, 0.0, 0.3), 0);
  // Times outside [0, 1] are refused.
  EXPECT_EQ(separation::certified_distance_sign(pp, x, 0.25, -0.5), 0);
  EXPECT_EQ(separation::certified_distance_sign(pp, x, 0.25, 1.5), 0);
}

}  // namespace
}  // namespace exactccd
