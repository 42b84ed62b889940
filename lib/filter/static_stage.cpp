#include "filter/static_stage.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace exactccd::filter {
namespace {

// Only predicates on the input points are used (no constructed line, vector or plane, which
// Epick would round): every test below is exact.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

Point point(const Vec3& v) { return {v.x, v.y, v.z}; }

int sign(CGAL::Orientation o) { return static_cast<int>(o); }

bool same(const Vec3& u, const Vec3& v) { return u.x == v.x && u.y == v.y && u.z == v.z; }

/// p on the closed segment [s, e] (a point when s == e). CGAL's collinear_are_ordered_along_line
/// (s, p, e) is true iff p lies between s and e on their common line, also when s == e.
bool on_segment(const Point& p, const Point& s, const Point& e) {
  return CGAL::collinear(s, e, p) && CGAL::collinear_are_ordered_along_line(s, p, e);
}

/// The closed segments [p0, p1] and [q0, q1] share a point; all four points coplanar, neither
/// segment degenerate. With o(x, y, z) the coplanar orientation (a 2D orientation in the common
/// plane, coherent over all triples of that plane; CGAL's coplanar_orientation), the segments
/// meet iff each one's endpoints are not strictly on one side of the other's line, unless all
/// four points are collinear; then iff an endpoint of one lies on the other.
bool coplanar_segments_meet(const Point& p0, const Point& p1, const Point& q0, const Point& q1) {
  const CGAL::Orientation o1 = CGAL::coplanar_orientation(p0, p1, q0);
  const CGAL::Orientation o2 = CGAL::coplanar_orientation(p0, p1, q1);
  if (o1 == CGAL::COLLINEAR && o2 == CGAL::COLLINEAR)
    return CGAL::collinear_are_ordered_along_line(p0, q0, p1) ||
           CGAL::collinear_are_ordered_along_line(p0, q1, p1) ||
           CGAL::collinear_are_ordered_along_line(q0, p0, q1);
  if (sign(o1) * sign(o2) > 0) return false;
  const CGAL::Orientation o3 = CGAL::coplanar_orientation(q0, q1, p0);
  const CGAL::Orientation o4 = CGAL::coplanar_orientation(q0, q1, p1);
  return sign(o3) * sign(o4) <= 0;
}

}  // namespace

bool is_static(const VertexFaceQuery& q) {
  return same(q.p_t0, q.p_t1) && same(q.a_t0, q.a_t1) && same(q.b_t0, q.b_t1) && same(q.c_t0, q.c_t1);
}

bool is_static(const EdgeEdgeQuery& q) {
  return same(q.a0_t0, q.a0_t1) && same(q.a1_t0, q.a1_t1) && same(q.b0_t0, q.b0_t1) &&
         same(q.b1_t0, q.b1_t1);
}

bool contact_at_end(const VertexFaceQuery& q, int end) {
  const Point p = point(end ? q.p_t1 : q.p_t0), a = point(end ? q.a_t1 : q.a_t0),
              b = point(end ? q.b_t1 : q.b_t0), c = point(end ? q.c_t1 : q.c_t0);
  if (CGAL::orientation(a, b, c, p) != CGAL::COPLANAR) return false;
  if (!CGAL::collinear(a, b, c)) {
    // Proper triangle, p in its plane: p is in the closed triangle iff, for each edge, p is not
    // strictly on the side opposite to the third vertex (coplanar_orientation(x, y, z, p) is
    // NEGATIVE exactly then).
    return CGAL::coplanar_orientation(a, b, c, p) != CGAL::NEGATIVE &&
           CGAL::coplanar_orientation(b, c, a, p) != CGAL::NEGATIVE &&
           CGAL::coplanar_orientation(c, a, b, p) != CGAL::NEGATIVE;
  }
  // Collinear or coincident vertices: the hull is the union of the three closed segments.
  return on_segment(p, a, b) || on_segment(p, b, c) || on_segment(p, c, a);
}

bool contact_at_end(const EdgeEdgeQuery& q, int end) {
  const Point p0 = point(end ? q.a0_t1 : q.a0_t0), p1 = point(end ? q.a1_t1 : q.a1_t0),
              q0 = point(end ? q.b0_t1 : q.b0_t0), q1 = point(end ? q.b1_t1 : q.b1_t0);
  const bool a_point = p0 == p1, b_point = q0 == q1;
  if (a_point) return on_segment(p0, q0, q1);
  if (b_point) return on_segment(q0, p0, p1);
  if (CGAL::orientation(p0, p1, q0, q1) != CGAL::COPLANAR) return false;
  return coplanar_segments_meet(p0, p1, q0, q1);
}

// CGAL's orientation(p, q, r, s) is the sign of det[q - p, r - p, s - p], and
// det[u, v, w] = u . (v x w): V = (b - a) . ((c - a) x (p - a)) = det[b - a, c - a, p - a] is
// orientation(a, b, c, p); V = (a1 - a0) . ((b0 - a0) x (b1 - a0)) is orientation(a0, a1, b0, b1).
int volume_sign_at_end(const VertexFaceQuery& q, int end) {
  return static_cast<int>(CGAL::orientation(point(end ? q.a_t1 : q.a_t0), point(end ? q.b_t1 : q.b_t0),
                                            point(end ? q.c_t1 : q.c_t0), point(end ? q.p_t1 : q.p_t0)));
}

int volume_sign_at_end(const EdgeEdgeQuery& q, int end) {
  return static_cast<int>(CGAL::orientation(point(end ? q.a0_t1 : q.a0_t0), point(end ? q.a1_t1 : q.a1_t0),
                                            point(end ? q.b0_t1 : q.b0_t0), point(end ? q.b1_t1 : q.b1_t0)));
}

}  // namespace exactccd::filter
