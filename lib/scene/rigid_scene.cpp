// The scene functions of rigid bodies (include/exactccd/rigid.hpp; docs/design.md 9.5): a broad
// phase of certified swept boxes (swept_box.hpp) in one bounding volume hierarchy per body and
// primitive type (scene/box_tree.hpp), traversed for every pair of bodies, then the primitive
// queries on options.threads threads.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>

#include "exactccd/rigid.hpp"
#include "rigid/swept_box.hpp"
#include "rigid/validation.hpp"
#include "scene/box_tree.hpp"
#include "scene/parallel.hpp"

namespace exactccd {
namespace {

scene::Box box_of(const rigid::Box& b) { return {{b.lo.x, b.lo.y, b.lo.z}, {b.hi.x, b.hi.y, b.hi.z}}; }

/// One body's primitives and their swept boxes (grown by d), with a tree per primitive type.
struct PreparedBody {
  std::vector<int> vertices;                 // the vertices its triangles reference
  std::vector<std::array<int, 2>> edges;     // unique, ascending
  std::vector<scene::Box> vertex_box;        // by vertex index
  scene::BoxTree vertex_tree, triangle_tree, edge_tree;

  PreparedBody(const RigidBody& body, double d) {
    const std::vector<rigid::Box> boxes = rigid::swept_boxes(body.t0, body.t1, body.vertices, d);
    vertex_box.reserve(boxes.size());
    for (const rigid::Box& b : boxes) vertex_box.push_back(box_of(b));
    for (const auto& t : body.triangles)
      for (int k = 0; k < 3; ++k) {
        vertices.push_back(t[k]);
        edges.push_back({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
      }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    vertex_tree.build(vertices.size(), [&](std::size_t i) { return vertex_box[vertices[i]]; }, 1);
    triangle_tree.build(body.triangles.size(), [&](std::size_t i) {
      const auto& t = body.triangles[i];
      return scene::hull(scene::hull(vertex_box[t[0]], vertex_box[t[1]]), vertex_box[t[2]]);
    }, 1);
    edge_tree.build(edges.size(), [&](std::size_t i) { return scene::hull(vertex_box[edges[i][0]], vertex_box[edges[i][1]]); }, 1);
  }
};

/// Every pair of primitives of two trees whose boxes overlap, as (i, j) sorted.
std::vector<std::array<int, 2>> overlapping(const scene::BoxTree& a, const scene::BoxTree& b) {
  std::vector<std::array<int, 2>> out;
  if (a.size() == 0 || b.size() == 0) return out;
  for (const auto& task : a.pair_tasks(b, 1)) a.pairs_from(b, task, [&](int i, int j) { out.push_back({i, j}); });
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<RigidCollision> collisions(const std::vector<RigidBody>& bodies, const SceneOptions& options) {
  const scene::SceneCall call(options.cancel);  // the default FP environment, and Ctrl-C (SceneOptions::cancel)
  validate(options);
  validate(bodies);
  std::vector<PreparedBody> prepared;
  prepared.reserve(bodies.size());
  for (const RigidBody& b : bodies) prepared.emplace_back(b, options.min_distance);
  // The candidates, in the order of the result.
  std::vector<RigidCollision> candidates;
  for (std::size_t a = 0; a < bodies.size(); ++a)
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (a == b) continue;
      for (const auto& [v, t] : overlapping(prepared[a].vertex_tree, prepared[b].triangle_tree)) {
        RigidCollision c;
        c.kind = CollisionKind::vertex_face;
        c.body_a = static_cast<int>(a), c.body_b = static_cast<int>(b);
        c.vertex = prepared[a].vertices[v], c.triangle = t;
        candidates.push_back(c);
      }
    }
  std::sort(candidates.begin(), candidates.end(), [](const RigidCollision& x, const RigidCollision& y) {
    return std::tie(x.body_a, x.vertex, x.body_b, x.triangle) < std::tie(y.body_a, y.vertex, y.body_b, y.triangle);
  });
  for (std::size_t a = 0; a < bodies.size(); ++a)
    for (std::size_t b = a + 1; b < bodies.size(); ++b)
      for (const auto& [i, j] : overlapping(prepared[a].edge_tree, prepared[b].edge_tree)) {
        RigidCollision c;
        c.kind = CollisionKind::edge_edge;
        c.body_a = static_cast<int>(a), c.body_b = static_cast<int>(b);
        c.edge_a = prepared[a].edges[i], c.edge_b = prepared[b].edges[j];
        candidates.push_back(c);
      }
  // The narrow phase.
  const CcdParams params{options.min_distance, options.tmax};
  std::vector<char> hit(candidates.size());
  // In chunks also on one thread: a set cancellation flag stops the loop between chunks.
  scene::call_chunks(candidates.size(), scene::resolve_threads(options.threads), 64, [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t k = begin; k < end; ++k) {
      RigidCollision& c = candidates[k];
      const RigidBody &A = bodies[c.body_a], &B = bodies[c.body_b];
      std::optional<TimeInterval> t;
      if (c.kind == CollisionKind::vertex_face) {
        const auto& tri = B.triangles[c.triangle];
        t = rigid_vertex_face_toi({A.t0, A.t1, B.t0, B.t1, A.vertices[c.vertex], B.vertices[tri[0]], B.vertices[tri[1]],
                                   B.vertices[tri[2]]}, params);
      } else {
        t = rigid_edge_edge_toi({A.t0, A.t1, B.t0, B.t1, A.vertices[c.edge_a[0]], A.vertices[c.edge_a[1]],
                                 B.vertices[c.edge_b[0]], B.vertices[c.edge_b[1]]}, params);
      }
      if (t) c.toi = *t, hit[k] = 1;
    }
    return true;
  });
  std::vector<RigidCollision> out;
  for (std::size_t k = 0; k < candidates.size(); ++k)
    if (hit[k]) out.push_back(candidates[k]);
  return out;
}

}  // namespace

void validate(const std::vector<RigidBody>& bodies) {
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const RigidBody& body = bodies[b];
    const std::string where = "exactccd: rigid body " + std::to_string(b);
    if (const char* why = rigid::invalid_motion(body.t0, body.t1)) throw std::invalid_argument(where + ": " + why);
    for (std::size_t i = 0; i < body.vertices.size(); ++i) {
      const Vec3& v = body.vertices[i];
      if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)))
        throw std::invalid_argument(where + ": vertex " + std::to_string(i) + " is not finite");
    }
    const int n = static_cast<int>(body.vertices.size());
    for (std::size_t t = 0; t < body.triangles.size(); ++t) {
      const auto& tri = body.triangles[t];
      for (int k = 0; k < 3; ++k)
        if (tri[k] < 0 || tri[k] >= n)
          throw std::invalid_argument(where + ": triangle " + std::to_string(t) + " has an index out of range");
      if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
        throw std::invalid_argument(where + ": triangle " + std::to_string(t) + " repeats a vertex index");
    }
  }
}

std::vector<RigidCollision> rigid_find_collisions(const std::vector<RigidBody>& bodies, const SceneOptions& options) {
  return collisions(bodies, options);
}

std::optional<TimeInterval> rigid_earliest_toi(const std::vector<RigidBody>& bodies, const SceneOptions& options) {
  std::optional<TimeInterval> best;
  for (const RigidCollision& c : collisions(bodies, options))
    if (!best || c.toi.lo < best->lo || (c.toi.lo == best->lo && c.toi.hi < best->hi)) best = c.toi;
  return best;
}

double rigid_max_collision_free_step(const std::vector<RigidBody>& bodies, const SceneOptions& options) {
  return max_collision_free_step(rigid_earliest_toi(bodies, options), options.tmax);
}

}  // namespace exactccd
