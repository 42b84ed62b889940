// Time of impact: known exact roots are enclosed by the tightest double interval, for every
// exact method (the filtered front end and the CGAL path) and the rational API.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "exactccd/exactccd.hpp"

namespace exactccd {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// p = (1/4, 1/4, z0 + t (z1 - z0)) against the static unit triangle in z = 0.
VertexFaceQuery falling_vertex(double z0, double z1) {
  return {{0.25, 0.25, z0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
          {0.25, 0.25, z1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
}

/// Edge b parallel to y at height z0 + t (z1 - z0) crossing the static x-axis edge [-1, 1].
EdgeEdgeQuery crossing_edges(double z0, double z1) {
  return {{-1, 0, 0}, {1, 0, 0}, {0.5, -1, z0}, {0.5, 1, z0},
          {-1, 0, 0}, {1, 0, 0}, {0.5, -1, z1}, {0.5, 1, z1}};
}

/// Checks lo <= t <= hi for the exact rational t, and tightness.
void expect_encloses(const std::optional<TimeInterval>& toi, const mpq_class& t) {
  ASSERT_TRUE(toi.has_value());
  EXPECT_LE(mpq_class(toi->lo), t);
  EXPECT_GE(mpq_class(toi->hi), t);
  const double nearest = t.get_d();
  if (mpq_class(nearest) == t) {
    EXPECT_EQ(toi->lo, nearest);
    EXPECT_EQ(toi->hi, nearest);
  } else {
    EXPECT_EQ(std::nextafter(toi->lo, kInf), toi->hi);
  }
}

TEST(VertexFaceToi, KnownRationalTimes) {
  for (Method m : {Method::filtered, Method::exact}) {
    SCOPED_TRACE(static_cast<int>(m));
    expect_encloses(vertex_face_toi(falling_vertex(1, -1), m), mpq_class(1, 2));
    expect_encloses(vertex_face_toi(falling_vertex(1, -2), m), mpq_class(1, 3));
    expect_encloses(vertex_face_toi(falling_vertex(2, -5), m), mpq_class(2, 7));
    // p static at height 2^-60, the triangle rising from z = 0 to z = 1: TOI 2^-60.
    const VertexFaceQuery rising{{0.25, 0.25, 0x1p-60}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                 {0.25, 0.25, 0x1p-60}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    expect_encloses(vertex_face_toi(rising, m), mpq_class(0x1p-60));
    // z = (1 - 2^-53) - t: the TOI 1 - 2^-53, the double just below 1.
    expect_encloses(vertex_face_toi(falling_vertex(1 - 0x1p-53, -0x1p-53), m),
                    mpq_class(1 - 0x1p-53));
    // z = 3 - 3.0625 t: a non-dyadic root close to 1, t = 48/49.
    expect_encloses(vertex_face_toi(falling_vertex(3, -0.0625), m), mpq_class(48, 49));
  }
}

TEST(EdgeEdgeToi, KnownRationalTimes) {
  for (Method m : {Method::filtered, Method::exact}) {
    SCOPED_TRACE(static_cast<int>(m));
    expect_encloses(edge_edge_toi(crossing_edges(1, -1), m), mpq_class(1, 2));
    expect_encloses(edge_edge_toi(crossing_edges(1, -2), m), mpq_class(1, 3));
    expect_encloses(edge_edge_toi(crossing_edges(5, -2), m), mpq_class(5, 7));
    // b static at height 2^-70, a rising from z = 0 to z = 1: TOI 2^-70.
    const EdgeEdgeQuery rising{{-1, 0, 0}, {1, 0, 0}, {0.5, -1, 0x1p-70}, {0.5, 1, 0x1p-70},
                               {-1, 0, 1}, {1, 0, 1}, {0.5, -1, 0x1p-70}, {0.5, 1, 0x1p-70}};
    expect_encloses(edge_edge_toi(rising, m), mpq_class(0x1p-70));
  }
}

TEST(Toi, IrreducibleCubicRootIsEnclosed) {
  // V(t) = det[b; c; p] = -4t^3 + 16t^2 + 32t - 12 (see the catalogue's vf_irrational_toi);
  // its root in [0, 1] is irrational, so the TOI must be two consecutive doubles around it.
  const VertexFaceQuery q{{-2, -1, 2}, {0, 0, 0}, {2, 1, 1},   {-2, -3, 0},
                          {3, -1, -1}, {0, 0, 0}, {-1, -1, 3}, {-3, -3, 1}};
  const auto cubic = [](double t) {
    const mpq_class x(t);
    return mpq_class(-12 + 32 * x + 16 * x * x - 4 * x * x * x);
  };
  for (Method m : {Method::filtered, Method::exact}) {
    const auto toi = vertex_face_toi(q, m);
    ASSERT_TRUE(toi.has_value());
    EXPECT_EQ(std::nextafter(toi->lo, kInf), toi->hi);
    EXPECT_LT(sgn(cubic(toi->lo)) * sgn(cubic(toi->hi)), 0) << "[" << toi->lo << ", " << toi->hi << "]";
    EXPECT_NEAR(toi->lo, 0.3261498573585535, 1e-15);
  }
}

TEST(Toi, NoCollisionMeansNoToi) {
  for (Method m : {Method::filtered, Method::exact}) {
    EXPECT_FALSE(vertex_face_toi(falling_vertex(1, 0x1p-30), m).has_value());
    EXPECT_FALSE(edge_edge_toi(crossing_edges(1, 0.5), m).has_value());
  }
}

TEST(Toi, NonFiniteInputThrows) {
  EXPECT_THROW(vertex_face_toi(falling_vertex(std::nan(""), 0)), std::invalid_argument);
  EXPECT_THROW(edge_edge_toi(crossing_edges(1, kInf)), std::invalid_argument);
  EXPECT_THROW(vertex_face_ccd(falling_vertex(-kInf, 0)), std::invalid_argument);
}

}  // namespace
}  // namespace exactccd
