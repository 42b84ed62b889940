// interval::parallel_factor_strategy (docs/design.md 5.2; interval_stage.cpp, item 6): edge
// pairs whose directions agree exactly in two coordinates (up to one sign), as on the parallel
// grid lines of a folding sheet. There V and the cross product w share the root of
// Delta = db_k - s da_k (the edges are parallel exactly when they are coplanar), which the
// plain isolation of V cannot decide. Random such pairs (full-significand coordinates, both
// signs s, Delta with and without a root in [0, 1], near-collinear placements that make
// contact at Delta's root): the filtered method's answers and TOIs must equal the exact
// method's (CGAL, independent of the interval stage), and the interval stage must decide them
// (not the integer stages).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "exactccd/exactccd.hpp"

namespace exactccd {
namespace {

/// a0 = (x0, y, z0), a1 = (x1, y + h, z1); b0, b1 on the parallel line y + dy: with s = +1,
/// b0 = (x0, y + dy, z2), b1 = (x1, y + dy + h, z3); with s = -1 the ends of b swap in x and
/// y. So da_x = s db_x and da_y = s db_y exactly (the same double subtractions), and
/// Delta = (db - s da)_z. collinear: dy = 0 and z on one line at t = 1/2 (contact candidates
/// at Delta's root).
EdgeEdgeQuery make_pair(std::mt19937_64& rng, bool negated, bool same_line) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double h = 0.125, dy = same_line ? 0.0 : 0.125 * (1 + static_cast<int>(rng() % 3));
  std::array<Vec3, 8> r{};
  for (int at = 0; at < 2; ++at) {
    const double x0 = u(rng), x1 = u(rng), y = 0.25 * static_cast<int>(rng() % 8);
    const double z0 = 0.05 * u(rng), z1 = 0.05 * u(rng);
    double z2 = 0.05 * u(rng), z3 = 0.05 * u(rng);
    if (same_line && at == 0) z2 = z0, z3 = z1;  // identical edges at t0: contact at t = 0
    const int o = 4 * at;
    r[o + 0] = {x0, y, z0};
    r[o + 1] = {x1, y + h, z1};
    if (!negated) {
      r[o + 2] = {x0, y + dy, z2};
      r[o + 3] = {x1, y + dy + h, z3};
    } else {
      r[o + 2] = {x1, y + dy + h, z2};
      r[o + 3] = {x0, y + dy, z3};
    }
  }
  return from_rows<EdgeEdgeQuery>(r);
}

TEST(ParallelFactorStrategy, AgreesWithTheExactMethodAndDecidesInIntervals) {
  std::mt19937_64 rng(31337);
  int queries = 0, collisions = 0, past_interval = 0;
  for (int i = 0; i < 3000; ++i) {
    const EdgeEdgeQuery q = make_pair(rng, i % 2 == 1, i % 7 == 0);
    StageCounters counters;
    const std::optional<TimeInterval> filtered = toi(q, Method::filtered, counters);
    const std::optional<TimeInterval> exact = toi(q, Method::exact);
    ++queries;
    ASSERT_EQ(filtered.has_value(), exact.has_value()) << "query " << i;
    if (exact) {
      ++collisions;
      EXPECT_EQ(filtered->lo, exact->lo) << "query " << i;
      EXPECT_EQ(filtered->hi, exact->hi) << "query " << i;
    }
    past_interval += counters.fixed_integer + counters.integer + counters.exact > 0;
  }
  EXPECT_GT(collisions, 0);
  // The strategy exists for these pairs. Measured on this generator (2026-12-02): 429 of 3000
  // pass the interval stage with it, 1722 of 3000 without it (the strategy disabled): a quarter
  // separates the two. (The rest: cells of Delta and F not separated within the budget, or F
  // not isolable in intervals.)
  EXPECT_LT(past_interval, queries / 4) << past_interval << " of " << queries;
}

}  // namespace
}  // namespace exactccd
