#include "scene/scene_primitives.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <string>

namespace exactccd {
namespace {

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("exactccd scene: " + what);
}

/// Checks the indices of element `i` of a list of `kind`s (a triangle, an edge, a point).
template <std::size_t N>
void require_valid_indices(const std::array<int, N>& element, std::size_t i, const char* kind,
                           std::size_t vertex_count) {
  for (std::size_t k = 0; k < N; ++k) {
    const int v = element[k];
    if (v < 0 || static_cast<std::size_t>(v) >= vertex_count)
      fail(std::string(kind) + " " + std::to_string(i) + " has vertex index " + std::to_string(v) +
           ", out of range [0, " + std::to_string(vertex_count) + ")");
    for (std::size_t l = 0; l < k; ++l)
      if (element[l] == v)
        fail(std::string(kind) + " " + std::to_string(i) + " repeats vertex index " + std::to_string(v) +
             " (a degenerate " + kind + ")");
  }
}

}  // namespace

void validate(const Scene& scene) {
  const std::size_t n = scene.positions_t0.size();
  if (scene.positions_t1.size() != n)
    fail("positions_t0 has " + std::to_string(n) + " vertices but positions_t1 has " +
         std::to_string(scene.positions_t1.size()));
  if (n > static_cast<std::size_t>(INT_MAX)) fail("more than INT_MAX vertices");
  scene::require_finite_positions(scene.positions_t0, "positions_t0");
  scene::require_finite_positions(scene.positions_t1, "positions_t1");
  scene::require_valid_triangles(scene.triangles, n);
  for (std::size_t i = 0; i < scene.edges.size(); ++i) require_valid_indices(scene.edges[i], i, "edge", n);
  for (std::size_t i = 0; i < scene.points.size(); ++i)
    require_valid_indices(std::array<int, 1>{scene.points[i]}, i, "point", n);
}

namespace scene {

void require_finite_positions(const std::vector<Vec3>& positions, const char* name) {
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec3& p = positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      fail(std::string(name) + "[" + std::to_string(i) + "] has a non-finite coordinate (NaN or infinity)");
  }
}

void require_valid_triangles(const std::vector<Triangle>& triangles, std::size_t vertex_count) {
  for (std::size_t i = 0; i < triangles.size(); ++i)
    require_valid_indices(triangles[i], i, "triangle", vertex_count);
}

ScenePrimitives scene_primitives(const Scene& s) {
  validate(s);
  ScenePrimitives p;
  p.edges = unique_edges(s.triangles);
  for (const auto& e : s.edges) p.edges.push_back({std::min(e[0], e[1]), std::max(e[0], e[1])});
  std::sort(p.edges.begin(), p.edges.end());
  p.edges.erase(std::unique(p.edges.begin(), p.edges.end()), p.edges.end());
  std::vector<bool> used(s.positions_t0.size(), false);
  for (const Triangle& t : s.triangles)
    for (int v : t) used[v] = true;
  for (const Edge& e : p.edges) used[e[0]] = used[e[1]] = true;
  for (int v : s.points) used[v] = true;
  for (std::size_t v = 0; v < used.size(); ++v)
    if (used[v]) p.vertices.push_back(static_cast<int>(v));
  p.candidates = find_candidates(s.positions_t0, s.positions_t1, s.triangles, p.edges, p.vertices);
  return p;
}

VertexFaceQuery vertex_face_query(const Scene& s, int v, int t) {
  const Triangle& f = s.triangles[t];
  const auto& x0 = s.positions_t0;
  const auto& x1 = s.positions_t1;
  return {x0[v], x0[f[0]], x0[f[1]], x0[f[2]], x1[v], x1[f[0]], x1[f[1]], x1[f[2]]};
}

EdgeEdgeQuery edge_edge_query(const Scene& s, const Edge& a, const Edge& b) {
  const auto& x0 = s.positions_t0;
  const auto& x1 = s.positions_t1;
  return {x0[a[0]], x0[a[1]], x0[b[0]], x0[b[1]], x1[a[0]], x1[a[1]], x1[b[0]], x1[b[1]]};
}

}  // namespace scene
}  // namespace exactccd
