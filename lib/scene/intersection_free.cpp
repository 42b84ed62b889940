// Exact static self-intersection check of a triangle mesh (exactccd::intersection_free).
//
// Why CGAL's do_intersect and not the CCD queries: a static mesh is a motion with t0 == t1, and
// "an edge of one triangle meets the other closed triangle" is a vertex-face query whose vertex
// sweeps the edge over [0, 1] against the static triangle, so the project's own exact queries
// could decide it. But CGAL's Triangle_3/Segment_3/Point_3 intersection tests are long-used and
// well-kept, handle the coplanar cases directly, and with Exact_predicates_inexact_constructions
// _kernel every do_intersect is a filtered predicate (interval arithmetic with an exact
// fallback: Do_intersect_3 is among the kernel's filtered predicates), so the answer is exact
// for double input and needs no construction. tests/scene/test_scene.cpp cross-checks both ways.
// CGAL's tests require non-degenerate triangles and segments (a precondition, unchecked in
// release builds), so each triangle is first reduced exactly to its hull: a triangle, a
// segment or a point.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <atomic>
#include <variant>

#include "exactccd/scene.hpp"
#include "scene/box_tree.hpp"
#include "scene/broad_phase.hpp"
#include "scene/parallel.hpp"
#include "scene/scene_primitives.hpp"

namespace exactccd {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;
/// A closed triangle's or segment's hull, reduced to a non-degenerate simplex.
using Simplex = std::variant<Point, Segment, Triangle>;

Point point(const Vec3& v) { return {v.x, v.y, v.z}; }

Simplex hull(const Point& a, const Point& b) {
  if (a == b) return a;
  return Segment(a, b);
}

Simplex hull(const Point& p, const Point& q, const Point& r) {
  if (!CGAL::collinear(p, q, r)) return Triangle(p, q, r);
  // Collinear: the segment between the two extreme points (exact order tests).
  if (CGAL::collinear_are_ordered_along_line(p, q, r)) return hull(p, r);
  if (CGAL::collinear_are_ordered_along_line(q, p, r)) return hull(q, r);
  return hull(p, q);
}

bool meets(const Point& a, const Point& b) { return a == b; }
template <class Other>
bool meets(const Point& a, const Other& b) {
  return CGAL::do_intersect(a, b);
}
template <class Other>
bool meets(const Other& a, const Point& b) {
  return CGAL::do_intersect(b, a);
}
template <class A, class B>
bool meets(const A& a, const B& b) {
  return CGAL::do_intersect(a, b);
}

bool meets(const Simplex& a, const Simplex& b) {
  return std::visit([](const auto& x, const auto& y) { return meets(x, y); }, a, b);
}

/// The number of vertex indices two triangles share; only_in_s and only_in_t receive the
/// positions in s and in t of the last shared one.
int shared_vertices(const std::array<int, 3>& s, const std::array<int, 3>& t, int& only_in_s, int& only_in_t) {
  int count = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (s[i] == t[j]) {
        ++count;
        only_in_s = i;
        only_in_t = j;
      }
  return count;
}

}  // namespace

bool intersection_free(const std::vector<Vec3>& positions, const std::vector<std::array<int, 3>>& triangles) {
  return intersection_free(positions, triangles, 1);
}

namespace {

// The pairs of triangles whose boxes overlap come from a bounding volume hierarchy over the
// triangles' boxes traversed against itself (scene/box_tree.hpp: every overlapping pair once,
// among a few more whose outward-rounded float boxes overlap, dropped by the exact test), in pieces handed out to the threads, and are decided as
// they are found: nothing is listed, and the first intersecting pair stops every thread.

/// intersection_free on `threads` threads (resolved, inside the call's scene::with_threads),
/// after the checks of the input.
bool intersection_free_on(const std::vector<Vec3>& positions, const std::vector<std::array<int, 3>>& triangles,
                          unsigned threads) {
  std::vector<Point> points(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) points[i] = point(positions[i]);
  std::vector<Simplex> hulls(triangles.size());
  scene::parallel_ranges(triangles.size(), threads, std::size_t{1} << 12, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) hulls[t] = hull(points[triangles[t][0]], points[triangles[t][1]], points[triangles[t][2]]);
  });
  // The edge of triangle t opposite its corner i.
  const auto opposite = [&](const std::array<int, 3>& t, int i) {
    return hull(points[t[(i + 1) % 3]], points[t[(i + 2) % 3]]);
  };
  // Whether triangles i and j meet where they must not.
  const auto meet = [&](int i, int j) {
    int corner_i = 0, corner_j = 0;
    const int shared = shared_vertices(triangles[i], triangles[j], corner_i, corner_j);
    if (shared == 0) return meets(hulls[i], hulls[j]);
    return shared == 1 && (meets(opposite(triangles[i], corner_i), hulls[j]) ||
                           meets(opposite(triangles[j], corner_j), hulls[i]));
  };
  const auto box_of = [&](std::size_t t) { return scene::swept_box(positions, positions, triangles[t].data(), 3); };
  scene::BoxTree tree;
  tree.build(triangles.size(), box_of, threads);
  std::atomic<bool> found{false};
  const auto tasks = tree.pair_tasks(tree, threads > 1 ? 32 * std::size_t{threads} : 1);
  scene::parallel_chunks(tasks.size(), threads, 1, [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t k = begin; k < end && !found.load(std::memory_order_relaxed); ++k)
      tree.pairs_from(tree, tasks[k], [&](int i, int j) {
        if (found.load(std::memory_order_relaxed)) return false;
        if (scene::overlap(box_of(static_cast<std::size_t>(i)), box_of(static_cast<std::size_t>(j))) && meet(i, j))
          found = true;
        return !found.load(std::memory_order_relaxed);
      });
    return !found.load(std::memory_order_relaxed);
  });
  return !found.load();
}

}  // namespace

bool intersection_free(const std::vector<Vec3>& positions, const std::vector<std::array<int, 3>>& triangles,
                       unsigned threads) {
  const scene::SceneCall call;  // the FP environment (not cancellable)
  scene::require_finite_positions(positions, "positions");
  scene::require_valid_triangles(triangles, positions.size());
  threads = scene::resolve_threads(threads);
  return scene::with_threads(threads, [&] { return intersection_free_on(positions, triangles, threads); });
}

}  // namespace exactccd
