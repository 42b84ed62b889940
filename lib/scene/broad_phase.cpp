#include "scene/broad_phase.hpp"

#include "scene/candidate_finder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace exactccd::scene {
namespace {

/// A box of one of the two sets being swept.
struct Item {
  double lo;  ///< lower bound on the sweep axis
  int index;
  bool from_a;
};

/// Strips along one axis: strip_of(y) = floor((y - origin) / width) clamped to [0, count),
/// which is monotone in y (every step is), so a box [lo, hi] lies in strips strip_of(lo) ..
/// strip_of(hi), and two overlapping boxes both lie in the strip of the larger of their lower
/// bounds (it is in both boxes' ranges): reporting a pair only there reports it once.
struct Strips {
  double origin = 0, width = 1;
  int count = 1;
  int strip_of(double y) const {
    const double q = std::floor((y - origin) / width);
    if (!(q > 0)) return 0;  // also -inf
    return q >= count - 1 ? count - 1 : static_cast<int>(q);
  }
};

/// Strips along `axis` about twice as wide as the boxes' mean extent on it, fewer when the
/// boxes would otherwise be listed more than four times over in total.
Strips choose_strips(const std::vector<const Box*>& boxes, int axis) {
  Strips strips;
  if (boxes.size() < 64) return strips;
  double lo = boxes[0]->lo[axis], hi = boxes[0]->hi[axis], mean = 0;
  for (const Box* b : boxes) {
    lo = std::min(lo, b->lo[axis]);
    hi = std::max(hi, b->hi[axis]);
    mean += (b->hi[axis] - b->lo[axis]) / static_cast<double>(boxes.size());
  }
  const double extent = hi - lo;
  if (!(extent > 0) || !std::isfinite(extent)) return strips;
  const double wanted = mean > 0 ? extent / mean : std::sqrt(static_cast<double>(boxes.size()));
  strips.origin = lo;
  for (int count = static_cast<int>(std::min(wanted, 4096.0)); count > 1; count /= 2) {
    strips.count = count;
    strips.width = extent / count;
    std::size_t entries = 0;
    for (const Box* b : boxes) entries += strips.strip_of(b->hi[axis]) - strips.strip_of(b->lo[axis]) + 1;
    if (entries <= 4 * boxes.size()) return strips;
  }
  return Strips{};
}

/// Calls report(i, j) for every i in boxes_a, j in boxes_b with overlapping boxes (when a and b
/// are the same set, each unordered pair once, i != j). Sort-and-sweep along the axis of
/// largest extent, within strips along the second largest (for sheets and shells, whose boxes
/// overlap along any one axis far more often than in space).
template <class Report>
void sweep(const std::vector<Box>& a, const std::vector<Box>& b, bool same_set, Report&& report) {
  std::vector<const Box*> all;
  all.reserve(a.size() + (same_set ? 0 : b.size()));
  for (const Box& x : a) all.push_back(&x);
  if (!same_set)
    for (const Box& x : b) all.push_back(&x);
  if (all.empty()) return;
  std::array<double, 3> extent{};
  for (int k = 0; k < 3; ++k) {
    double lo = all[0]->lo[k], hi = all[0]->hi[k];
    for (const Box* x : all) lo = std::min(lo, x->lo[k]), hi = std::max(hi, x->hi[k]);
    extent[k] = hi - lo;
  }
  std::array<int, 3> axes{0, 1, 2};
  std::stable_sort(axes.begin(), axes.end(), [&](int i, int j) { return extent[i] > extent[j]; });
  const int along = axes[0], across = axes[1];
  const Strips strips = choose_strips(all, across);

  // Sorted once along the sweep axis, then dealt out to the strips in that order.
  std::vector<Item> sorted;
  sorted.reserve(all.size());
  for (int i = 0; i < static_cast<int>(a.size()); ++i) sorted.push_back({a[i].lo[along], i, true});
  if (!same_set)
    for (int j = 0; j < static_cast<int>(b.size()); ++j) sorted.push_back({b[j].lo[along], j, false});
  std::sort(sorted.begin(), sorted.end(), [](const Item& x, const Item& y) {
    return x.lo < y.lo || (x.lo == y.lo && (x.from_a > y.from_a || (x.from_a == y.from_a && x.index < y.index)));
  });
  std::vector<std::vector<Item>> strip_items(strips.count);
  for (const Item& it : sorted) {
    const Box& box = it.from_a ? a[it.index] : b[it.index];
    for (int s = strips.strip_of(box.lo[across]), end = strips.strip_of(box.hi[across]); s <= end; ++s)
      strip_items[s].push_back(it);
  }
  for (int s = 0; s < strips.count; ++s) {
    const std::vector<Item>& items = strip_items[s];
    for (std::size_t u = 0; u < items.size(); ++u) {
      const Item& it = items[u];
      const Box& box = it.from_a ? a[it.index] : b[it.index];
      for (std::size_t w = u + 1; w < items.size() && items[w].lo <= box.hi[along]; ++w) {
        const Item& other = items[w];
        if (!same_set && other.from_a == it.from_a) continue;
        const Box& other_box = other.from_a ? a[other.index] : b[other.index];
        if (!overlap(box, other_box)) continue;
        if (strips.count > 1 && strips.strip_of(std::max(box.lo[across], other_box.lo[across])) != s) continue;
        if (same_set)
          report(std::min(it.index, other.index), std::max(it.index, other.index));
        else if (it.from_a)
          report(it.index, other.index);
        else
          report(other.index, it.index);
      }
    }
  }
}

}  // namespace

Box swept_box(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
              const int* vertices, int count) {
  const Vec3& first = positions_t0[vertices[0]];
  Box box;
  box.lo = {first.x, first.y, first.z};
  box.hi = box.lo;
  for (int i = 0; i < count; ++i)
    for (const Vec3* p : {&positions_t0[vertices[i]], &positions_t1[vertices[i]]}) {
      const double c[3] = {p->x, p->y, p->z};
      for (int k = 0; k < 3; ++k) {
        box.lo[k] = std::min(box.lo[k], c[k]);
        box.hi[k] = std::max(box.hi[k], c[k]);
      }
    }
  return box;
}

Box swept_box(const MovingMesh& mesh, const int* vertices, int count) {
  return swept_box(mesh.positions_t0, mesh.positions_t1, vertices, count);
}

// If dist(x, y) <= d for x in box A and y in box B, then |x_k - y_k| <= d on every axis k, so
// [A.lo_k - d, A.hi_k + d] meets [B.lo_k, B.hi_k]: the boxes overlap once one of them (here:
// both, the more conservative) is grown by d on every side, provided the grown bounds are at
// least as far out as the exact ones. The computed l = fl(A.lo_k - d) is, in any rounding
// direction, the exact difference x itself or one of the two doubles around it; so the double
// below it, nextafter(l, -inf), is <= x (the scene entry points install round-to-nearest
// anyway). Likewise nextafter(fl(A.hi_k + d), +inf) >= A.hi_k + d. The bounds and d are finite
// (or +-inf after an earlier overflow, which stays outside), so nothing is NaN; an overflow
// gives -inf / +inf, still outside. fl(. - d), fl(. + d) and nextafter are monotone, so the
// hull of inflated vertex boxes equals the inflated hull. The box test stays exact (<=) on the
// inflated bounds.
Box inflated(const Box& box, double d) {
  if (!(d > 0)) return box;
  Box out;
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    out.lo[k] = std::nextafter(box.lo[k] - d, -inf);
    out.hi[k] = std::nextafter(box.hi[k] + d, inf);
  }
  return out;
}

Candidates sweep_candidates(const std::vector<Box>& vertex_boxes, const std::vector<Triangle>& triangles,
                            const std::vector<Edge>& edges, const std::vector<int>& vertices,
                            const std::vector<int>& points) {
  const auto hull_of = [&](const int* v, int n) {
    Box box = vertex_boxes[v[0]];
    for (int i = 1; i < n; ++i) box = hull(box, vertex_boxes[v[i]]);
    return box;
  };
  std::vector<Box> vertex_list(vertices.size()), triangle_boxes(triangles.size()), edge_boxes(edges.size()),
      point_boxes(points.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) vertex_list[i] = vertex_boxes[vertices[i]];
  for (std::size_t t = 0; t < triangles.size(); ++t) triangle_boxes[t] = hull_of(triangles[t].data(), 3);
  for (std::size_t e = 0; e < edges.size(); ++e) edge_boxes[e] = hull_of(edges[e].data(), 2);
  for (std::size_t i = 0; i < points.size(); ++i) point_boxes[i] = vertex_boxes[points[i]];

  Candidates c;
  if (!triangles.empty())
    sweep(vertex_list, triangle_boxes, false, [&](int i, int t) {
      const int v = vertices[i];
      const Triangle& tri = triangles[t];
      if (tri[0] != v && tri[1] != v && tri[2] != v) c.vertex_face.push_back({v, t});
    });
  sweep(edge_boxes, edge_boxes, true, [&](int i, int j) {
    const Edge &a = edges[i], &b = edges[j];
    if (a[0] != b[0] && a[0] != b[1] && a[1] != b[0] && a[1] != b[1]) c.edge_edge.push_back({i, j});
  });
  if (!points.empty()) {
    // Isolated points are on no edge and distinct: no pair shares a vertex.
    if (!edges.empty())
      sweep(point_boxes, edge_boxes, false, [&](int i, int e) { c.point_edge.push_back({points[i], e}); });
    sweep(point_boxes, point_boxes, true, [&](int i, int j) { c.point_point.push_back({points[i], points[j]}); });
  }
  for (auto* list : {&c.vertex_face, &c.edge_edge, &c.point_edge, &c.point_point}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  return c;
}

Candidates find_candidates(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
                           const std::vector<Triangle>& triangles, const std::vector<Edge>& edges,
                           const std::vector<int>& vertices) {
  std::vector<Box> boxes(positions_t0.size());
  for (int v = 0; v < static_cast<int>(boxes.size()); ++v) boxes[v] = swept_box(positions_t0, positions_t1, &v, 1);
  return find_candidates(boxes, triangles, edges, vertices, {});
}

Candidates find_candidates(const std::vector<Box>& vertex_boxes, const std::vector<Triangle>& triangles,
                           const std::vector<Edge>& edges, const std::vector<int>& vertices,
                           const std::vector<int>& points, unsigned threads) {
  BroadPhaseTrees trees(triangles, edges, vertices, points);
  trees.fit(std::vector<Box>(vertex_boxes), threads);
  return trees.candidates(threads);
}

Candidates find_candidates(const MovingMesh& mesh, const std::vector<Edge>& edges) {
  std::vector<int> all(mesh.positions_t0.size());
  std::iota(all.begin(), all.end(), 0);
  return find_candidates(mesh.positions_t0, mesh.positions_t1, mesh.triangles, edges, all);
}

std::vector<std::array<int, 2>> overlapping_triangle_pairs(const std::vector<Vec3>& positions,
                                                           const std::vector<Triangle>& triangles) {
  std::vector<Box> boxes(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    boxes[t] = swept_box(positions, positions, triangles[t].data(), 3);
  std::vector<std::array<int, 2>> pairs;
  sweep(boxes, boxes, true, [&](int i, int j) { pairs.push_back({i, j}); });
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace exactccd::scene
