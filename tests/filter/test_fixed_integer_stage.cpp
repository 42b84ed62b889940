// filter::fixed_integer_stage (the integer stage in 1024-bit checked integers, in front of the
// GMP stage): wherever it decides, its answer and TOI equal the GMP stage's (filter::
// integer_stage, the existing exact stage) and, on a sample, the CGAL reference's
// (Method::exact); it decides the degenerate queries it is meant for; it defers (uncertain)
// beyond the exponent spread of its bit bound, and at the bound's edge it either decides
// exactly as GMP or defers. Inputs: random degenerate family instances, the hand-made catalogue
// (with its 2^996, 2^-1060 and translated copies), wide-exponent placements, and instances
// scaled per axis to an exponent spread of exactly kFixedIntegerSpreadLimit and one more.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <variant>

#include "exactccd/exactccd.hpp"
#include "exact/integer_ops.hpp"
#include "filter/integer_query.hpp"
#include "filter/integer_stage.hpp"
#include "generators/catalogue.hpp"
#include "generators/families.hpp"

namespace exactccd {
namespace {

using families::AnyQuery;

using pipeline::Outcome;

std::string describe(const Outcome& r) {
  std::ostringstream out;
  out << (r.answer == Outcome::Answer::collides    ? "collision"
          : r.answer == Outcome::Answer::separate ? "no collision"
                                                  : "uncertain");
  if (r.toi) out << std::hexfloat << " [" << r.toi->lo << ", " << r.toi->hi << "]";
  return out.str();
}

struct Tally {
  int queries = 0, decided = 0, deferred_by_spread = 0;
};

/// Both stages on q, with and without the TOI: a decision of the fixed stage must be the GMP
/// stage's, TOI included; beyond the spread limit the fixed stage must defer.
template <class Query>
void compare_with_gmp(const Query& q, const std::string& label, Tally& tally) {
  for (const bool want_toi : {false, true}) {
    const Outcome fixed = filter::fixed_integer_stage(q, want_toi);
    const Outcome gmp = filter::integer_stage(q, want_toi);
    ++tally.queries;
    if (filter::exponent_spread(q) > filter::kFixedIntegerSpreadLimit) {
      ++tally.deferred_by_spread;
      EXPECT_EQ(fixed.answer, Outcome::Answer::undecided) << label << ": beyond the spread limit it must defer";
      continue;
    }
    if (fixed.answer == Outcome::Answer::undecided) continue;
    ++tally.decided;
    ASSERT_NE(gmp.answer, Outcome::Answer::undecided) << label << ": fixed decided, GMP did not";
    EXPECT_EQ(describe(fixed), describe(gmp)) << label << (want_toi ? " (toi)" : " (ccd)");
  }
}

void compare_any(const AnyQuery& q, const std::string& label, Tally& tally) {
  std::visit([&](const auto& query) { compare_with_gmp(query, label, tally); }, q);
}

TEST(FixedIntegerStage, AgreesWithGmpOnRandomFamilyInstances) {
  std::mt19937_64 rng(20261202);
  Tally tally;
  for (int i = 0; i < 1500; ++i) {
    const families::Instance instance = families::random_instance(rng);
    compare_any(instance.query, "random instance " + std::to_string(i), tally);
  }
  // The stage is meant to decide these degenerate queries: most must not defer.
  EXPECT_GT(tally.decided, tally.queries / 2) << tally.decided << " of " << tally.queries;
}

TEST(FixedIntegerStage, AgreesWithTheExactMethodOnASample) {
  // The CGAL reference, independent of the integer stages' code: answers and TOIs.
  std::mt19937_64 rng(7);
  int decided = 0;
  for (int i = 0; i < 150; ++i) {
    const families::Instance instance = families::random_instance(rng);
    std::visit(
        [&](const auto& q) {
          const Outcome fixed = filter::fixed_integer_stage(q, true);
          if (fixed.answer == Outcome::Answer::undecided) return;
          ++decided;
          const std::optional<TimeInterval> reference = toi(q, Method::exact);
          ASSERT_EQ(fixed.answer == Outcome::Answer::collides, reference.has_value()) << "instance " << i;
          if (reference) {
            ASSERT_TRUE(fixed.toi.has_value()) << "instance " << i;
            EXPECT_EQ(fixed.toi->lo, reference->lo) << "instance " << i;
            EXPECT_EQ(fixed.toi->hi, reference->hi) << "instance " << i;
          }
        },
        instance.query);
  }
  EXPECT_GT(decided, 75);
}

template <class Entries>
void compare_catalogue(const Entries& entries, Tally& tally) {
  for (const auto& e : entries) {
    std::array<Vec3, 8> r{};
    const auto exact_rows = rows(e.query);
    for (std::size_t i = 0; i < exact_rows.size(); ++i)
      r[i] = {exact_rows[i].x.get_d(), exact_rows[i].y.get_d(), exact_rows[i].z.get_d()};  // exact: doubles
    using Query = std::conditional_t<std::is_same_v<std::decay_t<decltype(e.query)>, RationalVertexFaceQuery>,
                                     VertexFaceQuery, EdgeEdgeQuery>;
    compare_with_gmp(from_rows<Query>(r), "catalogue " + e.name, tally);
  }
}

TEST(FixedIntegerStage, AgreesWithGmpOnTheCatalogue) {
  Tally tally;
  compare_catalogue(catalogue::vertex_face_cases(), tally);
  compare_catalogue(catalogue::edge_edge_cases(), tally);
  EXPECT_GT(tally.decided, 0);
  // The translated copies (by 2^20, 2^40 of small coordinates) keep spreads below the limit;
  // the catalogue has no case beyond it: the stage must decide most cases.
  EXPECT_GT(tally.decided, tally.queries / 2) << tally.decided << " of " << tally.queries;
}

TEST(FixedIntegerStage, DefersOrAgreesOnWideExponents) {
  std::mt19937_64 rng(99);
  Tally tally;
  for (int i = 0; i < 400; ++i) {
    const auto& pool = families::all_families();
    const families::Family& family = pool[static_cast<std::size_t>(rng() % pool.size())];
    const auto style = static_cast<families::WideStyle>(rng() % families::kWideStyleCount);
    const auto instance = families::make_wide(family, static_cast<int>(rng() % 40), rng() % 2 == 0, style, rng);
    if (!instance) continue;
    compare_any(instance->query, std::string("wide ") + families::wide_style_name(style), tally);
  }
  // The extremes style spans 2^-1074..2^1023: those must be deferred by the spread test.
  EXPECT_GT(tally.deferred_by_spread, 0);
  EXPECT_GT(tally.decided, 0);
}

/// q with the coordinates of axis `axis` multiplied by 2^s (exact for the mild placements used
/// here: no overflow or underflow). A per-axis power-of-two scale keeps every answer and TOI.
template <class Query>
Query scale_axis(const Query& q, int axis, int s) {
  auto r = rows(q);
  for (Vec3& v : r) (axis == 0 ? v.x : axis == 1 ? v.y : v.z) = std::ldexp(axis == 0 ? v.x : axis == 1 ? v.y : v.z, s);
  return from_rows<Query>(r);
}

TEST(FixedIntegerStage, AtTheSpreadLimitDecidesLikeGmpAndDefersBeyond) {
  std::mt19937_64 rng(5);
  Tally at_limit, beyond;
  for (int i = 0; i < 400; ++i) {
    const families::Instance instance = families::random_instance(rng);
    std::visit(
        [&](const auto& q) {
          // Scale one axis so that the spread is exactly the limit, then one more: for a large
          // scale the spread grows by one per bit, so a correction or two lands on the target.
          for (int target : {filter::kFixedIntegerSpreadLimit, filter::kFixedIntegerSpreadLimit + 1}) {
            const int axis = static_cast<int>(rng() % 3);
            int s = rng() % 2 ? target : -target;
            for (int step = 0; step < 4; ++step) {
              const auto scaled = scale_axis(q, axis, s);
              const int spread = filter::exponent_spread(scaled);
              if (spread == target) {
                compare_with_gmp(scaled, "spread " + std::to_string(target) + ", instance " + std::to_string(i),
                                 target == filter::kFixedIntegerSpreadLimit ? at_limit : beyond);
                break;
              }
              s += (s > 0 ? 1 : -1) * (target - spread);
            }
          }
        },
        instance.query);
  }
  ASSERT_GT(at_limit.queries, 100);
  ASSERT_GT(beyond.queries, 100);
  EXPECT_EQ(beyond.deferred_by_spread, beyond.queries);
  // At the limit the bound covers the common path: most decisions need no GMP.
  EXPECT_GT(at_limit.decided, at_limit.queries / 4) << at_limit.decided << " of " << at_limit.queries;
}

TEST(FixedIntegerStage, OneMoreBitOfSpreadDefers) {
  // A plain crossing (p = (1, 1) through the triangle (0, 0), (2^L', 0), (0, 4) at t = 1/2;
  // frexp exponents 1, 3 and L' + 1) with L' = limit + 1: spread limit + 1, so the stage
  // defers; the GMP stage decides.
  const auto crossing = [](int bits) {
    const double far = std::ldexp(1.0, bits);
    return VertexFaceQuery{{1, 1, 1}, {0, 0, 0}, {far, 0, 0}, {0, 4, 0}, {1, 1, -1}, {0, 0, 0}, {far, 0, 0}, {0, 4, 0}};
  };
  const VertexFaceQuery q = crossing(filter::kFixedIntegerSpreadLimit + 1);
  ASSERT_EQ(filter::exponent_spread(q), filter::kFixedIntegerSpreadLimit + 1);
  EXPECT_EQ(filter::fixed_integer_stage(q, true).answer, Outcome::Answer::undecided);
  const Outcome gmp = filter::integer_stage(q, true);
  ASSERT_EQ(gmp.answer, Outcome::Answer::collides);
  EXPECT_EQ(gmp.toi->lo, 0.5);
  // The same crossing at the limit: decided by the fixed stage, as by GMP.
  const VertexFaceQuery r = crossing(filter::kFixedIntegerSpreadLimit);
  ASSERT_EQ(filter::exponent_spread(r), filter::kFixedIntegerSpreadLimit);
  const Outcome fixed = filter::fixed_integer_stage(r, true);
  ASSERT_EQ(fixed.answer, Outcome::Answer::collides);
  EXPECT_EQ(fixed.toi->lo, 0.5);
  EXPECT_EQ(fixed.toi->hi, 0.5);
}

TEST(FixedIntegerStage, OverflowThrowsInsteadOfWrapping) {
  // The checked type is what makes the stage exact beyond its bound: an overflow must throw.
  const exact::FixedInteger top = exact::shifted(exact::FixedInteger(1), exact::kFixedIntegerBits - 1);
  EXPECT_THROW(exact::shifted(top, 1), std::overflow_error);
  EXPECT_THROW(static_cast<void>(top * 2), std::overflow_error);
  EXPECT_THROW(static_cast<void>(top + top), std::overflow_error);
  EXPECT_THROW(exact::shifted(exact::FixedInteger(-top), 1), std::overflow_error);
  EXPECT_EQ(exact::shifted(exact::FixedInteger(-3), 4), exact::FixedInteger(-48));
}

}  // namespace
}  // namespace exactccd
