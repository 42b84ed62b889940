// exactccd::SceneBroadPhase (exactccd/scene.hpp): the scene's topology, vertex boxes and
// bounding volume hierarchies (streamed_step.hpp's SceneTrees) kept across calls; update()
// refits; the scene functions stream the trees' pairs into the narrow phase.
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "exactccd/scene.hpp"
#include "numeric/fp_environment.hpp"
#include "scene/parallel.hpp"
#include "scene/scene_primitives.hpp"
#include "scene/streamed_step.hpp"

namespace exactccd {

/// Everything kept across calls: the scene, its trees (with the buffers of their streams), the
/// task arena. Heap-allocated behind SceneBroadPhase's unique_ptr, so it never moves: `trees`
/// refers to `scene`'s topology.
struct SceneBroadPhase::State {
  State(const Scene& s, const SceneOptions& o)
      : scene(s), options(o), params{o.min_distance, o.tmax}, threads(scene::resolve_threads(o.threads)),
        arena(static_cast<int>(threads)),
        trees(scene::with_threads(threads, [&] { return std::make_unique<scene::SceneTrees>(scene, params, threads); },
                                  &arena)) {}

  /// f() on the object's threads (scene::with_threads, in the kept arena when one is needed).
  template <class F>
  auto run(F&& f) -> decltype(f()) {
    return scene::with_threads(threads, f, &arena);
  }

  Scene scene;
  SceneOptions options;
  CcdParams params;
  unsigned threads;
  scene::KeptArena arena;  // for calls from a thread whose task arena has more slots than `threads`
  std::unique_ptr<scene::SceneTrees> trees;  // validates the scene, builds the trees
  /// The candidates listed for the current positions, when asked for (candidates()).
  mutable std::mutex candidates_mutex;
  mutable std::optional<SceneCandidates> candidates;
};

SceneBroadPhase::SceneBroadPhase(const Scene& scene, const SceneOptions& options) {
  const scene::SceneCall call(options.cancel);  // FP environment and SceneOptions::cancel, here only
  validate(options);
  state_ = std::make_unique<State>(scene, options);  // validates the scene, builds the trees
  state_->options.cancel = nullptr;                  // the flag need not outlive this call
}

SceneBroadPhase::~SceneBroadPhase() = default;
SceneBroadPhase::SceneBroadPhase(SceneBroadPhase&&) noexcept = default;
SceneBroadPhase& SceneBroadPhase::operator=(SceneBroadPhase&&) noexcept = default;

void SceneBroadPhase::update(const std::vector<Vec3>& positions_t1) {
  const scene::SceneCall call;  // the FP environment (not cancellable)
  if (positions_t1.size() != state_->scene.positions_t0.size())
    throw std::invalid_argument("exactccd SceneBroadPhase::update: positions_t1 has " +
                                std::to_string(positions_t1.size()) + " vertices but positions_t0 has " +
                                std::to_string(state_->scene.positions_t0.size()));
  scene::require_finite_positions(positions_t1, "positions_t1");
  state_->scene.positions_t1 = positions_t1;
  state_->candidates.reset();
  state_->run([&] { state_->trees->refit(state_->scene, state_->params, state_->threads); });
}

std::vector<Collision> SceneBroadPhase::find_collisions() const {
  const scene::SceneCall call;  // the FP environment (not cancellable)
  return state_->run([&] { return scene::find_collisions(state_->scene, *state_->trees, state_->params, state_->threads); });
}

std::optional<TimeInterval> SceneBroadPhase::earliest_toi() const {
  const scene::SceneCall call;  // the FP environment (not cancellable)
  return state_->run([&] { return scene::earliest_toi(state_->scene, *state_->trees, state_->params, state_->threads); });
}

bool SceneBroadPhase::is_collision_free() const {
  const scene::SceneCall call;  // the FP environment (not cancellable)
  return state_->run([&] { return !scene::any_collision(state_->scene, *state_->trees, state_->params, state_->threads); });
}

double SceneBroadPhase::max_collision_free_step() const {
  return exactccd::max_collision_free_step(earliest_toi(), state_->params.tmax);
}

const Scene& SceneBroadPhase::scene() const { return state_->scene; }

const std::vector<std::array<int, 2>>& SceneBroadPhase::edges() const { return state_->trees->topology().edges; }

const SceneCandidates& SceneBroadPhase::candidates() const {
  const scene::SceneCall call;  // the FP environment (not cancellable)
  const std::lock_guard<std::mutex> lock(state_->candidates_mutex);
  if (!state_->candidates)
    state_->candidates = state_->run([&] { return state_->trees->trees().candidates(state_->threads); });
  return *state_->candidates;
}

}  // namespace exactccd
