// Stage 1's certified Bernstein coefficients of the volume (certified_volume_bernstein, also
// used by the scene's time bound) against exact rational arithmetic: wherever the filter gives a
// value and an error bound, the exact coefficient lies strictly within it, and the signs agree
// with certified_group_sign's. On bundled data, wide-exponent families (where a constant
// absolute underflow term once failed) and random near-degenerate queries. Also stage 1's
// three verdicts (volume_exclusion) against exact signs and under exact scalings.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"
#include "questions/contact_question.hpp"
#include "filter/unit_scaling.hpp"
#include "filter/volume_exclusion.hpp"
#include "generators/families.hpp"
#include "io/benchmark_csv.hpp"

namespace exactccd {
namespace {

namespace fs = std::filesystem;
using Rows = std::array<Vec3, 8>;
using QVec = std::array<mpq_class, 3>;

QVec exact_difference(const Vec3& a, const Vec3& b) {
  return {mpq_class(a.x) - mpq_class(b.x), mpq_class(a.y) - mpq_class(b.y), mpq_class(a.z) - mpq_class(b.z)};
}

mpq_class det(const QVec& u, const QVec& v, const QVec& w) {
  return u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

/// |exact - value| < error, in exact arithmetic (value and error are doubles).
bool within(const mpq_class& exact, const filter::CertifiedSum& s) {
  return abs(exact - mpq_class(s.value)) < mpq_class(s.error);
}

struct Tally {
  std::size_t queries = 0, certified = 0;
};

/// Checks one query's volume V = det[r1 - r0, r2 - r0, r3 - r0] (rows r0..r3 at t0, +4 at t1).
void check(const Rows& r, const std::string& where, Tally& tally) {
  ++tally.queries;
  const auto d = [&](int i, int t) {
    return Vec3{r[i + 4 * t].x - r[4 * t].x, r[i + 4 * t].y - r[4 * t].y, r[i + 4 * t].z - r[4 * t].z};
  };
  const auto beta = filter::certified_volume_bernstein(d(1, 0), d(1, 1), d(2, 0), d(2, 1), d(3, 0), d(3, 1));
  if (!beta) return;
  ++tally.certified;
  QVec u[2], v[2], w[2];
  for (int t = 0; t < 2; ++t) {
    u[t] = exact_difference(r[1 + 4 * t], r[4 * t]);
    v[t] = exact_difference(r[2 + 4 * t], r[4 * t]);
    w[t] = exact_difference(r[3 + 4 * t], r[4 * t]);
  }
  const mpq_class exact[4] = {det(u[0], v[0], w[0]),
                              det(u[1], v[0], w[0]) + det(u[0], v[1], w[0]) + det(u[0], v[0], w[1]),
                              det(u[1], v[1], w[0]) + det(u[1], v[0], w[1]) + det(u[0], v[1], w[1]),
                              det(u[1], v[1], w[1])};
  for (int m = 0; m < 4; ++m) {
    EXPECT_TRUE(within(exact[m], (*beta)[m]))
        << where << ": beta_" << m << " = " << exact[m].get_d() << " outside " << (*beta)[m].value << " +- "
        << (*beta)[m].error;
    const int s = sgn(exact[m]);
    if ((*beta)[m].value > (*beta)[m].error) {
      EXPECT_EQ(s, 1) << where << " beta_" << m;
    }
    if ((*beta)[m].value < -(*beta)[m].error) {
      EXPECT_EQ(s, -1) << where << " beta_" << m;
    }
  }
}

TEST(CertifiedVolumeBernstein, EnclosesTheExactCoefficientsOnBundledData) {
  Tally tally;
  for (const char* dir : {"sim", "catalogue", "families"})
    for (const auto& e : fs::directory_iterator(fs::path(EXACTCCD_SOURCE_DIR) / "data" / dir)) {
      if (e.path().extension() != ".csv") continue;
      std::ifstream in(e.path());
      const io::BenchmarkQueries q = io::read_benchmark_csv(in, e.path().string());
      for (std::size_t i = 0; i < q.size(); ++i)
        if (const auto rows = io::exact_double_rows(q.rows[i]))
          check(*rows, e.path().filename().string() + "#" + std::to_string(i), tally);
    }
  EXPECT_GT(tally.certified, tally.queries / 2) << "the filter should certify most bundled queries";
}

TEST(CertifiedVolumeBernstein, EnclosesTheExactCoefficientsOnWideFamilies) {
  Tally tally;
  std::mt19937_64 rng(1202);
  for (const families::Family& f : families::all_families())
    for (int style = 0; style < families::kWideStyleCount; ++style)
      for (int k : {0, 20, 52})
        for (bool toward : {true, false})
          for (int repeat = 0; repeat < 3; ++repeat)
            if (const auto inst = families::make_wide(f, k, toward, static_cast<families::WideStyle>(style), rng))
              std::visit([&](const auto& q) { check(rows(q), f.name + " wide", tally); }, inst->query);
  EXPECT_GT(tally.queries, 500u);
  EXPECT_GT(tally.certified, 0u);
}

TEST(CertifiedVolumeBernstein, EnclosesTheExactCoefficientsOnRandomQueries) {
  Tally tally;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1074, 1000);
  for (int n = 0; n < 3000; ++n) {
    Rows r;
    const int e = n % 3 == 0 ? exponent(rng) / 4 : 0;  // a third at scales 2^-268..2^250
    for (Vec3& p : r) p = {std::ldexp(unit(rng), e), std::ldexp(unit(rng), e), std::ldexp(unit(rng), e)};
    if (n % 2 == 0) r[7] = r[3];  // a static fourth point: nearer degenerate volumes
    check(r, "random #" + std::to_string(n), tally);
  }
  EXPECT_GT(tally.certified, 1000u);
}

/// The exact Bernstein coefficients (times C(3, m)) of V for rows r (V = det[r1 - r0, r2 - r0,
/// r3 - r0]).
std::array<mpq_class, 4> exact_bernstein(const Rows& r) {
  QVec u[2], v[2], w[2];
  for (int t = 0; t < 2; ++t) {
    u[t] = exact_difference(r[1 + 4 * t], r[4 * t]);
    v[t] = exact_difference(r[2 + 4 * t], r[4 * t]);
    w[t] = exact_difference(r[3 + 4 * t], r[4 * t]);
  }
  return {det(u[0], v[0], w[0]), det(u[1], v[0], w[0]) + det(u[0], v[1], w[0]) + det(u[0], v[0], w[1]),
          det(u[1], v[1], w[0]) + det(u[1], v[0], w[1]) + det(u[0], v[1], w[1]), det(u[1], v[1], w[1])};
}

filter::Exclusion exclusion_of(const Rows& r) {
  return filter::volume_exclusion(from_rows<EdgeEdgeQuery>(r));  // edge-edge: V = det[r1 - r0, ...]
}

Rows scaled(const Rows& r, int s) {
  Rows out = r;
  for (Vec3& p : out) p = {std::ldexp(p.x, s), std::ldexp(p.y, s), std::ldexp(p.z, s)};
  return out;
}

// excluded only when the exact Bernstein coefficients all have one strict sign (a sufficient
// condition for V != 0 on [0, 1]); a scaling by a power of two that keeps every value normal
// leaves the verdict unchanged (what lets the filtered method retry only after out_of_range);
// tiny queries are out_of_range, and excluded once scaled towards 1 when their unit-size
// original is.
TEST(VolumeExclusion, VerdictsAgreeWithExactSignsAndAreScaleInvariantInRange) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::size_t verdicts[3] = {0, 0, 0};
  for (int n = 0; n < 4000; ++n) {
    Rows r;
    for (Vec3& p : r) p = {unit(rng), unit(rng), unit(rng)};
    if (n % 2 == 0) r[7] = r[3];  // nearer-degenerate volumes: more not_proven verdicts
    if (n % 4 == 1)                // nearly coplanar at t = 0: the fourth point near the plane
      r[3] = {r[0].x + r[1].x - r[2].x, r[0].y + r[1].y - r[2].y, r[0].z + r[1].z - r[2].z};
    const filter::Exclusion e = exclusion_of(r);
    ++verdicts[static_cast<int>(e)];
    const auto beta = exact_bernstein(r);
    if (e == filter::Exclusion::excluded) {
      const int s = sgn(beta[0]);
      for (const mpq_class& b : beta) EXPECT_EQ(sgn(b), s) << "query " << n << ": excluded with mixed signs";
      EXPECT_NE(s, 0) << "query " << n;
    }
    EXPECT_NE(e, filter::Exclusion::out_of_range) << "query " << n << " is of unit size";
    for (int k : {-300, -37, -1, 1, 5, 200})
      EXPECT_EQ(exclusion_of(scaled(r, k)), e) << "query " << n << " scaled by 2^" << k;
    // Tiny (the underflow guard) and huge (products overflow) copies are out of range, and the
    // filtered method's retry on the copy scaled towards 1 decides them in stage 1 when the
    // unit-size query is excluded there.
    for (int k : {-1000, 600}) {
      const Rows far = scaled(r, k);
      EXPECT_EQ(exclusion_of(far), filter::Exclusion::out_of_range) << "query " << n << " scaled by 2^" << k;
      if (e != filter::Exclusion::excluded) continue;
      bool was_scaled = false;
      const EdgeEdgeQuery unit_query = filter::scaled_to_unit(from_rows<EdgeEdgeQuery>(far), was_scaled);
      EXPECT_TRUE(was_scaled);
      EXPECT_TRUE(filter::volume_excluded(unit_query)) << "query " << n;
      StageCounters counters;
      EXPECT_FALSE(questions::contact_question(from_rows<EdgeEdgeQuery>(far), pipeline::Question{}, &counters));
      EXPECT_EQ(counters.volume_exclusion, 1u) << "query " << n << " scaled by 2^" << k << ": not decided by the retry";
    }
  }
  EXPECT_GT(verdicts[static_cast<int>(filter::Exclusion::excluded)], 500u);
  EXPECT_GT(verdicts[static_cast<int>(filter::Exclusion::not_proven)], 500u);
}

}  // namespace
}  // namespace exactccd
