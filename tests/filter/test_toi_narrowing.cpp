// The TOI of a coplanar collision (V identically zero) in the in-plane root cell the interval
// stage hands over (filter/toi_narrowing.hpp, InPlaneToiStage; interval/coplanar_roots.hpp):
// random queries moving in one plane (full-significand coordinates, so their contact times are
// not doubles), whose TOI must equal the exact method's (CGAL, independent of the filter) bit
// for bit whenever the stage gives one; the stage must give most of them (the integer stages
// took them all before). Deliberately wrong cells (a wrong sign, a cell without the root, an
// earlier candidate) must give no TOI. And contact::visit_in_plane_poly must name the
// polynomials of for_each_in_plane_poly in its order (the index the interval stage hands over).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
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

struct Tally {
  int handed_over = 0;  // the interval stage handed over an in-plane root cell
  int certified = 0;    // and the stage narrowed it to the TOI
};

/// Runs the interval stage and the in-plane TOI stage on q; a TOI the stage gives must equal
/// the exact method's; the filtered method's answer and TOI must equal it too.
template <class Query>
void check_query(const Query& q, Tally& tally) {
  const std::optional<TimeInterval> exact = answer_query(q, CcdParams{}, Method::exact, true, nullptr);
  EXPECT_EQ(answer_query(q, CcdParams{}, Method::filtered, true, nullptr), exact);
  pipeline::Findings findings;
  (void)filter::interval_stage(q, true, findings);
  if (!findings.in_plane_toi_cell) return;
  ++tally.handed_over;
  ASSERT_TRUE(exact) << "a cell handed over for a query that does not collide";
  const std::optional<TimeInterval> toi = filter::toi_in_plane_cell(q, *findings.in_plane_toi_cell);
  if (!toi) return;
  ++tally.certified;
  EXPECT_EQ(toi->lo, exact->lo);
  EXPECT_EQ(toi->hi, exact->hi);
}

template <class Query>
Tally check_random_queries(std::uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  Tally tally;
  for (int i = 0; i < n; ++i) check_query(from_rows<Query>(coplanar_rows(rng)), tally);
  return tally;
}

TEST(InPlaneToi, VertexFaceEqualsExactTois) {
  const Tally tally = check_random_queries<VertexFaceQuery>(20261205, 400);
  EXPECT_GT(tally.handed_over, 40);
  EXPECT_GT(tally.certified, tally.handed_over * 3 / 4);
}

TEST(InPlaneToi, EdgeEdgeEqualsExactTois) {
  const Tally tally = check_random_queries<EdgeEdgeQuery>(20261206, 400);
  EXPECT_GT(tally.handed_over, 40);
  EXPECT_GT(tally.certified, tally.handed_over * 3 / 4);
}

/// A query with a handed-over cell the stage narrows, and that cell.
template <class Query>
std::pair<Query, pipeline::InPlaneRootCell> certified_example(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  for (;;) {
    const Query q = from_rows<Query>(coplanar_rows(rng));
    pipeline::Findings findings;
    (void)filter::interval_stage(q, true, findings);
    if (findings.in_plane_toi_cell && filter::toi_in_plane_cell(q, *findings.in_plane_toi_cell))
      return {q, *findings.in_plane_toi_cell};
  }
}

template <class Query>
void check_wrong_cells(std::uint64_t seed) {
  const auto [q, cell] = certified_example<Query>(seed);
  const TimeInterval toi = *filter::toi_in_plane_cell(q, cell);
  ASSERT_LT(cell.lo, toi.lo) << "the example's root is not inside its cell";
  pipeline::InPlaneRootCell wrong = cell;
  wrong.sign_at_lo = -cell.sign_at_lo;  // the signs at the ends contradict it
  EXPECT_FALSE(filter::toi_in_plane_cell(q, wrong));
  wrong = cell;
  wrong.hi = toi.lo;  // (lo, toi.lo): the root is not in it, no sign change
  EXPECT_FALSE(filter::toi_in_plane_cell(q, wrong));
  wrong = cell;
  wrong.later_from = toi.lo;  // another candidate may hold before the root
  EXPECT_FALSE(filter::toi_in_plane_cell(q, wrong));
  wrong = cell;
  wrong.poly = (cell.poly + 1) % 10;  // another polynomial's signs
  const std::optional<TimeInterval> other = filter::toi_in_plane_cell(q, wrong);
  EXPECT_TRUE(!other || !(*other == toi)) << "another polynomial gave the same TOI";
}

TEST(InPlaneToi, VertexFaceWrongCellsGiveNoToi) { check_wrong_cells<VertexFaceQuery>(7); }
TEST(InPlaneToi, EdgeEdgeWrongCellsGiveNoToi) { check_wrong_cells<EdgeEdgeQuery>(8); }

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
  ASSERT_EQ(order.size(), static_cast<std::size_t>(contact::first_degenerate_poly(P) + 4 * contact::degenerate_segment_count(P)));
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
