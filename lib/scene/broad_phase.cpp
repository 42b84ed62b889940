#include "scene/broad_phase.hpp"

#include <algorithm>
#include <numeric>

namespace exactccd::scene {
namespace {

bool overlap(const Box& a, const Box& b) {
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

/// Calls report(i, j) for every i in boxes_a, j in boxes_b with overlapping boxes (when a and b
/// are the same set, each unordered pair once, i != j). Sort-and-sweep on x.
template <class Report>
void sweep(const std::vector<Box>& a, const std::vector<Box>& b, bool same_set, Report&& report) {
  struct Item {
    double lo_x;
    int index;
    bool from_a;
  };
  std::vector<Item> items;
  items.reserve(a.size() + (same_set ? 0 : b.size()));
  for (int i = 0; i < static_cast<int>(a.size()); ++i) items.push_back({a[i].lo[0], i, true});
  if (!same_set)
    for (int j = 0; j < static_cast<int>(b.size()); ++j) items.push_back({b[j].lo[0], j, false});
  std::sort(items.begin(), items.end(), [](const Item& x, const Item& y) {
    return x.lo_x < y.lo_x || (x.lo_x == y.lo_x && (x.from_a > y.from_a || (x.from_a == y.from_a && x.index < y.index)));
  });
  for (std::size_t s = 0; s < items.size(); ++s) {
    const Item& it = items[s];
    const Box& box = it.from_a ? a[it.index] : b[it.index];
    for (std::size_t u = s + 1; u < items.size() && items[u].lo_x <= box.hi[0]; ++u) {
      const Item& other = items[u];
      if (!same_set && other.from_a == it.from_a) continue;
      const Box& other_box = other.from_a ? a[other.index] : b[other.index];
      if (!overlap(box, other_box)) continue;
      if (same_set)
        report(std::min(it.index, other.index), std::max(it.index, other.index));
      else if (it.from_a)
        report(it.index, other.index);
      else
        report(other.index, it.index);
    }
  }
}

}  // namespace

Box swept_box(const MovingMesh& mesh, const int* vertices, int count) {
  Box box;
  box.lo = {mesh.positions_t0[vertices[0]].x, mesh.positions_t0[vertices[0]].y, mesh.positions_t0[vertices[0]].z};
  box.hi = box.lo;
  for (int i = 0; i < count; ++i)
    for (const Vec3* p : {&mesh.positions_t0[vertices[i]], &mesh.positions_t1[vertices[i]]}) {
      const double c[3] = {p->x, p->y, p->z};
      for (int k = 0; k < 3; ++k) {
        box.lo[k] = std::min(box.lo[k], c[k]);
        box.hi[k] = std::max(box.hi[k], c[k]);
      }
    }
  return box;
}

Candidates find_candidates(const MovingMesh& mesh, const std::vector<Edge>& edges) {
  const int n = static_cast<int>(mesh.positions_t0.size());
  std::vector<Box> vertex_boxes(n), triangle_boxes(mesh.triangles.size()), edge_boxes(edges.size());
  for (int v = 0; v < n; ++v) vertex_boxes[v] = swept_box(mesh, &v, 1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    triangle_boxes[t] = swept_box(mesh, mesh.triangles[t].data(), 3);
  for (std::size_t e = 0; e < edges.size(); ++e) edge_boxes[e] = swept_box(mesh, edges[e].data(), 2);

  Candidates c;
  sweep(vertex_boxes, triangle_boxes, false, [&](int v, int t) {
    const Triangle& tri = mesh.triangles[t];
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

}  // namespace exactccd::scene
