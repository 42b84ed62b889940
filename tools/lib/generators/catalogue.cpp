// The hand-derived degenerate catalogue. Each case states its motion, where the volume V(t)
// vanishes and why the primitives do or do not touch there. Coordinates are written as
// doubles that are exact binary fractions (0.25, 0x1p-52, ...), converted exactly to mpq_class.
#include "generators/catalogue.hpp"

#include <cmath>
#include <functional>

namespace exactccd::catalogue {
namespace {

RationalVec3 P(double x, double y, double z) { return {mpq_class(x), mpq_class(y), mpq_class(z)}; }

mpq_class Q(long num, long den = 1) { return mpq_class(num, den); }

VertexFaceEntry vf(std::string name, std::string category, RationalVertexFaceQuery q, bool collides,
                   std::optional<mpq_class> toi = std::nullopt) {
  return {std::move(name), std::move(category), std::move(q), collides, std::move(toi), {}};
}

EdgeEdgeEntry ee(std::string name, std::string category, RationalEdgeEdgeQuery q, bool collides,
                 std::optional<mpq_class> toi = std::nullopt) {
  return {std::move(name), std::move(category), std::move(q), collides, std::move(toi), {}};
}

// The unit right triangle a = (0,0,0), b = (1,0,0), c = (0,1,0), static, in the plane z = 0.
// Its closed hull is {x >= 0, y >= 0, x + y <= 1, z = 0}.
RationalVertexFaceQuery point_vs_unit_triangle(const RationalVec3& p0, const RationalVec3& p1) {
  return {p0, P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), p1, P(0, 0, 0), P(1, 0, 0), P(0, 1, 0)};
}

// The static edge a = [(-1,0,0), (1,0,0)] on the x axis.
RationalEdgeEdgeQuery edge_vs_x_axis(const RationalVec3& b0_t0, const RationalVec3& b1_t0,
                                     const RationalVec3& b0_t1, const RationalVec3& b1_t1) {
  return {P(-1, 0, 0), P(1, 0, 0), b0_t0, b1_t0, P(-1, 0, 0), P(1, 0, 0), b0_t1, b1_t1};
}

}  // namespace

std::vector<VertexFaceEntry> vertex_face_base_cases() {
  std::vector<VertexFaceEntry> c;
  // For a static triangle in z = 0, V(t) is a positive multiple of p_z(t), so the only
  // candidate time is where p crosses z = 0; there p must lie in the closed triangle.

  // p = (1/4, 1/4, 1 - 2t): z = 0 at t = 1/2, p = (1/4, 1/4, 0): barycentrics (1/2, 1/4, 1/4).
  c.push_back(vf("vf_interior_fall", "vertex_through_interior",
                 point_vs_unit_triangle(P(0.25, 0.25, 1), P(0.25, 0.25, -1)), true, Q(1, 2)));
  // p = (0, 0, 1 - 3t): z = 0 at t = 1/3, p = (0,0,0) = a, a vertex of the closed triangle.
  c.push_back(vf("vf_through_vertex_a", "vertex_through_vertex",
                 point_vs_unit_triangle(P(0, 0, 1), P(0, 0, -2)), true, Q(1, 3)));
  // p = (1, 0, 1 - 2t): z = 0 at t = 1/2 at b.
  c.push_back(vf("vf_through_vertex_b", "vertex_through_vertex",
                 point_vs_unit_triangle(P(1, 0, 1), P(1, 0, -1)), true, Q(1, 2)));
  // p = (1/2, 0, 1 - 2t): z = 0 at t = 1/2 at (1/2, 0, 0), on edge ab (y = 0).
  c.push_back(vf("vf_through_edge_ab", "vertex_through_edge",
                 point_vs_unit_triangle(P(0.5, 0, 1), P(0.5, 0, -1)), true, Q(1, 2)));
  // p = (1/2, 1/2, 1 - 2t): at t = 1/2, (1/2, 1/2, 0) has x + y = 1: on edge bc.
  c.push_back(vf("vf_through_edge_bc", "vertex_through_edge",
                 point_vs_unit_triangle(P(0.5, 0.5, 1), P(0.5, 0.5, -1)), true, Q(1, 2)));
  // p = (1/2, -2^-20, 1 - 2t): at t = 1/2, y = -2^-20 < 0: just outside edge ab.
  c.push_back(vf("vf_just_outside_edge_ab", "vertex_through_edge",
                 point_vs_unit_triangle(P(0.5, -0x1p-20, 1), P(0.5, -0x1p-20, -1)), false));
  // p = (1/2, 1/2 + 2^-40, 1 - 2t): at t = 1/2, x + y = 1 + 2^-40 > 1: just outside bc.
  c.push_back(vf("vf_just_outside_edge_bc", "vertex_through_edge",
                 point_vs_unit_triangle(P(0.5, 0.5 + 0x1p-40, 1), P(0.5, 0.5 + 0x1p-40, -1)), false));
  // p = (-2^-52, -2^-52, 1 - 2t): at t = 1/2 just outside vertex a.
  c.push_back(vf("vf_just_outside_vertex_a", "vertex_through_vertex",
                 point_vs_unit_triangle(P(-0x1p-52, -0x1p-52, 1), P(-0x1p-52, -0x1p-52, -1)), false));
  // p = (2, 2, 1 - 2t): crosses the plane at (2, 2, 0), far outside.
  c.push_back(vf("vf_beside_triangle", "no_contact",
                 point_vs_unit_triangle(P(2, 2, 1), P(2, 2, -1)), false));
  // p_z = 1 - t (1 - 2^-30) > 0 on [0, 1]: p stops 2^-30 above the interior.
  c.push_back(vf("vf_stops_short", "no_contact",
                 point_vs_unit_triangle(P(0.25, 0.25, 1), P(0.25, 0.25, 0x1p-30)), false));
  // p_z = 1 - t: reaches z = 0 exactly at t = 1, inside.
  c.push_back(vf("vf_contact_at_t1", "contact_at_t1",
                 point_vs_unit_triangle(P(0.25, 0.25, 1), P(0.25, 0.25, 0)), true, Q(1)));
  // p_z(1) = 2^-52 > 0: the contact would come just after t = 1.
  c.push_back(vf("vf_just_misses_at_t1", "contact_at_t1",
                 point_vs_unit_triangle(P(0.25, 0.25, 1), P(0.25, 0.25, 0x1p-52)), false));
  // p starts in the triangle (z = 0 at t = 0) and leaves upwards.
  c.push_back(vf("vf_contact_at_t0", "contact_at_t0",
                 point_vs_unit_triangle(P(0.25, 0.25, 0), P(0.25, 0.25, 1)), true, Q(0)));
  // p starts on vertex a and leaves along (1, 1, 1).
  c.push_back(vf("vf_contact_at_t0_on_vertex", "contact_at_t0",
                 point_vs_unit_triangle(P(0, 0, 0), P(1, 1, 1)), true, Q(0)));
  // Nothing moves; p = (1/4, 1/4, 0) lies in the triangle for all t: TOI 0.
  c.push_back(vf("vf_static_touching", "static",
                 point_vs_unit_triangle(P(0.25, 0.25, 0), P(0.25, 0.25, 0)), true, Q(0)));
  // Nothing moves; p = (1/4, 1/4, 1) is always 1 above the plane.
  c.push_back(vf("vf_static_apart", "static",
                 point_vs_unit_triangle(P(0.25, 0.25, 1), P(0.25, 0.25, 1)), false));

  // Grazing (double root). a = (0,0,0), b = (1,0,0) static, c(t) = (0, 1, 1 - 2t),
  // p(t) = (px, 1/4 + t/2, 1/2 - t). n = (b - a) x (c - a) = (0, -(1 - 2t), 1) and
  // V = n . p = -(1 - 2t)(1/4 + t/2) + 1/2 - t = t^2 - t + 1/4 = (t - 1/2)^2 >= 0:
  // coplanar only at t = 1/2, where the triangle is the unit triangle and p = (px, 1/2, 0).
  // Inside iff 0 <= px <= 1/2.
  const auto grazing = [](double px) {
    return RationalVertexFaceQuery{P(px, 0.25, 0.5), P(0, 0, 0), P(1, 0, 0), P(0, 1, 1),
                                   P(px, 0.75, -0.5), P(0, 0, 0), P(1, 0, 0), P(0, 1, -1)};
  };
  c.push_back(vf("vf_grazing_inside", "grazing", grazing(0.25), true, Q(1, 2)));
  c.push_back(vf("vf_grazing_on_edge", "grazing", grazing(0.5), true, Q(1, 2)));
  c.push_back(vf("vf_grazing_outside", "grazing", grazing(0.75), false));

  // Coplanar for all t (everything in z = 0, V = 0 identically): in-plane motion.
  // p = (2 - 3t, 1/4, 0) enters the triangle through bc (x + y <= 1) at 2 - 3t = 3/4: t = 5/12.
  c.push_back(vf("vf_coplanar_slide_into", "coplanar_sliding",
                 point_vs_unit_triangle(P(2, 0.25, 0), P(-1, 0.25, 0)), true, Q(5, 12)));
  // p = (2 - 3t, 2, 0): y = 2 > 1 always: slides beside the triangle, never in it.
  c.push_back(vf("vf_coplanar_slide_beside", "coplanar_sliding",
                 point_vs_unit_triangle(P(2, 2, 0), P(-1, 2, 0)), false));
  // p starts inside (t = 0) and slides out: TOI 0.
  c.push_back(vf("vf_coplanar_start_inside", "coplanar_sliding",
                 point_vs_unit_triangle(P(0.25, 0.25, 0), P(5, 5, 0)), true, Q(0)));
  // The triangle slides: a = (s,0,0), b = (s+1,0,0), c = (s,1,0), s = -2 + 3t; p = (1/2, 1/4, 0).
  // Inside iff 1/2 - s >= 0 and (1/2 - s) + 1/4 <= 1: s in [-1/4, 1/2]; first at
  // s = -1/4: t = 7/12.
  c.push_back(vf("vf_coplanar_triangle_sweeps_over_point", "coplanar_sliding",
                 {P(0.5, 0.25, 0), P(-2, 0, 0), P(-1, 0, 0), P(-2, 1, 0),
                  P(0.5, 0.25, 0), P(1, 0, 0), P(2, 0, 0), P(1, 1, 0)},
                 true, Q(7, 12)));

  // Degenerate triangles: the hull is a segment or a point (n = 0, V = 0 for all t).
  // Collinear a = (0,0,0), b = (1,0,0), c = (2,0,0): hull = [0, 2] on the x axis.
  const auto collinear = [](const RationalVec3& p0, const RationalVec3& p1) {
    return RationalVertexFaceQuery{p0, P(0, 0, 0), P(1, 0, 0), P(2, 0, 0),
                                   p1, P(0, 0, 0), P(1, 0, 0), P(2, 0, 0)};
  };
  // p = (1/2, 0, 1 - 2t) is on the x axis at t = 1/2, at x = 1/2 in [0, 2].
  c.push_back(vf("vf_collinear_triangle_hit", "degenerate_triangle",
                 collinear(P(0.5, 0, 1), P(0.5, 0, -1)), true, Q(1, 2)));
  // p = (3/2, 0, 1 - 2t): x = 3/2 lies between b and c: still the hull.
  c.push_back(vf("vf_collinear_triangle_hit_beyond_b", "degenerate_triangle",
                 collinear(P(1.5, 0, 1), P(1.5, 0, -1)), true, Q(1, 2)));
  // p = (1/2, 1/8, 1 - 2t): y = 1/8 is never 0, so p is never on the x axis.
  c.push_back(vf("vf_collinear_triangle_miss", "degenerate_triangle",
                 collinear(P(0.5, 0.125, 1), P(0.5, 0.125, -1)), false));
  // p = (3, 0, 1 - 2t): on the axis at t = 1/2 but x = 3 > 2.
  c.push_back(vf("vf_collinear_triangle_miss_beyond_end", "degenerate_triangle",
                 collinear(P(3, 0, 1), P(3, 0, -1)), false));
  // a = b = (0,0,0), c = (1,1,0): hull = segment from the origin to (1,1,0).
  // p = (1/2, 1/2, 1 - 2t) reaches its midpoint at t = 1/2.
  c.push_back(vf("vf_coincident_vertices_hit", "degenerate_triangle",
                 {P(0.5, 0.5, 1), P(0, 0, 0), P(0, 0, 0), P(1, 1, 0),
                  P(0.5, 0.5, -1), P(0, 0, 0), P(0, 0, 0), P(1, 1, 0)},
                 true, Q(1, 2)));
  // p = (1/2, 3/8, 1 - 2t): at z = 0, (1/2, 3/8) is off the diagonal.
  c.push_back(vf("vf_coincident_vertices_miss", "degenerate_triangle",
                 {P(0.5, 0.375, 1), P(0, 0, 0), P(0, 0, 0), P(1, 1, 0),
                  P(0.5, 0.375, -1), P(0, 0, 0), P(0, 0, 0), P(1, 1, 0)},
                 false));
  // a = b = c = (1,1,1): the hull is that point. p = (2t, 2t, 2t) passes it at t = 1/2.
  c.push_back(vf("vf_point_triangle_hit", "degenerate_triangle",
                 {P(0, 0, 0), P(1, 1, 1), P(1, 1, 1), P(1, 1, 1),
                  P(2, 2, 2), P(1, 1, 1), P(1, 1, 1), P(1, 1, 1)},
                 true, Q(1, 2)));
  // p = (2t, 2t, 5t/2) equals (1,1,1) only if t = 1/2 and t = 2/5: never.
  c.push_back(vf("vf_point_triangle_miss", "degenerate_triangle",
                 {P(0, 0, 0), P(1, 1, 1), P(1, 1, 1), P(1, 1, 1),
                  P(2, 2, 2.5), P(1, 1, 1), P(1, 1, 1), P(1, 1, 1)},
                 false));

  // Subnormal gap: p_z = 1 - t (1 - 2^-1074) stays >= 2^-1074 > 0: never touches.
  c.push_back(vf("vf_subnormal_gap_at_t1", "subnormal",
                 point_vs_unit_triangle(P(0.25, 0.25, 1), P(0.25, 0.25, 0x1p-1074)), false));
  // p_z = 2^-1074 (1 - 2t): crosses z = 0 at t = 1/2 inside (a subnormal-only motion).
  c.push_back(vf("vf_subnormal_crossing", "subnormal",
                 point_vs_unit_triangle(P(0.25, 0.25, 0x1p-1074), P(0.25, 0.25, -0x1p-1074)), true,
                 Q(1, 2)));

  // An irrational TOI. a = 0 static, b = (2,1,1) -> (-1,-1,3), c = (-2,-3,0) -> (-3,-3,1),
  // p = (-2,-1,2) -> (3,-1,-1). V = det[b; c; p] = -4 t^3 + 16 t^2 + 32 t - 12, irreducible
  // over Q (no rational root p/q with p | 12, q | 4 is a root), one root in [0, 1]:
  // r = 0.32614985735855..., where p = beta b + gamma c with beta = 0.5401..., gamma = 0.3959...,
  // 1 - beta - gamma = 0.0639... > 0 (computed with exact rationals and bisection to 2^-80):
  // inside.
  VertexFaceEntry irrational =
      vf("vf_irrational_toi", "irrational_root",
         {P(-2, -1, 2), P(0, 0, 0), P(2, 1, 1), P(-2, -3, 0), P(3, -1, -1), P(0, 0, 0), P(-1, -1, 3),
          P(-3, -3, 1)},
         true);
  irrational.toi_polynomial = {Q(-12, 1), Q(32, 1), Q(16, 1), Q(-4, 1)};
  c.push_back(std::move(irrational));
  return c;
}

std::vector<EdgeEdgeEntry> edge_edge_base_cases() {
  std::vector<EdgeEdgeEntry> c;
  // Edge a on the x axis, [-1, 1]; edge b parallel to the y axis at height z(t).
  // V is a multiple of z(t) (a and b span the x and y directions), so contact needs z = 0.
  // b = [(0,-1,z), (0,1,z)], z = 1 - 2t: at t = 1/2 the edges cross at the origin.
  c.push_back(ee("ee_crossing", "crossing",
                 edge_vs_x_axis(P(0, -1, 1), P(0, 1, 1), P(0, -1, -1), P(0, 1, -1)), true, Q(1, 2)));
  // z = 1 - 3t: crossing at t = 1/3.
  c.push_back(ee("ee_crossing_at_third", "crossing",
                 edge_vs_x_axis(P(0.5, -1, 1), P(0.5, 1, 1), P(0.5, -1, -2), P(0.5, 1, -2)), true,
                 Q(1, 3)));
  // b at x = 2: when z = 0 it crosses the x axis at x = 2, beyond a's end at 1.
  c.push_back(ee("ee_pass_beside", "no_contact",
                 edge_vs_x_axis(P(2, -1, 1), P(2, 1, 1), P(2, -1, -1), P(2, 1, -1)), false));
  // b at x = 1: crosses exactly through a's endpoint (1, 0, 0) at t = 1/2.
  c.push_back(ee("ee_through_endpoint", "edge_through_endpoint",
                 edge_vs_x_axis(P(1, -1, 1), P(1, 1, 1), P(1, -1, -1), P(1, 1, -1)), true, Q(1, 2)));
  // b at x = 1 + 2^-52: misses a's endpoint by one ulp.
  c.push_back(ee("ee_misses_endpoint_by_ulp", "edge_through_endpoint",
                 edge_vs_x_axis(P(1 + 0x1p-52, -1, 1), P(1 + 0x1p-52, 1, 1), P(1 + 0x1p-52, -1, -1),
                                P(1 + 0x1p-52, 1, -1)),
                 false));
  // b = [(0,0,z), (0,1,z)], z = 1 - 2t: V = -2z; at t = 1/2 b0 = (0,0,0) touches a's
  // interior (a T-junction).
  c.push_back(ee("ee_t_junction", "edge_through_endpoint",
                 edge_vs_x_axis(P(0, 0, 1), P(0, 1, 1), P(0, 0, -1), P(0, 1, -1)), true, Q(1, 2)));
  // b = [(1,0,z), (2,1,z)], a = [(0,0,0), (1,0,0)]: V = -z, coplanar only at z = 0 (t = 1/2)
  // where b0 = (1,0,0) = a1: endpoint to endpoint.
  c.push_back(ee("ee_endpoint_to_endpoint", "edge_through_endpoint",
                 {P(0, 0, 0), P(1, 0, 0), P(1, 0, 1), P(2, 1, 1), P(0, 0, 0), P(1, 0, 0), P(1, 0, -1),
                  P(2, 1, -1)},
                 true, Q(1, 2)));
  // Same with b0 = (1 + 2^-52, 0, z): at z = 0, b has y >= 0 with y = 0 only at x = 1 + 2^-52.
  c.push_back(ee("ee_endpoint_misses_endpoint", "edge_through_endpoint",
                 {P(0, 0, 0), P(1, 0, 0), P(1 + 0x1p-52, 0, 1), P(2, 1, 1), P(0, 0, 0), P(1, 0, 0),
                  P(1 + 0x1p-52, 0, -1), P(2, 1, -1)},
                 false));

  // Parallel and collinear edges (w = da x db = 0), all in z = 0 (V = 0 for all t).
  // a = [(0,0,0), (1,0,0)], b = [(0,1,0), (1,1,0)]: parallel, 1 apart, static.
  c.push_back(ee("ee_parallel_static_apart", "parallel",
                 {P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(1, 1, 0), P(0, 0, 0), P(1, 0, 0), P(0, 1, 0),
                  P(1, 1, 0)},
                 false));
  // b = [(1/2, y, 0), (3/2, y, 0)], y = 1 - 2t: collinear with a at t = 1/2, overlapping [1/2, 1].
  c.push_back(ee("ee_parallel_becoming_collinear_overlap", "parallel",
                 {P(0, 0, 0), P(1, 0, 0), P(0.5, 1, 0), P(1.5, 1, 0), P(0, 0, 0), P(1, 0, 0),
                  P(0.5, -1, 0), P(1.5, -1, 0)},
                 true, Q(1, 2)));
  // b = [(2, y, 0), (3, y, 0)]: collinear at t = 1/2 but [2, 3] and [0, 1] are disjoint.
  c.push_back(ee("ee_parallel_becoming_collinear_disjoint", "parallel",
                 {P(0, 0, 0), P(1, 0, 0), P(2, 1, 0), P(3, 1, 0), P(0, 0, 0), P(1, 0, 0), P(2, -1, 0),
                  P(3, -1, 0)},
                 false));
  // Parallel in 3-D at distance 1 (b at z = 1), static: not coplanar.
  c.push_back(ee("ee_parallel_skew_static", "parallel",
                 {P(0, 0, 0), P(1, 0, 0), P(0, 0, 1), P(1, 0, 1), P(0, 0, 0), P(1, 0, 0), P(0, 0, 1),
                  P(1, 0, 1)},
                 false));
  // Collinear overlapping, static: [0, 2] and [1, 3] share [1, 2] at t = 0.
  c.push_back(ee("ee_collinear_overlap_static", "collinear",
                 {P(0, 0, 0), P(2, 0, 0), P(1, 0, 0), P(3, 0, 0), P(0, 0, 0), P(2, 0, 0), P(1, 0, 0),
                  P(3, 0, 0)},
                 true, Q(0)));
  // Collinear disjoint, static: [0, 1] and [2, 3].
  c.push_back(ee("ee_collinear_disjoint_static", "collinear",
                 {P(0, 0, 0), P(1, 0, 0), P(2, 0, 0), P(3, 0, 0), P(0, 0, 0), P(1, 0, 0), P(2, 0, 0),
                  P(3, 0, 0)},
                 false));
  // Collinear touching end to end, static: [0, 1] and [1, 2] share x = 1.
  c.push_back(ee("ee_collinear_touching_static", "collinear",
                 {P(0, 0, 0), P(1, 0, 0), P(1, 0, 0), P(2, 0, 0), P(0, 0, 0), P(1, 0, 0), P(1, 0, 0),
                  P(2, 0, 0)},
                 true, Q(0)));
  // Collinear sliding: b = [3 - 4t, 4 - 4t] on the x axis reaches a's end x = 1 at t = 1/2.
  c.push_back(ee("ee_collinear_sliding_into_contact", "collinear",
                 {P(0, 0, 0), P(1, 0, 0), P(3, 0, 0), P(4, 0, 0), P(0, 0, 0), P(1, 0, 0), P(-1, 0, 0),
                  P(0, 0, 0)},
                 true, Q(1, 2)));

  // Coplanar for all t (z = 0), not parallel: b = [(1/2, 2 - 3t), (1/2, 3 - 3t)] slides down
  // the line x = 1/2 onto a = [(0,0), (1,0)]; it contains y = 0 once 2 - 3t <= 0: t = 2/3.
  c.push_back(ee("ee_coplanar_slide_into", "coplanar_sliding",
                 {P(0, 0, 0), P(1, 0, 0), P(0.5, 2, 0), P(0.5, 3, 0), P(0, 0, 0), P(1, 0, 0),
                  P(0.5, -1, 0), P(0.5, 0, 0)},
                 true, Q(2, 3)));
  // The same at x = 3/2: the line x = 3/2 misses a = [0, 1].
  c.push_back(ee("ee_coplanar_slide_beside", "coplanar_sliding",
                 {P(0, 0, 0), P(1, 0, 0), P(1.5, 2, 0), P(1.5, 3, 0), P(0, 0, 0), P(1, 0, 0),
                  P(1.5, -1, 0), P(1.5, 0, 0)},
                 false));

  // Zero-length edges (points).
  // b = the point (1/2, 0, 1 - 2t): on a at t = 1/2.
  c.push_back(ee("ee_point_hits_edge", "zero_length_edge",
                 edge_vs_x_axis(P(0.5, 0, 1), P(0.5, 0, 1), P(0.5, 0, -1), P(0.5, 0, -1)), true,
                 Q(1, 2)));
  // b = the point (1/2, 1/8, 1 - 2t): never on the x axis.
  c.push_back(ee("ee_point_misses_edge", "zero_length_edge",
                 edge_vs_x_axis(P(0.5, 0.125, 1), P(0.5, 0.125, 1), P(0.5, 0.125, -1),
                                P(0.5, 0.125, -1)),
                 false));
  // Both points: a = origin, b = (1 - 2t)(1, 1, 1): equal at t = 1/2.
  c.push_back(ee("ee_points_meet", "zero_length_edge",
                 {P(0, 0, 0), P(0, 0, 0), P(1, 1, 1), P(1, 1, 1), P(0, 0, 0), P(0, 0, 0), P(-1, -1, -1),
                  P(-1, -1, -1)},
                 true, Q(1, 2)));
  // b = (1 - 2t, 1 - 2t, 1 - 1.5t): zero needs t = 1/2 and t = 2/3: never.
  c.push_back(ee("ee_points_miss", "zero_length_edge",
                 {P(0, 0, 0), P(0, 0, 0), P(1, 1, 1), P(1, 1, 1), P(0, 0, 0), P(0, 0, 0), P(-1, -1, -0.5),
                  P(-1, -1, -0.5)},
                 false));

  // Contact at the ends of the step.
  // b crosses a at the origin at t = 0 (z = t).
  c.push_back(ee("ee_contact_at_t0", "contact_at_t0",
                 edge_vs_x_axis(P(0, -1, 0), P(0, 1, 0), P(0, -1, 1), P(0, 1, 1)), true, Q(0)));
  // z = 1 - t: crossing at t = 1.
  c.push_back(ee("ee_contact_at_t1", "contact_at_t1",
                 edge_vs_x_axis(P(0, -1, 1), P(0, 1, 1), P(0, -1, 0), P(0, 1, 0)), true, Q(1)));
  // z(1) = 2^-52 > 0: would cross just after t = 1.
  c.push_back(ee("ee_just_misses_at_t1", "contact_at_t1",
                 edge_vs_x_axis(P(0, -1, 1), P(0, 1, 1), P(0, -1, 0x1p-52), P(0, 1, 0x1p-52)), false));
  // Nothing moves: crossing at the origin for all t (TOI 0), and skew (z = 1) never.
  c.push_back(ee("ee_static_crossing", "static",
                 edge_vs_x_axis(P(0, -1, 0), P(0, 1, 0), P(0, -1, 0), P(0, 1, 0)), true, Q(0)));
  c.push_back(ee("ee_static_skew", "static",
                 edge_vs_x_axis(P(0, -1, 1), P(0, 1, 1), P(0, -1, 1), P(0, 1, 1)), false));

  // Grazing (double root). a = [(-1,0,0), (1,0,0)]; b0 = (xb, -1, t - 1/2),
  // b1 = (xb, t + 1/2, 1/2 - t). With r = b0 - a0, s = b1 - a0:
  // V = 2 (r_y s_z - r_z s_y) = 2 (-(1/2 - t) - (t - 1/2)(t + 1/2)) = -2 (t - 1/2)^2:
  // coplanar only at t = 1/2, where b = [(xb,-1,0), (xb,1,0)] crosses the x axis at x = xb.
  const auto grazing = [](double xb) {
    return RationalEdgeEdgeQuery{P(-1, 0, 0), P(1, 0, 0), P(xb, -1, -0.5), P(xb, 0.5, 0.5),
                                 P(-1, 0, 0), P(1, 0, 0), P(xb, -1, 0.5), P(xb, 1.5, -0.5)};
  };
  c.push_back(ee("ee_grazing_inside", "grazing", grazing(0.5), true, Q(1, 2)));
  c.push_back(ee("ee_grazing_at_endpoint", "grazing", grazing(1), true, Q(1, 2)));
  c.push_back(ee("ee_grazing_outside", "grazing", grazing(1.5), false));

  // Subnormal: b at height z = 2^-1074 (1 - 2t) crosses a at t = 1/2.
  c.push_back(ee("ee_subnormal_crossing", "subnormal",
                 edge_vs_x_axis(P(0, -1, 0x1p-1074), P(0, 1, 0x1p-1074), P(0, -1, -0x1p-1074),
                                P(0, 1, -0x1p-1074)),
                 true, Q(1, 2)));
  // z = 1 - t (1 - 2^-1074) >= 2^-1074 > 0: never.
  c.push_back(ee("ee_subnormal_gap_at_t1", "subnormal",
                 edge_vs_x_axis(P(0, -1, 1), P(0, 1, 1), P(0, -1, 0x1p-1074), P(0, 1, 0x1p-1074)), false));

  // An irrational TOI. a0 = 0 static, a1 = (-1,-2,1) -> (-3,0,-3), b0 = (-2,3,-1) -> (-2,2,-2),
  // b1 = (0,0,3) -> (0,-3,-2). V = det[a1; b0; b1] = -4 t^3 - 4 t^2 + 41 t - 21, irreducible
  // over Q (no candidate p/q, p | 21, q | 4, is a root), one root in [0, 1]:
  // r = 0.55990426715194..., where the segments meet with alpha = 0.3201..., beta = 0.6606...
  // (exact rationals, bisection to 2^-80): collision.
  EdgeEdgeEntry irrational =
      ee("ee_irrational_toi", "irrational_root",
         {P(0, 0, 0), P(-1, -2, 1), P(-2, 3, -1), P(0, 0, 3), P(0, 0, 0), P(-3, 0, -3), P(-2, 2, -2),
          P(0, -3, -2)},
         true);
  irrational.toi_polynomial = {Q(-21, 1), Q(41, 1), Q(-4, 1), Q(-4, 1)};
  c.push_back(std::move(irrational));
  return c;
}

namespace {

/// Applies f to every coordinate; nullopt when a result is not exactly a double.
template <class Query>
std::optional<Query> transformed(const Query& q, const std::function<mpq_class(const mpq_class&)>& f) {
  std::array<RationalVec3, 8> r = rows(q);
  for (RationalVec3& p : r)
    for (mpq_class* x : {&p.x, &p.y, &p.z}) {
      *x = f(*x);
      const double d = x->get_d();
      if (!std::isfinite(d) || mpq_class(d) != *x) return std::nullopt;
    }
  return from_rows<Query>(r);
}

mpq_class power_of_two(int e) {
  mpq_class x(1);
  if (e >= 0)
    mpq_mul_2exp(x.get_mpq_t(), x.get_mpq_t(), static_cast<unsigned long>(e));
  else
    mpq_div_2exp(x.get_mpq_t(), x.get_mpq_t(), static_cast<unsigned long>(-e));
  return x;
}

/// The base cases plus their exact scaled and translated copies (the transforms return
/// mpq_class explicitly: a GMP expression template would refer to a destroyed temporary): x -> 2^e x keeps every
/// volume's sign pattern (all polynomials scale by positive powers of two), x -> x + 2^k
/// (every coordinate, both times) moves the whole scene rigidly; neither changes an answer.
template <class E>
std::vector<E> with_copies(std::vector<E> base) {
  std::vector<E> out = base;
  const auto add = [&](const E& e, const std::string& suffix, const std::string& category,
                       const std::function<mpq_class(const mpq_class&)>& f) {
    if (auto q = transformed(e.query, f)) {
      E copy = e;
      copy.name += suffix;
      copy.category = category;
      copy.query = *q;
      out.push_back(std::move(copy));
    }
  };
  for (const E& e : base) {
    if (e.category == "subnormal") continue;  // already at the bottom of the range
    add(e, "_x2^996", "huge_coordinates", [](const mpq_class& x) -> mpq_class { return x * power_of_two(996); });
    add(e, "_x2^-1060", "subnormal", [](const mpq_class& x) -> mpq_class { return x * power_of_two(-1060); });
    add(e, "_plus2^20", "large_offset", [](const mpq_class& x) -> mpq_class { return x + power_of_two(20); });
    add(e, "_plus2^40", "large_offset", [](const mpq_class& x) -> mpq_class { return x + power_of_two(40); });
  }
  return out;
}

}  // namespace

std::vector<VertexFaceEntry> vertex_face_cases() { return with_copies(vertex_face_base_cases()); }

std::vector<EdgeEdgeEntry> edge_edge_cases() { return with_copies(edge_edge_base_cases()); }

}  // namespace exactccd::catalogue
