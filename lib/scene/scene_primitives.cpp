#include "scene/scene_primitives.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <string>

#include "api/number_text.hpp"
#include "scene/candidate_finder.hpp"
#include "scene/parallel.hpp"
#include "scene/time_bounds.hpp"

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

void validate(const Scene2d& scene) {
  const std::size_t n = scene.positions_t0.size();
  if (scene.positions_t1.size() != n)
    fail("positions_t0 has " + std::to_string(n) + " vertices but positions_t1 has " +
         std::to_string(scene.positions_t1.size()));
  if (n > static_cast<std::size_t>(INT_MAX)) fail("more than INT_MAX vertices");
  for (const auto* positions : {&scene.positions_t0, &scene.positions_t1})
    for (std::size_t i = 0; i < positions->size(); ++i) {
      const Vec2& p = (*positions)[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        fail(std::string(positions == &scene.positions_t0 ? "positions_t0" : "positions_t1") + "[" +
             std::to_string(i) + "] has a non-finite coordinate (NaN or infinity)");
    }
  for (std::size_t i = 0; i < scene.edges.size(); ++i) require_valid_indices(scene.edges[i], i, "edge", n);
  for (std::size_t i = 0; i < scene.points.size(); ++i)
    require_valid_indices(std::array<int, 1>{scene.points[i]}, i, "point", n);
}

void validate(const SceneOptions& options) {
  scene::require_valid_params(CcdParams{options.min_distance, options.tmax});
  if (options.threads > kMaxThreads)
    fail("threads must be in 0.." + std::to_string(kMaxThreads) + " (0: every hardware thread), not " +
         std::to_string(options.threads));
}

namespace scene {

void require_valid_params(const CcdParams& params) {
  if (!(std::isfinite(params.min_distance) && params.min_distance >= 0))
    fail("min_distance must be finite and >= 0, not " + shortest_text(params.min_distance));
  if (!(params.tmax > 0 && params.tmax <= 1))
    fail("tmax must be in (0, 1], not " + shortest_text(params.tmax));
}

void require_finite_positions(const std::vector<Vec3>& positions, const char* name) {
  for (std::size_t i = 0; i < positions.size(); ++i) {
    // x - x is +0 for a finite x (any rounding mode: an exact zero difference is +0 except
    // rounding downwards, where it is -0, which also compares equal to 0) and NaN for an
    // infinity or a NaN; a sum with a NaN term is NaN, which compares unequal to 0.
    const Vec3& p = positions[i];
    if (!((p.x - p.x) + (p.y - p.y) + (p.z - p.z) == 0))
      fail(std::string(name) + "[" + std::to_string(i) + "] has a non-finite coordinate (NaN or infinity)");
  }
}

void require_valid_triangles(const std::vector<Triangle>& triangles, std::size_t vertex_count) {
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    // The usual case at a few comparisons; a bad triangle gets require_valid_indices' message.
    const Triangle& t = triangles[i];
    const auto in_range = [&](int v) { return v >= 0 && static_cast<std::size_t>(v) < vertex_count; };
    if (!in_range(t[0]) || !in_range(t[1]) || !in_range(t[2]) || t[0] == t[1] || t[0] == t[2] || t[1] == t[2])
      require_valid_indices(t, i, "triangle", vertex_count);
  }
}

namespace {

/// The primitives of a 3D or 2D scene (validated), without candidates; `with_points`: whether
/// isolated points form point-edge and point-point pairs.
template <class SceneT>
ScenePrimitives topology(const SceneT& s, bool with_points) {
  const std::vector<Triangle>& triangles = triangles_of(s);
  ScenePrimitives p;
  p.edges = unique_edges(triangles);  // sorted, unique
  if (!s.edges.empty()) {  // the extra edges sorted and merged in
    const auto middle = static_cast<std::ptrdiff_t>(p.edges.size());
    for (const auto& e : s.edges) p.edges.push_back({std::min(e[0], e[1]), std::max(e[0], e[1])});
    std::sort(p.edges.begin() + middle, p.edges.end());
    std::inplace_merge(p.edges.begin(), p.edges.begin() + middle, p.edges.end());
    p.edges.erase(std::unique(p.edges.begin(), p.edges.end()), p.edges.end());
  }
  // Bytes, not std::vector<bool>: a store per mark instead of a read-modify-write of a bit. The
  // triangles' edges have only the triangles' vertices: the extra edges' are marked on their own.
  std::vector<char> used(s.positions_t0.size(), 0);
  for (const Triangle& t : triangles)
    for (int v : t) used[static_cast<std::size_t>(v)] = 1;
  for (const auto& e : s.edges) used[static_cast<std::size_t>(e[0])] = used[static_cast<std::size_t>(e[1])] = 1;
  for (int v : s.points) used[static_cast<std::size_t>(v)] = 1;
  p.vertices.reserve(used.size());
  for (std::size_t v = 0; v < used.size(); ++v)
    if (used[v]) p.vertices.push_back(static_cast<int>(v));
  if (with_points && !s.points.empty()) {
    std::vector<char> on_edge(s.positions_t0.size(), 0);
    for (const Edge& e : p.edges) on_edge[static_cast<std::size_t>(e[0])] = on_edge[static_cast<std::size_t>(e[1])] = 1;
    for (int v : s.points)
      if (!on_edge[static_cast<std::size_t>(v)]) p.points.push_back(v);
    std::sort(p.points.begin(), p.points.end());
    p.points.erase(std::unique(p.points.begin(), p.points.end()), p.points.end());
  }
  return p;
}

// Each vertex's box over [0, tmax], grown by d: the exact swept box (input coordinates) over
// the whole step, else the certified enclosure of add_vertex_until; then inflated() (both
// proofs next to their code). A pair within d at some t in [0, tmax] has overlapping boxes.
template <class Point>
void boxes_of(const std::vector<Point>& x0, const std::vector<Point>& x1, const CcdParams& params, unsigned threads,
              std::vector<Box>& boxes) {
  boxes.resize(x0.size());
  parallel_ranges(boxes.size(), threads, std::size_t{1} << 14, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      const Vec3 a = lift(x0[v]), b = lift(x1[v]);
      Box box;
      if (params.whole_step()) {
        box.lo = {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
        box.hi = {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
      } else {
        box = empty_box();
        add_vertex_until(box, a, b, params.tmax);
      }
      boxes[v] = inflated(box, params.min_distance);
    }
  });
}

}  // namespace

std::vector<Box> vertex_boxes(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, const CcdParams& params,
                              unsigned threads) {
  std::vector<Box> boxes;
  boxes_of(x0, x1, params, threads, boxes);
  return boxes;
}

std::vector<Box> vertex_boxes(const std::vector<Vec2>& x0, const std::vector<Vec2>& x1, const CcdParams& params,
                              unsigned threads) {
  std::vector<Box> boxes;
  boxes_of(x0, x1, params, threads, boxes);
  return boxes;
}

void vertex_boxes(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, const CcdParams& params, unsigned threads,
                  std::vector<Box>& boxes) {
  boxes_of(x0, x1, params, threads, boxes);
}

ScenePrimitives scene_topology(const Scene& s, const CcdParams& params) {
  validate(s);
  return topology(s, !params.contact_only());
}

ScenePrimitives scene_topology(const Scene2d& s, const CcdParams&) {
  validate(s);
  return topology(s, true);
}

ScenePrimitives scene_primitives(const Scene& s, const CcdParams& params, unsigned threads) {
  ScenePrimitives p = scene_topology(s, params);
  BroadPhaseTrees trees(s.triangles, p.edges, p.vertices, p.points);
  trees.fit(vertex_boxes(s.positions_t0, s.positions_t1, params, threads), threads);
  p.candidates = trees.candidates(threads);
  return p;
}

ScenePrimitives scene_primitives(const Scene2d& s, const CcdParams& params, unsigned threads) {
  ScenePrimitives p = scene_topology(s, params);
  BroadPhaseTrees trees(triangles_of(s), p.edges, p.vertices, p.points);
  trees.fit(vertex_boxes(s.positions_t0, s.positions_t1, params, threads), threads);
  p.candidates = trees.candidates(threads);
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
