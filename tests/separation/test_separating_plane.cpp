// The contact question's separating-plane stage (separation/separating_plane.hpp) and the per-end
// gap test it rests on (separation::gap_certified_at_each_end):
//  - the bound: configurations at distance exactly d at t0 and at t1 (built from integers, 53-bit
//    coordinates so that projections round; at scales from the subnormal range to 2^960, in
//    every rounding mode) are never certified along their exact gap direction, and at a quarter
//    of that distance they are;
//  - soundness: on random queries near contact (points crossing triangles, edges crossing
//    edges, touching at an end, sliding in a plane, small-integer grids) the stage never calls
//    apart a query that the exact method (CGAL) finds colliding;
//  - use: neighbouring elements of a nearly flat cloth moving alike, whose volume changes sign
//    (stage 1 cannot decide them), are decided by this stage in the filtered pipeline.
#include <gtest/gtest.h>

#include <array>
#include <cfenv>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "exactccd/exactccd.hpp"
#include "separation/separating_plane.hpp"
#include "filter/volume_exclusion.hpp"
#include "kinds/primitive_kinds.hpp"
#include "questions/contact_question.hpp"
#include "separation/separating_direction.hpp"

namespace exactccd {
namespace {

using Rows = std::array<Vec3, 8>;

// ---------------------------------------------------------------------------------------------
// The bound.

double scaled(std::int64_t v, int k) { return std::ldexp(static_cast<double>(v), k); }

/// Integer points p + gap (1, 2, 2) + u (2, -1, 0) + v (2, 0, -1): the second set lies at
/// exactly 3 s along (1, 2, 2) from the first's plane, spans orthogonal to it (the closest points
/// interior), for vertex-face (point; triangle) and edge-edge (edge; edge).
std::array<std::array<std::int64_t, 3>, 4> tangent_points(bool vertex_face, const std::array<std::int64_t, 3>& p,
                                                        std::int64_t s, std::int64_t m) {
  const auto at = [&](std::int64_t gap, std::int64_t u, std::int64_t v) {
    return std::array<std::int64_t, 3>{p[0] + gap + 2 * u + 2 * v, p[1] + 2 * gap - u, p[2] + 2 * gap - v};
  };
  if (vertex_face) return {at(0, 0, 0), at(s, -m, -m), at(s, 2 * m, -m), at(s, -m, 2 * m)};
  return {at(0, -m, 0), at(0, m, 0), at(s, 0, -m), at(s, 0, m)};
}

TEST(SeparatingPlaneBound, NeverCertifiesDistanceDAtEitherEndInAnyRoundingMode) {
  std::mt19937_64 rng(314);
  std::uniform_int_distribution<std::int64_t> base(-(std::int64_t{1} << 51), std::int64_t{1} << 51);
  const Vec3 n{0.5, 1.0, 1.0};  // (1, 2, 2) normalised by its largest component, exactly
  int useful = 0, cases = 0;
  for (const int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
    for (const int k : {-1074, -1040, -700, -60, 0, 60, 700, 960}) {
      for (int trial = 0; trial < 24; ++trial) {
        const bool vertex_face = trial % 2 == 0;
        const std::int64_t s = (std::int64_t{1} << 20) + trial, m = (std::int64_t{1} << (trial % 4 < 2 ? 20 : 40)) + 3 * trial;
        // Each end its own placement: the gap is exactly 3 s at t0 and at t1 (and larger
        // between them where the placements differ); trial % 3 == 0 keeps both ends equal.
        const std::array<std::int64_t, 3> p0{base(rng), base(rng), base(rng)};
        const std::array<std::int64_t, 3> p1 = trial % 3 == 0 ? p0 : std::array<std::int64_t, 3>{base(rng), base(rng), base(rng)};
        const auto a = tangent_points(vertex_face, p0, s, m), b = tangent_points(vertex_face, p1, s, m);
        Rows x;
        for (int i = 0; i < 4; ++i) {
          x[i] = {scaled(a[i][0], k), scaled(a[i][1], k), scaled(a[i][2], k)};
          x[i + 4] = {scaled(b[i][0], k), scaled(b[i][1], k), scaled(b[i][2], k)};
        }
        const double d = scaled(3 * s, k);  // the exact distance at t0 and at t1
        std::array<separation::Side, 4> side;
        for (int i = 0; i < 4; ++i) side[i] = i < (vertex_face ? 1 : 2) ? separation::Side::first : separation::Side::second;
        const separation::SideRows<8> rows(side);
        const int before = std::fegetround();
        std::fesetround(mode);
        const bool at_d = separation::gap_certified_at_each_end(separation::ProjectionFrame<8>(x, d), rows, n);
        const bool at_quarter = separation::gap_certified_at_each_end(separation::ProjectionFrame<8>(x, d / 4), rows, n);
        std::fesetround(before);
        EXPECT_FALSE(at_d) << (vertex_face ? "vf" : "ee") << " k=" << k << " trial " << trial << " mode " << mode;
        ++cases;
        useful += at_quarter;
      }
    }
  }
  EXPECT_EQ(useful, cases) << "at a quarter of the distance every configuration is certified apart";
}

// A set with no rows would keep infinite bounds and an infinite gap: never certified (fails
// without the guard in gap_certified_at_each_end).
TEST(SeparatingPlaneBound, AnEmptySetIsNeverCertified) {
  Rows x;
  for (int i = 0; i < 8; ++i) x[i] = {static_cast<double>(i), 2.0 * i, -1.0 * i};
  const separation::ProjectionFrame<8> frame(x, 0.0);
  for (const separation::Side only : {separation::Side::first, separation::Side::second, separation::Side::none}) {
    std::array<separation::Side, 4> side;
    side.fill(only);
    const separation::SideRows<8> rows(side);
    for (const Vec3& n : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0.5, 1, -1}})
      EXPECT_FALSE(separation::gap_certified_at_each_end(frame, rows, n)) << static_cast<int>(only);
  }
}

// ---------------------------------------------------------------------------------------------
// Soundness against the exact method.

/// Random queries near contact, of the kind `vertex_face`: a point or an edge crossing the
/// other primitive through its interior (separated at both ends, on opposite sides), touching
/// it at t0 or t1, sliding in a plane across or past it, and small-integer grid motions.
Rows near_contact(bool vertex_face, int family, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0), small(-1e-3, 1e-3);
  std::uniform_int_distribution<int> grid(-2, 2);
  Rows r;
  const auto jitter = [&](Vec3 v, double e) { return Vec3{v.x + e * small(rng), v.y + e * small(rng), v.z + e * small(rng)}; };
  if (family == 3) {  // small-integer grid: exact degeneracies everywhere
    for (Vec3& p : r) p = {grid(rng) * 0.25, grid(rng) * 0.25, grid(rng) * (rng() % 2 ? 0.25 : 0.0)};
    return r;
  }
  // The other primitive in the plane z = 0 (slightly tilted), from t0 to t1 moving a little.
  const Vec3 a{unit(rng), unit(rng), 0}, b{unit(rng), unit(rng), 0}, c{unit(rng), unit(rng), 0};
  const Vec3 inside{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, 0};
  const double lift = family == 0 ? 0.5 : 0.0;  // crossing: from above to below
  Vec3 q0, q1;
  if (family == 2) {  // sliding in the plane from outside the triangle to inside (or past it)
    q0 = {inside.x + 2 * unit(rng), inside.y + 2 * unit(rng), 0};
    q1 = {inside.x + small(rng), inside.y + small(rng), 0};
  } else {
    q0 = {inside.x + 0.1 * unit(rng), inside.y + 0.1 * unit(rng), lift};
    q1 = {inside.x + 0.1 * unit(rng), inside.y + 0.1 * unit(rng), -lift};
    if (family == 1) q0 = a.x < 0 ? Vec3{(a.x + b.x) / 2, (a.y + b.y) / 2, 0} : q0;  // on an edge at t0
  }
  if (vertex_face) {
    r = {q0, a, b, c, q1, jitter(a, 1), jitter(b, 1), jitter(c, 1)};
  } else {  // edge-edge: an edge crossing or sliding onto the edge (a, b)
    const Vec3 d{q0.x - 0.3, q0.y + 0.2, q0.z}, e{q1.x - 0.3, q1.y + 0.2, q1.z};
    const Vec3 mid{(a.x + b.x) / 2, (a.y + b.y) / 2, 0};
    const Vec3 across{mid.x + (b.y - a.y), mid.y - (a.x - b.x), 0};  // through the edge's midpoint
    r = {a, b, family == 2 ? q0 : Vec3{2 * mid.x - across.x, 2 * mid.y - across.y, lift}, family == 2 ? d : across,
         jitter(a, 1), jitter(b, 1), family == 2 ? q1 : Vec3{2 * mid.x - across.x, 2 * mid.y - across.y, -lift},
         family == 2 ? e : Vec3{across.x, across.y, -lift}};
  }
  return r;
}

TEST(SeparatingPlaneStage, NeverSeparatesACollidingQuery) {
  std::mt19937_64 rng(2718);
  int separated = 0, colliding = 0;
  for (int n = 0; n < 6000; ++n) {
    const bool vertex_face = n % 2 == 0;
    const Rows r = near_contact(vertex_face, (n / 2) % 4, rng);
    bool apart = false, collides = false;
    if (vertex_face) {
      const auto q = from_rows<VertexFaceQuery>(r);
      apart = separation::separated_by_plane(q);
      collides = vertex_face_ccd(q, Method::exact);
    } else {
      const auto q = from_rows<EdgeEdgeQuery>(r);
      apart = separation::separated_by_plane(q);
      collides = edge_edge_ccd(q, Method::exact);
    }
    separated += apart;
    colliding += collides;
    EXPECT_FALSE(apart && collides) << (vertex_face ? "vertex-face" : "edge-edge") << " query " << n << " (family "
                                    << (n / 2) % 4 << ") collides but was separated";
  }
  // Both outcomes are common: the test exercises the stage.
  EXPECT_GT(separated, 600);
  EXPECT_GT(colliding, 600);
}

// ---------------------------------------------------------------------------------------------
// Use.

/// Neighbouring elements of a jittered flat grid (spacing 1, not sharing a vertex), the whole
/// patch dropping by 0.3 with a slight tilt and jitter: nearly coplanar throughout, V changing
/// sign, apart in the plane by about one spacing.
Rows cloth_neighbours(bool vertex_face, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> jitter(-0.02, 0.02), tilt(-0.01, 0.01);
  const double tx = tilt(rng), ty = tilt(rng);
  const auto node = [&](double x, double y) { return Vec3{x + jitter(rng), y + jitter(rng), 1e-3 * jitter(rng)}; };
  const auto moved = [&](const Vec3& p) {
    return Vec3{p.x + 0.01 * jitter(rng), p.y + 0.01 * jitter(rng), p.z - 0.3 + tx * p.x + ty * p.y + 1e-3 * jitter(rng)};
  };
  Rows r;
  if (vertex_face) {  // the vertex (2, 0) against the triangle (0, 0), (1, 0), (0, 1)
    const Vec3 p = node(2, 0), a = node(0, 0), b = node(1, 0), c = node(0, 1);
    r = {p, a, b, c, moved(p), moved(a), moved(b), moved(c)};
  } else {  // the edge (0, 0)-(1, 0) against the edge (0, 1)-(1, 2)... its neighbour two rows up
    const Vec3 a0 = node(0, 0), a1 = node(1, 0), b0 = node(0, 1.5), b1 = node(1, 2);
    r = {a0, a1, b0, b1, moved(a0), moved(a1), moved(b0), moved(b1)};
  }
  return r;
}

TEST(SeparatingPlaneStage, DecidesNearlyCoplanarClothNeighbours) {
  std::mt19937_64 rng(99);
  int passed_stage_1 = 0, decided_here = 0;
  for (int n = 0; n < 4000; ++n) {
    const bool vertex_face = n % 2 == 0;
    const Rows r = cloth_neighbours(vertex_face, rng);
    StageCounters counters;
    std::optional<TimeInterval> answer;
    bool excluded = false;
    if (vertex_face) {
      const auto q = from_rows<VertexFaceQuery>(r);
      excluded = filter::volume_excluded(q);
      answer = questions::contact_question(q, pipeline::Question{}, &counters);
    } else {
      const auto q = from_rows<EdgeEdgeQuery>(r);
      excluded = filter::volume_excluded(q);
      answer = questions::contact_question(q, pipeline::Question{}, &counters);
    }
    ASSERT_FALSE(answer) << "query " << n << ": the neighbours never touch";
    if (excluded) continue;
    ++passed_stage_1;
    decided_here += counters.separating_direction == 1;
  }
  EXPECT_GT(passed_stage_1, 800);  // the volume changes sign for a quarter of them
  EXPECT_EQ(decided_here, passed_stage_1) << "of the queries stage 1 passes on";
}

}  // namespace
}  // namespace exactccd
