#include "scene/broad_phase.hpp"

#include <algorithm>
#include <cmath>
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

bool overlap(const Box& a, const Box& b) {
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

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

Candidates find_candidates(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
                           const std::vector<Triangle>& triangles, const std::vector<Edge>& edges,
                           const std::vector<int>& vertices) {
  std::vector<Box> vertex_boxes(vertices.size()), triangle_boxes(triangles.size()), edge_boxes(edges.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    vertex_boxes[i] = swept_box(positions_t0, positions_t1, &vertices[i], 1);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    triangle_boxes[t] = swept_box(positions_t0, positions_t1, triangles[t].data(), 3);
  for (std::size_t e = 0; e < edges.size(); ++e)
    edge_boxes[e] = swept_box(positions_t0, positions_t1, edges[e].data(), 2);

  Candidates c;
  sweep(vertex_boxes, triangle_boxes, false, [&](int i, int t) {
    const int v = vertices[i];
    const Triangle& tri = triangles[t];
    if (tri[0] != v && tri[1] != v && tri[2] != v) c.vertex_face.push_back({v, t});
  });
  sweep(edge_boxes, edge_boxes, true, [&](int i, int j) {
    const Edge &a = edges[i], &b = edges[j];
    if (a[0] != b[0] && a[0] != b[1] && a[1] != b[0] && a[1] != b[1]) c.edge_edge.push_back({i, j});
  });
  std::sort(c.vertex_face.begin(), c.vertex_face.end());
  c.vertex_face.erase(std::unique(c.vertex_face.begin(), c.vertex_face.end()), c.vertex_face.end());
  std::sort(c.edge_edge.begin(), c.edge_edge.end());
  c.edge_edge.erase(std::unique(c.edge_edge.begin(), c.edge_edge.end()), c.edge_edge.end());
  return c;
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
