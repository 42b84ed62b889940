// The hand-derived minimum-separation catalogue: CcdParams (min_distance d, tmax) for every
// primitive kind. Each case's answer and time of impact was derived by hand (the comment above
// it; docs/min-separation-catalogue.md has the table), independently of the library's code,
// and checked with exact rational arithmetic by tools/min_separation_catalogue.py, which also
// computed the tightest double intervals of the TOIs that are not doubles (1/3, 2/3,
// 1/2 - 2^-1075, and the irrational 1 - 1/sqrt(2), 1 - sqrt(2)/4, 1 - 1/sqrt(3)) and wrote the
// tables below. Both exact methods (filtered and exact) must give the derived answer, and
// the TOI bit for bit.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "exactccd/exactccd.hpp"

namespace exactccd {
namespace {

constexpr double kNone = 0.0;                    // the TOI bounds of a miss (unused)
constexpr double kSub = 0x1p-1074;               // the smallest subnormal
constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kBelowQuarter = 0x1.fffffffffffffp-3;  // nextafter(0.25, 0)
constexpr double kBelow5_16 = 0x1.3ffffffffffffp-2;     // nextafter(0.3125, 0)
constexpr double kBelow3_8 = 0x1.7ffffffffffffp-2;      // nextafter(0.375, 0)
constexpr double kBelowHalf = 0x1.fffffffffffffp-2;     // nextafter(0.5, 0)

/// One case: the query, d, tmax and the derived answer; [lo, hi] is the expected TOI.
template <class Query>
struct Case {
  const char* name;
  Query q;
  double d;
  double tmax;
  bool collides;
  double lo;
  double hi;
};

template <class Query>
void PrintTo(const Case<Query>& c, std::ostream* os) {
  *os << c.name;
}

std::string hex(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

// clang-format off
// BEGIN CASE TABLES (tools/min_separation_catalogue.py)
std::vector<Case<VertexFaceQuery>> vf_cases() {
  return {
      // height 1-2t over the interior point (1,1); 1-2t = 1/4 at t = 3/8
      {"vf_face_descent",
       {{1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {1.0, 1.0, -1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.25, 1.0, true, 0.375, 0.375},
      // height 1-2t reaches 0 at t = 1/2
      {"vf_face_descent_d0",
       {{1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {1.0, 1.0, -1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.0, 1.0, true, 0.5, 0.5},
      // height 1-3t = 0 at t = 1/3, not a double
      {"vf_face_descent_third_d0",
       {{1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {1.0, 1.0, -2.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.0, 1.0, true, 0x1.5555555555555p-2, 0x1.5555555555556p-2},
      // x = -2+4t at height 1/4: dist = sqrt(x^2+1/16) for x < 0, 1/4 once x >= 0 (t = 1/2)
      {"vf_face_parallel_pass_exact_d",
       {{-2.0, 1.0, 0.25}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {2.0, 1.0, 0.25}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.25, 1.0, true, 0.5, 0.5},
      // minimum distance 1/4 > d
      {"vf_face_parallel_pass_below_d",
       {{-2.0, 1.0, 0.25}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {2.0, 1.0, 0.25}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       kBelowQuarter, 1.0, false, kNone, kNone},
      // p - (2,0,0) = (1-t)(0,-3/4,1) outside the face: dist 5(1-t)/4 = 5/16 at t = 3/4
      {"vf_edge_interior",
       {{2.0, -0.75, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {2.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.3125, 1.0, true, 0.75, 0.75},
      // nearest point (2,0,0) on edge: dist sqrt(1/16+(1-2t)^2), minimum 1/4 at t = 1/2 (double root)
      {"vf_edge_tangent",
       {{2.0, -0.25, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {2.0, -0.25, -1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.25, 1.0, true, 0.5, 0.5},
      // minimum distance 1/4 > d
      {"vf_edge_tangent_below_d",
       {{2.0, -0.25, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {2.0, -0.25, -1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       kBelowQuarter, 1.0, false, kNone, kNone},
      // dist to edge sqrt(2)(1-t) = 1/2 at t = 1 - sqrt(2)/4
      {"vf_edge_irrational",
       {{2.0, -1.0, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {2.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.5, 1.0, true, 0x1.4afb0ccc06219p-1, 0x1.4afb0ccc0621ap-1},
      // nearest point the vertex (0,0,0): dist sqrt(25/256+(1-2t)^2), minimum 5/16 at t = 1/2
      {"vf_vertex_tangent",
       {{-0.1875, -0.25, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {-0.1875, -0.25, -1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.3125, 1.0, true, 0.5, 0.5},
      // minimum distance 5/16 > d
      {"vf_vertex_tangent_below_d",
       {{-0.1875, -0.25, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {-0.1875, -0.25, -1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       kBelow5_16, 1.0, false, kNone, kNone},
      // 25/256 + (1-2t)^2 = 169/256: 1-2t = 3/4, t = 1/8
      {"vf_vertex_13_16",
       {{-0.1875, -0.25, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {-0.1875, -0.25, -1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.8125, 1.0, true, 0.125, 0.125},
      // dist to vertex sqrt(2)(1-t) = 1 at t = 1 - 1/sqrt(2)
      {"vf_vertex_irrational",
       {{-1.0, -1.0, 0.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       1.0, 1.0, true, 0x1.2bec333018866p-2, 0x1.2bec333018867p-2},
      // static point at height 1, face rises to z = t: gap 1-t = 1/4 at t = 3/4
      {"vf_rising_triangle",
       {{1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {1.0, 1.0, 1.0}, {0.0, 0.0, 1.0}, {4.0, 0.0, 1.0}, {0.0, 4.0, 1.0}},
       0.25, 1.0, true, 0.75, 0.75},
      // point z = 2-2t, face z = t: gap 2-3t = 1/2 at t = 1/2
      {"vf_both_moving",
       {{1.0, 1.0, 2.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {1.0, 1.0, 0.0}, {0.0, 0.0, 1.0}, {4.0, 0.0, 1.0}, {0.0, 4.0, 1.0}},
       0.5, 1.0, true, 0.5, 0.5},
      // c_z = 4-8t, plane z = c_z y/4 is 1-2t over (1,1) (inside), = 1/2 at t = 1/4
      {"vf_tilting_triangle_d0",
       {{1.0, 1.0, 0.5}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 4.0},
        {1.0, 1.0, 0.5}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, -4.0}},
       0.0, 1.0, true, 0.25, 0.25},
      // collinear triangle = segment; p - (2,0,0) = (1-2t)(0,3/4,1): 5|1-2t|/4 = 5/16 at 3/8
      {"vf_collinear_triangle",
       {{2.0, 0.75, 1.0}, {0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {4.0, 0.0, 0.0},
        {2.0, -0.75, -1.0}, {0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {4.0, 0.0, 0.0}},
       0.3125, 1.0, true, 0.375, 0.375},
      // dist to the segment sqrt(1/16+(1-2t)^2) >= 1/4 > d (crosses the plane, never the hull)
      {"vf_collinear_triangle_tangent_below_d",
       {{2.0, 0.25, 1.0}, {0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {4.0, 0.0, 0.0},
        {2.0, 0.25, -1.0}, {0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {4.0, 0.0, 0.0}},
       kBelowQuarter, 1.0, false, kNone, kNone},
      // triangle = point (1,1,1); p - it = (1-t)(3,4,0): 5(1-t) = 5/4 at t = 3/4
      {"vf_point_triangle",
       {{4.0, 5.0, 1.0}, {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0},
        {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}},
       1.25, 1.0, true, 0.75, 0.75},
      // dist sqrt((2t-1)^2 + 1/16 + 9/256) >= 5/16 > 1/4
      {"vf_point_triangle_pass_miss",
       {{0.0, 1.25, 1.1875}, {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0},
        {2.0, 1.25, 1.1875}, {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}},
       0.25, 1.0, false, kNone, kNone},
      // initial height 1/4 <= 1/2
      {"vf_initially_within",
       {{1.0, 1.0, 0.25}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {1.0, 1.0, 2.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.5, 1.0, true, 0.0, 0.0},
      // initial height 1/4 = d
      {"vf_initially_exactly_d",
       {{1.0, 1.0, 0.25}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {1.0, 1.0, 2.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.25, 1.0, true, 0.0, 0.0},
      // vf_edge_interior reaches d at 3/4 > tmax
      {"vf_after_tmax",
       {{2.0, -0.75, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {2.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.3125, 0.5, false, kNone, kNone},
      // vf_edge_interior reaches d exactly at tmax = 3/4
      {"vf_at_tmax_edge",
       {{2.0, -0.75, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {2.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.3125, 0.75, true, 0.75, 0.75},
      // vf_face_descent reaches d exactly at tmax = 3/8
      {"vf_at_tmax_face",
       {{1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {1.0, 1.0, -1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.25, 0.375, true, 0.375, 0.375},
      // vf_face_descent reaches d at 3/8 > tmax
      {"vf_just_before_tmax",
       {{1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {1.0, 1.0, -1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.25, kBelow3_8, false, kNone, kNone},
      // initial distance 1 <= d
      {"vf_huge_d",
       {{1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {1.0, 1.0, -1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       1e300, 1.0, true, 0.0, 0.0},
      // height 2^-1073 (1-2t) = 2^-1074 at t = 1/4
      {"vf_subnormal_descent",
       {{1.0, 1.0, 0x0.0000000000002p-1022}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {1.0, 1.0, -0x0.0000000000002p-1022}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       kSub, 1.0, true, 0.25, 0.25},
      // height 2^-1074, enters over the face (x = -2+4t = 0) at t = 1/2
      {"vf_subnormal_parallel_pass",
       {{-2.0, 1.0, 0x0.0000000000001p-1022}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {2.0, 1.0, 0x0.0000000000001p-1022}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       kSub, 1.0, true, 0.5, 0.5},
      // minimum distance 2^-1074 > 0
      {"vf_subnormal_parallel_pass_d0",
       {{-2.0, 1.0, 0x0.0000000000001p-1022}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {2.0, 1.0, 0x0.0000000000001p-1022}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       0.0, 1.0, false, kNone, kNone},
      // 1-2t = 2^-1074 at t = 1/2 - 2^-1075: in (pred(1/2), 1/2)
      {"vf_subnormal_d_ordinary_descent",
       {{1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0},
        {1.0, 1.0, -1.0}, {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}},
       kSub, 1.0, true, 0x1.fffffffffffffp-2, 0.5},
  };
}

std::vector<Case<EdgeEdgeQuery>> ee_cases() {
  return {
      // crossed edges, b at height 1-2t, closest points interior: 1-2t = 1/4
      {"ee_interior_descent",
       {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, -1.0, 1.0}, {0.0, 1.0, 1.0},
        {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, -1.0, -1.0}, {0.0, 1.0, -1.0}},
       0.25, 1.0, true, 0.375, 0.375},
      // 1-2t = 0
      {"ee_interior_descent_d0",
       {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, -1.0, 1.0}, {0.0, 1.0, 1.0},
        {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, -1.0, -1.0}, {0.0, 1.0, -1.0}},
       0.0, 1.0, true, 0.5, 0.5},
      // b at height 1/4, x = -3+6t: dist sqrt((x+1)^2+1/16) for x < -1; = 1/4 at x = -1, t = 1/3
      {"ee_crossed_slide_exact_d",
       {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {-3.0, -1.0, 0.25}, {-3.0, 1.0, 0.25},
        {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {3.0, -1.0, 0.25}, {3.0, 1.0, 0.25}},
       0.25, 1.0, true, 0x1.5555555555555p-2, 0x1.5555555555556p-2},
      // minimum distance 1/4 > d
      {"ee_crossed_slide_below_d",
       {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {-3.0, -1.0, 0.25}, {-3.0, 1.0, 0.25},
        {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {3.0, -1.0, 0.25}, {3.0, 1.0, 0.25}},
       kBelowQuarter, 1.0, false, kNone, kNone},
      // a1 = (1,0,0) to b: sqrt(1/16+(1-2t)^2), minimum 1/4 at t = 1/2 (double root)
      {"ee_endpoint_tangent",
       {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.25, -1.0, 1.0}, {1.25, 1.0, 1.0},
        {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.25, -1.0, -1.0}, {1.25, 1.0, -1.0}},
       0.25, 1.0, true, 0.5, 0.5},
      // minimum distance 1/4 > d
      {"ee_endpoint_tangent_below_d",
       {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.25, -1.0, 1.0}, {1.25, 1.0, 1.0},
        {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.25, -1.0, -1.0}, {1.25, 1.0, -1.0}},
       kBelowQuarter, 1.0, false, kNone, kNone},
      // 1/16 + (1-2t)^2 = 25/256: 1-2t = 3/16, t = 13/32
      {"ee_endpoint_5_16",
       {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.25, -1.0, 1.0}, {1.25, 1.0, 1.0},
        {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.25, -1.0, -1.0}, {1.25, 1.0, -1.0}},
       0.3125, 1.0, true, 0.40625, 0.40625},
      // parallel at height 1/4, b0 x = 4-4t: overlap (and dist 1/4) from x = 2, t = 1/2
      {"ee_parallel_slide_exact_d",
       {{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {4.0, 0.0, 0.25}, {6.0, 0.0, 0.25},
        {0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {0.0, 0.0, 0.25}, {2.0, 0.0, 0.25}},
       0.25, 1.0, true, 0.5, 0.5},
      // minimum distance 1/4 > d
      {"ee_parallel_slide_below_d",
       {{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {4.0, 0.0, 0.25}, {6.0, 0.0, 0.25},
        {0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {0.0, 0.0, 0.25}, {2.0, 0.0, 0.25}},
       kBelowQuarter, 1.0, false, kNone, kNone},
      // static overlapping parallel edges 1/4 apart
      {"ee_parallel_static_exact_d",
       {{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {1.0, 0.25, 0.0}, {3.0, 0.25, 0.0},
        {0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {1.0, 0.25, 0.0}, {3.0, 0.25, 0.0}},
       0.25, 1.0, true, 0.0, 0.0},
      // constant distance 1/4 > d
      {"ee_parallel_static_below_d",
       {{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {1.0, 0.25, 0.0}, {3.0, 0.25, 0.0},
        {0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {1.0, 0.25, 0.0}, {3.0, 0.25, 0.0}},
       kBelowQuarter, 1.0, false, kNone, kNone},
      // collinear, b0 x = 4-3t meets a1 x = 2 at t = 2/3
      {"ee_collinear_approach_d0",
       {{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {6.0, 0.0, 0.0},
        {0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {3.0, 0.0, 0.0}},
       0.0, 1.0, true, 0x1.5555555555555p-1, 0x1.5555555555556p-1},
      // b = (0, u..u+2, u), u = 1-t: dist sqrt(2) u = 1/2 at t = 1 - sqrt(2)/4
      {"ee_irrational_endpoint",
       {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 1.0}, {0.0, 3.0, 1.0},
        {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 2.0, 0.0}},
       0.5, 1.0, true, 0x1.4afb0ccc06219p-1, 0x1.4afb0ccc0621ap-1},
      // a = origin; b through (0, 3(1-2t)/4, 1-2t): 5|1-2t|/4 = 5/16 at 3/8
      {"ee_zero_length_a",
       {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {-1.0, 0.75, 1.0}, {1.0, 0.75, 1.0},
        {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {-1.0, -0.75, -1.0}, {1.0, -0.75, -1.0}},
       0.3125, 1.0, true, 0.375, 0.375},
      // two points: 5(1-t) = 5/4 at 3/4
      {"ee_both_zero_length",
       {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {3.0, 4.0, 0.0}, {3.0, 4.0, 0.0},
        {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}},
       1.25, 1.0, true, 0.75, 0.75},
      // initial distance 1/4 = d
      {"ee_initially_within",
       {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, -1.0, 0.25}, {0.0, 1.0, 0.25},
        {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, -1.0, 2.0}, {0.0, 1.0, 2.0}},
       0.25, 1.0, true, 0.0, 0.0},
      // ee_interior_descent reaches d at 3/8 > 1/4
      {"ee_after_tmax",
       {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, -1.0, 1.0}, {0.0, 1.0, 1.0},
        {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, -1.0, -1.0}, {0.0, 1.0, -1.0}},
       0.25, 0.25, false, kNone, kNone},
      // ee_interior_descent reaches d exactly at tmax
      {"ee_at_tmax",
       {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, -1.0, 1.0}, {0.0, 1.0, 1.0},
        {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, -1.0, -1.0}, {0.0, 1.0, -1.0}},
       0.25, 0.375, true, 0.375, 0.375},
      // initial distance 1 <= d
      {"ee_huge_d",
       {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, -1.0, 1.0}, {0.0, 1.0, 1.0},
        {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, -1.0, -1.0}, {0.0, 1.0, -1.0}},
       1e300, 1.0, true, 0.0, 0.0},
      // a at z = -1+2t, b at z = 1-2t, crossed: gap |2-4t| = 1/2 at 3/8
      {"ee_both_moving",
       {{-1.0, 0.0, -1.0}, {1.0, 0.0, -1.0}, {0.0, -1.0, 1.0}, {0.0, 1.0, 1.0},
        {-1.0, 0.0, 1.0}, {1.0, 0.0, 1.0}, {0.0, -1.0, -1.0}, {0.0, 1.0, -1.0}},
       0.5, 1.0, true, 0.375, 0.375},
  };
}

std::vector<Case<PointEdgeQuery>> pe_cases() {
  return {
      // p = (1-2t)(0,3/4,1) over the interior: 5|1-2t|/4 = 5/16 at 3/8
      {"pe_interior",
       {{0.0, 0.75, 1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
        {0.0, -0.75, -1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}},
       0.3125, 1.0, true, 0.375, 0.375},
      // passes through (0,0,0) at t = 1/2
      {"pe_interior_d0",
       {{0.0, 0.75, 1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
        {0.0, -0.75, -1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}},
       0.0, 1.0, true, 0.5, 0.5},
      // y = 1-3t = 0 at t = 1/3, not a double
      {"pe_interior_third_d0",
       {{0.0, 1.0, 0.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
        {0.0, -2.0, 0.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}},
       0.0, 1.0, true, 0x1.5555555555555p-2, 0x1.5555555555556p-2},
      // sqrt(1/16+(1-2t)^2), minimum 1/4 at t = 1/2
      {"pe_interior_tangent",
       {{0.0, 0.25, 1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
        {0.0, 0.25, -1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}},
       0.25, 1.0, true, 0.5, 0.5},
      // minimum distance 1/4 > d
      {"pe_interior_tangent_below_d",
       {{0.0, 0.25, 1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
        {0.0, 0.25, -1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}},
       kBelowQuarter, 1.0, false, kNone, kNone},
      // nearest is the end (1,0,0): sqrt(2)(1-t) = 1 at t = 1 - 1/sqrt(2)
      {"pe_vertex_irrational",
       {{2.0, 1.0, 0.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
        {1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}},
       1.0, 1.0, true, 0x1.2bec333018866p-2, 0x1.2bec333018867p-2},
      // nearest is the end (1,0,0): sqrt(9/256+1/16+(1-2t)^2), minimum 5/16 at 1/2
      {"pe_vertex_tangent",
       {{1.1875, 0.25, 1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
        {1.1875, 0.25, -1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}},
       0.3125, 1.0, true, 0.5, 0.5},
      // minimum distance 5/16 > d
      {"pe_vertex_tangent_below_d",
       {{1.1875, 0.25, 1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
        {1.1875, 0.25, -1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}},
       kBelow5_16, 1.0, false, kNone, kNone},
      // on the line, x = 3-4t reaches the end x = 1 at 1/2
      {"pe_slide_along_line_d0",
       {{3.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
        {-1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}},
       0.0, 1.0, true, 0.5, 0.5},
      // edge = point (1,1,1): 5(1-t) = 5/4 at 3/4
      {"pe_zero_length_edge",
       {{4.0, 5.0, 1.0}, {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0},
        {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}},
       1.25, 1.0, true, 0.75, 0.75},
      // b_z = 3-4t, the edge crosses x = 0 at z = b_z/2 = 1 (the point) at t = 1/4
      {"pe_rotating_edge_d0",
       {{0.0, 0.0, 1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 3.0},
        {0.0, 0.0, 1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, -1.0}},
       0.0, 1.0, true, 0.25, 0.25},
      // all translate by (1,2,3): constant distance 1/4 = d
      {"pe_same_motion_exact_d",
       {{0.0, 0.25, 0.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
        {1.0, 2.25, 3.0}, {0.0, 2.0, 3.0}, {2.0, 2.0, 3.0}},
       0.25, 1.0, true, 0.0, 0.0},
      // constant distance 1/4 > d
      {"pe_same_motion_below_d",
       {{0.0, 0.25, 0.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
        {1.0, 2.25, 3.0}, {0.0, 2.0, 3.0}, {2.0, 2.0, 3.0}},
       kBelowQuarter, 1.0, false, kNone, kNone},
      // pe_interior reaches d at 3/8 > 1/4
      {"pe_after_tmax",
       {{0.0, 0.75, 1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
        {0.0, -0.75, -1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}},
       0.3125, 0.25, false, kNone, kNone},
      // pe_interior reaches d exactly at tmax
      {"pe_at_tmax",
       {{0.0, 0.75, 1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
        {0.0, -0.75, -1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}},
       0.3125, 0.375, true, 0.375, 0.375},
      // initial distance 5/4 <= d
      {"pe_huge_d",
       {{0.0, 0.75, 1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
        {0.0, -0.75, -1.0}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}},
       1e300, 1.0, true, 0.0, 0.0},
  };
}

std::vector<Case<PointPointQuery>> pp_cases() {
  return {
      // 5(1-t) = 5/4 at 3/4
      {"pp_approach",
       {{3.0, 4.0, 0.0}, {0.0, 0.0, 0.0},
        {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}},
       1.25, 1.0, true, 0.75, 0.75},
      // meet at t = 1
      {"pp_approach_d0",
       {{3.0, 4.0, 0.0}, {0.0, 0.0, 0.0},
        {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}},
       0.0, 1.0, true, 1.0, 1.0},
      // meet at 1 > tmax
      {"pp_approach_d0_tmax",
       {{3.0, 4.0, 0.0}, {0.0, 0.0, 0.0},
        {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}},
       0.0, 0.5, false, kNone, kNone},
      // sqrt((2t-1)^2+25/256), minimum 5/16 at 1/2
      {"pp_pass_tangent",
       {{-1.0, 0.1875, 0.25}, {0.0, 0.0, 0.0},
        {1.0, 0.1875, 0.25}, {0.0, 0.0, 0.0}},
       0.3125, 1.0, true, 0.5, 0.5},
      // minimum distance 5/16 > d
      {"pp_pass_tangent_below_d",
       {{-1.0, 0.1875, 0.25}, {0.0, 0.0, 0.0},
        {1.0, 0.1875, 0.25}, {0.0, 0.0, 0.0}},
       kBelow5_16, 1.0, false, kNone, kNone},
      // (2t-1)^2 + 25/256 = 169/256: 2t-1 = -3/4, t = 1/8
      {"pp_pass_13_16",
       {{-1.0, 0.1875, 0.25}, {0.0, 0.0, 0.0},
        {1.0, 0.1875, 0.25}, {0.0, 0.0, 0.0}},
       0.8125, 1.0, true, 0.125, 0.125},
      // sqrt(3)(1-t) = 1 at t = 1 - 1/sqrt(3)
      {"pp_irrational",
       {{1.0, 1.0, 1.0}, {0.0, 0.0, 0.0},
        {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}},
       1.0, 1.0, true, 0x1.b0cb174df99c7p-2, 0x1.b0cb174df99c8p-2},
      // x_p = 2t, x_q = 2-2t: |2-4t| = 1/2 at 3/8
      {"pp_both_moving",
       {{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0},
        {2.0, 0.0, 0.0}, {0.0, 0.0, 0.0}},
       0.5, 1.0, true, 0.375, 0.375},
      // meet at 1/2
      {"pp_both_moving_d0",
       {{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0},
        {2.0, 0.0, 0.0}, {0.0, 0.0, 0.0}},
       0.0, 1.0, true, 0.5, 0.5},
      // zero relative motion, constant distance 1/4 = d
      {"pp_same_motion_exact_d",
       {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.25},
        {1.0, 1.0, 1.0}, {1.0, 1.0, 1.25}},
       0.25, 1.0, true, 0.0, 0.0},
      // constant distance 1/4 > d
      {"pp_same_motion_below_d",
       {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.25},
        {1.0, 1.0, 1.0}, {1.0, 1.0, 1.25}},
       kBelowQuarter, 1.0, false, kNone, kNone},
      // coincident at t = 0
      {"pp_coincident_d0",
       {{1.0, 2.0, 3.0}, {1.0, 2.0, 3.0},
        {1.0, 2.0, 3.0}, {1.0, 2.0, 3.0}},
       0.0, 1.0, true, 0.0, 0.0},
      // x = 2^-1072 (1-2t): |1-2t| = 1/4 at 3/8
      {"pp_subnormal",
       {{0x0.0000000000004p-1022, 0.0, 0.0}, {0.0, 0.0, 0.0},
        {-0x0.0000000000004p-1022, 0.0, 0.0}, {0.0, 0.0, 0.0}},
       kSub, 1.0, true, 0.375, 0.375},
      // D = 1e300 (a double): dist D + D(1-t) = D(2-t) = D at t = 1 (squares overflow doubles)
      {"pp_huge_coordinates",
       {{1e300, 0.0, 0.0}, {-1e300, 0.0, 0.0},
        {1e300, 0.0, 0.0}, {0.0, 0.0, 0.0}},
       1e300, 1.0, true, 1.0, 1.0},
      // as above, D(2-t) > D on [0, 1/2]
      {"pp_huge_coordinates_tmax",
       {{1e300, 0.0, 0.0}, {-1e300, 0.0, 0.0},
        {1e300, 0.0, 0.0}, {0.0, 0.0, 0.0}},
       1e300, 0.5, false, kNone, kNone},
      // initial distance 2e300 <= DBL_MAX
      {"pp_max_d",
       {{1e300, 0.0, 0.0}, {-1e300, 0.0, 0.0},
        {1e300, 0.0, 0.0}, {0.0, 0.0, 0.0}},
       kMax, 1.0, true, 0.0, 0.0},
      // pp_approach reaches d at 3/4 > tmax = 2^-1074
      {"pp_tiny_tmax",
       {{3.0, 4.0, 0.0}, {0.0, 0.0, 0.0},
        {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}},
       1.25, kSub, false, kNone, kNone},
      // coincident at t = 0 <= tmax = 2^-1074
      {"pp_tiny_tmax_initial",
       {{1.0, 2.0, 3.0}, {1.0, 2.0, 3.0},
        {4.0, 2.0, 3.0}, {1.0, 2.0, 3.0}},
       0.0, kSub, true, 0.0, 0.0},
  };
}

std::vector<Case<EdgeEdge2dQuery>> ee2_cases() {
  return {
      // static crossing segments: distance 0 <= d
      {"ee2_crossing_at_t0",
       {{-1.0, 0.0}, {1.0, 0.0}, {0.0, -1.0}, {0.0, 1.0},
        {-1.0, 0.0}, {1.0, 0.0}, {0.0, -1.0}, {0.0, 1.0}},
       0.5, 1.0, true, 0.0, 0.0},
      // crossing at t = 0
      {"ee2_crossing_at_t0_d0",
       {{-1.0, 0.0}, {1.0, 0.0}, {0.0, -1.0}, {0.0, 1.0},
        {-1.0, 0.0}, {1.0, 0.0}, {5.0, -1.0}, {5.0, 1.0}},
       0.0, 1.0, true, 0.0, 0.0},
      // b0 = (0, 1-2t) reaches a at 1/2
      {"ee2_endpoint_sweep_d0",
       {{-1.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.0, 3.0},
        {-1.0, 0.0}, {1.0, 0.0}, {0.0, -1.0}, {0.0, 1.0}},
       0.0, 1.0, true, 0.5, 0.5},
      // b0 = (0, 1-2t): 1-2t = 1/4 at 3/8
      {"ee2_endpoint_sweep",
       {{-1.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.0, 3.0},
        {-1.0, 0.0}, {1.0, 0.0}, {0.0, -1.0}, {0.0, 1.0}},
       0.25, 1.0, true, 0.375, 0.375},
      // contact exactly at tmax = 1/2
      {"ee2_endpoint_sweep_at_tmax",
       {{-1.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.0, 3.0},
        {-1.0, 0.0}, {1.0, 0.0}, {0.0, -1.0}, {0.0, 1.0}},
       0.0, 0.5, true, 0.5, 0.5},
      // contact at 1/2 > tmax
      {"ee2_endpoint_sweep_before_tmax",
       {{-1.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.0, 3.0},
        {-1.0, 0.0}, {1.0, 0.0}, {0.0, -1.0}, {0.0, 1.0}},
       0.0, kBelowHalf, false, kNone, kNone},
      // parallel 1/4 apart, b0 x = 4-4t: overlap from x = 2, t = 1/2
      {"ee2_parallel_slide_exact_d",
       {{0.0, 0.0}, {2.0, 0.0}, {4.0, 0.25}, {6.0, 0.25},
        {0.0, 0.0}, {2.0, 0.0}, {0.0, 0.25}, {2.0, 0.25}},
       0.25, 1.0, true, 0.5, 0.5},
      // minimum distance 1/4 > d
      {"ee2_parallel_slide_below_d",
       {{0.0, 0.0}, {2.0, 0.0}, {4.0, 0.25}, {6.0, 0.25},
        {0.0, 0.0}, {2.0, 0.0}, {0.0, 0.25}, {2.0, 0.25}},
       kBelowQuarter, 1.0, false, kNone, kNone},
      // a1 = origin to b0 = (1-t, 1-t): sqrt(2)(1-t) = 1 at 1 - 1/sqrt(2)
      {"ee2_corner_irrational",
       {{-1.0, 0.0}, {0.0, 0.0}, {1.0, 1.0}, {2.0, 1.0},
        {-1.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}},
       1.0, 1.0, true, 0x1.2bec333018866p-2, 0x1.2bec333018867p-2},
      // b0 x = 4-3t meets a1 x = 2 at 2/3
      {"ee2_collinear_approach_d0",
       {{0.0, 0.0}, {2.0, 0.0}, {4.0, 0.0}, {6.0, 0.0},
        {0.0, 0.0}, {2.0, 0.0}, {1.0, 0.0}, {3.0, 0.0}},
       0.0, 1.0, true, 0x1.5555555555555p-1, 0x1.5555555555556p-1},
      // b stays on x = 2, a ends at x = 1: distance >= 1
      {"ee2_pass_by_d0",
       {{-1.0, 0.0}, {1.0, 0.0}, {2.0, 1.0}, {2.0, 3.0},
        {-1.0, 0.0}, {1.0, 0.0}, {2.0, -3.0}, {2.0, -1.0}},
       0.0, 1.0, false, kNone, kNone},
      // b0 y = 1-4t: dist sqrt(1+(1-4t)^2) until b spans y = 0 (t = 1/4), then 1
      {"ee2_pass_by_exact_d",
       {{-1.0, 0.0}, {1.0, 0.0}, {2.0, 1.0}, {2.0, 3.0},
        {-1.0, 0.0}, {1.0, 0.0}, {2.0, -3.0}, {2.0, -1.0}},
       1.0, 1.0, true, 0.25, 0.25},
      // b = point (0, 1-2t) crosses a at 1/2
      {"ee2_zero_length_b_d0",
       {{-1.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.0, 1.0},
        {-1.0, 0.0}, {1.0, 0.0}, {0.0, -1.0}, {0.0, -1.0}},
       0.0, 1.0, true, 0.5, 0.5},
      // initial distance 1 <= d
      {"ee2_huge_d",
       {{-1.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.0, 3.0},
        {-1.0, 0.0}, {1.0, 0.0}, {0.0, -1.0}, {0.0, 1.0}},
       1e300, 1.0, true, 0.0, 0.0},
  };
}

std::vector<Case<PointEdge2dQuery>> pe2_cases() {
  return {
      // |1-2t| = 1/4 at 3/8
      {"pe2_interior",
       {{0.0, 1.0}, {-1.0, 0.0}, {1.0, 0.0},
        {0.0, -1.0}, {-1.0, 0.0}, {1.0, 0.0}},
       0.25, 1.0, true, 0.375, 0.375},
      // crosses at 1/2
      {"pe2_interior_d0",
       {{0.0, 1.0}, {-1.0, 0.0}, {1.0, 0.0},
        {0.0, -1.0}, {-1.0, 0.0}, {1.0, 0.0}},
       0.0, 1.0, true, 0.5, 0.5},
      // nearest is the end (1,0): sqrt(2)(1-t) = 1 at 1 - 1/sqrt(2)
      {"pe2_vertex_irrational",
       {{2.0, 1.0}, {-1.0, 0.0}, {1.0, 0.0},
        {1.0, 0.0}, {-1.0, 0.0}, {1.0, 0.0}},
       1.0, 1.0, true, 0x1.2bec333018866p-2, 0x1.2bec333018867p-2},
      // at y = 1/4, x = -3+6t: sqrt((x+1)^2+1/16) for x < -1, 1/4 from x = -1 (t = 1/3)
      {"pe2_pass_beside_exact_d",
       {{-3.0, 0.25}, {-1.0, 0.0}, {1.0, 0.0},
        {3.0, 0.25}, {-1.0, 0.0}, {1.0, 0.0}},
       0.25, 1.0, true, 0x1.5555555555555p-2, 0x1.5555555555556p-2},
      // minimum distance 1/4 > d
      {"pe2_pass_beside_below_d",
       {{-3.0, 0.25}, {-1.0, 0.0}, {1.0, 0.0},
        {3.0, 0.25}, {-1.0, 0.0}, {1.0, 0.0}},
       kBelowQuarter, 1.0, false, kNone, kNone},
      // edge = origin: 5(1-t) = 5/4 at 3/4
      {"pe2_zero_length_edge",
       {{3.0, 4.0}, {0.0, 0.0}, {0.0, 0.0},
        {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}},
       1.25, 1.0, true, 0.75, 0.75},
      // x = 3-4t reaches the end x = 1 at 1/2
      {"pe2_slide_along_line_d0",
       {{3.0, 0.0}, {-1.0, 0.0}, {1.0, 0.0},
        {-1.0, 0.0}, {-1.0, 0.0}, {1.0, 0.0}},
       0.0, 1.0, true, 0.5, 0.5},
      // b_y = 3-4t: the edge crosses x = 0 at y = b_y/2 = 1 at t = 1/4
      {"pe2_rotating_edge_d0",
       {{0.0, 1.0}, {-1.0, 0.0}, {1.0, 3.0},
        {0.0, 1.0}, {-1.0, 0.0}, {1.0, -1.0}},
       0.0, 1.0, true, 0.25, 0.25},
      // reaches d at 3/8 > 1/4
      {"pe2_after_tmax",
       {{0.0, 1.0}, {-1.0, 0.0}, {1.0, 0.0},
        {0.0, -1.0}, {-1.0, 0.0}, {1.0, 0.0}},
       0.25, 0.25, false, kNone, kNone},
      // initial distance 1/2 = d
      {"pe2_initially_within",
       {{0.0, 0.5}, {-1.0, 0.0}, {1.0, 0.0},
        {0.0, 3.0}, {-1.0, 0.0}, {1.0, 0.0}},
       0.5, 1.0, true, 0.0, 0.0},
      // initial distance 1 <= d
      {"pe2_huge_d",
       {{0.0, 1.0}, {-1.0, 0.0}, {1.0, 0.0},
        {0.0, -1.0}, {-1.0, 0.0}, {1.0, 0.0}},
       1e300, 1.0, true, 0.0, 0.0},
  };
}

std::vector<Case<PointPoint2dQuery>> pp2_cases() {
  return {
      // |2t-1| = 1/4 at 3/8
      {"pp2_cross",
       {{-1.0, 0.0}, {0.0, 0.0},
        {1.0, 0.0}, {0.0, 0.0}},
       0.25, 1.0, true, 0.375, 0.375},
      // meet at 1/2
      {"pp2_cross_d0",
       {{-1.0, 0.0}, {0.0, 0.0},
        {1.0, 0.0}, {0.0, 0.0}},
       0.0, 1.0, true, 0.5, 0.5},
      // sqrt((2t-1)^2+1/16), minimum 1/4 at 1/2
      {"pp2_pass_tangent",
       {{-1.0, 0.25}, {0.0, 0.0},
        {1.0, 0.25}, {0.0, 0.0}},
       0.25, 1.0, true, 0.5, 0.5},
      // minimum distance 1/4 > d
      {"pp2_pass_tangent_below_d",
       {{-1.0, 0.25}, {0.0, 0.0},
        {1.0, 0.25}, {0.0, 0.0}},
       kBelowQuarter, 1.0, false, kNone, kNone},
      // minimum distance 1/4 > 0
      {"pp2_pass_d0",
       {{-1.0, 0.25}, {0.0, 0.0},
        {1.0, 0.25}, {0.0, 0.0}},
       0.0, 1.0, false, kNone, kNone},
      // sqrt(2)(1-t) = 1 at 1 - 1/sqrt(2)
      {"pp2_irrational",
       {{1.0, 1.0}, {0.0, 0.0},
        {0.0, 0.0}, {0.0, 0.0}},
       1.0, 1.0, true, 0x1.2bec333018866p-2, 0x1.2bec333018867p-2},
      // zero relative motion, distance 1/4 = d
      {"pp2_same_motion_exact_d",
       {{0.0, 0.0}, {0.0, 0.25},
        {3.0, 3.0}, {3.0, 3.25}},
       0.25, 1.0, true, 0.0, 0.0},
      // constant distance 1/4 > 1/8
      {"pp2_same_motion_below_d",
       {{0.0, 0.0}, {0.0, 0.25},
        {3.0, 3.0}, {3.0, 3.25}},
       0.125, 1.0, false, kNone, kNone},
      // pp2_cross reaches d exactly at tmax
      {"pp2_at_tmax",
       {{-1.0, 0.0}, {0.0, 0.0},
        {1.0, 0.0}, {0.0, 0.0}},
       0.25, 0.375, true, 0.375, 0.375},
      // initial distance 1 <= d
      {"pp2_huge_d",
       {{-1.0, 0.0}, {0.0, 0.0},
        {1.0, 0.0}, {0.0, 0.0}},
       1e300, 1.0, true, 0.0, 0.0},
  };
}
// END CASE TABLES
// clang-format on

const char* method_name(Method m) { return m == Method::filtered ? "filtered" : "exact"; }

template <class Query>
void check_case(const Case<Query>& c) {
  const CcdParams params{c.d, c.tmax};
  SCOPED_TRACE(std::string(c.name) + ": d = " + hex(c.d) + ", tmax = " + hex(c.tmax));
  for (Method m : {Method::filtered, Method::exact}) {
    SCOPED_TRACE(method_name(m));
    EXPECT_EQ(ccd(c.q, params, m), c.collides);
    const std::optional<TimeInterval> t = toi(c.q, params, m);
    ASSERT_EQ(t.has_value(), c.collides);
    if (t) {
      EXPECT_EQ(t->lo, c.lo) << hex(t->lo) << " != " << hex(c.lo);
      EXPECT_EQ(t->hi, c.hi) << hex(t->hi) << " != " << hex(c.hi);
    }
  }
  EXPECT_EQ(ccd(c.q, params), c.collides) << "the default method";
}

template <class Query>
std::string case_name(const ::testing::TestParamInfo<Case<Query>>& info) {
  std::string n = info.param.name;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

using VertexFace = ::testing::TestWithParam<Case<VertexFaceQuery>>;
using EdgeEdge = ::testing::TestWithParam<Case<EdgeEdgeQuery>>;
using PointEdge = ::testing::TestWithParam<Case<PointEdgeQuery>>;
using PointPoint = ::testing::TestWithParam<Case<PointPointQuery>>;
using EdgeEdge2d = ::testing::TestWithParam<Case<EdgeEdge2dQuery>>;
using PointEdge2d = ::testing::TestWithParam<Case<PointEdge2dQuery>>;
using PointPoint2d = ::testing::TestWithParam<Case<PointPoint2dQuery>>;

TEST_P(VertexFace, BothExactMethodsGiveTheDerivedAnswerAndToi) { check_case(GetParam()); }
TEST_P(EdgeEdge, BothExactMethodsGiveTheDerivedAnswerAndToi) { check_case(GetParam()); }
TEST_P(PointEdge, BothExactMethodsGiveTheDerivedAnswerAndToi) { check_case(GetParam()); }
TEST_P(PointPoint, BothExactMethodsGiveTheDerivedAnswerAndToi) { check_case(GetParam()); }
TEST_P(EdgeEdge2d, BothExactMethodsGiveTheDerivedAnswerAndToi) { check_case(GetParam()); }
TEST_P(PointEdge2d, BothExactMethodsGiveTheDerivedAnswerAndToi) { check_case(GetParam()); }
TEST_P(PointPoint2d, BothExactMethodsGiveTheDerivedAnswerAndToi) { check_case(GetParam()); }

INSTANTIATE_TEST_SUITE_P(MinSeparation, VertexFace, ::testing::ValuesIn(vf_cases()), case_name<VertexFaceQuery>);
INSTANTIATE_TEST_SUITE_P(MinSeparation, EdgeEdge, ::testing::ValuesIn(ee_cases()), case_name<EdgeEdgeQuery>);
INSTANTIATE_TEST_SUITE_P(MinSeparation, PointEdge, ::testing::ValuesIn(pe_cases()), case_name<PointEdgeQuery>);
INSTANTIATE_TEST_SUITE_P(MinSeparation, PointPoint, ::testing::ValuesIn(pp_cases()), case_name<PointPointQuery>);
INSTANTIATE_TEST_SUITE_P(MinSeparation, EdgeEdge2d, ::testing::ValuesIn(ee2_cases()),
                         case_name<EdgeEdge2dQuery>);
INSTANTIATE_TEST_SUITE_P(MinSeparation, PointEdge2d, ::testing::ValuesIn(pe2_cases()),
                         case_name<PointEdge2dQuery>);
INSTANTIATE_TEST_SUITE_P(MinSeparation, PointPoint2d, ::testing::ValuesIn(pp2_cases()),
                         case_name<PointPoint2dQuery>);

TEST(MinSeparationCatalogueContents, AtLeastFortyEightCasesUniqueNamesExpectedIntervalsTight) {
  EXPECT_EQ(kBelowQuarter, std::nextafter(0.25, 0.0));
  EXPECT_EQ(kBelow5_16, std::nextafter(0.3125, 0.0));
  EXPECT_EQ(kBelow3_8, std::nextafter(0.375, 0.0));
  EXPECT_EQ(kBelowHalf, std::nextafter(0.5, 0.0));
  EXPECT_EQ(kSub, std::numeric_limits<double>::denorm_min());
  std::set<std::string> names;
  std::size_t total = 0;
  auto scan = [&](const auto& cases) {
    for (const auto& c : cases) {
      ++total;
      EXPECT_TRUE(names.insert(c.name).second) << "duplicate " << c.name;
      if (!c.collides) continue;
      EXPECT_TRUE(c.lo == c.hi || std::nextafter(c.lo, 2.0) == c.hi) << c.name << ": not adjacent doubles";
      EXPECT_LE(0.0, c.lo) << c.name;
      EXPECT_LE(c.hi, c.tmax) << c.name;
    }
  };
  scan(vf_cases());
  scan(ee_cases());
  scan(pe_cases());
  scan(pp_cases());
  scan(ee2_cases());
  scan(pe2_cases());
  scan(pp2_cases());
  EXPECT_GE(total, 48u);
}

// ---- invalid parameters and coordinates: std::invalid_argument from both exact methods ----

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

std::vector<CcdParams> invalid_params() {
  return {
      {-1.0, 1.0},   {-kSub, 1.0},  {kNaN, 1.0},  {kInf, 1.0}, {-kInf, 1.0},
      {0.25, 0.0},   {0.25, -0.0},  {0.25, -0.5}, {0.25, std::nextafter(1.0, 2.0)},
      {0.25, 1.5},   {0.25, kNaN},  {0.25, kInf}, {kNaN, kNaN},
  };
}

template <class Query>
void expect_invalid_arguments_throw(const Query& q) {
  const CcdParams ok{0.25, 1.0};
  for (Method m : {Method::filtered, Method::exact}) {
    SCOPED_TRACE(method_name(m));
    ASSERT_NO_THROW(ccd(q, ok, m));  // the base query is valid
    for (const CcdParams& p : invalid_params()) {
      SCOPED_TRACE("d = " + hex(p.min_distance) + ", tmax = " + hex(p.tmax));
      EXPECT_THROW(ccd(q, p, m), std::invalid_argument);
      EXPECT_THROW(toi(q, p, m), std::invalid_argument);
    }
    // a NaN or infinite coordinate in any row
    auto r = rows(q);
    for (std::size_t i = 0; i < r.size(); ++i)
      for (double bad : {kNaN, kInf, -kInf}) {
        auto s = r;
        s[i].x = bad;
        const Query b = from_rows<Query>(s);
        SCOPED_TRACE("row " + std::to_string(i) + " x = " + hex(bad));
        EXPECT_THROW(ccd(b, ok, m), std::invalid_argument);
        EXPECT_THROW(toi(b, ok, m), std::invalid_argument);
      }
  }
  // Only the exact methods answer queries with parameters (ccd.hpp).
  EXPECT_THROW(ccd(q, ok, static_cast<Method>(7)), std::invalid_argument);  // no such method
  EXPECT_THROW(toi(q, ok, static_cast<Method>(7)), std::invalid_argument);
}

TEST(MinSeparationInvalidArguments, VertexFace) { expect_invalid_arguments_throw(vf_cases().front().q); }
TEST(MinSeparationInvalidArguments, EdgeEdge) { expect_invalid_arguments_throw(ee_cases().front().q); }
TEST(MinSeparationInvalidArguments, PointEdge) { expect_invalid_arguments_throw(pe_cases().front().q); }
TEST(MinSeparationInvalidArguments, PointPoint) { expect_invalid_arguments_throw(pp_cases().front().q); }
TEST(MinSeparationInvalidArguments, EdgeEdge2d) { expect_invalid_arguments_throw(ee2_cases().front().q); }
TEST(MinSeparationInvalidArguments, PointEdge2d) { expect_invalid_arguments_throw(pe2_cases().front().q); }
TEST(MinSeparationInvalidArguments, PointPoint2d) { expect_invalid_arguments_throw(pp2_cases().front().q); }

}  // namespace
}  // namespace exactccd
