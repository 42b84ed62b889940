// Scene-level CCD (exactccd/scene.hpp), 3D and 2D scenes by the same templates: the broad
// phase's pairs streamed into the shared narrow phase (lib/scene/streamed_step.hpp: the exact
// primitive queries with CcdParams{min_distance, tmax}, on several threads) as they are found.
#include <cmath>

#include "exactccd/scene.hpp"
#include "numeric/fp_environment.hpp"
#include "scene/narrow_phase.hpp"
#include "scene/parallel.hpp"
#include "scene/scene_primitives.hpp"
#include "scene/streamed_step.hpp"

namespace exactccd {
namespace {

CcdParams params_of(const SceneOptions& options) {
  validate(options);
  return {options.min_distance, options.tmax};
}

// Each call builds the scene's topology and trees (scene::SceneTrees) and streams their pairs
// into the narrow phase (scene/streamed_step.hpp), on options.threads threads at most
// (scene::with_threads); SceneBroadPhase keeps the trees instead.

template <class SceneT>
std::vector<Collision> find_collisions_in(const SceneT& scene, const SceneOptions& options) {
  const scene::SceneCall call(options.cancel);  // FP environment and SceneOptions::cancel
  const CcdParams params = params_of(options);
  const unsigned threads = scene::resolve_threads(options.threads);
  return scene::with_threads(threads, [&] {
    const scene::SceneTrees trees(scene, params, threads);
    return scene::find_collisions(scene, trees, params, threads);
  });
}

template <class SceneT>
std::optional<TimeInterval> earliest_toi_in(const SceneT& scene, const SceneOptions& options) {
  const scene::SceneCall call(options.cancel);  // FP environment and SceneOptions::cancel
  const CcdParams params = params_of(options);
  const unsigned threads = scene::resolve_threads(options.threads);
  return scene::with_threads(threads, [&] {
    const scene::SceneTrees trees(scene, params, threads);
    return scene::earliest_toi(scene, trees, params, threads);
  });
}

template <class SceneT>
bool is_collision_free_in(const SceneT& scene, const SceneOptions& options) {
  const scene::SceneCall call(options.cancel);  // FP environment and SceneOptions::cancel
  const CcdParams params = params_of(options);
  const unsigned threads = scene::resolve_threads(options.threads);
  return scene::with_threads(threads, [&] {
    const scene::SceneTrees trees(scene, params, threads);
    return !scene::any_collision(scene, trees, params, threads);
  });
}

}  // namespace

std::vector<Collision> find_collisions(const Scene& scene, const SceneOptions& options) {
  return find_collisions_in(scene, options);
}

std::vector<Collision> find_collisions(const Scene2d& scene, const SceneOptions& options) {
  return find_collisions_in(scene, options);
}

std::optional<TimeInterval> earliest_toi(const std::vector<Collision>& collisions) {
  const scene::SceneCall call;  // the FP environment (not cancellable)
  return scene::earliest_of(collisions);
}

std::optional<TimeInterval> earliest_toi(const Scene& scene, const SceneOptions& options) {
  return earliest_toi_in(scene, options);
}

std::optional<TimeInterval> earliest_toi(const Scene2d& scene, const SceneOptions& options) {
  return earliest_toi_in(scene, options);
}

bool is_collision_free(const Scene& scene, const SceneOptions& options) {
  return is_collision_free_in(scene, options);
}

bool is_collision_free(const Scene2d& scene, const SceneOptions& options) {
  return is_collision_free_in(scene, options);
}

double max_collision_free_step(const std::optional<TimeInterval>& earliest, double tmax) {
  const scene::SceneCall call;  // the FP environment (not cancellable)
  scene::require_valid_params(CcdParams{0.0, tmax});
  if (!earliest) return tmax;
  // Every collision time t >= lo; the largest double s < lo gives [0, s] without one (and
  // s < lo <= t <= tmax).
  if (earliest->lo <= 0) return 0.0;
  return std::nextafter(earliest->lo, 0.0);
}

double max_collision_free_step(const Scene& scene, const SceneOptions& options) {
  return max_collision_free_step(earliest_toi(scene, options), options.tmax);
}

double max_collision_free_step(const Scene2d& scene, const SceneOptions& options) {
  return max_collision_free_step(earliest_toi(scene, options), options.tmax);
}

}  // namespace exactccd
