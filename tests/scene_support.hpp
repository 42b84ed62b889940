// Helpers of the scene tests: random and degenerate small scenes, and the brute-force all-pairs
// reference that find_collisions must reproduce.
#pragma once

#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include "exactccd/exactccd.hpp"

namespace exactccd::testing {

/// A random scene: n vertices, triangles / extra edges / points over random distinct indices.
/// degenerate: coordinates on the grid {-2..2} / 4, with coplanar (z = 0) and static vertices
/// and repeated positions mixed in; otherwise uniform in [-1, 1]^3 at t0 and t1.
inline Scene random_scene(std::mt19937_64& rng, int n, int triangles, int edges, int points, bool degenerate) {
  std::uniform_int_distribution<int> grid(-2, 2), pick(0, n - 1), choice(0, 5);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Scene s;
  const bool flat = degenerate && choice(rng) == 0;  // the whole scene in the plane z = 0
  for (int i = 0; i < n; ++i) {
    Vec3 p0, p1;
    if (degenerate) {
      p0 = {grid(rng) * 0.25, grid(rng) * 0.25, flat ? 0.0 : grid(rng) * 0.25};
      p1 = {grid(rng) * 0.25, grid(rng) * 0.25, flat ? 0.0 : grid(rng) * 0.25};
      const int c = choice(rng);
      if (c == 0) p1 = p0;                                     // static
      if (c == 1 && i > 0) p0 = s.positions_t0[pick(rng) % i];  // a repeated position
    } else {
      p0 = {uniform(rng), uniform(rng), uniform(rng)};
      p1 = {uniform(rng), uniform(rng), uniform(rng)};
    }
    s.positions_t0.push_back(p0);
    s.positions_t1.push_back(p1);
  }
  const auto distinct = [&](int count) {
    std::vector<int> v;
    while (static_cast<int>(v.size()) < count) {
      const int x = pick(rng);
      if (std::find(v.begin(), v.end(), x) == v.end()) v.push_back(x);
    }
    return v;
  };
  for (int t = 0; t < triangles; ++t) {
    const auto v = distinct(3);
    s.triangles.push_back({v[0], v[1], v[2]});
  }
  for (int e = 0; e < edges; ++e) {
    const auto v = distinct(2);
    s.edges.push_back({v[0], v[1]});
  }
  for (int p = 0; p < points; ++p) s.points.push_back(pick(rng));
  return s;
}

/// A random 3D scene (scene_support's, with triangles and extra edges) plus isolated points:
/// `extra` new vertices listed as points, and a listed point on an edge.
inline Scene scene_with_points(std::mt19937_64& rng, int n, int triangles, int edges, int extra, bool degenerate) {
  Scene s = random_scene(rng, n, triangles, edges, 1, degenerate);
  std::uniform_int_distribution<int> grid(-2, 2), pick(0, n - 1);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (int i = 0; i < extra; ++i) {
    const int v = static_cast<int>(s.positions_t0.size());
    if (degenerate) {
      s.positions_t0.push_back({grid(rng) * 0.25, grid(rng) * 0.25, grid(rng) * 0.25});
      s.positions_t1.push_back(i == 0 ? s.positions_t0.back() : Vec3{grid(rng) * 0.25, grid(rng) * 0.25, 0.0});
    } else {
      s.positions_t0.push_back({uniform(rng), uniform(rng), uniform(rng)});
      s.positions_t1.push_back({uniform(rng), uniform(rng), uniform(rng)});
    }
    s.points.push_back(v);
  }
  if (!s.triangles.empty()) s.points.push_back(s.triangles[0][1]);  // on an edge: not isolated
  if (extra > 0) s.points.push_back(s.points[1]);                   // a repeat is harmless
  return s;
}

/// The scene's VF vertices (referenced by anything) and EE edges, as scene.hpp defines them.
inline std::vector<int> scene_vertices(const Scene& s) {
  std::set<int> v(s.points.begin(), s.points.end());
  for (const auto& t : s.triangles) v.insert(t.begin(), t.end());
  for (const auto& e : s.edges) v.insert(e.begin(), e.end());
  return {v.begin(), v.end()};
}
inline std::vector<std::array<int, 2>> scene_edges(const Scene& s) {
  std::set<std::array<int, 2>> e;
  const auto add = [&](int a, int b) { e.insert({std::min(a, b), std::max(a, b)}); };
  for (const auto& t : s.triangles)
    for (int i = 0; i < 3; ++i) add(t[i], t[(i + 1) % 3]);
  for (const auto& x : s.edges) add(x[0], x[1]);
  return {e.begin(), e.end()};
}

inline VertexFaceQuery vf_query(const Scene& s, int v, int t) {
  const auto& f = s.triangles[t];
  const auto &x0 = s.positions_t0, &x1 = s.positions_t1;
  return {x0[v], x0[f[0]], x0[f[1]], x0[f[2]], x1[v], x1[f[0]], x1[f[1]], x1[f[2]]};
}
inline EdgeEdgeQuery ee_query(const Scene& s, const std::array<int, 2>& a, const std::array<int, 2>& b) {
  const auto &x0 = s.positions_t0, &x1 = s.positions_t1;
  return {x0[a[0]], x0[a[1]], x0[b[0]], x0[b[1]], x1[a[0]], x1[a[1]], x1[b[0]], x1[b[1]]};
}

/// Every non-adjacent VF and EE pair, each answered independently with `method`; in the order
/// find_collisions promises.
inline std::vector<Collision> brute_force_collisions(const Scene& s, Method method = Method::exact) {
  std::vector<Collision> out;
  for (int v : scene_vertices(s))
    for (int t = 0; t < static_cast<int>(s.triangles.size()); ++t) {
      const auto& f = s.triangles[t];
      if (f[0] == v || f[1] == v || f[2] == v) continue;
      if (const auto toi = vertex_face_toi(vf_query(s, v, t), method)) {
        Collision c;
        c.kind = CollisionKind::vertex_face;
        c.vertex = v;
        c.triangle = t;
        c.toi = *toi;
        out.push_back(c);
      }
    }
  const auto edges = scene_edges(s);
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto &a = edges[i], &b = edges[j];
      if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1]) continue;
      if (const auto toi = edge_edge_toi(ee_query(s, a, b), method)) {
        Collision c;
        c.kind = CollisionKind::edge_edge;
        c.edge_a = a;
        c.edge_b = b;
        c.toi = *toi;
        out.push_back(c);
      }
    }
  return out;
}

inline bool same(const Collision& a, const Collision& b) {
  return a.kind == b.kind && a.vertex == b.vertex && a.triangle == b.triangle && a.edge_a == b.edge_a &&
         a.edge_b == b.edge_b && a.vertex_b == b.vertex_b && a.toi == b.toi;
}

}  // namespace exactccd::testing
