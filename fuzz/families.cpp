// The degenerate families. Each base configuration is written in a local frame with small
// exact coordinates; d = 2^-k is the perturbation (0 when unperturbed), applied towards or
// away from contact. The comment on each states the answer by construction. Then an exact
// symmetry (axis permutation, sign flips), a power-of-two scale and an integer offset place it
// randomly; the answer is kept only if every coordinate stayed exact (checked with TwoSum).
#include "fuzz/families.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace exactccd::families {
namespace {

using V = Vec3;

VertexFaceQuery vf(V p0, V a0, V b0, V c0, V p1, V a1, V b1, V c1) {
  return {p0, a0, b0, c0, p1, a1, b1, c1};
}
EdgeEdgeQuery ee(V a00, V a10, V b00, V b10, V a01, V a11, V b01, V b11) {
  return {a00, a10, b00, b10, a01, a11, b01, b11};
}

// The unit triangle (0,0,0), (1,0,0), (0,1,0), static, and the static edge [-1, 1] on x.
VertexFaceQuery point_vs_triangle(V p0, V p1) {
  return vf(p0, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, p1, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
}
EdgeEdgeQuery edge_vs_axis(V b0_t0, V b1_t0, V b0_t1, V b1_t1) {
  return ee({-1, 0, 0}, {1, 0, 0}, b0_t0, b1_t0, {-1, 0, 0}, {1, 0, 0}, b0_t1, b1_t1);
}

struct Base {
  AnyQuery query;
  std::optional<bool> expected;  ///< nullopt where the construction does not settle it
};

/// `when` if the condition holds, else "unknown".
std::optional<bool> known_if(bool condition, bool when) {
  return condition ? std::optional<bool>(when) : std::nullopt;
}

// --- vertex-face --------------------------------------------------------------------------
// p falls through z = 0 at t = 1/2 at (-s d, -s d): a vertex hit for d = 0; s = +1 (away)
// puts it outside both edges at a, s = -1 (toward) inside the triangle while 2d <= 1.
Base vertex_through_vertex(double d, bool toward) {
  const double s = toward ? -d : d;
  return {point_vs_triangle({-s, -s, 1}, {-s, -s, -1}), toward ? known_if(d <= 0.5, true) : d == 0};
}
// Through the edge ab at (1/2, -s d): outside for away, inside for toward while d <= 1/2.
Base vertex_through_edge(double d, bool toward) {
  const double s = toward ? -d : d;
  return {point_vs_triangle({0.5, -s, 1}, {0.5, -s, -1}), toward ? known_if(d <= 0.5, true) : d == 0};
}
// Everything in z = 0 (coplanar for all t) but p at height e: p slides (2 - 3t, 1/4) into
// the triangle. Any e != 0 keeps p off the plane (V constant nonzero): no contact either way.
Base coplanar_sliding_vf(double d, bool toward) {
  const double e = toward ? -d : d;
  return {point_vs_triangle({2, 0.25, e}, {-1, 0.25, e}), d == 0};
}
// Grazing: V = (t - 1/2)^2 + e (catalogue's vf_grazing with p raised by e). e > 0 (away):
// V > 0, no contact. e < 0 (toward, |e| <= 1/4): first root t* = 1/2 - sqrt(|e|), where
// p = a + (1/4)(b - a) + (1/2 - sqrt(|e|)/2)(c - a): inside.
Base grazing_vf(double d, bool toward) {
  const double e = toward ? -d : d;
  return {vf({0.25, 0.25, 0.5 + e}, {0, 0, 0}, {1, 0, 0}, {0, 1, 1}, {0.25, 0.75, -0.5 + e}, {0, 0, 0},
             {1, 0, 0}, {0, 1, -1}),
          toward ? known_if(d <= 0.25, true) : d == 0};
}
// p starts at height e above the interior and rises: contact at t = 0 only if e = 0; e < 0
// (toward) starts below and crosses the interior at t = -e / (1 - e) > 0.
Base contact_at_t0_vf(double d, bool toward) {
  const double e = toward ? -d : d;
  return {point_vs_triangle({0.25, 0.25, e}, {0.25, 0.25, 1}), toward || d == 0};
}
// p falls from 1 to height e at t = 1: contact at t = 1 iff e <= 0.
Base contact_at_t1_vf(double d, bool toward) {
  const double e = toward ? -d : d;
  return {point_vs_triangle({0.25, 0.25, 1}, {0.25, 0.25, e}), toward || d == 0};
}
// The collinear triangle (0,0,0), (1,0,0), (2,0,0) (its hull: [0, 2] on x); p falls through
// z = 0 at (1/2, e): on the hull only if e = 0.
Base degenerate_triangle(double d, bool toward) {
  const double e = toward ? -d : d;
  return {vf({0.5, e, 1}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0.5, e, -1}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}),
          d == 0};
}
// Nothing moves; p rests at height e over the interior: contact only if e = 0.
Base nearly_static_vf(double d, bool toward) {
  const double e = toward ? -d : d;
  return {point_vs_triangle({0.25, 0.25, e}, {0.25, 0.25, e}), d == 0};
}

// --- edge-edge ----------------------------------------------------------------------------
// b (parallel to y) falls through z = 0 at t = 1/2 at x = 1 + s d: through a's endpoint for
// d = 0; toward (x < 1) crosses a, away (x > 1) misses it.
Base edge_through_endpoint(double d, bool toward) {
  const double x = 1 + (toward ? -d : d);
  return {edge_vs_axis({x, -1, 1}, {x, 1, 1}, {x, -1, -1}, {x, 1, -1}), toward || d == 0};
}
// a = [0, 1] on x; b = [1/2, 3/2] parallel to a at height e, sweeping y = 1 - 2t: the lines
// are parallel (always coplanar); at e = 0 they become collinear and overlap at t = 1/2.
Base parallel_edges(double d, bool toward) {
  const double e = toward ? -d : d;
  return {ee({0, 0, 0}, {1, 0, 0}, {0.5, 1, e}, {1.5, 1, e}, {0, 0, 0}, {1, 0, 0}, {0.5, -1, e},
             {1.5, -1, e}),
          d == 0};
}
// Static collinear a = [0, 1], b = [1 + s d, 2]: toward overlaps, away leaves a gap.
Base collinear_edges(double d, bool toward) {
  const double x = 1 + (toward ? -d : d);
  return {ee({0, 0, 0}, {1, 0, 0}, {x, 0, 0}, {2, 0, 0}, {0, 0, 0}, {1, 0, 0}, {x, 0, 0}, {2, 0, 0}),
          toward || d == 0};
}
// Grazing (catalogue's ee_grazing) at xb = 1 + s d: V = -2 (t - 1/2)^2, contact only at
// t = 1/2 where b crosses the x axis at xb: inside a for toward, outside for away.
Base grazing_ee(double d, bool toward) {
  const double xb = 1 + (toward ? -d : d);
  return {ee({-1, 0, 0}, {1, 0, 0}, {xb, -1, -0.5}, {xb, 0.5, 0.5}, {-1, 0, 0}, {1, 0, 0},
             {xb, -1, 0.5}, {xb, 1.5, -0.5}),
          toward || d == 0};
}
// b crossing a at height e rises to 1: contact at t = 0 iff e = 0; toward starts below.
Base contact_at_t0_ee(double d, bool toward) {
  const double e = toward ? -d : d;
  return {edge_vs_axis({0, -1, e}, {0, 1, e}, {0, -1, 1}, {0, 1, 1}), toward || d == 0};
}
// b falls from 1 to height e at t = 1.
Base contact_at_t1_ee(double d, bool toward) {
  const double e = toward ? -d : d;
  return {edge_vs_axis({0, -1, 1}, {0, 1, 1}, {0, -1, e}, {0, 1, e}), toward || d == 0};
}
// b is a point falling through z = 0 at (1/2, e): on a only if e = 0.
Base zero_length_edge(double d, bool toward) {
  const double e = toward ? -d : d;
  return {edge_vs_axis({0.5, e, 1}, {0.5, e, 1}, {0.5, e, -1}, {0.5, e, -1}), d == 0};
}
// Nothing moves; b crosses over a at height e: contact only if e = 0.
Base nearly_static_ee(double d, bool toward) {
  const double e = toward ? -d : d;
  return {edge_vs_axis({0, -1, e}, {0, 1, e}, {0, -1, e}, {0, 1, e}), d == 0};
}
// In z = 0 for all t: a = [0, 1] on x; b on the line x = 1 + s d slides down y (from
// [2, 3] to [-1, 0]): it reaches y = 0 at t = 2/3, on a iff x <= 1.
Base coplanar_sliding_ee(double d, bool toward) {
  const double x = 1 + (toward ? -d : d);
  return {ee({0, 0, 0}, {1, 0, 0}, {x, 2, 0}, {x, 3, 0}, {0, 0, 0}, {1, 0, 0}, {x, -1, 0}, {x, 0, 0}),
          toward || d == 0};
}

/// x + o, and whether it is exact (Knuth's TwoSum error term is zero).
double exact_sum(double x, double o, bool& exact) {
  const double s = x + o;
  const double bb = s - x;
  const double err = (x - (s - bb)) + (o - bb);
  exact = exact && err == 0;
  return s;
}

/// Applies an exact symmetry (axis permutation, sign flips), the scale 2^scale and the offset;
/// `exact` turns false if any coordinate was rounded.
template <class Query>
Query place(const Query& q, const std::array<int, 3>& axes, const std::array<double, 3>& signs,
            int scale, const std::array<double, 3>& offset, bool& exact) {
  std::array<Vec3, 8> r = rows(q);
  for (Vec3& p : r) {
    const double c[3] = {p.x, p.y, p.z};
    double out[3];
    for (int k = 0; k < 3; ++k) out[k] = exact_sum(std::ldexp(signs[k] * c[axes[k]], scale), offset[k], exact);
    p = {out[0], out[1], out[2]};
  }
  return from_rows<Query>(r);
}

/// A random placement with offsets of magnitude 2^e, e in [min_offset_exponent,
/// max_offset_exponent], times an integer in [-8, 8].
Instance randomly_placed(const Base& base, std::mt19937_64& rng, int min_offset_exponent,
                         int max_offset_exponent) {
  std::array<int, 3> axes = {0, 1, 2};
  std::shuffle(axes.begin(), axes.end(), rng);
  std::uniform_int_distribution<int> coin(0, 1), scale(-4, 4), offset(-8, 8),
      exponent(min_offset_exponent, max_offset_exponent);
  const std::array<double, 3> signs = {coin(rng) ? 1.0 : -1.0, coin(rng) ? 1.0 : -1.0, coin(rng) ? 1.0 : -1.0};
  std::array<double, 3> shift;
  for (double& o : shift) o = std::ldexp(offset(rng), exponent(rng));
  const int s = scale(rng);
  bool exact = true;
  Instance out;
  std::visit([&](const auto& q) { out.query = place(q, axes, signs, s, shift, exact); }, base.query);
  if (exact) out.expected = base.expected;
  return out;
}

/// How many coordinates differ between two queries, if each differs by exactly +-d; -1 if
/// some coordinate differs by anything else (the perturbation was rounded).
int perturbed_coordinates(const AnyQuery& base, const AnyQuery& moved, double d) {
  const auto a = std::visit([](const auto& q) { return rows(q); }, base);
  const auto b = std::visit([](const auto& q) { return rows(q); }, moved);
  int count = 0;
  for (int i = 0; i < 8; ++i)
    for (const auto& [x, y] : {std::pair{a[i].x, b[i].x}, {a[i].y, b[i].y}, {a[i].z, b[i].z}}) {
      if (x == y) continue;
      if (std::fabs(y - x) != d) return -1;  // nearby doubles: the difference is exact
      ++count;
    }
  return count;
}

template <Base (*Make)(double, bool), int MinOffsetExponent = 0, int MaxOffsetExponent = 0>
Instance generate(int k, bool toward, std::mt19937_64& rng) {
  const double d = k == kUnperturbed ? 0.0 : std::ldexp(1.0, -k);
  Base base = Make(d, toward);
  if (d != 0) {
    // The construction's answer holds only if every coordinate it perturbs moved by exactly d,
    // as at a coarse d (2^-10) where nothing can round.
    const Base still = Make(0, toward);
    const double coarse = 0x1p-10;
    const int expected_moves = perturbed_coordinates(still.query, Make(coarse, toward).query, coarse);
    if (perturbed_coordinates(still.query, base.query, d) != expected_moves) base.expected.reset();
  }
  return randomly_placed(base, rng, MinOffsetExponent, MaxOffsetExponent);
}

}  // namespace

const std::vector<Family>& all_families() {
  static const std::vector<Family> families = {
      {"vf_vertex_through_vertex", true, generate<vertex_through_vertex>},
      {"vf_vertex_through_edge", true, generate<vertex_through_edge>},
      {"vf_coplanar_sliding", true, generate<coplanar_sliding_vf>},
      {"vf_grazing", true, generate<grazing_vf>},
      {"vf_contact_at_t0", true, generate<contact_at_t0_vf>},
      {"vf_contact_at_t1", true, generate<contact_at_t1_vf>},
      {"vf_degenerate_triangle", true, generate<degenerate_triangle>},
      {"vf_nearly_static", true, generate<nearly_static_vf>},
      {"vf_large_offset", true, generate<vertex_through_edge, 20, 60>},
      {"ee_edge_through_endpoint", false, generate<edge_through_endpoint>},
      {"ee_parallel", false, generate<parallel_edges>},
      {"ee_collinear", false, generate<collinear_edges>},
      {"ee_grazing", false, generate<grazing_ee>},
      {"ee_contact_at_t0", false, generate<contact_at_t0_ee>},
      {"ee_contact_at_t1", false, generate<contact_at_t1_ee>},
      {"ee_zero_length_edge", false, generate<zero_length_edge>},
      {"ee_nearly_static", false, generate<nearly_static_ee>},
      {"ee_coplanar_sliding", false, generate<coplanar_sliding_ee>},
      {"ee_large_offset", false, generate<edge_through_endpoint, 20, 60>},
  };
  return families;
}

const Family* find_family(const std::string& name) {
  for (const Family& f : all_families())
    if (f.name == name) return &f;
  return nullptr;
}

Instance random_instance(std::mt19937_64& rng, std::optional<bool> vertex_face) {
  std::vector<const Family*> pool;
  for (const Family& f : all_families())
    if (!vertex_face || f.vertex_face == *vertex_face) pool.push_back(&f);
  std::uniform_int_distribution<std::size_t> pick(0, pool.size() - 1);
  std::uniform_int_distribution<int> k(-1, 60), coin(0, 1);
  return pool[pick(rng)]->make(k(rng), coin(rng) == 1, rng);
}

}  // namespace exactccd::families
