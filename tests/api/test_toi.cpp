// Time of impact: known exact roots are enclosed by the tightest double interval, for every
// exact method (the filtered front end, the CGAL path) and the rational API.
//
// The tightness contract: lo == hi == t when the exact TOI t is a double, otherwise
// hi == nextafter(lo, +inf) and lo < t < hi. Rational TOIs are compared exactly with
// mpq_class; irrational ones (roots of irreducible cubics) by the sign of the cubic at lo and
// hi, evaluated exactly in mpq_class.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"
#include "methods/methods.hpp"

namespace exactccd {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// p = (1/4, 1/4, z0 + t (z1 - z0)) against the static unit triangle (0,0,0), (1,0,0), (0,1,0).
/// V(t) is a positive multiple of p_z(t): the TOI is z0 / (z0 - z1) when that is in [0, 1].
VertexFaceQuery falling_vertex(double z0, double z1) {
  return {{0.25, 0.25, z0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
          {0.25, 0.25, z1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
}

/// Edge b = [(1/2, -1, z), (1/2, 1, z)], z = z0 + t (z1 - z0), against the static x-axis edge
/// [-1, 1]: V is a multiple of z, and at z = 0 they cross at (1/2, 0, 0). TOI z0 / (z0 - z1).
EdgeEdgeQuery crossing_edges(double z0, double z1) {
  return {{-1, 0, 0}, {1, 0, 0}, {0.5, -1, z0}, {0.5, 1, z0},
          {-1, 0, 0}, {1, 0, 0}, {0.5, -1, z1}, {0.5, 1, z1}};
}

/// Edge b static at height h over the x-axis edge a, which rises from z = 0 to z = 1:
/// a and b cross at (1/2, 0, h) when a's height t equals h: TOI h (for 0 <= h <= 1).
EdgeEdgeQuery rising_edge(double h) {
  return {{-1, 0, 0}, {1, 0, 0}, {0.5, -1, h}, {0.5, 1, h},
          {-1, 0, 1}, {1, 0, 1}, {0.5, -1, h}, {0.5, 1, h}};
}

// ---- Irreducible cubics ------------------------------------------------------------------
// The companion matrix of t^3 - 3t + 1 gives rows linear in t whose determinant is the cubic:
//   det [ (t, 0, 1); (-1, t, -3); (0, -1, t) ] = t (t^2 - 3) + 1 = t^3 - 3t + 1,
// and whose left null vector is (1, t, t^2): 1 r1 + t r2 + t^2 r3 = 0 exactly at a root
// (column 1: t - t = 0; column 2: t^2 - t^2 = 0; column 3: 1 - 3t + t^3 = 0).
// t^3 - 3t + 1 has no rational root (+-1 give -1 and 3), so it is irreducible over Q; its
// roots are 2 cos(2 pi/9) = 1.532..., 2 cos(4 pi/9) = 0.3472963553338606977...,
// 2 cos(8 pi/9) = -1.879...: exactly one in [0, 1], with V(0) = 1 > 0 > V(1) = -1.
// The doubles around it: 0.34729635533386066 < r < 0.3472963553338607, consecutive doubles
// (checked below: the cubic, evaluated exactly, is positive at lo and negative at hi).
constexpr double kCompanionLo = 0.34729635533386066;
constexpr double kCompanionHi = 0.3472963553338607;
const std::vector<mpq_class> kCompanionCubic = {1, -3, 0, 1};  // c0 + c1 t + c2 t^2 + c3 t^3

/// VF: p = 0 static, a = r1, b = r2, c = r3. V = det[a - p; b - p; c - p] = t^3 - 3t + 1, and
/// at the root p = 0 = (1 a + t b + t^2 c) / (1 + t + t^2): barycentrics all > 0, so p is in
/// the triangle's interior. TOI = 2 cos(4 pi/9), irrational.
VertexFaceQuery companion_vertex_face() {
  return {{0, 0, 0}, {0, 0, 1}, {-1, 0, -3}, {0, -1, 0},
          {0, 0, 0}, {1, 0, 1}, {-1, 1, -3}, {0, -1, 1}};
}

/// EE: a0 = 0 static, a1 = -3 r1 = (-3t, 0, -3), b0 = r2, b1 = r3. V = det[a1; b0; b1] =
/// -3 (t^3 - 3t + 1). At the root a1 = 3 (t b0 + t^2 b1), so alpha a1 = b0 + beta (b1 - b0) with
/// alpha = 1 / (3 (t + t^2)) = 0.712... and beta = t / (1 + t) = 0.257...: both in [0, 1], the
/// segments meet. TOI = 2 cos(4 pi/9).
EdgeEdgeQuery companion_edge_edge() {
  return {{0, 0, 0}, {0, 0, -3}, {-1, 0, -3}, {0, -1, 0},
          {0, 0, 0}, {-3, 0, -3}, {-1, 1, -3}, {0, -1, 1}};
}

/// The catalogue's vf_irrational_toi: V = -4t^3 + 16t^2 + 32t - 12 (irreducible; root
/// 0.32614985735855...), p in the interior there.
VertexFaceQuery catalogue_cubic_vertex_face() {
  return {{-2, -1, 2}, {0, 0, 0}, {2, 1, 1},   {-2, -3, 0},
          {3, -1, -1}, {0, 0, 0}, {-1, -1, 3}, {-3, -3, 1}};
}
const std::vector<mpq_class> kCatalogueCubic = {-12, 32, 16, -4};

// ---- Two coplanarity times: the earliest contact is not always the first root -------------
// VF: a = (0,0,0), b = (1,0,0) static, c(t) = (0, 1, 1 - 2t), p(t) = (px(t), 1/4 + t/2, 7/16 - t).
// n = (b - a) x (c - a) = (0, -(1 - 2t), 1), V = n . p = -(1 - 2t)(1/4 + t/2) + 7/16 - t
//   = t^2 - t + 3/16 = (t - 1/4)(t - 3/4).
// The triangle projects onto the unit triangle of the xy plane and its plane is not vertical,
// so a coplanar p is in it iff px >= 0, py >= 0, px + py <= 1.
// t = 1/4: py = 3/8; t = 3/4: py = 5/8.
//  - px = 1 - t: px + py = 9/8 > 1 at t = 1/4 (outside), 7/8 at t = 3/4 (inside): TOI 3/4.
//  - px = t: px + py = 5/8 at t = 1/4 (inside): TOI 1/4.
VertexFaceQuery two_root_vertex_face(double px0, double px1) {
  return {{px0, 0.25, 0.4375}, {0, 0, 0}, {1, 0, 0}, {0, 1, 1},
          {px1, 0.75, -0.5625}, {0, 0, 0}, {1, 0, 0}, {0, 1, -1}};
}

// EE: a = [(-1,0,0), (1,0,0)] static, b0 = (x(t), -1, t - 1/2), b1 = (x(t), t + 1/2, 7/16 - t).
// With r = b0 - a0, s = b1 - a0: V = 2 (r_y s_z - r_z s_y) = 2 (-(7/16 - t) - (t - 1/2)(t + 1/2))
//   = -2 (t^2 - t + 3/16) = -2 (t - 1/4)(t - 3/4).
// b lies in the plane X = x(t); at a root its point with y = 0 has z = 0 (t = 1/4: parameter
// 4/7, z = -1/4 + (4/7)(7/16) = 0; t = 3/4: parameter 4/9, z = 1/4 - (4/9)(9/16) = 0), i.e. b
// meets the x axis at (x(t), 0, 0): contact iff -1 <= x(t) <= 1.
//  - x = 2 - 2t: x(1/4) = 3/2 (miss), x(3/4) = 1/2 (hit): TOI 3/4.
//  - x = 2t: x(1/4) = 1/2 (hit): TOI 1/4.
EdgeEdgeQuery two_root_edge_edge(double x0, double x1) {
  return {{-1, 0, 0}, {1, 0, 0}, {x0, -1, -0.5}, {x0, 0.5, 0.4375},
          {-1, 0, 0}, {1, 0, 0}, {x1, -1, 0.5},  {x1, 1.5, -0.5625}};
}

// ---- Helpers ---------------------------------------------------------------------------

RationalVec3 exact(const Vec3& p) { return {mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)}; }

template <class Query>
auto to_rational(const Query& q) {
  using R = std::conditional_t<std::is_same_v<Query, VertexFaceQuery>, RationalVertexFaceQuery,
                               RationalEdgeEdgeQuery>;
  std::array<RationalVec3, 8> r;
  const auto d = rows(q);
  for (std::size_t i = 0; i < 8; ++i) r[i] = exact(d[i]);
  return from_rows<R>(r);
}

std::optional<TimeInterval> toi_of(const VertexFaceQuery& q, Method m) { return vertex_face_toi(q, m); }
std::optional<TimeInterval> toi_of(const EdgeEdgeQuery& q, Method m) { return edge_edge_toi(q, m); }
std::optional<TimeInterval> toi_of(const RationalVertexFaceQuery& q) { return vertex_face_toi(q); }
std::optional<TimeInterval> toi_of(const RationalEdgeEdgeQuery& q) { return edge_edge_toi(q); }
bool ccd_of(const VertexFaceQuery& q, Method m) { return vertex_face_ccd(q, m); }
bool ccd_of(const EdgeEdgeQuery& q, Method m) { return edge_edge_ccd(q, m); }
bool ccd_of(const RationalVertexFaceQuery& q) { return vertex_face_ccd(q); }
bool ccd_of(const RationalEdgeEdgeQuery& q) { return edge_edge_ccd(q); }

/// The TOI of q from every exact entry point: filtered, exact (CGAL) and the rational API,
/// each labelled. Also checks the boolean query agrees with the TOI's presence.
template <class Query>
std::vector<std::pair<std::string, std::optional<TimeInterval>>> all_tois(const Query& q) {
  std::vector<std::pair<std::string, std::optional<TimeInterval>>> out;
  for (Method m : {Method::filtered, Method::exact}) {
    const std::string label = m == Method::filtered ? "filtered" : "exact";
    out.emplace_back(label, toi_of(q, m));
    EXPECT_EQ(ccd_of(q, m), out.back().second.has_value()) << label << ": ccd and toi disagree";
  }
  const auto r = to_rational(q);
  out.emplace_back("rational", toi_of(r));
  EXPECT_EQ(ccd_of(r), out.back().second.has_value()) << "rational: ccd and toi disagree";
  return out;
}

/// lo <= hi, both in [0, 1], width at most 2 ulp, and the stronger contract: a point or two
/// consecutive doubles.
void expect_tight(const TimeInterval& toi) {
  EXPECT_LE(0.0, toi.lo);
  EXPECT_LE(toi.lo, toi.hi);
  EXPECT_LE(toi.hi, 1.0);
  EXPECT_LE(toi.hi, std::nextafter(std::nextafter(toi.lo, kInf), kInf)) << "wider than 2 ulp";
  EXPECT_TRUE(toi.lo == toi.hi || std::nextafter(toi.lo, kInf) == toi.hi)
      << "[" << toi.lo << ", " << toi.hi << "] is not the tightest enclosure";
}

/// Every exact entry point returns the tightest enclosure of the exact rational TOI t.
template <class Query>
void expect_toi(const Query& q, const mpq_class& t) {
  const double nearest = t.get_d();
  const bool t_is_double = mpq_class(nearest) == t;
  for (const auto& [label, toi] : all_tois(q)) {
    SCOPED_TRACE(label + " for t = " + t.get_str());
    ASSERT_TRUE(toi.has_value());
    expect_tight(*toi);
    EXPECT_LE(mpq_class(toi->lo), t);
    EXPECT_GE(mpq_class(toi->hi), t);
    if (t_is_double) {
      EXPECT_EQ(toi->lo, nearest);
      EXPECT_EQ(toi->hi, nearest);
    } else {
      EXPECT_LT(mpq_class(toi->lo), t);
      EXPECT_GT(mpq_class(toi->hi), t);
      EXPECT_EQ(std::nextafter(toi->lo, kInf), toi->hi);
    }
  }
}

/// c0 + c1 x + c2 x^2 + ... evaluated exactly at the double x.
mpq_class evaluate(const std::vector<mpq_class>& c, double x) {
  const mpq_class xq(x);
  mpq_class v = 0, power = 1;
  for (const mpq_class& k : c) {
    v += k * power;
    power *= xq;
  }
  return v;
}

/// Every exact entry point returns two consecutive doubles around a simple root of `cubic`
/// (an irrational TOI): the cubic is nonzero with opposite signs at lo and hi.
template <class Query>
void expect_irrational_toi(const Query& q, const std::vector<mpq_class>& cubic) {
  for (const auto& [label, toi] : all_tois(q)) {
    SCOPED_TRACE(label);
    ASSERT_TRUE(toi.has_value());
    expect_tight(*toi);
    EXPECT_EQ(std::nextafter(toi->lo, kInf), toi->hi) << "an irrational TOI is not a double";
    const int s_lo = sgn(evaluate(cubic, toi->lo));
    const int s_hi = sgn(evaluate(cubic, toi->hi));
    EXPECT_NE(s_lo, 0);
    EXPECT_EQ(s_lo, -s_hi) << "the root is not inside [" << toi->lo << ", " << toi->hi << "]";
  }
}

template <class Query>
void expect_no_toi(const Query& q) {
  for (const auto& [label, toi] : all_tois(q)) EXPECT_FALSE(toi.has_value()) << label;
}

/// Applies f to every coordinate (callers assert the result is exact).
template <class Query>
Query transformed(const Query& q, const std::function<double(double)>& f) {
  auto r = rows(q);
  for (Vec3& p : r)
    for (double* x : {&p.x, &p.y, &p.z}) *x = f(*x);
  return from_rows<Query>(r);
}

/// Exact scaling by 2^e (asserted exact: scaling back restores every coordinate).
template <class Query>
Query scaled(const Query& q, int e) {
  const Query s = transformed(q, [e](double x) { return std::ldexp(x, e); });
  const auto back = rows(transformed(s, [e](double x) { return std::ldexp(x, -e); }));
  const auto orig = rows(q);
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(back[i].x, orig[i].x);
    EXPECT_EQ(back[i].y, orig[i].y);
    EXPECT_EQ(back[i].z, orig[i].z);
  }
  return s;
}

/// Exact translation of every coordinate by d (asserted exact).
template <class Query>
Query translated(const Query& q, double d) {
  const Query s = transformed(q, [d](double x) { return x + d; });
  const auto moved = rows(s);
  const auto orig = rows(q);
  for (std::size_t i = 0; i < 8; ++i)
    for (auto [m, o] : {std::pair{moved[i].x, orig[i].x}, std::pair{moved[i].y, orig[i].y},
                        std::pair{moved[i].z, orig[i].z}})
      EXPECT_EQ(mpq_class(m), mpq_class(o) + mpq_class(d)) << "translation by " << d << " not exact";
  return s;
}

// ---- Rational TOIs ---------------------------------------------------------------------

TEST(VertexFaceToi, FallingOntoStaticTriangle) {
  expect_toi(falling_vertex(1, -1), mpq_class(1, 2));   // z = 1 - 2t
  expect_toi(falling_vertex(1, -2), mpq_class(1, 3));   // z = 1 - 3t
  expect_toi(falling_vertex(2, -5), mpq_class(2, 7));   // z = 2 - 7t
  expect_toi(falling_vertex(3, -0.0625), mpq_class(48, 49));  // z = 3 - (49/16) t
  expect_toi(falling_vertex(1, 0), mpq_class(1));       // arrives exactly at t = 1
  expect_toi(falling_vertex(0, -1), mpq_class(0));      // starts on the triangle
}

TEST(VertexFaceToi, TinyAndNearOne) {
  // p static at height 2^-60, the triangle rising from z = 0 to z = 1: V ~ 2^-60 - t, TOI 2^-60.
  const VertexFaceQuery rising{{0.25, 0.25, 0x1p-60}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                               {0.25, 0.25, 0x1p-60}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  expect_toi(rising, mpq_class(0x1p-60));
  // z = (1 - 2^-53) - t: TOI 1 - 2^-53, the double just below 1.
  expect_toi(falling_vertex(1 - 0x1p-53, -0x1p-53), mpq_class(1 - 0x1p-53));
  // z = 1 - (1 + 2^-52) t: TOI 1 / (1 + 2^-52), not a double, in (1 - 2^-52, 1 - 2^-53).
  expect_toi(falling_vertex(1, -0x1p-52), 1 / (1 + mpq_class(0x1p-52)));
}

TEST(EdgeEdgeToi, CrossingEdges) {
  expect_toi(crossing_edges(1, -1), mpq_class(1, 2));
  expect_toi(crossing_edges(1, -2), mpq_class(1, 3));
  expect_toi(crossing_edges(5, -2), mpq_class(5, 7));
  expect_toi(crossing_edges(1, 0), mpq_class(1));
  expect_toi(crossing_edges(0, 1), mpq_class(0));
}

TEST(EdgeEdgeToi, TinyAndNearOne) {
  expect_toi(rising_edge(0x1p-60), mpq_class(0x1p-60));
  expect_toi(rising_edge(0x1p-70), mpq_class(0x1p-70));
  // z = 1 - (1 + 2^60) t: TOI 1 / (1 + 2^60), tiny and not a double.
  expect_toi(crossing_edges(1, -0x1p60), 1 / (1 + mpq_class(0x1p60)));
  expect_toi(crossing_edges(1 - 0x1p-53, -0x1p-53), mpq_class(1 - 0x1p-53));
  expect_toi(rising_edge(1 - 0x1p-53), mpq_class(1 - 0x1p-53));
}

TEST(Toi, EarliestOfTwoCoplanarTimes) {
  // See two_root_vertex_face / two_root_edge_edge: V = +-(t - 1/4)(t - 3/4).
  expect_toi(two_root_vertex_face(1, 0), mpq_class(3, 4));  // first coplanarity outside
  expect_toi(two_root_vertex_face(0, 1), mpq_class(1, 4));  // first coplanarity inside
  expect_toi(two_root_edge_edge(2, 0), mpq_class(3, 4));
  expect_toi(two_root_edge_edge(0, 2), mpq_class(1, 4));
}

// ---- Irrational TOIs -------------------------------------------------------------------

TEST(Toi, CompanionCubicRootIsTwoCos4PiOver9) {
  // The enclosure of 2 cos(4 pi/9) = 0.3472963553338606977...: the cubic is +9.3e-17 at lo
  // and -5.3e-17 at hi (exact mpq_class evaluation), and lo, hi are consecutive doubles.
  EXPECT_EQ(std::nextafter(kCompanionLo, kInf), kCompanionHi);
  EXPECT_GT(evaluate(kCompanionCubic, kCompanionLo), 0);
  EXPECT_LT(evaluate(kCompanionCubic, kCompanionHi), 0);
  const std::vector<mpq_class> ee_cubic = {-3, 9, 0, -3};  // V of the EE query
  expect_irrational_toi(companion_vertex_face(), kCompanionCubic);
  expect_irrational_toi(companion_edge_edge(), ee_cubic);
  for (const auto& [label, toi] : all_tois(companion_vertex_face())) {
    ASSERT_TRUE(toi.has_value()) << label;
    EXPECT_EQ(toi->lo, kCompanionLo) << label;
    EXPECT_EQ(toi->hi, kCompanionHi) << label;
  }
  for (const auto& [label, toi] : all_tois(companion_edge_edge())) {
    ASSERT_TRUE(toi.has_value()) << label;
    EXPECT_EQ(toi->lo, kCompanionLo) << label;
    EXPECT_EQ(toi->hi, kCompanionHi) << label;
  }
}

TEST(Toi, CatalogueCubicRootIsEnclosed) {
  expect_irrational_toi(catalogue_cubic_vertex_face(), kCatalogueCubic);
  const auto toi = vertex_face_toi(catalogue_cubic_vertex_face());
  ASSERT_TRUE(toi.has_value());
  EXPECT_NEAR(toi->lo, 0.3261498573585535, 1e-15);
}

// ---- Scale and translation invariance ----------------------------------------------------
// x -> 2^e x multiplies every polynomial of the query by a positive power of two and
// x -> x + d moves the scene rigidly: neither changes the TOI (when every coordinate stays an
// exact double). 2^996 puts coordinates near 1e300; 2^-1000 near 1e-301 (and 2^-60 becomes
// the subnormal 2^-1060).

TEST(Toi, ScaledAndTranslatedCopiesKeepTheToi) {
  for (int e : {996, -1000}) {
    SCOPED_TRACE("scaled by 2^" + std::to_string(e));
    expect_toi(scaled(falling_vertex(1, -2), e), mpq_class(1, 3));
    expect_toi(scaled(falling_vertex(1 - 0x1p-53, -0x1p-53), e), mpq_class(1 - 0x1p-53));
    expect_toi(scaled(crossing_edges(1, -2), e), mpq_class(1, 3));
    expect_toi(scaled(rising_edge(0x1p-60), e), mpq_class(0x1p-60));
    expect_toi(scaled(two_root_vertex_face(1, 0), e), mpq_class(3, 4));
    expect_toi(scaled(two_root_edge_edge(2, 0), e), mpq_class(3, 4));
    expect_irrational_toi(scaled(companion_vertex_face(), e), kCompanionCubic);
    expect_irrational_toi(scaled(companion_edge_edge(), e), std::vector<mpq_class>{-3, 9, 0, -3});
  }
  for (double d : {0x1p20, -0x1p30}) {
    SCOPED_TRACE("translated by " + std::to_string(d));
    expect_toi(translated(falling_vertex(1, -2), d), mpq_class(1, 3));
    expect_toi(translated(crossing_edges(1, -2), d), mpq_class(1, 3));
    expect_toi(translated(two_root_vertex_face(1, 0), d), mpq_class(3, 4));
    expect_toi(translated(two_root_edge_edge(2, 0), d), mpq_class(3, 4));
    expect_irrational_toi(translated(companion_vertex_face(), d), kCompanionCubic);
  }
}

// ---- No contact ------------------------------------------------------------------------

TEST(Toi, NoCollisionMeansNoToi) {
  expect_no_toi(falling_vertex(1, 0x1p-30));    // stops 2^-30 above the triangle
  expect_no_toi(falling_vertex(1, 0x1p-1074));  // stops 2^-1074 above it
  expect_no_toi(crossing_edges(1, 0.5));
  expect_no_toi(crossing_edges(1, 0x1p-1074));
  // p static 2^-1074 above the interior: never in the plane z = 0.
  expect_no_toi(falling_vertex(0x1p-1074, 0x1p-1074));
  // p slides across the whole triangle at height 2^-1074: V = 2^-1074 > 0 for all t.
  expect_no_toi(VertexFaceQuery{{-1, 0.25, 0x1p-1074}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                {2, 0.25, 0x1p-1074}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  // In the plane z = 0, p = (2 - 3t, -2^-1074, 0) slides along edge ab at distance 2^-1074
  // outside it (y < 0 for all t): coplanar for all t, never in the closed triangle.
  expect_no_toi(VertexFaceQuery{{2, -0x1p-1074, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                {-1, -0x1p-1074, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  // Edge b parallel to a = [(-1,0,0), (1,0,0)] at y = 2^-1074, sliding along x in z = 0:
  // parallel and coplanar for all t, never collinear.
  expect_no_toi(EdgeEdgeQuery{{-1, 0, 0}, {1, 0, 0}, {-3, 0x1p-1074, 0}, {-2, 0x1p-1074, 0},
                              {-1, 0, 0}, {1, 0, 0}, {2, 0x1p-1074, 0}, {3, 0x1p-1074, 0}});
}

// ---- Non-finite input --------------------------------------------------------------------

TEST(Toi, NonFiniteInputThrows) {
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(), kInf, -kInf};
  // Every method of the tools: the library's and the baselines (which throw alike).
  using tools::Method;
  const Method methods[] = {Method::filtered,     Method::exact,        Method::naive,
                            Method::naive_tolerance, Method::naive_mpfr24, Method::naive_mpfr53,
                            Method::naive_mpfr113, Method::naive_mpfr256};
  for (double x : bad)
    for (int row = 0; row < 8; ++row)
      for (int axis = 0; axis < 3; ++axis) {
        SCOPED_TRACE("value " + std::to_string(x) + " at row " + std::to_string(row) + " axis " +
                     std::to_string(axis));
        const auto poison = [&](auto q) {
          auto r = rows(q);
          (axis == 0 ? r[row].x : axis == 1 ? r[row].y : r[row].z) = x;
          return from_rows<decltype(q)>(r);
        };
        const VertexFaceQuery vf = poison(falling_vertex(1, -1));
        const EdgeEdgeQuery ee = poison(crossing_edges(1, -1));
        for (Method m : methods) {
          EXPECT_THROW(tools::ccd(vf, m), std::invalid_argument);
          EXPECT_THROW(tools::toi(vf, m), std::invalid_argument);
          EXPECT_THROW(tools::ccd(ee, m), std::invalid_argument);
          EXPECT_THROW(tools::toi(ee, m), std::invalid_argument);
        }
        for (exactccd::Method m : {exactccd::Method::filtered, exactccd::Method::exact}) {
          EXPECT_THROW(vertex_face_ccd(vf, m), std::invalid_argument);
          EXPECT_THROW(vertex_face_toi(vf, m), std::invalid_argument);
          EXPECT_THROW(edge_edge_ccd(ee, m), std::invalid_argument);
          EXPECT_THROW(edge_edge_toi(ee, m), std::invalid_argument);
        }
        EXPECT_THROW(vertex_face_ccd(vf), std::invalid_argument);
        EXPECT_THROW(edge_edge_toi(ee), std::invalid_argument);
      }
}

}  // namespace
}  // namespace exactccd
