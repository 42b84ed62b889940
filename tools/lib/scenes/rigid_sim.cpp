#include "scenes/rigid_sim.hpp"

#include <algorithm>
#include <cmath>

#include "rigid/swept_box.hpp"

namespace exactccd::rigid_sim {
namespace {

/// The unit quaternion of a turn by |w| t about w (spatial angular velocity w, time t).
Quaternion turn(const Vec3& w, double t) {
  const double speed = std::sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
  if (speed == 0) return {1, 0, 0, 0};
  const double half = 0.5 * speed * t, s = std::sin(half) / speed;
  return {std::cos(half), w.x * s, w.y * s, w.z * s};
}

Quaternion multiply(const Quaternion& p, const Quaternion& q) {
  return {p.w * q.w - p.x * q.x - p.y * q.y - p.z * q.z, p.w * q.x + p.x * q.w + p.y * q.z - p.z * q.y,
          p.w * q.y - p.x * q.z + p.y * q.w + p.z * q.x, p.w * q.z + p.x * q.y - p.y * q.x + p.z * q.w};
}

/// A body on a prescribed path: c(t) = c0 + v t + a t^2 / 2, q(t) = turn(w, t) q0.
struct Path {
  Vec3 c0, v, a, w;
  Quaternion q0;
  RigidPose at(double t) const {
    return {{c0.x + v.x * t + 0.5 * a.x * t * t, c0.y + v.y * t + 0.5 * a.y * t * t, c0.z + v.z * t + 0.5 * a.z * t * t},
            multiply(turn(w, t), q0)};
  }
};

/// Poses of the bodies at steps 0..steps of length dt from time t0, each q1 signed for the short arc.
std::vector<std::vector<RigidPose>> poses(const std::vector<Path>& paths, double t0, double dt, int steps) {
  std::vector<std::vector<RigidPose>> out;
  for (int k = 0; k <= steps; ++k) {
    std::vector<RigidPose> at;
    for (std::size_t b = 0; b < paths.size(); ++b) {
      RigidPose p = paths[b].at(t0 + k * dt);
      if (k > 0) {
        const Quaternion& prev = out.back()[b].q;
        if (prev.w * p.q.w + prev.x * p.q.x + prev.y * p.q.y + prev.z * p.q.z < 0) p.q = {-p.q.w, -p.q.x, -p.q.y, -p.q.z};
      }
      at.push_back(p);
    }
    out.push_back(at);
  }
  return out;
}

Body box(double half) {
  Body b;
  for (int i = 0; i < 8; ++i) b.vertices.push_back({i & 1 ? half : -half, i & 2 ? half : -half, i & 4 ? half : -half});
  // Two triangles per face, outward.
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) b.triangles.push_back({f[0], f[1], f[2]}), b.triangles.push_back({f[0], f[2], f[3]});
  return b;
}

Body grid(int n, double half) {
  Body b;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) b.vertices.push_back({-half + 2 * half * i / n, -half + 2 * half * j / n, 0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int v = j * (n + 1) + i;
      b.triangles.push_back({v, v + 1, v + n + 2}), b.triangles.push_back({v, v + n + 2, v + n + 1});
    }
  return b;
}

Body torus(double major, double minor, int around, int tube) {
  Body b;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      const double u = 2 * pi * i / around, v = 2 * pi * j / tube;
      const double r = major + minor * std::cos(v);
      b.vertices.push_back({r * std::cos(u), r * std::sin(u), minor * std::sin(v)});
    }
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      const int a = i * tube + j, bb = ((i + 1) % around) * tube + j, c = ((i + 1) % around) * tube + (j + 1) % tube,
                d = i * tube + (j + 1) % tube;
      b.triangles.push_back({a, bb, c}), b.triangles.push_back({a, c, d});
    }
  return b;
}

bool overlap(const rigid::Box& a, const rigid::Box& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
         b.lo.z <= a.hi.z;
}

rigid::Box join(const rigid::Box& a, const rigid::Box& b) {
  return {{std::min(a.lo.x, b.lo.x), std::min(a.lo.y, b.lo.y), std::min(a.lo.z, b.lo.z)},
          {std::max(a.hi.x, b.hi.x), std::max(a.hi.y, b.hi.y), std::max(a.hi.z, b.hi.z)}};
}

}  // namespace

Scene box_on_plane() {
  Scene s;
  s.name = "box";
  s.bodies = {box(0.5), grid(6, 2.0)};
  const Path falling{{0.1, -0.2, 1.1}, {0.4, 0.3, -1.0}, {0, 0, -9.81}, {5.0, -3.0, 2.0},
                     multiply(turn({1, 2, 0.5}, 0.7), Quaternion{1, 0, 0, 0})};
  const Path plane{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {1, 0, 0, 0}};
  s.poses = poses({falling, plane}, 0.0, 1.0 / 120, 72);
  return s;
}

Scene interlocked_rings() {
  Scene s;
  s.name = "rings";
  s.bodies = {torus(1.0, 0.15, 24, 6), torus(1.0, 0.15, 24, 6)};
  // Ring B stands in the x-z plane through A's hole (its center at (1, 0, 0)), then tumbles and
  // drifts; ring A turns slowly about its axis.
  const Path a{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0.4}, {1, 0, 0, 0}};
  const double h = std::sqrt(0.5);
  const Path b{{1.0, 0, 0}, {-0.35, 0.1, 0.05}, {0, 0, 0}, {0.9, -0.6, 1.2}, {h, h, 0, 0}};
  s.poses = poses({a, b}, 0.0, 1.0 / 60, 60);
  return s;
}

std::vector<Scene> all_scenes() { return {box_on_plane(), interlocked_rings()}; }

std::vector<std::array<int, 2>> unique_edges(const Body& body) {
  std::vector<std::array<int, 2>> e;
  for (const auto& t : body.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      e.push_back({std::min(a, b), std::max(a, b)});
    }
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

StepQueries step_queries(const Scene& scene, std::size_t step) {
  const std::vector<RigidPose>& p0 = scene.poses.at(step);
  const std::vector<RigidPose>& p1 = scene.poses.at(step + 1);
  std::vector<std::vector<rigid::Box>> vertex_box(scene.bodies.size());
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    vertex_box[b] = rigid::swept_boxes(p0[b], p1[b], scene.bodies[b].vertices);
  StepQueries out;
  for (std::size_t a = 0; a < scene.bodies.size(); ++a)
    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
      if (a == b) continue;
      const Body &A = scene.bodies[a], &B = scene.bodies[b];
      for (std::size_t v = 0; v < A.vertices.size(); ++v)
        for (const auto& t : B.triangles) {
          const rigid::Box tb = join(join(vertex_box[b][t[0]], vertex_box[b][t[1]]), vertex_box[b][t[2]]);
          if (!overlap(vertex_box[a][v], tb)) continue;
          out.vertex_face.push_back({p0[a], p1[a], p0[b], p1[b], A.vertices[v], B.vertices[t[0]], B.vertices[t[1]],
                                     B.vertices[t[2]]});
        }
      if (b < a) continue;
      const auto ea = unique_edges(A), eb = unique_edges(B);
      for (const auto& e : ea) {
        const rigid::Box box_a = join(vertex_box[a][e[0]], vertex_box[a][e[1]]);
        for (const auto& f : eb) {
          if (!overlap(box_a, join(vertex_box[b][f[0]], vertex_box[b][f[1]]))) continue;
          out.edge_edge.push_back({p0[a], p1[a], p0[b], p1[b], A.vertices[e[0]], A.vertices[e[1]], B.vertices[f[0]],
                                   B.vertices[f[1]]});
        }
      }
    }
  return out;
}

}  // namespace exactccd::rigid_sim
