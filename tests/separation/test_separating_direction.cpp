// separation/separating_direction.hpp: the certified separating direction in plain doubles with
// a static error bound. It must never certify a pair that comes within d: configurations at
// distance exactly d (built from integers, so the distance is known exactly, with 53-bit
// coordinates so that the projections round) at scales from the subnormal range to 2^960, at
// rest and in common motion (then every cell of [0, 1] holds the tangency), over [0, 1] and
// over random cells (ProjectionFrame::over); random moving point pairs with d the exact
// distance at a double time, rounded up. And it must be useful: at a quarter of that distance
// the same configurations are certified apart.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfenv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"
#include "separation/separating_direction.hpp"
#include "contact/separation_terms.hpp"

namespace exactccd {
namespace {

using separation::ProjectionFrame;

/// The caller's rounding mode for the library calls of a test (the proof holds in each).
class RoundingMode : public ::testing::TestWithParam<int> {
 protected:
  /// f() with the parameter's rounding mode installed, the previous one restored after.
  template <class F>
  auto in_mode(F&& f) {
    const int before = std::fegetround();
    std::fesetround(GetParam());
    const auto result = f();
    std::fesetround(before);
    return result;
  }
};

/// v 2^k, exactly (v an integer below 2^53, the result a double).
double scaled(std::int64_t v, int k) { return std::ldexp(static_cast<double>(v), k); }

/// A configuration of one kind at distance exactly 3 s 2^k (s an integer): the gap lies along
/// the direction (1, 2, 2), of length 3, and the primitives span directions orthogonal to it,
/// (2, -1, 0) and (2, 0, -1); the closest points are interior (or the points themselves).
struct Tangency {
  std::vector<std::array<std::int64_t, 3>> first, second;  // integer points of A and of B
};

Tangency tangency(const std::string& kind, std::mt19937_64& rng, std::int64_t s, std::int64_t m) {
  std::uniform_int_distribution<std::int64_t> base(-(std::int64_t{1} << 51), std::int64_t{1} << 51);
  const std::array<std::int64_t, 3> p{base(rng), base(rng), base(rng)};
  const auto at = [&](std::int64_t gap, std::int64_t u, std::int64_t v) {  // p + gap (1,2,2) + u (2,-1,0) + v (2,0,-1)
    return std::array<std::int64_t, 3>{p[0] + gap + 2 * u + 2 * v, p[1] + 2 * gap - u, p[2] + 2 * gap - v};
  };
  if (kind == "vf") return {{at(s, 0, 0)}, {at(0, -m, -m), at(0, 2 * m, -m), at(0, -m, 2 * m)}};
  if (kind == "ee") return {{at(0, -m, 0), at(0, m, 0)}, {at(s, 0, -m), at(s, 0, m)}};
  if (kind == "pe") return {{at(s, 0, 0)}, {at(0, -m, 0), at(0, m, 0)}};
  return {{at(s, 0, 0)}, {at(0, 0, 0)}};  // pp
}

/// The rows (all points at t0, then at t1) of a tangency scaled by 2^k, every point moving by
/// the same integer vector w 2^k.
template <class Kind>
std::array<Vec3, 2 * Kind::points> rows_of(const Tangency& t, int k, const std::array<std::int64_t, 3>& w) {
  std::array<Vec3, 2 * Kind::points> r;
  int i = 0;
  for (const auto* side : {&t.first, &t.second})
    for (const auto& p : *side) {
      r[i] = {scaled(p[0], k), scaled(p[1], k), scaled(p[2], k)};
      r[i + Kind::points] = {scaled(p[0] + w[0], k), scaled(p[1] + w[1], k), scaled(p[2] + w[2], k)};
      ++i;
    }
  return r;
}

template <class Kind, class InMode>
void check_tangencies(const std::string& kind, InMode&& in_mode) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<std::int64_t> motion(-(std::int64_t{1} << 50), std::int64_t{1} << 50);
  int certified_apart = 0, cases = 0;
  for (const int k : {-1074, -1040, -700, -60, 0, 60, 700, 960}) {
    for (int trial = 0; trial < 40; ++trial) {
      // Spans of 2^20 keep the natural directions (cross products) exact, so the direction
      // found is the exact normal and only the error bound stands between the computed gap and
      // d |n|; spans of 2^40 round them.
      const std::int64_t s = (std::int64_t{1} << 20) + trial, m = (std::int64_t{1} << (trial % 2 ? 20 : 40)) + 3 * trial;
      const Tangency t = tangency(kind, rng, s, m);
      const std::array<std::int64_t, 3> w = trial % 4 == 0 ? std::array<std::int64_t, 3>{0, 0, 0}
                                                           : std::array<std::int64_t, 3>{motion(rng), motion(rng), motion(rng)};
      const auto x = rows_of<Kind>(t, k, w);
      const double d = scaled(3 * s, k);  // the exact distance at every t
      const std::string where = kind + " k=" + std::to_string(k) + " trial " + std::to_string(trial);
      const auto frame = in_mode([&] { return ProjectionFrame<2 * Kind::points>(x, d); });
      EXPECT_FALSE(in_mode([&] { return separation::primitives_separated<Kind>(frame); })) << where;
      // The kind's own feature pair (feature 0) is the one at distance d.
      EXPECT_FALSE(in_mode([&] { return separation::feature_separated<Kind>(frame, Kind::features[0]); }))
          << where << " feature 0";
      for (int cell = 0; cell < 8; ++cell) {
        double a = unit(rng), b = unit(rng);
        if (a > b) std::swap(a, b);
        EXPECT_FALSE(in_mode([&] { return separation::primitives_separated<Kind>(frame.over(a, b)); }))
            << where << " cell [" << a << ", " << b << "]";
      }
      // Useful: at a quarter of the distance the configuration at rest is certified apart.
      if (w[0] == 0 && w[1] == 0 && w[2] == 0) {
        ++cases;
        certified_apart += in_mode(
            [&] { return separation::primitives_separated<Kind>(ProjectionFrame<2 * Kind::points>(x, d / 4)); });
      }
    }
  }
  EXPECT_EQ(certified_apart, cases) << kind << ": configurations at rest, d a quarter of their distance";
}

#define EXACTCCD_IN_MODE [this](auto&& f) { return in_mode(f); }
TEST_P(RoundingMode, NeverCertifiesExactTangenciesVertexFace) { check_tangencies<kinds::VertexFace>("vf", EXACTCCD_IN_MODE); }
TEST_P(RoundingMode, NeverCertifiesExactTangenciesEdgeEdge) { check_tangencies<kinds::EdgeEdge>("ee", EXACTCCD_IN_MODE); }
TEST_P(RoundingMode, NeverCertifiesExactTangenciesPointEdge) { check_tangencies<kinds::PointEdge>("pe", EXACTCCD_IN_MODE); }
TEST_P(RoundingMode, NeverCertifiesExactTangenciesPointPoint) { check_tangencies<kinds::PointPoint>("pp", EXACTCCD_IN_MODE); }
#undef EXACTCCD_IN_MODE

/// The least double whose square is at least q (q >= 0 rational, about 2^(2k) in size).
double sqrt_up(const mpq_class& q, int k) {
  mpq_class unit_sized = q;  // q 2^(-2k), exactly
  if (k > 0) mpq_div_2exp(unit_sized.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(2 * k));
  if (k < 0) mpq_mul_2exp(unit_sized.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-2 * k));
  double r = std::ldexp(std::sqrt(unit_sized.get_d()), k);
  if (!std::isfinite(r)) return r;
  while (mpq_class(r) * mpq_class(r) < q) r = std::nextafter(r, std::numeric_limits<double>::infinity());
  while (r > 0) {
    const double below = std::nextafter(r, 0.0);
    if (mpq_class(below) * mpq_class(below) < q) break;
    r = below;
  }
  return r;
}

// Random point pairs with full-precision coordinates (moving, or at rest: then the natural
// direction y - x rounds and the gap along it is d |n| up to rounding), d the exact distance at
// a double time t rounded up: the pair is within d at t, so no direction may separate it over
// [0, 1] or over a cell holding t.
TEST_P(RoundingMode, NeverCertifiesRandomPointPairsWithinDistance) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0), unit(0.0, 1.0);
  int checked = 0;
  for (const int k : {-1070, -500, 0, 500, 1000}) {
    for (int trial = 0; trial < 300; ++trial) {
      std::array<Vec3, 4> x;
      for (Vec3& p : x) p = {std::ldexp(coordinate(rng), k), std::ldexp(coordinate(rng), k), std::ldexp(coordinate(rng), k)};
      if (trial % 3 == 1) x[3] = {x[2].x + std::ldexp(coordinate(rng), k - 30), x[2].y, x[2].z};  // short relative motion
      if (trial % 3 == 2) x[2] = x[0], x[3] = x[1];  // at rest: the distance is d (up to d's rounding) at every t
      const double t = unit(rng);
      const auto at = [&](int i) {
        return std::array<mpq_class, 3>{mpq_class(x[i].x) + mpq_class(t) * (mpq_class(x[i + 2].x) - mpq_class(x[i].x)),
                                        mpq_class(x[i].y) + mpq_class(t) * (mpq_class(x[i + 2].y) - mpq_class(x[i].y)),
                                        mpq_class(x[i].z) + mpq_class(t) * (mpq_class(x[i + 2].z) - mpq_class(x[i].z))};
      };
      const auto p = at(0), q = at(1);
      mpq_class sq = 0;
      for (int c = 0; c < 3; ++c) sq += (q[c] - p[c]) * (q[c] - p[c]);
      const double d = sqrt_up(sq, k);
      if (!std::isfinite(d)) continue;
      ++checked;
      const auto frame = in_mode([&] { return ProjectionFrame<4>(x, d); });
      EXPECT_FALSE(in_mode([&] { return separation::primitives_separated<kinds::PointPoint>(frame); }))
          << "k=" << k << " trial " << trial;
      const double a = t * unit(rng), b = t + (1 - t) * unit(rng);
      EXPECT_FALSE(in_mode([&] { return separation::primitives_separated<kinds::PointPoint>(frame.over(a, b)); }))
          << "k=" << k << " trial " << trial << " cell [" << a << ", " << b << "] t=" << t;
    }
  }
  EXPECT_GT(checked, 1400);
}

// Coordinates at the ends of the double range: huge (the frame scales down), subnormal (it
// scales up by more than 2^1000), a d far beyond the coordinates (d 2^s overflows: never
// certified) and d = 0 with the points apart (certified).
TEST_P(RoundingMode, ExtremeMagnitudes) {
  const double big = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  const std::array<Vec3, 4> huge{Vec3{-big, 0, 0}, Vec3{big, 0, 0}, Vec3{-big, 1, 0}, Vec3{big, 1, 0}};
  const auto separated = [&](const std::array<Vec3, 4>& x, double d) {
    return in_mode([&] { return separation::primitives_separated<kinds::PointPoint>(ProjectionFrame<4>(x, d)); });
  };
  EXPECT_TRUE(separated(huge, big));
  const std::array<Vec3, 4> sub{Vec3{0, 0, 0}, Vec3{4 * tiny, 0, 0}, Vec3{0, tiny, 0}, Vec3{4 * tiny, tiny, 0}};
  EXPECT_TRUE(separated(sub, 2 * tiny));
  EXPECT_FALSE(separated(sub, 4 * tiny));
  EXPECT_FALSE(separated(sub, big));
  EXPECT_TRUE(separated(sub, 0.0));
  const std::array<Vec3, 4> same{};
  EXPECT_FALSE(separated(same, 0.0));
}

// A point-edge near miss at every scale: the point (0.52, 0.48, 0.001) u beside the middle of
// the edge from 0 to (u, u, 0), at distance 0.028 u, d = u / 256. No axis separates (the
// point's z is below d, its x and y within the edge's), nor the point-point directions (the
// point projects between the ends); only the point-edge direction e x (r x e) does, and it must
// be formed without overflow or underflow at every scale (r x e is normalised first; without
// that it fails from about 2^345 and below 2^-355).
TEST_P(RoundingMode, PointEdgeNearMissCertifiedAtEveryScale) {
  for (int k = -1000; k <= 1000; k += 5) {
    const double u = std::ldexp(1.0, k);
    const Vec3 p{0.52 * u, 0.48 * u, 0.001 * u}, a{0, 0, 0}, b{u, u, 0};
    const std::array<Vec3, 6> x{p, a, b, p, a, b};
    EXPECT_TRUE(in_mode([&] { return separation::primitives_separated<kinds::PointEdge>(ProjectionFrame<6>(x, u / 256)); }))
        << "scale 2^" << k;
  }
}

// The gap test decided against the threshold's bounds (T at |n| = 1 and 2, precomputed per
// frame) is the test against T itself, for normalised directions whose length ranges over
// [1, sqrt 3] and gaps at, just around and between the bounds, at every scale, d from 0 to far
// above the coordinates, and both error bounds (a frame and its cells, ProjectionFrame::over).
TEST_P(RoundingMode, ThresholdBoundsDecideAsTheThreshold) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> component(-1.0, 1.0);
  const double inf = std::numeric_limits<double>::infinity();
  int between = 0;
  for (const int k : {-1074, -1030, -500, -20, 0, 30, 500, 1000}) {
    for (const double d_scale : {0.0, 0x1p-60, 0x1p-8, 1.0, 0x1p+1000}) {
      std::array<Vec3, 8> x;
      for (Vec3& p : x) p = {std::ldexp(component(rng), k), std::ldexp(component(rng), k), std::ldexp(component(rng), k)};
      const double d = std::min(std::ldexp(d_scale, k), std::numeric_limits<double>::max());
      const auto whole = in_mode([&] { return ProjectionFrame<8>(x, d); });
      ASSERT_TRUE(whole.usable);
      for (const auto& frame : {whole, in_mode([&] { return whole.over(0.25, 0.75); })}) {
        for (int trial = 0; trial < 200; ++trial) {
          // One component exactly +-1, the others in [-1, 1]; every fourth trial at the extremes.
          std::array<double, 3> c{component(rng), component(rng), component(rng)};
          if (trial % 4 == 1) c = {1.0, -1.0, 1.0};
          if (trial % 4 == 2) c = {0x1p-1074, -0.0, 1e-300};
          c[static_cast<std::size_t>(trial) % 3] = trial % 2 ? 1.0 : -1.0;
          const Vec3 n{c[0], c[1], c[2]};
          const double t = in_mode([&] { return separation::gap_threshold(frame, n); });
          EXPECT_LE(frame.threshold_at_least, t);
          EXPECT_LE(t, frame.threshold_at_most);
          const double mid = frame.threshold_at_least + (frame.threshold_at_most - frame.threshold_at_least) / 2;
          for (const double g : {t, std::nextafter(t, inf), std::nextafter(t, -inf), frame.threshold_at_least,
                                 frame.threshold_at_most, std::nextafter(frame.threshold_at_most, inf), mid, -t, 0.0}) {
            between += g > frame.threshold_at_least && !(g > frame.threshold_at_most);
            EXPECT_EQ(in_mode([&] { return separation::gap_exceeds_threshold(frame, n, g); }), g > t)
                << "k " << k << " d " << d << " n " << n.x << " " << n.y << " " << n.z << " g " << g;
          }
        }
      }
    }
  }
  EXPECT_GT(between, 0);  // the square root's band was exercised
}

INSTANTIATE_TEST_SUITE_P(SeparatingDirection, RoundingMode,
                         ::testing::Values(FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO),
                         [](const ::testing::TestParamInfo<int>& info) {
                           switch (info.param) {
                             case FE_UPWARD: return std::string("upward");
                             case FE_DOWNWARD: return std::string("downward");
                             case FE_TOWARDZERO: return std::string("towardzero");
                             default: return std::string("nearest");
                           }
                         });

}  // namespace
}  // namespace exactccd
