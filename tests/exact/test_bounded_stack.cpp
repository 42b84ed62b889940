// The exact paths must not need more stack than a common thread has. exactccd's own root
// isolation once recursed one level per bit of root separation, and so does CGAL's Descartes
// method on the exact path (192 bytes per level): a query mixing 2^-1074 and 2^1000 has roots
// about 2^-2074 apart, about 2100 levels, which crashed on a 1 MB stack in a sanitizer build
// and needs more than 256 KB in a release build. Each query here is answered on a thread whose
// whole stack is 256 KB (so a 1 MB stack is covered with room to spare), by the filtered method
// (its integer stage and then its CGAL fallback) and by the CGAL path. The answers and TOIs are
// derived by hand below. With either the old recursive isolation or CGAL's recursion on the
// caller's stack, this test crashes (checked by reverting each).
#include <gtest/gtest.h>
#include <pthread.h>

#include <cmath>
#include <functional>
#include <optional>

#include "exactccd/exactccd.hpp"

namespace exactccd {
namespace {

constexpr std::size_t kStackBytes = std::size_t{256} << 10;  // the whole thread stack

/// Runs `work` on a new thread whose stack is exactly kStackBytes; returns once it finished.
/// A stack overflow kills the test process (SIGSEGV), which CTest reports as a failure.
void run_on_small_stack(const std::function<void()>& work) {
  pthread_attr_t attr;
  ASSERT_EQ(pthread_attr_init(&attr), 0);
  ASSERT_EQ(pthread_attr_setstacksize(&attr, kStackBytes), 0);
  pthread_t thread;
  auto body = [](void* arg) -> void* {
    (*static_cast<const std::function<void()>*>(arg))();
    return nullptr;
  };
  ASSERT_EQ(pthread_create(&thread, &attr, body, const_cast<std::function<void()>*>(&work)), 0);
  ASSERT_EQ(pthread_join(thread, nullptr), 0);
  pthread_attr_destroy(&attr);
}

// Before the shear below: a = 0 and b = (1, 0, 0) static; c(t) = (0, 2^999 t, z(t)) with z from
// -2^-1073 to 2^1000; p(t) = (0, y(t), y(t)) with y from -2^-1074 to 2^1000. Then
//   V = (b - a) . ((c - a) x (p - a)) = c.y p.z - c.z p.y = y(t) (c.y(t) - z(t)),
// with roots r2 = 2^-1074 / (2^-1074 + 2^1000) (y = 0), about 2^-2074, and
// r1 = 2^-1073 / (2^999 + 2^-1073) (c.y = z), about 2^-2072: r2 < r1, the two about 2^-2073 apart.
// Contact needs V = 0. V(0) = (-2^-1074)(0 + 2^-1073) != 0. At r2, p = (0, 0, 0) = a, a vertex of
// the triangle: contact. So the query collides and its TOI is r2, which lies strictly between 0
// and the smallest subnormal 2^-1074: the tightest enclosure is [0, 2^-1074].
// The shear x' = x + y (determinant 1, time independent) is applied to every point so that no
// three points share a coordinate for all t (which would let the interval stage factor V and
// isolate each factor's single root separately); it maps the closed triangle onto the closed
// triangle, so answer and TOI are unchanged, and every sheared coordinate is exact:
//   a = 0, b = (1, 0, 0), c: (0, 0, -2^-1073) -> (2^999, 2^999, 2^1000),
//   p: (-2^-1074, -2^-1074, -2^-1074) -> (2^1000, 2^1000, 2^1000).
VertexFaceQuery close_roots_vertex_face() {
  return VertexFaceQuery{{-0x1p-1074, -0x1p-1074, -0x1p-1074}, {0, 0, 0}, {1, 0, 0}, {0, 0, -0x1p-1073},
                         {0x1p1000, 0x1p1000, 0x1p1000}, {0, 0, 0}, {1, 0, 0}, {0x1p999, 0x1p999, 0x1p1000}};
}

// The same four moving points as an edge-edge query: a0 = a, a1 = b, b0 = c, b1 = p. V is the same
// determinant, V(0) != 0, and at r2 the endpoint b1 = p meets the endpoint a0 = a: the same TOI.
EdgeEdgeQuery close_roots_edge_edge() {
  return EdgeEdgeQuery{{0, 0, 0}, {1, 0, 0}, {0, 0, -0x1p-1073}, {-0x1p-1074, -0x1p-1074, -0x1p-1074},
                       {0, 0, 0}, {1, 0, 0}, {0x1p999, 0x1p999, 0x1p1000}, {0x1p1000, 0x1p1000, 0x1p1000}};
}

const TimeInterval kCloseRootsToi{0.0, 0x1p-1074};

TEST(BoundedStack, ExpectedToiIsTheSmallestSubnormalCell) {
  // The hand-derived enclosure is two consecutive doubles (checked apart from the library).
  EXPECT_EQ(std::nextafter(kCloseRootsToi.lo, 1.0), kCloseRootsToi.hi);
}

class BoundedStack : public ::testing::TestWithParam<Method> {};

TEST_P(BoundedStack, EdgeEdgeWithRootsTwoToTheMinus2073ApartOnAQuarterMegabyteStack) {
  std::optional<TimeInterval> toi;
  bool collides = false;
  run_on_small_stack([&] {
    collides = edge_edge_ccd(close_roots_edge_edge(), GetParam());
    toi = edge_edge_toi(close_roots_edge_edge(), GetParam());
  });
  EXPECT_TRUE(collides);
  ASSERT_TRUE(toi.has_value());
  EXPECT_EQ(toi->lo, kCloseRootsToi.lo);
  EXPECT_EQ(toi->hi, kCloseRootsToi.hi);
}

TEST_P(BoundedStack, VertexFaceWithRootsTwoToTheMinus2073ApartOnAQuarterMegabyteStack) {
  std::optional<TimeInterval> toi;
  bool collides = false;
  run_on_small_stack([&] {
    collides = vertex_face_ccd(close_roots_vertex_face(), GetParam());
    toi = vertex_face_toi(close_roots_vertex_face(), GetParam());
  });
  EXPECT_TRUE(collides);
  ASSERT_TRUE(toi.has_value());
  EXPECT_EQ(toi->lo, kCloseRootsToi.lo);
  EXPECT_EQ(toi->hi, kCloseRootsToi.hi);
}

INSTANTIATE_TEST_SUITE_P(ExactMethods, BoundedStack,
                         ::testing::Values(Method::filtered, Method::exact),
                         [](const ::testing::TestParamInfo<Method>& info) {
                           return info.param == Method::filtered ? "filtered" : "exact";
                         });

}  // namespace
}  // namespace exactccd
