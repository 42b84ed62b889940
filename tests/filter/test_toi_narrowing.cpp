// The TOI of a collision at a root of another polynomial of the rule than V, in the root cell the
// interval stage hands over (filter/toi_narrowing.hpp, RuleRootToiStage): coplanar collisions (V
// identically zero, interval/coplanar_roots.hpp) first:
// random queries moving in one plane (full-significand coordinates, so their contact times are
// not doubles), whose TOI must equal the exact method's (CGAL, independent of the filter) bit
// for bit whenever the stage gives one; the stage must give most of them (the integer stages
// took them all before). Deliberately wrong cells (a wrong sign, a cell without the root, an
// earlier candidate) must give no TOI. The same for queries whose V factors (three points on
// one grid line: interval/factored_roots.hpp), and a linear factor's root against its exact
// rational value. And contact::visit_in_plane_poly must name the polynomials of
// for_each_in_plane_poly in its order (the index the interval stage hands over).
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

#include "contact/contact_polynomials.hpp"
#include "exactccd/exactccd.hpp"
#include "filter/interval_stage.hpp"
#include "filter/toi_narrowing.hpp"

namespace exactccd {
namespace {

/// Eight rows in the plane y = `plane` for all t (so V vanishes identically), x and z drawn from
/// [-1, 1] with full significands: the second primitive moves across the first one's path.
std::array<Vec3, 8> coplanar_rows(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double plane = 0.125 * static_cast<int>(rng() % 8) - 0.5;
  std::array<Vec3, 8> r{};
  for (int i = 0; i < 4; ++i) {
    r[i] = {u(rng), plane, u(rng)};
    // The first point sweeps from one side to the other; the rest move a little.
    const double sweep = i == 0 ? -2 * r[i].x : 0.25 * u(rng);
    r[i + 4] = {r[i].x + sweep, plane, r[i].z + 0.25 * u(rng)};
  }
  return r;
}

/// Eight rows where three points share one coordinate for all t (z: the same value at t0 for
/// all three, and at t1), as on a grid line of a folding sheet: two components of one segment
/// test's cross product vanish identically, and V factors (interval/factored_roots.hpp). The
/// three are p, a, b (vertex-face: p against edge (a, b)) or a0, b0, b1 (edge-edge: a0 against
/// edge b); the first point sweeps across the others.
std::array<Vec3, 8> grid_line_rows(std::mt19937_64& rng, bool vertex_face) {
  std::array<Vec3, 8> r = coplanar_rows(rng);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double z0 = u(rng), z1 = u(rng);
  for (auto& p : r) p.y = u(rng);  // no longer in one plane
  for (const int i : vertex_face ? std::array<int, 3>{0, 1, 2} : std::array<int, 3>{0, 2, 3}) {
    r[i].z = z0;
    r[i + 4].z = z1;
  }
  return r;
}

struct Tally {
  int handed_over = 0;  // the interval stage handed over a root cell (RuleRootCell)
  int certified = 0;    // and the stage narrowed it to the TOI
};

/// Runs the interval stage and the rule-root TOI stage on q; a TOI the stage gives must equal
/// the exact method's; the filtered method's answer and TOI must equal it too.
template <class Query>
void check_query(const Query& q, Tally& tally) {
  const std::optional<TimeInterval> exact = answer_query(q, CcdParams{}, Method::exact, true, nullptr);
  EXPECT_EQ(answer_query(q, CcdParams{}, Method::filtered, true, nullptr), exact);
  filter::RootCells findings;
  (void)filter::interval_stage(q, true, findings);
  if (!findings.rule_toi_cell) return;
  ++tally.handed_over;
  ASSERT_TRUE(exact) << "a cell handed over for a query that does not collide";
  const std::optional<TimeInterval> toi = filter::toi_in_rule_cell(q, *findings.rule_toi_cell);
  if (!toi) return;
  ++tally.certified;
  EXPECT_EQ(toi->lo, exact->lo);
  EXPECT_EQ(toi->hi, exact->hi);
}

enum class Motion { coplanar, grid_line };

/// n queries of the kind moving as `motion` says (coplanar_rows, grid_line_rows) through
/// check_query: most collisions' cells must be handed over and narrowed by the stage.
template <class Query>
void check_queries(Motion motion, std::uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  Tally tally;
  for (int i = 0; i < n; ++i) {
    const bool vertex_face = std::is_same_v<Query, VertexFaceQuery>;
    check_query(from_rows<Query>(motion == Motion::coplanar ? coplanar_rows(rng) : grid_line_rows(rng, vertex_face)), tally);
  }
  EXPECT_GT(tally.handed_over, n / 10);
  EXPECT_GT(tally.certified, tally.handed_over * 3 / 4);
}

TEST(InPlaneToi, VertexFaceEqualsExactTois) { check_queries<VertexFaceQuery>(Motion::coplanar, 20261205, 400); }
TEST(InPlaneToi, EdgeEdgeEqualsExactTois) { check_queries<EdgeEdgeQuery>(Motion::coplanar, 20261206, 400); }
TEST(FactoredToi, VertexFaceEqualsExactTois) { check_queries<VertexFaceQuery>(Motion::grid_line, 20261207, 400); }
TEST(FactoredToi, EdgeEdgeEqualsExactTois) { check_queries<EdgeEdgeQuery>(Motion::grid_line, 20261208, 400); }

/// A query with a handed-over cell the stage narrows, and that cell.
template <class Query>
std::pair<Query, filter::RuleRootCell> certified_example(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  for (;;) {
    const Query q = from_rows<Query>(coplanar_rows(rng));
    filter::RootCells findings;
    (void)filter::interval_stage(q, true, findings);
    if (findings.rule_toi_cell && filter::toi_in_rule_cell(q, *findings.rule_toi_cell))
      return {q, *findings.rule_toi_cell};
  }
}

template <class Query>
void check_wrong_cells(std::uint64_t seed) {
  const auto [q, cell] = certified_example<Query>(seed);
  const TimeInterval toi = *filter::toi_in_rule_cell(q, cell);
  ASSERT_LT(cell.lo, toi.lo) << "the example's root is not inside its cell";
  filter::RuleRootCell wrong = cell;
  wrong.sign_at_lo = -cell.sign_at_lo;  // the signs at the ends contradict it
  EXPECT_FALSE(filter::toi_in_rule_cell(q, wrong));
  wrong = cell;
  wrong.hi = toi.lo;  // (lo, toi.lo): the root is not in it, no sign change
  EXPECT_FALSE(filter::toi_in_rule_cell(q, wrong));
  wrong = cell;
  wrong.later_from = toi.lo;  // another candidate may hold before the root
  EXPECT_FALSE(filter::toi_in_rule_cell(q, wrong));
  wrong = cell;
  wrong.poly = filter::RulePoly{(cell.poly.in_plane + 1) % 10};  // another polynomial's signs
  const std::optional<TimeInterval> other = filter::toi_in_rule_cell(q, wrong);
  EXPECT_TRUE(!other || !(*other == toi)) << "another polynomial gave the same TOI";
}

TEST(InPlaneToi, VertexFaceWrongCellsGiveNoToi) { check_wrong_cells<VertexFaceQuery>(7); }
TEST(InPlaneToi, EdgeEdgeWrongCellsGiveNoToi) { check_wrong_cells<EdgeEdgeQuery>(8); }

/// The tightest double interval around a rational r in [0, 1].
TimeInterval tightest(const mpq_class& r) {
  const double d = r.get_d();  // truncates towards zero: r >= 0, so d <= r
  if (mpq_class(d) == r) return {d, d};
  return {d, std::nextafter(d, std::numeric_limits<double>::infinity())};
}

/// A linear factor of V (filter::RulePoly naming a coordinate of a relative motion, as the
/// factored view hands over): its root in (0, 1), the exact rational d0 / (d0 - d1) of the
/// exact differences, narrowed to the tightest double interval.
TEST(FactoredToi, LinearFactorRootIsTightest) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const std::array<Vec3, 8> r = coplanar_rows(rng);
    const VertexFaceQuery q = from_rows<VertexFaceQuery>(r);
    const int from = static_cast<int>(rng() % 4), to = (from + 1 + static_cast<int>(rng() % 3)) % 4;
    const mpq_class d0 = mpq_class(r[to].x) - mpq_class(r[from].x);
    const mpq_class d1 = mpq_class(r[to + 4].x) - mpq_class(r[from + 4].x);
    if (sgn(d0) * sgn(d1) >= 0) continue;  // no root in (0, 1)
    const filter::RuleRootCell cell{0.0, 1.0, sgn(d0), filter::RulePoly{-1, from, to, 0},
                                      std::numeric_limits<double>::infinity()};
    const std::optional<TimeInterval> toi = filter::toi_in_rule_cell(q, cell);
    ASSERT_TRUE(toi) << "query " << i;
    const TimeInterval expected = tightest(mpq_class(d0 / (d0 - d1)));
    EXPECT_EQ(toi->lo, expected.lo) << "query " << i;
    EXPECT_EQ(toi->hi, expected.hi) << "query " << i;
  }
}

/// The addresses of the polynomials for_each_in_plane_poly visits, in order.
template <class Polys>
std::vector<const void*> visited_in_order(const Polys& P) {
  std::vector<const void*> order;
  contact::for_each_in_plane_poly(P, [&](const auto& p) { order.push_back(&p); });
  return order;
}

template <class Query>
void check_indices() {
  std::mt19937_64 rng(3);
  const auto P = contact::polynomials(from_rows<Query>(coplanar_rows(rng)));
  const std::vector<const void*> order = visited_in_order(P);
  const int count = contact::first_degenerate_poly(P) + 4 * contact::degenerate_segment_count(P);
  ASSERT_EQ(order.size(), static_cast<std::size_t>(count));
  for (int i = -1; i <= static_cast<int>(order.size()); ++i) {
    int calls = 0;
    const void* seen = nullptr;
    contact::visit_in_plane_poly(P, i, [&](const auto& p) { ++calls, seen = &p; });
    const bool in_range = 0 <= i && i < static_cast<int>(order.size());
    EXPECT_EQ(calls, in_range ? 1 : 0) << "index " << i;
    if (in_range) {
      EXPECT_EQ(seen, order[static_cast<std::size_t>(i)]) << "index " << i;
    }
  }
}

TEST(InPlanePolyIndex, VertexFaceMatchesEnumeration) { check_indices<VertexFaceQuery>(); }
TEST(InPlanePolyIndex, EdgeEdgeMatchesEnumeration) { check_indices<EdgeEdgeQuery>(); }

}  // namespace
}  // namespace exactccd
