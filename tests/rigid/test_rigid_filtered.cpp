// The rigid filtered method against the rigid exact path (docs/design.md, 9.4): the same answers
// and the same TOIs, bit for bit, on random queries with small integer components (exactly
// degenerate often: coplanar, parallel, motions in one plane), on the bundled tumbling-body
// sets (every seventh query), with random d and tmax; the same after scaling every length by
// powers of two from the subnormal to the overflow range and each body's quaternions by others
// (exact: the answer and TOI cannot change); and under exact common changes of frame.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "exactccd/rigid.hpp"
#include "io/rigid_csv.hpp"
#include "rigid/rigid_layout.hpp"
#include "rigid_support.hpp"

namespace exactccd {
namespace {

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
  for (int body = 0; body < 2; ++body) {  // not through zero: flip q1 when antiparallel or opposite
    RigidPose& t1 = body == 0 ? q.a_t1 : q.b_t1;
    const RigidPose& t0 = body == 0 ? q.a_t0 : q.b_t0;
    if (t0.q.w * t1.q.w + t0.q.x * t1.q.x + t0.q.y * t1.q.y + t0.q.z * t1.q.z < 0)
      t1.q = {-t1.q.w, -t1.q.x, -t1.q.y, -t1.q.z};
  }
  rigid::set_points(q, [&](Vec3& p) { p = v(); });
  return q;
}

std::string describe(const std::array<double, rigid::kQueryNumbers>& x) {
  std::string s;
  char buf[40];
  for (const double v : x) std::snprintf(buf, sizeof buf, "%a,", v), s += buf;
  return s;
}

/// Filtered and exact agree on the query for the question (TOI bit for bit, answers).
template <class Query>
void agree(const Query& q, const CcdParams& p, const std::string& what) {
  const auto exact = toi(q, p, Method::exact);
  const auto filtered = toi(q, p, Method::filtered);
  ASSERT_EQ(filtered.has_value(), exact.has_value()) << what << " d=" << p.min_distance << " tmax=" << p.tmax << "\n"
                                                    << describe(rigid::to_numbers(q));
  if (exact) {
    EXPECT_EQ(filtered->lo, exact->lo) << what << "\n" << describe(rigid::to_numbers(q));
    EXPECT_EQ(filtered->hi, exact->hi) << what << "\n" << describe(rigid::to_numbers(q));
  }
  EXPECT_EQ(ccd(q, p, Method::filtered), exact.has_value()) << what << "\n" << describe(rigid::to_numbers(q));
}

template <class Query>
void random_agreement(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < count; ++i) {
    const Query q = random_query<Query>(rng, i % 4 == 3);
    const double d = i % 3 == 0 ? 0.0 : i % 3 == 1 ? std::ldexp(1.0, -int(unit(rng) * 8)) : unit(rng) / 7;
    const double tmax = i % 2 ? 1.0 : 0.25 + unit(rng) * 0.75;
    agree(q, CcdParams{0, 1}, "random " + std::to_string(i));
    agree(q, CcdParams{d, tmax}, "random " + std::to_string(i));
  }
}

TEST(RigidFiltered, EqualsExactOnRandomQueriesVertexFace) { random_agreement<RigidVertexFaceQuery>(11, 160); }
TEST(RigidFiltered, EqualsExactOnRandomQueriesEdgeEdge) { random_agreement<RigidEdgeEdgeQuery>(12, 160); }

TEST(RigidFiltered, EqualsExactOnRandomEdgeEdgeMotionsInOnePlane) {
  // Every point in z = 0 and every rotation about z (small integers: often exactly parallel,
  // collinear, touching at dyadic times): the volume vanishes for all t and the plane's
  // candidates decide (rigid/coplanar_walk.hpp) where they can; answers and TOIs as exact.
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 300; ++i) {
    const RigidEdgeEdgeQuery q = random_query<RigidEdgeEdgeQuery>(rng, true);
    agree(q, CcdParams{0, 1}, "planar " + std::to_string(i));
    agree(q, CcdParams{0, i % 2 ? 0.5 : 0.125 + unit(rng) * 0.875}, "planar " + std::to_string(i));
  }
}

/// Every seventh query of the bundled tumbling-body sets, at d = 0, and at d = 2^-9 with
/// tmax 0.75 (the bodies have size about 1).
TEST(RigidFiltered, EqualsExactOnTheTumblingBodies) {
  namespace fs = std::filesystem;
  int compared = 0;
  for (const char* name : {"rigid-sim-box-vertex-face.csv", "rigid-sim-box-edge-edge.csv",
                           "rigid-sim-rings-vertex-face.csv", "rigid-sim-rings-edge-edge.csv"}) {
    const fs::path path = fs::path(EXACTCCD_SOURCE_DIR) / "data" / "rigid" / name;
    std::ifstream in(path);
    ASSERT_TRUE(in) << path;
    const io::RigidQueries queries = io::read_rigid_csv(in, path.string());
    const bool vf = std::string(name).find("vertex-face") != std::string::npos;
    for (std::size_t i = 0; i < queries.size(); i += 7) {
      for (const CcdParams& p : {CcdParams{}, CcdParams{0x1p-9, 0.75}}) {
        const std::string what = std::string(name) + " #" + std::to_string(i);
        if (vf)
          agree(rigid::from_numbers<RigidVertexFaceQuery>(queries.numbers[i].data()), p, what);
        else
          agree(rigid::from_numbers<RigidEdgeEdgeQuery>(queries.numbers[i].data()), p, what);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

/// A vertex turning about a random axis by up to about 150 degrees against a static triangle in
/// the plane tangent (nearly: rounded) to its path's sphere at the middle of its arc, offset by
/// +-2^-k: where the arc bulges beyond its chord, a plane the chord stays behind (the sagitta of
/// the direction stage, the tangential contacts of the interval stage).
TEST(RigidFiltered, EqualsExactWhereTheArcBulgesBeyondItsChord) {
  std::mt19937_64 rng(41);
  std::uniform_int_distribution<int> axis(-3, 3), turn(1, 7);
  int collisions = 0, count = 0;
  for (int i = 0; i < 150; ++i) {
    const Vec3 k{double(axis(rng)), double(axis(rng)), double(1 + turn(rng) % 3)};
    const double w = 8.0 / turn(rng);  // q1 = (w, k): a turn by 2 atan(|k| / w)
    const Quaternion q1{w, k.x, k.y, k.z};
    const Vec3 p{1, -0.5, 0.25};
    // The arc's middle: the rotation by h = q0 / |q0| + q1 / |q1| (halfway along the great circle).
    const double n1 = std::sqrt(w * w + k.x * k.x + k.y * k.y + k.z * k.z);
    const Quaternion h{1 + w / n1, k.x / n1, k.y / n1, k.z / n1};
    const double hn = h.w * h.w + h.x * h.x + h.y * h.y + h.z * h.z;
    const Vec3 u{h.x, h.y, h.z};
    const double s = h.w * h.w - (u.x * u.x + u.y * u.y + u.z * u.z), uv = u.x * p.x + u.y * p.y + u.z * p.z;
    const Vec3 c{u.y * p.z - u.z * p.y, u.z * p.x - u.x * p.z, u.x * p.y - u.y * p.x};
    const Vec3 m{(s * p.x + 2 * uv * u.x + 2 * h.w * c.x) / hn, (s * p.y + 2 * uv * u.y + 2 * h.w * c.y) / hn,
                 (s * p.z + 2 * uv * u.z + 2 * h.w * c.z) / hn};
    // Two directions perpendicular to m (any), the triangle around m + offset m / |m|.
    const Vec3 e1 = std::fabs(m.x) < 0.5 ? Vec3{0, -m.z, m.y} : Vec3{-m.y, m.x, 0};
    const Vec3 e2{m.y * e1.z - m.z * e1.y, m.z * e1.x - m.x * e1.z, m.x * e1.y - m.y * e1.x};
    const double mn = std::sqrt(m.x * m.x + m.y * m.y + m.z * m.z);
    const double offset = (i % 3 - 1) * std::ldexp(1.0, -(4 + i % 40));
    const Vec3 o{m.x * (1 + offset / mn), m.y * (1 + offset / mn), m.z * (1 + offset / mn)};
    const auto corner = [&](double a, double b) {
      return Vec3{o.x + a * e1.x + b * e2.x, o.y + a * e1.y + b * e2.y, o.z + a * e1.z + b * e2.z};
    };
    const RigidVertexFaceQuery q{{{0, 0, 0}, {1, 0, 0, 0}}, {{0, 0, 0}, q1}, {{0, 0, 0}, {1, 0, 0, 0}},
                                 {{0, 0, 0}, {1, 0, 0, 0}}, p, corner(-4, -3), corner(4, -3), corner(0, 5)};
    for (const CcdParams& params : {CcdParams{}, CcdParams{0x1p-8, 1.0}, CcdParams{0x1p-20, 0.5}}) {
      agree(q, params, "bulge " + std::to_string(i));
      collisions += ccd(q, params, Method::exact);
      ++count;
    }
  }
  EXPECT_GT(collisions, count / 5);
  EXPECT_LT(collisions, count * 4 / 5);
}

/// The query with every length (translations, points) and d times 2^e and each body's
/// quaternions times 2^fa, 2^fb: the same question (docs/design.md 9.1), when every product is
/// exact (checked by scaling back).
template <class Query>
std::optional<std::pair<Query, double>> scaled(const Query& q, double d, int e, int fa, int fb) {
  Query out = q;
  bool exact = true;
  const auto s = [&](double v, int k) {
    const double r = std::ldexp(v, k);
    if (!std::isfinite(r) || std::ldexp(r, -k) != v) exact = false;
    return r;
  };
  const auto vec = [&](Vec3& v) { v = {s(v.x, e), s(v.y, e), s(v.z, e)}; };
  for (RigidPose* p : {&out.a_t0, &out.a_t1, &out.b_t0, &out.b_t1}) {
    vec(p->c);
    const int f = p == &out.a_t0 || p == &out.a_t1 ? fa : fb;
    p->q = {s(p->q.w, f), s(p->q.x, f), s(p->q.y, f), s(p->q.z, f)};
  }
  rigid::set_points(out, vec);
  const double sd = s(d, e);
  if (!exact) return std::nullopt;
  return std::pair{out, sd};
}

template <class Query>
void wide_agreement(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  const int exponents[] = {-1070, -1040, -600, -200, 200, 600, 1000};
  const int quaternion_exponents[] = {-1070, -900, -300, 0, 300, 1000};
  int checked = 0;
  for (int i = 0; i < count; ++i) {
    const Query q = random_query<Query>(rng, i % 4 == 3);
    const double d = i % 2 ? 0.0 : 0.25;
    const auto want = toi(q, CcdParams{d, 1.0}, Method::exact);
    const int e = exponents[i % 7], fa = quaternion_exponents[i % 6], fb = quaternion_exponents[(i / 6) % 6];
    const auto x = scaled(q, d, e, fa, fb);
    if (!x) continue;
    for (const Method m : {Method::filtered, Method::exact}) {
      const auto got = toi(x->first, CcdParams{x->second, 1.0}, m);
      ASSERT_EQ(got.has_value(), want.has_value()) << "wide " << i << " e=" << e << " method " << int(m);
      if (got) {
        EXPECT_TRUE(got->lo == want->lo && got->hi == want->hi) << "wide " << i << " e=" << e << " method " << int(m);
      }
    }
    ++checked;
  }
  EXPECT_GT(checked, count / 2);
}

TEST(RigidFiltered, SubnormalAndHugeScalesVertexFace) { wide_agreement<RigidVertexFaceQuery>(21, 120); }
TEST(RigidFiltered, SubnormalAndHugeScalesEdgeEdge) { wide_agreement<RigidEdgeEdgeQuery>(22, 120); }

/// A common rigid change of frame applied exactly: a quarter turn about x composed on the left of
/// every quaternion (R(g q) = R(g) R(q)) and applied to the translations (a signed permutation),
/// then a power-of-two translation.
template <class Query>
Query moved(const Query& q, const Vec3& shift) {
  Query out = q;
  // g = (1, 1, 0, 0): R(g) (x, y, z) = (x, -z, y)
  for (RigidPose* p : {&out.a_t0, &out.a_t1, &out.b_t0, &out.b_t1}) {
    p->c = {p->c.x + shift.x, -p->c.z + shift.y, p->c.y + shift.z};
    const Quaternion r = p->q;  // g r, g = (1, 1, 0, 0)
    p->q = {r.w - r.x, r.x + r.w, r.y - r.z, r.z + r.y};
  }
  return out;
}

template <class Query>
void frame_invariance(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  int collisions = 0;
  for (int i = 0; i < count; ++i) {
    const Query q = random_query<Query>(rng, i % 3 == 2);
    const Query m = moved(q, {0x1p10, -0x1p-3, 0x1p6});
    for (const double d : {0.0, 0.125, 0.5}) {
      const auto a = toi(q, CcdParams{d, 1.0}), b = toi(m, CcdParams{d, 1.0});
      ASSERT_EQ(a.has_value(), b.has_value()) << "invariance " << i << " d " << d;
      if (a) {
        EXPECT_TRUE(a->lo == b->lo && a->hi == b->hi) << "invariance " << i << " d " << d;
      }
      collisions += a.has_value();
    }
  }
  EXPECT_GT(collisions, count / 10);
}

TEST(RigidFiltered, CommonChangeOfFrameChangesNothingVertexFace) { frame_invariance<RigidVertexFaceQuery>(31, 100); }
TEST(RigidFiltered, CommonChangeOfFrameChangesNothingEdgeEdge) { frame_invariance<RigidEdgeEdgeQuery>(32, 100); }

}  // namespace
}  // namespace exactccd
