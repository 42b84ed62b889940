// Rigid queries with times of impact known in closed form (derived by hand in the comments),
// by both methods; bad input; the two exact derivations (contact rule, feature-pair terms)
// against each other; the degrees of docs/design.md 9.2.
//
// Rotations about the z axis: q(t) = (1, 0, 0, t) turns by theta(t) = 2 atan(t), so a body point
// (r, 0, 0) is at r (1 - t^2, 2t, 0) / (1 + t^2), and a direction (cos phi, sin phi) is reached at
// t = tan(phi / 2) = sin(phi) / (1 + cos(phi)): t = 1/2 for (3, 4)/5, t = 1/3 for (4, 3)/5,
// t = sqrt(2) - 1 for (1, 1)/sqrt(2).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "exactccd/exactccd.h"
#include "exactccd/rigid.hpp"
#include "exact/rational_query.hpp"
#include "rigid/exact_rigid.hpp"
#include "rigid_support.hpp"

namespace exactccd {
namespace {

using namespace rigid_test;

class RigidClosedForm : public ::testing::TestWithParam<Method> {};

/// The vertex (5, 0, 0) of A turns about z by a quarter turn; B's triangle is static in the
/// half-plane through the z axis towards `direction` (a = (0,0,-1), b = 2 direction, c = (0,0,1)):
/// the vertex, at distance 5 from the axis, meets its interior when it reaches that direction.
RigidVertexFaceQuery turning_vertex(const Vec3& direction) {
  return vertex_face({RigidPose{{0, 0, 0}, kIdentity}, RigidPose{{0, 0, 0}, z_turn(1)}}, still(), {5, 0, 0},
                     {0, 0, -1}, {2 * direction.x, 2 * direction.y, 0}, {0, 0, 1});
}

TEST_P(RigidClosedForm, VertexTurningIntoATriangle) {
  // Direction (3, 4): in the plane 4x - 3y = 0 when 4 (1 - t^2) - 6t = 0, i.e. 2t^2 + 3t - 2 = 0,
  // t = 1/2, at (3, 4, 0), the middle of the triangle's section z = 0 from 0 to (6, 8, 0).
  const auto half = rigid_vertex_face_toi(turning_vertex({3, 4, 0}), {}, GetParam());
  ASSERT_TRUE(half);
  EXPECT_EQ(half->lo, 0.5);
  EXPECT_EQ(half->hi, 0.5);
  // Direction (4, 3): 3 (1 - t^2) - 8t = 0, t = 1/3, at (4, 3, 0).
  const auto third = rigid_vertex_face_toi(turning_vertex({4, 3, 0}), {}, GetParam());
  ASSERT_TRUE(third);
  EXPECT_TRUE(tightly_encloses(*third, mpq_class(1, 3))) << third->lo << " " << third->hi;
  // Direction (1, 1): 1 - t^2 = 2t, t = sqrt(2) - 1, the root of t^2 + 2t - 1.
  const auto root2 = rigid_vertex_face_toi(turning_vertex({2, 2, 0}), {}, GetParam());
  ASSERT_TRUE(root2);
  EXPECT_TRUE(tightly_encloses_root(*root2, {-1, 2, 1})) << root2->lo << " " << root2->hi;
  // Before the time limit only.
  EXPECT_FALSE(rigid_vertex_face_ccd(turning_vertex({3, 4, 0}), {0, 0.25}, GetParam()));
  EXPECT_TRUE(rigid_vertex_face_ccd(turning_vertex({3, 4, 0}), {0, 0.5}, GetParam()));
  // Direction (-3, 4) (t = 2 > 1): never reached in the step.
  EXPECT_FALSE(rigid_vertex_face_ccd(turning_vertex({-3, 4, 0}), {}, GetParam()));
}

TEST_P(RigidClosedForm, TriangleTurningOntoAStaticVertex) {
  // B's triangle (0,0,-1), (10,0,0), (0,0,1) in the x-z plane turns about the z axis (through
  // its vertices a and c); A's vertex is static at (3, 4, 0), at distance 5 < 10 from the axis:
  // reached when the triangle's direction is (3, 4)/5, at t = 1/2.
  const auto q = vertex_face(still(), {RigidPose{{0, 0, 0}, kIdentity}, RigidPose{{0, 0, 0}, z_turn(1)}}, {3, 4, 0},
                             {0, 0, -1}, {10, 0, 0}, {0, 0, 1});
  const auto t = rigid_vertex_face_toi(q, {}, GetParam());
  ASSERT_TRUE(t);
  EXPECT_EQ(t->lo, 0.5);
  EXPECT_EQ(t->hi, 0.5);
}

TEST_P(RigidClosedForm, BothBodiesTurning) {
  // A turns by +2 atan(t), B by -2 atan(t) (q = (1, 0, 0, -t)): the relative angle is 4 atan(t).
  // A's vertex starts at angle -4 atan(1/2), direction (cos, sin) = (-7, -24)/25 (double-angle
  // formulas from tan(2 atan(1/2)) = 4/3); B's triangle points along (1, 0). They meet when
  // 4 atan(t) = 4 atan(1/2): t = 1/2, A's vertex at (15, -20, 0) (rotated by cos 3/5, sin 4/5),
  // B's triangle direction (3, -4)/5, 25 < 30 from the axis. No earlier contact: the relative
  // angle runs from -106.3 to 73.7 degrees and crosses 0 (mod 180) once.
  const auto q = vertex_face({RigidPose{{0, 0, 0}, kIdentity}, RigidPose{{0, 0, 0}, z_turn(1)}},
                             {RigidPose{{0, 0, 0}, kIdentity}, RigidPose{{0, 0, 0}, z_turn(-1)}}, {-7, -24, 0},
                             {0, 0, -1}, {30, 0, 0}, {0, 0, 1});
  const auto t = rigid_vertex_face_toi(q, {}, GetParam());
  ASSERT_TRUE(t);
  EXPECT_EQ(t->lo, 0.5);
  EXPECT_EQ(t->hi, 0.5);
  // The same motion seen from a frame translated by (2^20, -3, 7) and turned by a quarter turn
  // about x (q = (1, 1, 0, 0) on both bodies, composed on the left of each quaternion): the
  // same time. (1,1,0,0) (1,0,0,t) = (1, 1, -t, t).
  const Vec3 shift{0x1p20, -3, 7};
  const auto moved = vertex_face({RigidPose{shift, {1, 1, 0, 0}}, RigidPose{shift, {1, 1, -1, 1}}},
                                 {RigidPose{shift, {1, 1, 0, 0}}, RigidPose{shift, {1, 1, 1, -1}}}, {-7, -24, 0},
                                 {0, 0, -1}, {30, 0, 0}, {0, 0, 1});
  const auto tm = rigid_vertex_face_toi(moved, {}, GetParam());
  ASSERT_TRUE(tm);
  EXPECT_EQ(tm->lo, 0.5);
  EXPECT_EQ(tm->hi, 0.5);
}

TEST_P(RigidClosedForm, EdgeSweepingThroughAnEdge) {
  // A's edge (0,0,0)-(10,0,0) turns about the z axis through its end a0; B's vertical edge at
  // (3, 4) (or (1, 1)) is met when A's edge points there: t = 1/2 (or sqrt(2) - 1).
  const std::array<RigidPose, 2> turning{RigidPose{{0, 0, 0}, kIdentity}, RigidPose{{0, 0, 0}, z_turn(1)}};
  const auto half = rigid_edge_edge_toi(edge_edge(turning, still(), {0, 0, 0}, {10, 0, 0}, {3, 4, -1}, {3, 4, 1}), {},
                                        GetParam());
  ASSERT_TRUE(half);
  EXPECT_EQ(half->lo, 0.5);
  EXPECT_EQ(half->hi, 0.5);
  const auto root2 = rigid_edge_edge_toi(edge_edge(turning, still(), {0, 0, 0}, {10, 0, 0}, {1, 1, -1}, {1, 1, 1}), {},
                                         GetParam());
  ASSERT_TRUE(root2);
  EXPECT_TRUE(tightly_encloses_root(*root2, {-1, 2, 1}));
  // Out of reach: the edge is 10 long, (8, 8) is 11.3 from the axis.
  EXPECT_FALSE(rigid_edge_edge_ccd(edge_edge(turning, still(), {0, 0, 0}, {10, 0, 0}, {8, 8, -1}, {8, 8, 1}), {},
                                   GetParam()));
}

TEST_P(RigidClosedForm, CoplanarEdgesForTheWholeStep) {
  // Everything in the plane z = 0 (the volume vanishes for every t: the in-plane candidates).
  // A's edge (0,0,0)-(10,0,0) turns about z; B's edge (3,4,0)-(3,10,0): the ray at angle theta
  // meets the line x = 3 at y = 3 tan(theta), first at the end (3, 4) when tan(theta) = 4/3,
  // t = 1/2 (5 < 10 from the axis).
  const std::array<RigidPose, 2> turning{RigidPose{{0, 0, 0}, kIdentity}, RigidPose{{0, 0, 0}, z_turn(1)}};
  const auto q = edge_edge(turning, still(), {0, 0, 0}, {10, 0, 0}, {3, 4, 0}, {3, 10, 0});
  const auto t = rigid_edge_edge_toi(q, {}, GetParam());
  ASSERT_TRUE(t);
  EXPECT_EQ(t->lo, 0.5);
  EXPECT_EQ(t->hi, 0.5);
  // B's edge starting beyond reach along the line, (3, 9.6)-(3, 12): |(3, 9.6)| > 10.
  EXPECT_FALSE(rigid_edge_edge_ccd(edge_edge(turning, still(), {0, 0, 0}, {10, 0, 0}, {3, 9.6, 0}, {3, 12, 0}), {},
                                   GetParam()));
}

TEST_P(RigidClosedForm, MinimumSeparationToATurningVertex) {
  // A's vertex (1, 0, 0) turns about z: (cos, sin, 0) with sin = 2t / (1 + t^2). B's triangle in
  // the plane y = 1 ((-5,1,-5), (5,1,-5), (0,1,5)) holds the vertex's projection (cos, 1, 0) in its
  // interior; the distance is 1 - sin. With d = 1/4: sin = 3/4 at 3t^2 - 8t + 3 = 0, the earliest
  // root t = (4 - sqrt(7)) / 3 = 0.4514; with d = 0 the vertex touches the plane at t = 1 exactly.
  const auto q = vertex_face({RigidPose{{0, 0, 0}, kIdentity}, RigidPose{{0, 0, 0}, z_turn(1)}}, still(), {1, 0, 0},
                             {-5, 1, -5}, {5, 1, -5}, {0, 1, 5});
  const auto near = rigid_vertex_face_toi(q, {0.25, 1.0}, GetParam());
  ASSERT_TRUE(near);
  EXPECT_TRUE(tightly_encloses_root(*near, {3, -8, 3})) << near->lo << " " << near->hi;
  const auto touch = rigid_vertex_face_toi(q, {}, GetParam());
  ASSERT_TRUE(touch);
  EXPECT_EQ(touch->lo, 1.0);
  EXPECT_EQ(touch->hi, 1.0);
  EXPECT_FALSE(rigid_vertex_face_ccd(q, {0.25, 0.45}, GetParam()));
  EXPECT_TRUE(rigid_vertex_face_ccd(q, {0.25, 0.46}, GetParam()));
}

TEST_P(RigidClosedForm, MinimumSeparationBetweenEdges) {
  // A's edge (0,0,0)-(10,0,0) turns about z; B's edge (3,4,1)-(3,4,2) is vertical above (3, 4).
  // The closest points are B's lower end and its foot on A's edge (5 cos(phi - theta) in [0, 10]),
  // at distance sqrt(h^2 + 1), h = 5 sin(phi - theta) = (4 - 6t - 4t^2) / (1 + t^2) (phi the angle
  // of (3, 4)). With d = 5/4, h = 3/4: 19 t^2 + 24 t - 13 = 0, t = 0.4091.
  const std::array<RigidPose, 2> turning{RigidPose{{0, 0, 0}, kIdentity}, RigidPose{{0, 0, 0}, z_turn(1)}};
  const auto q = edge_edge(turning, still(), {0, 0, 0}, {10, 0, 0}, {3, 4, 1}, {3, 4, 2});
  const auto t = rigid_edge_edge_toi(q, {1.25, 1.0}, GetParam());
  ASSERT_TRUE(t);
  EXPECT_TRUE(tightly_encloses_root(*t, {-13, 24, 19})) << t->lo << " " << t->hi;
  EXPECT_FALSE(rigid_edge_edge_ccd(q, {0.999, 1.0}, GetParam()));  // never nearer than 1
}

TEST_P(RigidClosedForm, ContactAtTheStart) {
  // The vertex (5, 0, 0) starts in the triangle (0,0,-1), (6,0,0), (0,0,1): TOI [0, 0].
  const auto t = rigid_vertex_face_toi(turning_vertex({3, 0, 0}), {}, GetParam());
  ASSERT_TRUE(t);
  EXPECT_EQ(t->lo, 0.0);
  EXPECT_EQ(t->hi, 0.0);
}

TEST_P(RigidClosedForm, BadInputIsRefused) {
  auto q = turning_vertex({3, 4, 0});
  const Method m = GetParam();
  const auto refused = [&](const RigidVertexFaceQuery& x, const CcdParams& p = {}) {
    EXPECT_THROW(rigid_vertex_face_toi(x, p, m), std::invalid_argument);
    EXPECT_THROW(rigid_vertex_face_ccd(x, p, m), std::invalid_argument);
  };
  auto x = q;
  x.a_t1.q = {-2, 0, 0, 0};  // q1 = -2 q0: q(2/3) = 0
  refused(x);
  x = q;
  x.a_t0.q = {1, 2, -3, 4}, x.a_t1.q = {-0.5, -1, 1.5, -2};  // q1 = -q0 / 2
  refused(x);
  x = q;
  x.b_t1.q = {0, 0, 0, 0};
  refused(x);
  x = q;
  x.b_t0.q = {-0.0, 0, 0, 0};
  refused(x);
  x = q;
  x.a_t0.c.y = std::nan("");
  refused(x);
  x = q;
  x.p.z = std::numeric_limits<double>::infinity();
  refused(x);
  x = q;
  x.b_t1.q.w = std::numeric_limits<double>::infinity();
  refused(x);
  refused(q, {-1.0, 1.0});
  refused(q, {0.0, 0.0});
  refused(q, {0.0, 1.5});
  // A negative dot product alone is fine (the long arc): q1 = (-1, 0, 0, 1e-300) is not parallel
  // to q0 = (1, 0, 0, 0); nor is q1 = -q0 + a tiny change.
  x = q;
  x.a_t1.q = {-1, 0, 0, 1e-300};
  EXPECT_NO_THROW(rigid_vertex_face_toi(x, {}, m));
  x.a_t0.q = {1, 2, -3, 4}, x.a_t1.q = {-0.5, -1, 1.5, -2.0000000000000004};
  EXPECT_NO_THROW(rigid_vertex_face_ccd(x, {}, m));
}

TEST(RigidEntryPoint, RefusesAsTheLinearEntryPoint) {
  // One entry point for both motion models (api/entry_point.cpp): the rigid function's name,
  // the motion model's own reason for a bad query, the parameters' numbers as they read back.
  const auto message = [](auto&& call) {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  const auto q = turning_vertex({3, 4, 0});
  EXPECT_EQ(message([&] { (void)rigid_vertex_face_toi(q, {0, 1.0000000000000002}); }),
            "exactccd::rigid_vertex_face_toi: tmax must be in (0, 1], not 1.0000000000000002");
  EXPECT_EQ(message([&] { (void)rigid_vertex_face_ccd(q, {-1e-300, 1}); }),
            "exactccd::rigid_vertex_face_ccd: min_distance must be finite and >= 0, not -1e-300");
  EXPECT_EQ(message([&] { (void)rigid_vertex_face_ccd(q, {}, static_cast<Method>(7)); }),
            "exactccd::rigid_vertex_face_ccd: unknown method 7");
  auto bad = q;
  bad.b_t1.q = {0, 0, 0, 0};
  EXPECT_EQ(message([&] { (void)rigid_vertex_face_toi(bad, {}); }),
            "exactccd::rigid_vertex_face_toi: body B: zero quaternion at t = 1");
}

INSTANTIATE_TEST_SUITE_P(Methods, RigidClosedForm, ::testing::Values(Method::filtered, Method::exact),
                         [](const auto& info) { return info.param == Method::filtered ? "filtered" : "exact"; });

/// A random query with small integer (or half-integer) components; `planar` puts every point
/// and translation in z = 0 with rotations about z only (coplanar for all t).
template <class Query>
Query random_query(std::mt19937_64& rng, bool planar) {
  std::uniform_int_distribution<int> small(-4, 4);
  const auto v = [&] { return Vec3{small(rng) / 2.0, small(rng) / 2.0, planar ? 0.0 : small(rng) / 2.0}; };
  const auto quat = [&] {
    for (;;) {
      const Quaternion r{double(small(rng)), planar ? 0.0 : small(rng), planar ? 0.0 : small(rng), double(small(rng))};
      if (r.w != 0 || r.x != 0 || r.y != 0 || r.z != 0) return r;
    }
  };
  Query q;
  for (RigidPose* p : {&q.a_t0, &q.a_t1, &q.b_t0, &q.b_t1}) *p = {v(), quat()};
  for (int body = 0; body < 2; ++body) {  // not through zero: flip q1 when antiparallel
    RigidPose& t1 = body == 0 ? q.a_t1 : q.b_t1;
    const RigidPose& t0 = body == 0 ? q.a_t0 : q.b_t0;
    if (t0.q.w * t1.q.w + t0.q.x * t1.q.x + t0.q.y * t1.q.y + t0.q.z * t1.q.z < 0)
      t1.q = {-t1.q.w, -t1.q.x, -t1.q.y, -t1.q.z};
  }
  if constexpr (std::is_same_v<Query, RigidVertexFaceQuery>)
    q.p = v(), q.a = v(), q.b = v(), q.c = v();
  else
    q.a0 = v(), q.a1 = v(), q.b0 = v(), q.b1 = v();
  return q;
}

template <class Query>
void contact_rule_equals_terms(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  int collisions = 0;
  for (int i = 0; i < count; ++i) {
    const Query q = random_query<Query>(rng, i % 3 == 2);
    const auto r = exact::to_rational(q);
    for (const double tmax : {1.0, 0.5}) {
      const RationalCcdParams p{0, tmax};
      const auto rule = rigid::exact_toi(r, p);
      const auto terms = rigid::exact_separation_toi(r, p);
      ASSERT_EQ(rule.has_value(), terms.has_value()) << "query " << i << " tmax " << tmax;
      if (rule) {
        EXPECT_EQ(rule->lo, terms->lo) << "query " << i;
        EXPECT_EQ(rule->hi, terms->hi) << "query " << i;
        ++collisions;
      }
    }
  }
  EXPECT_GT(collisions, count / 20);  // the sample must hold collisions to compare
}

TEST(RigidExact, ContactRuleEqualsFeatureTermsAtZeroDistanceVertexFace) {
  contact_rule_equals_terms<RigidVertexFaceQuery>(1, 120);
}
TEST(RigidExact, ContactRuleEqualsFeatureTermsAtZeroDistanceEdgeEdge) {
  contact_rule_equals_terms<RigidEdgeEdgeQuery>(2, 120);
}

TEST(RigidExact, DegreesOfTheReducedPolynomials) {
  // docs/design.md 9.2: for generic motions the volume has degree 5 (vertex-face and edge-edge),
  // the in-plane polynomials at most 6 (vertex-face) and 9 (edge-edge), the terms at most 10.
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> digit(-9, 9);
  const auto v = [&] { return Vec3{double(digit(rng)), double(digit(rng)), double(digit(rng))}; };
  const auto quat = [&] { return Quaternion{10.0 + digit(rng), double(digit(rng)), double(digit(rng)), double(digit(rng))}; };
  for (int i = 0; i < 5; ++i) {
    const RigidVertexFaceQuery vf{{v(), quat()}, {v(), quat()}, {v(), quat()}, {v(), quat()}, v(), v(), v(), v()};
    const auto a = rigid::reduced_degrees(exact::to_rational(vf), mpq_class(1, 7));
    EXPECT_EQ(a.volume, 5);
    EXPECT_EQ(a.in_plane, 6);
    EXPECT_EQ(a.term, 10);
    const RigidEdgeEdgeQuery ee{{v(), quat()}, {v(), quat()}, {v(), quat()}, {v(), quat()}, v(), v(), v(), v()};
    const auto b = rigid::reduced_degrees(exact::to_rational(ee), mpq_class(1, 7));
    EXPECT_EQ(b.volume, 5);
    EXPECT_EQ(b.in_plane, 9);
    EXPECT_EQ(b.term, 10);
  }
}

}  // namespace
}  // namespace exactccd

namespace exactccd {
namespace {

TEST(RigidCApi, StatusesAndAnswers) {
  // The vertex turning into the triangle towards (3, 4): TOI 1/2 (VertexTurningIntoATriangle).
  double q[EXACTCCD_RIGID_QUERY_SIZE] = {0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0,
                                          0, 0, 0, 0, 1, 0, 0, 0, 5, 0, 0, 0, 0, -1, 6, 8, 0, 0, 0, 1};
  int collides = -1;
  double lo = -1, hi = -1;
  EXPECT_EQ(exactccd_rigid_toi(EXACTCCD_VERTEX_FACE, q, 0, 1, &collides, &lo, &hi), EXACTCCD_OK);
  EXPECT_EQ(collides, 1);
  EXPECT_EQ(lo, 0.5);
  EXPECT_EQ(hi, 0.5);
  EXPECT_EQ(exactccd_rigid_ccd(EXACTCCD_VERTEX_FACE, q, 0, 0.25, &collides), EXACTCCD_OK);
  EXPECT_EQ(collides, 0);
  EXPECT_EQ(exactccd_rigid_toi(EXACTCCD_VERTEX_FACE, q, 0, 1, &collides, nullptr, nullptr), EXACTCCD_OK);
  EXPECT_EQ(exactccd_rigid_ccd(EXACTCCD_VERTEX_FACE, nullptr, 0, 1, &collides), EXACTCCD_ERROR_NULL);
  EXPECT_EQ(exactccd_rigid_ccd(EXACTCCD_VERTEX_FACE, q, 0, 1, nullptr), EXACTCCD_ERROR_NULL);
  EXPECT_EQ(exactccd_rigid_ccd(EXACTCCD_POINT_EDGE, q, 0, 1, &collides), EXACTCCD_ERROR_PARAMETER);
  EXPECT_EQ(exactccd_rigid_ccd(EXACTCCD_VERTEX_FACE, q, -1, 1, &collides), EXACTCCD_ERROR_PARAMETER);
  EXPECT_EQ(exactccd_rigid_ccd(EXACTCCD_VERTEX_FACE, q, 0, 0, &collides), EXACTCCD_ERROR_PARAMETER);
  q[12] = std::nan("");
  EXPECT_EQ(exactccd_rigid_ccd(EXACTCCD_EDGE_EDGE, q, 0, 1, &collides), EXACTCCD_ERROR_NON_FINITE);
  q[12] = 0;
  q[10] = -2, q[13] = 0;  // qA1 = (-2, 0, 0, 0) = -2 qA0
  EXPECT_EQ(exactccd_rigid_ccd(EXACTCCD_VERTEX_FACE, q, 0, 1, &collides), EXACTCCD_ERROR_ROTATION);
  EXPECT_STREQ(exactccd_status_string(EXACTCCD_ERROR_ROTATION), "a rigid body's quaternion path passes through zero");
}

}  // namespace
}  // namespace exactccd
