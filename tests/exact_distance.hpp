// The independent exact distance of the minimum-separation tests: CGAL's squared distances
// between Point_3 / Segment_3 / Triangle_3 with rational coordinates (Simple_cartesian<mpq_class>),
// which share no code with the library's separation stages. Degenerate primitives are their
// hulls. Used by tests/separation/test_min_separation_properties.cpp and
// tests/datasets/test_separation_families.cpp (both link CGAL::CGAL).
#pragma once

#include <CGAL/Simple_cartesian.h>
#include <CGAL/gmpxx.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>

namespace exactccd::testing {

using ExactKernel = CGAL::Simple_cartesian<mpq_class>;
using P3 = ExactKernel::Point_3;
using S3 = ExactKernel::Segment_3;
using T3 = ExactKernel::Triangle_3;

/// The squared distance of p to the closed segment [a, b] (a point when a == b).
inline mpq_class sq_point_segment(const P3& p, const P3& a, const P3& b) {
  if (a == b) return CGAL::squared_distance(p, a);
  return CGAL::squared_distance(p, S3(a, b));
}

/// The squared distance of the closed segments [a0, a1] and [b0, b1].
inline mpq_class sq_segment_segment(const P3& a0, const P3& a1, const P3& b0, const P3& b1) {
  if (a0 == a1) return sq_point_segment(a0, b0, b1);
  if (b0 == b1) return sq_point_segment(b0, a0, a1);
  return CGAL::squared_distance(S3(a0, a1), S3(b0, b1));
}

/// The squared distance of p to the closed triangle (a, b, c) (its hull when degenerate).
inline mpq_class sq_point_triangle(const P3& p, const P3& a, const P3& b, const P3& c) {
  if (CGAL::collinear(a, b, c))  // a segment or a point: the distance to its hull
    return std::min({sq_point_segment(p, a, b), sq_point_segment(p, b, c), sq_point_segment(p, c, a)});
  return CGAL::squared_distance(p, T3(a, b, c));
}

}  // namespace exactccd::testing
