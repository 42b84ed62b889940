// The scene functions as one streamed pass (pair_stream.hpp): a scene's topology and trees
// (SceneTrees), and the three questions (every collision, the earliest, whether any) answered
// over the pairs as the traversal finds them. Shared by the scene functions (scene_ccd.cpp),
// SceneBroadPhase (scene_broad_phase.cpp, which keeps the trees across calls) and the CLI's
// --stats.
#pragma once

#include <optional>
#include <vector>

#include "exactccd/scene.hpp"
#include "scene/candidate_finder.hpp"
#include "scene/pair_stream.hpp"
#include "scene/parallel.hpp"
#include "scene/scene_primitives.hpp"
#include "scene/step_stats.hpp"

namespace exactccd::scene {

/// A scene's topology (ScenePrimitives without candidates) and its trees fitted to the vertex
/// boxes of the question `params`. The trees refer to the topology and to the scene's
/// triangles: the object does not move, and the scene must outlive it.
class SceneTrees {
 public:
  /// Validates the scene, finds its topology, builds the trees on up to `threads` threads.
  SceneTrees(const Scene& scene, const CcdParams& params, unsigned threads);
  /// As above in the plane.
  SceneTrees(const Scene2d& scene, const CcdParams& params, unsigned threads);
  SceneTrees(const SceneTrees&) = delete;
  SceneTrees& operator=(const SceneTrees&) = delete;

  /// Refits the trees to the scene's current positions (same topology and vertex count), the
  /// vertex boxes computed in place: nothing is allocated.
  void refit(const Scene& scene, const CcdParams& params, unsigned threads);

  /// The scene's vertex-face vertices, edges and isolated points (no candidates).
  const ScenePrimitives& topology() const { return prim_; }
  /// The trees.
  const BroadPhaseTrees& trees() const { return trees_; }
  /// The buffers of the streams over the trees (pieces of work, the workers' batches), kept
  /// with them and lent to one stream at a time (a concurrent stream uses its own).
  Kept<StreamBuffers>& stream_buffers() const { return stream_buffers_; }

 private:
  ScenePrimitives prim_;
  BroadPhaseTrees trees_;
  mutable Kept<StreamBuffers> stream_buffers_;
};

/// Every colliding pair of the scene (the scene's find_collisions), over the trees' pairs as
/// they are found, on up to `threads` threads; only colliding pairs are kept. `stats` (may be
/// null) receives the candidate counts and the loop's times.
std::vector<Collision> find_collisions(const Scene& scene, const SceneTrees& trees, const CcdParams& params,
                                       unsigned threads, StepStats* stats = nullptr);
/// As above in the plane.
std::vector<Collision> find_collisions(const Scene2d& scene, const SceneTrees& trees, const CcdParams& params,
                                       unsigned threads, StepStats* stats = nullptr);

/// The earliest time of impact of the scene (its earliest_toi), the window shrinking as
/// collisions are found (EarliestCollision, narrow_phase.hpp).
std::optional<TimeInterval> earliest_toi(const Scene& scene, const SceneTrees& trees, const CcdParams& params,
                                         unsigned threads, StepStats* stats = nullptr);
/// As above in the plane.
std::optional<TimeInterval> earliest_toi(const Scene2d& scene, const SceneTrees& trees, const CcdParams& params,
                                         unsigned threads, StepStats* stats = nullptr);

/// Whether some pair of the scene collides (not is_collision_free), stopping at the first.
bool any_collision(const Scene& scene, const SceneTrees& trees, const CcdParams& params, unsigned threads,
                   StepStats* stats = nullptr);
/// As above in the plane.
bool any_collision(const Scene2d& scene, const SceneTrees& trees, const CcdParams& params, unsigned threads,
                   StepStats* stats = nullptr);

/// exactccd::find_collisions(scene, options) with the step's counters and times in `stats`
/// (setup included): what `exactccd scene --stats` prints.
std::vector<Collision> find_collisions(const Scene& scene, const SceneOptions& options, StepStats* stats);

}  // namespace exactccd::scene
