// The primitives of a public exactccd::Scene (exactccd/scene.hpp) and its broad-phase
// candidates, shared by the scene functions, the CLI and the scene benchmark.
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "exactccd/scene.hpp"
#include "scene/broad_phase.hpp"

namespace exactccd::scene {

/// A scene's vertex-face vertices, its edges, its isolated points and its candidate pairs.
struct ScenePrimitives {
  /// Vertices referenced by a triangle, an extra edge or a point; ascending, no duplicates.
  std::vector<int> vertices;
  /// The triangles' unique edges and the extra edges, each ascending, sorted, no duplicates.
  std::vector<Edge> edges;
  /// The isolated points taking part in point-edge and point-point pairs: listed points that
  /// are an endpoint of no edge, ascending, no duplicates. Empty for a 3D scene with d = 0.
  std::vector<int> points;
  /// {vertex, triangle}, {edge i, edge j} (indices into `edges`, i < j), {point, edge},
  /// {point p, point q} (p < q), pairs sharing a vertex index excluded; every list sorted.
  /// Only pairs whose boxes over [0, tmax], grown by d, overlap.
  Candidates candidates;
};

/// Throws std::invalid_argument naming `name`[i] when a position has a NaN or infinite
/// coordinate.
void require_finite_positions(const std::vector<Vec3>& positions, const char* name);

/// Throws std::invalid_argument when a triangle has an index outside [0, vertex_count) or a
/// repeated index.
void require_valid_triangles(const std::vector<Triangle>& triangles, std::size_t vertex_count);

/// Validates the scene (exactccd::validate) and computes its primitives and candidates for the
/// question "within distance params.min_distance at some t in [0, params.tmax]" (params
/// assumed valid: exactccd::validate(SceneOptions)); the broad phase on up to `threads` threads
/// (the result does not depend on them).
ScenePrimitives scene_primitives(const Scene& scene, const CcdParams& params = {}, unsigned threads = 1);

/// As above for a scene in the plane (no triangles; isolated points for every d).
ScenePrimitives scene_primitives(const Scene2d& scene, const CcdParams& params = {}, unsigned threads = 1);

/// scene_primitives() without the candidates (validates the scene).
ScenePrimitives scene_topology(const Scene& scene, const CcdParams& params);

/// As above for a scene in the plane.
ScenePrimitives scene_topology(const Scene2d& scene, const CcdParams& params);

/// The box of every vertex over the times [0, params.tmax], grown by params.min_distance (the
/// exact swept box when tmax = 1, else add_vertex_until's certified one; inflated()): two
/// primitives within that distance at some such time have overlapping hulls of their
/// vertices' boxes. 2D points lie in the plane z = 0. On up to `threads` threads.
std::vector<Box> vertex_boxes(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
                              const CcdParams& params, unsigned threads = 1);

/// As above for points in the plane.
std::vector<Box> vertex_boxes(const std::vector<Vec2>& positions_t0, const std::vector<Vec2>& positions_t1,
                              const CcdParams& params, unsigned threads = 1);

/// The boxes of vertex_boxes(positions_t0, positions_t1, params, threads) written into `boxes`
/// (resized; nothing allocated when it has the size already: a line search's refit).
void vertex_boxes(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
                  const CcdParams& params, unsigned threads, std::vector<Box>& boxes);

/// Throws std::invalid_argument unless params.min_distance is finite and >= 0 and params.tmax
/// is in (0, 1].
void require_valid_params(const CcdParams& params);

/// The triangles of a scene (none in the plane).
inline const std::vector<Triangle>& triangles_of(const Scene& s) { return s.triangles; }
inline const std::vector<Triangle>& triangles_of(const Scene2d&) {
  static const std::vector<Triangle> none;
  return none;
}

/// A point as a 3D point (the plane z = 0 for Vec2).
inline Vec3 lift(const Vec3& p) { return p; }
inline Vec3 lift(const Vec2& p) { return {p.x, p.y, 0.0}; }

/// The rows of a pair's query of n points per time: the vertices of side a, then of side b
/// (na + nb = n of them), at t = 0 and then at t = 1, in the query's row order.
template <std::size_t n, class Point>
std::array<Point, 2 * n> pair_rows(const std::vector<Point>& x0, const std::vector<Point>& x1, const int* a, int na,
                                   const int* b, int nb) {
  if (na < 0 || nb < 0 || static_cast<std::size_t>(na + nb) != n)
    throw std::logic_error("exactccd scene: a pair's sides do not make up its query");
  // Every row written below (no zero fill first: a `rep stos` that showed in profiles), straight
  // from the sides (no array of the vertices in between).
  std::array<Point, 2 * n> r;
  const auto put = [&](std::size_t k, int vertex) {
    r[k] = x0[static_cast<std::size_t>(vertex)];
    r[n + k] = x1[static_cast<std::size_t>(vertex)];
  };
  for (int i = 0; i < na; ++i) put(static_cast<std::size_t>(i), a[i]);
  for (int i = 0; i < nb; ++i) put(static_cast<std::size_t>(na + i), b[i]);
  return r;
}

/// The query of a pair (pair_rows as the query's rows).
template <class Query, class Point>
Query pair_query(const std::vector<Point>& x0, const std::vector<Point>& x1, const int* a, int na,
                 const int* b, int nb) {
  constexpr std::size_t n = std::tuple_size<decltype(rows(std::declval<Query>()))>::value / 2;
  return from_rows<Query>(pair_rows<n>(x0, x1, a, na, b, nb));
}

/// The vertex-face query of vertex v against triangle t of the scene.
VertexFaceQuery vertex_face_query(const Scene& scene, int v, int t);

/// The edge-edge query of edges a and b of the scene.
EdgeEdgeQuery edge_edge_query(const Scene& scene, const Edge& a, const Edge& b);

}  // namespace exactccd::scene
