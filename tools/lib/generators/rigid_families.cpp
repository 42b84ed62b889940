// The degenerate rigid families (rigid_families.hpp). Turning about the z axis with the path
// q(t) = (1, 0, 0, s t) from the identity turns by theta = 2 atan(s t): cos theta =
// (1 - s^2 t^2) / (1 + s^2 t^2), sin theta = 2 s t / (1 + s^2 t^2); a direction (cos phi, sin phi)
// is reached at s t = tan(phi / 2) = sin phi / (1 + cos phi): (3, 4) / 5 at s t = 1/2, (7, 24) / 25
// at s t = 3/4, the y axis at s t = 1. eps = 2^-k. Each family's derivation is at its maker.
#include "generators/rigid_families.hpp"

#include <array>
#include <cmath>

#include "io/benchmark_csv.hpp"  // exact_double
#include "rigid/quaternion.hpp"
#include "rigid/rigid_layout.hpp"

namespace exactccd::rigid_families {
namespace {

using families::KnownToi;
using families::rational_toi;

constexpr Quaternion kIdentity{1, 0, 0, 0};

std::array<RigidPose, 2> still() { return {RigidPose{{0, 0, 0}, kIdentity}, RigidPose{{0, 0, 0}, kIdentity}}; }
std::array<RigidPose, 2> z_turn(double s) {
  return {RigidPose{{0, 0, 0}, kIdentity}, RigidPose{{0, 0, 0}, {1, 0, 0, s}}};
}

double eps(int k) { return k < 0 ? 0.0 : std::ldexp(1.0, -k); }

Instance vf(const std::array<RigidPose, 2>& a, const std::array<RigidPose, 2>& b, const Vec3& p, const Vec3& ta,
            const Vec3& tb, const Vec3& tc, std::optional<bool> expected, std::optional<KnownToi> toi, double d = 0) {
  return {RigidVertexFaceQuery{a[0], a[1], b[0], b[1], p, ta, tb, tc}, d, expected, std::move(toi)};
}
Instance ee(const std::array<RigidPose, 2>& a, const std::array<RigidPose, 2>& b, const Vec3& a0, const Vec3& a1,
            const Vec3& b0, const Vec3& b1, std::optional<bool> expected, std::optional<KnownToi> toi, double d = 0) {
  return {RigidEdgeEdgeQuery{a[0], a[1], b[0], b[1], a0, a1, b0, b1}, d, expected, std::move(toi)};
}

/// A root of c0 + c1 t + c2 t^2 + ... in [from, to] (opposite signs at the ends).
KnownToi root(std::vector<mpq_class> c, const mpq_class& from, const mpq_class& to) { return {std::move(c), from, to}; }

// A's vertex (5, 0, 0) turns a quarter turn (s = 1) in the plane z = 0. B's static triangle
// a = (0, 0, h), b = (6, 8, h), c = (0, 0, 2 + h): its points at height 0 are, for h = 0, the edge
// ab only (z = 2v in the barycentric coordinate v of c), which the vertex meets at t = 1/2 at
// (3, 4, 0) (u = 1/2 along ab). h = eps > 0: the triangle is above z = 0, never met. h = -eps: its
// section z = 0 is {(6u, 8u, 0) : u in [0, 1 - eps/2]}, v = eps/2 > 0, holding (3, 4, 0): the
// vertex meets the interior at t = 1/2.
Instance vertex_onto_edge(int k, bool toward) {
  const double h = toward ? -eps(k) : eps(k);
  const bool hit = toward || k < 0;
  return vf(z_turn(1), still(), {5, 0, 0}, {0, 0, h}, {6, 8, h}, {0, 0, 2 + h}, hit,
            hit ? std::optional(rational_toi(mpq_class(1, 2))) : std::nullopt);
}

// A's edge (0,0,0)-(10,0,0) turns a quarter turn in z = 0 about its end a0; B's static edge
// (3, 4, h)-(3, 4, 5 + h) is vertical. h = 0: only B's end (3, 4, 0) is at height 0, reached by A's
// edge (length 10 > 5) at t = 1/2. h = eps: B above z = 0, never met; h = -eps: B crosses z = 0 at
// (3, 4, 0): met at t = 1/2.
Instance sweep_through_end(int k, bool toward) {
  const double h = toward ? -eps(k) : eps(k);
  const bool hit = toward || k < 0;
  return ee(z_turn(1), still(), {0, 0, 0}, {10, 0, 0}, {3, 4, h}, {3, 4, 5 + h}, hit,
            hit ? std::optional(rational_toi(mpq_class(1, 2))) : std::nullopt);
}

// A's vertex (1, 0, 0) turns with s = 2: (cos, sin, 0), sin = 4t / (1 + 4t^2) <= 1, = 1 only at
// t = 1/2. B's static triangle (-1, y, -1), (1, y, -1), (0, y, 1) in the plane y = 1 + h holds every
// (x, y, 0) with |x| <= 1/2 in its interior. h = 0: the vertex's circle touches the plane at
// (0, 1, 0), t = 1/2 (tangentially: a double root). h = eps: never. h = -eps (k >= 4): sin = 1 - eps
// first at the root of (1 - eps) - 4t + 4 (1 - eps) t^2 in [0, 1/2] (values 1 - eps > 0 and -2 eps
// < 0 at the ends), where |x| = cos = sqrt(1 - (1 - eps)^2) <= sqrt(2 eps) < 1/2.
Instance circle_tangent_to_face(int k, bool toward) {
  const int kk = k < 0 ? k : std::max(k, 4);
  const double h = toward ? -eps(kk) : eps(kk);
  const double y = 1 + h;
  std::optional<bool> expected = toward || kk < 0;
  std::optional<KnownToi> toi;
  if (kk < 0) toi = rational_toi(mpq_class(1, 2));
  else if (toward) {
    const mpq_class e(eps(kk)), one_minus = 1 - e;
    toi = root({one_minus, -4, 4 * one_minus}, 0, mpq_class(1, 2));
  }
  return vf(z_turn(2), still(), {1, 0, 0}, {-1, y, -1}, {1, y, -1}, {0, y, 1}, expected, toi);
}

// A's vertex (5, y0, 0) turns a quarter turn: y(t) = 5 sin + y0 cos, x(t) = 5 cos - y0 sin. B's
// static triangle (0, 0, -1), (10, 0, 0), (0, 0, 1) in the plane y = 0 holds (x, 0, 0) for 0 < x < 10
// in its interior. y0 = 0: the vertex starts on it: TOI 0. y0 = eps: y > 0 throughout: never.
// y0 = -eps: y = 0 when tan = eps / 5, i.e. eps t^2 + 10 t - eps = 0 (tan = 2t / (1 - t^2)), the root
// in [0, 1/2] (values -eps and 5 - 3 eps / 4), x = 5 cos + eps sin in (0, 10).
Instance contact_at_start(int k, bool toward) {
  const double y0 = toward ? -eps(k) : eps(k);
  std::optional<KnownToi> toi;
  if (k < 0) toi = rational_toi(0);
  else if (toward) {
    const mpq_class e(eps(k));
    toi = root({-e, 10, e}, 0, mpq_class(1, 2));
  }
  return vf(z_turn(1), still(), {5, y0, 0}, {0, 0, -1}, {10, 0, 0}, {0, 0, 1}, toward || k < 0, toi);
}

// A's vertex (5, 0, 0) turns a quarter turn: x = 5 cos >= 0, = 0 only at t = 1, at (0, 5, 0). B's
// static triangle (h, 0, -1), (h, 10, 0), (h, 0, 1) in the plane x = h holds (h, y, 0) for 0 < y < 10.
// h = 0: TOI 1. h = -eps: never. h = eps: 5 cos = eps, i.e. (eps - 5) + (5 + eps) t^2 = 0, the root
// in [1/2, 1] (values below 0 and 2 eps), y = 5 sin in (0, 10).
Instance contact_at_end(int k, bool toward) {
  const double h = toward ? eps(k) : -eps(k);
  std::optional<KnownToi> toi;
  if (k < 0) toi = rational_toi(1);
  else if (toward) {
    const mpq_class e(eps(k));
    toi = root({e - 5, 0, 5 + e}, mpq_class(1, 2), 1);
  }
  return vf(z_turn(1), still(), {5, 0, 0}, {h, 0, -1}, {h, 10, 0}, {h, 0, 1}, toward || k < 0, toi);
}

// As vertex_onto_edge towards (7, 24) / 25, reached at t = 3/4 at (7, 24, 0) / 5 = 1/10 of the
// edge (0, 0, h)-(14, 48, h) (length 50).
Instance contact_at_three_quarters(int k, bool toward) {
  const double h = toward ? -eps(k) : eps(k);
  const bool hit = toward || k < 0;
  return vf(z_turn(1), still(), {5, 0, 0}, {0, 0, h}, {14, 48, h}, {0, 0, 2 + h}, hit,
            hit ? std::optional(rational_toi(mpq_class(3, 4))) : std::nullopt);
}

// A's edge (0,0,0)-(10,0,0) turns a quarter turn in z = 0; B's static edge (3, 4, h0)-(6, 8, h1)
// lies on the ray towards (3, 4) when h0 = h1 = 0, reached (all of it, collinear with A's edge)
// at t = 1/2, never touched before (A meets that ray only then). h0 = h1 = eps: never. h0 = -eps,
// h1 = eps: B crosses z = 0 at (4.5, 6, 0), 7.5 from the axis: met at t = 1/2.
Instance collinear_at_contact(int k, bool toward) {
  const double h1 = eps(k), h0 = toward ? -eps(k) : eps(k);
  const bool hit = toward || k < 0;
  return ee(z_turn(1), still(), {0, 0, 0}, {10, 0, 0}, {3, 4, h0}, {6, 8, h1}, hit,
            hit ? std::optional(rational_toi(mpq_class(1, 2))) : std::nullopt);
}

// Everything in z = 0 (the volume vanishes for all t). A's edge (0,0,0)-(10,0,0) turns a quarter
// turn; B's edge (3, y0, 0)-(3, 10, 0) with y0 = 4 (unperturbed), 4 - eps (towards) or 4 + eps
// (away): A's ray at angle theta meets the line x = 3 at y = 3 tan theta, first at B's end when
// tan theta = y0 / 3, i.e. y0 t^2 + 6 t - y0 = 0: TOI 1/2 for y0 = 4; for 4 - eps the root in
// [0, 1/2] (values -y0 and 3 eps / 4), for 4 + eps the root in [1/2, 1] (values -3 eps / 4 and 6)
// (4 itself when 4 +- eps rounds to 4, k > 50); the end is about 5 < 10 from the axis: every variant
// collides.
Instance planar_motion(int k, bool toward) {
  const double y0 = k < 0 ? 4.0 : toward ? 4 - eps(k) : 4 + eps(k);  // 4 itself when 4 +- eps rounds
  const mpq_class y(y0);
  KnownToi toi = y0 == 4 ? rational_toi(mpq_class(1, 2))
                         : root({-y, 6, y}, y0 < 4 ? mpq_class(0) : mpq_class(1, 2), y0 < 4 ? mpq_class(1, 2) : mpq_class(1));
  return ee(z_turn(1), still(), {0, 0, 0}, {10, 0, 0}, {3, y0, 0}, {3, 10, 0}, true, toi);
}

// Minimum separation. A's vertex (1, 0, 0) turns a quarter turn: distance 1 + g - sin to B's static
// triangle (-5, y, -5), (5, y, -5), (0, y, 5) in the plane y = 1 + g (the vertex projects into its
// interior). d = eps (d = 1/4 unperturbed), g = 0 (towards): within d when sin >= 1 - d, i.e.
// (1 - d) - 2t + (1 - d) t^2 <= 0, first at its root in [0, 1] (values 1 - d and -2d). g = 2 eps
// (away): the distance stays >= 2 eps > d.
Instance turning_vertex_within_distance(int k, bool toward) {
  const double d = k < 0 ? 0.25 : eps(k);
  const double y = toward || k < 0 ? 1.0 : 1 + 2 * eps(k);
  std::optional<KnownToi> toi;
  if (toward || k < 0) {
    const mpq_class one_minus = 1 - mpq_class(d);
    toi = root({one_minus, -2, one_minus}, 0, 1);
  }
  return vf(z_turn(1), still(), {1, 0, 0}, {-5, y, -5}, {5, y, -5}, {0, y, 5}, toward || k < 0, toi, d);
}

// A's edge (0,0,0)-(10,0,0) turns a quarter turn in z = 0; B's static edge (3, 4, 1)-(3, 4, 2). The
// distance is sqrt(1 + h^2), h = 5 sin(phi - theta) = (4 - 6t - 4t^2) / (1 + t^2) (the foot of
// (3, 4) on A's line, at 5 cos(phi - theta) in [0, 10], and B's lower end), least (1) at t = 1/2.
// d = 1 (unperturbed): reached exactly there, tangentially. d = 1 - eps (away): never. d = 1 + eps
// (towards): when (4 - 6t - 4t^2)^2 - (d^2 - 1)(1 + t^2)^2 = 0, first at its root in [0, 1/2]
// (values 16 - (d^2 - 1) > 0 and -(d^2 - 1) 25/16 < 0).
Instance edges_within_distance(int k, bool toward) {
  const double d = k < 0 ? 1.0 : toward ? 1 + eps(k) : 1 - eps(k);
  std::optional<KnownToi> toi;
  if (k < 0) toi = rational_toi(mpq_class(1, 2));
  else if (toward) {
    const mpq_class e2 = mpq_class(d) * mpq_class(d) - 1;
    toi = root({16 - e2, -48, 4 - 2 * e2, 48, 16 - e2}, 0, mpq_class(1, 2));
  }
  return ee(z_turn(1), still(), {0, 0, 0}, {10, 0, 0}, {3, 4, 1}, {3, 4, 2}, toward || k < 0, toi, d);
}

/// The 24 rotations of the cube as quaternions with entries in {0, +-1} (any length will do).
const std::vector<Quaternion>& cube_rotations() {
  static const std::vector<Quaternion> r = [] {
    std::vector<Quaternion> out{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    for (const double s : {1.0, -1.0}) {
      out.push_back({1, s, 0, 0}), out.push_back({1, 0, s, 0}), out.push_back({1, 0, 0, s});
      out.push_back({0, 1, s, 0}), out.push_back({0, 1, 0, s}), out.push_back({0, 0, 1, s});
      for (const double s2 : {1.0, -1.0}) out.push_back({1, s, s2, 1}), out.push_back({1, s, s2, -1});
    }
    return out;
  }();
  return r;
}

}  // namespace

const std::vector<Family>& all_families() {
  static const std::vector<Family> f{
      {"rigid_vf_vertex_onto_edge", true, vertex_onto_edge},
      {"rigid_ee_sweep_through_end", false, sweep_through_end},
      {"rigid_vf_circle_tangent_to_face", true, circle_tangent_to_face},
      {"rigid_vf_contact_at_start", true, contact_at_start},
      {"rigid_vf_contact_at_end", true, contact_at_end},
      {"rigid_vf_contact_at_three_quarters", true, contact_at_three_quarters},
      {"rigid_ee_collinear_at_contact", false, collinear_at_contact},
      {"rigid_ee_planar_motion", false, planar_motion},
      {"rigid_vf_turning_vertex_within_distance", true, turning_vertex_within_distance},
      {"rigid_ee_edges_within_distance", false, edges_within_distance},
  };
  return f;
}

std::optional<Instance> placed(const Instance& instance, std::mt19937_64& rng) {
  const auto& rotations = cube_rotations();
  const Quaternion g = rotations[std::uniform_int_distribution<std::size_t>(0, rotations.size() - 1)(rng)];
  const int scale_exponent = std::uniform_int_distribution<int>(-8, 8)(rng);
  std::uniform_int_distribution<int> digit(-64, 64), exponent(-6, 6);
  const Vec3 shift{std::ldexp(digit(rng), exponent(rng)), std::ldexp(digit(rng), exponent(rng)),
                   std::ldexp(digit(rng), exponent(rng))};
  // R(g) is a signed permutation: its entries M(g) / |g|^2 are 0 or +-1, exactly.
  const double n2 = g.w * g.w + g.x * g.x + g.y * g.y + g.z * g.z;
  bool exact = true;
  const auto keep = [&](const mpq_class& x) {
    const std::optional<double> d = io::exact_double(x);
    if (!d) exact = false;
    return d ? *d : 0.0;
  };
  // Column k of R(g): M(g) e_k / |g|^2 (small integers: exact), entries 0 or +-1.
  std::array<Vec3, 3> column;
  for (int k = 0; k < 3; ++k) {
    const Vec3 m = rigid::rotate_scaled(g, Vec3{k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0});
    column[k] = {m.x / n2, m.y / n2, m.z / n2};
  }
  const auto rotate = [&](const Vec3& v) {  // one nonzero term per row: exact
    return Vec3{column[0].x * v.x + column[1].x * v.y + column[2].x * v.z,
                column[0].y * v.x + column[1].y * v.y + column[2].y * v.z,
                column[0].z * v.x + column[1].z * v.y + column[2].z * v.z};
  };
  const auto pose = [&](const RigidPose& p) {
    const Vec3 m = rotate(p.c);
    RigidPose out;
    out.c = {keep(mpq_class(std::ldexp(m.x, scale_exponent)) + shift.x),
             keep(mpq_class(std::ldexp(m.y, scale_exponent)) + shift.y),
             keep(mpq_class(std::ldexp(m.z, scale_exponent)) + shift.z)};
    out.q = rigid::product(g, p.q);  // small integers: exact
    return out;
  };
  const auto point = [&](const Vec3& p) {
    return Vec3{keep(mpq_class(std::ldexp(p.x, scale_exponent))), keep(mpq_class(std::ldexp(p.y, scale_exponent))),
                keep(mpq_class(std::ldexp(p.z, scale_exponent)))};
  };
  Instance out = instance;
  out.min_distance = keep(mpq_class(std::ldexp(instance.min_distance, scale_exponent)));
  std::visit([&](auto& q) {
    q.a_t0 = pose(q.a_t0), q.a_t1 = pose(q.a_t1), q.b_t0 = pose(q.b_t0), q.b_t1 = pose(q.b_t1);
    rigid::set_points(q, [&](Vec3& p) { p = point(p); });
  }, out.query);
  if (!exact) return std::nullopt;
  return out;
}

Instance make(const Family& family, int k, bool toward, std::mt19937_64& rng) {
  const Instance base = family.make(k, toward);
  for (int attempt = 0; attempt < 100; ++attempt)
    if (const auto p = placed(base, rng)) return *p;
  return base;
}

}  // namespace exactccd::rigid_families
