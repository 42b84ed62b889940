// The exact power-of-two normalisation of a query (filter/unit_scaling.hpp, scale_to_unit) against
// the C library's std::ldexp, coordinate by coordinate: the same scaled query when every
// coordinate scales exactly, `false` with the output untouched when one would round (a tiny
// coordinate pushed into the subnormal range), over the whole exponent range (scaling up and
// down, the boundaries of the multiplication paths at 2^-1022 and 2^1000 included).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "exactccd/exactccd.hpp"
#include "filter/unit_scaling.hpp"

namespace exactccd {
namespace {

using Rows = std::array<Vec3, 8>;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// The reference: s brings the largest magnitude into [1, 2); the query scales when s != 0 and
/// every coordinate x satisfies ldexp(ldexp(x, s), -s) == x.
struct Reference {
  int s = 0;
  bool scales = false;
  Rows rows{};
};

Reference reference(const Rows& r) {
  double largest = 0;
  for (const Vec3& p : r) largest = std::max({largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  Reference ref;
  if (largest == 0) return ref;
  const int s = ref.s = -std::ilogb(largest);
  if (s == 0) return ref;
  ref.scales = true;
  for (std::size_t i = 0; i < r.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double x = (&r[i].x)[k], y = std::ldexp(x, s);
      if (std::ldexp(y, -s) != x) ref.scales = false;
      (&ref.rows[i].x)[k] = y;
    }
  return ref;
}

/// A random double of magnitude about 2^e (any sign; e clamped to the double range).
double around(std::mt19937_64& rng, int e) {
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  const double m = std::bernoulli_distribution(0.5)(rng) ? mantissa(rng) : -mantissa(rng);
  return std::ldexp(m, std::clamp(e, -1074, 1023));
}

TEST(ScaleToUnit, EqualsLdexpCoordinateByCoordinate) {
  std::mt19937_64 rng(2026);
  std::uniform_int_distribution<int> top(-1074, 1023), spread(0, 80), far_spread(0, 1100), pick(0, 7);
  std::size_t scaled = 0, refused = 0;
  // The largest exponents near the edges of the code's paths first, then random ones.
  const int edges[] = {-1074, -1060, -1023, -1022, -1021, -60, -1, 0, 1, 2, 999, 1000, 1001, 1023};
  for (int n = 0; n < 40000; ++n) {
    const int e = n < 14 * 200 ? edges[n / 200] : top(rng);
    Rows r;
    for (Vec3& p : r)
      for (double* x : {&p.x, &p.y, &p.z}) *x = around(rng, e - (n % 3 == 0 ? far_spread(rng) : spread(rng)));
    if (n % 5 == 0) r[static_cast<std::size_t>(pick(rng))].y = 0;  // exact zeros scale exactly
    (&r[static_cast<std::size_t>(pick(rng))].x)[n % 3] = around(rng, e);  // one coordinate at the top
    const Reference ref = reference(r);
    const EdgeEdgeQuery q = from_rows<EdgeEdgeQuery>(r);
    Rows sentinel;
    for (Vec3& p : sentinel) p = {0.25, -0.5, 0.75};
    EdgeEdgeQuery out = from_rows<EdgeEdgeQuery>(sentinel);
    const bool result = filter::scale_to_unit(q, out);
    ASSERT_EQ(result, ref.scales) << "query " << n << ", largest exponent about " << e;
    const Rows got = rows(out), expected = result ? ref.rows : sentinel;
    for (std::size_t i = 0; i < 8; ++i)
      for (int k = 0; k < 3; ++k)
        ASSERT_TRUE(same_bits((&got[i].x)[k], (&expected[i].x)[k]))
            << "query " << n << ", row " << i << ", coordinate " << k << ": " << (&got[i].x)[k] << " instead of "
            << (&expected[i].x)[k];
    scaled += result;
    refused += !result && ref.s != 0;
  }
  // Both outcomes are met often: scaled queries, and refusals (underflow when scaling down).
  EXPECT_GT(scaled, 10000u);
  EXPECT_GT(refused, 1000u);
}

}  // namespace
}  // namespace exactccd
