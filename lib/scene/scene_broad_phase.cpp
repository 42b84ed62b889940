// exactccd::SceneBroadPhase (exactccd/scene.hpp): the scene's topology, vertex boxes and
// bounding volume hierarchies (candidate_finder.hpp) kept across calls; update() refits.
#include <stdexcept>
#include <string>
#include <utility>

#include "exactccd/scene.hpp"
#include "filter/fp_environment.hpp"
#include "scene/candidate_finder.hpp"
#include "scene/parallel.hpp"
#include "scene/scene_primitives.hpp"

namespace exactccd {

/// Everything kept across calls. Heap-allocated behind SceneBroadPhase's unique_ptr, so it
/// never moves: `trees` refers to `prim`'s and `scene`'s topology.
struct SceneBroadPhase::State {
  State(const Scene& s, const SceneOptions& o)
      : scene(s), options(o), params{o.min_distance, o.tmax}, prim(scene::scene_topology(scene, params)),
        trees(scene.triangles, prim.edges, prim.vertices, prim.points) {}

  Scene scene;
  SceneOptions options;
  CcdParams params;
  scene::ScenePrimitives prim;  // topology; prim.candidates: the current candidates
  scene::BroadPhaseTrees trees;

  /// Fits the trees to the current positions (builds on the first call) and finds the candidates.
  void refresh() {
    const unsigned threads = scene::resolve_threads(options.threads);
    trees.fit(scene::vertex_boxes(scene.positions_t0, scene.positions_t1, params), threads);
    prim.candidates = trees.candidates(threads);
  }
};

SceneBroadPhase::SceneBroadPhase(const Scene& scene, const SceneOptions& options) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  validate(options);
  const scene::CancelScope cancel_scope(options.cancel);  // SceneOptions::cancel, here only
  state_ = std::make_unique<State>(scene, options);  // validates the scene
  state_->options.cancel = nullptr;                  // the flag need not outlive this call
  state_->refresh();
}

SceneBroadPhase::~SceneBroadPhase() = default;
SceneBroadPhase::SceneBroadPhase(SceneBroadPhase&&) noexcept = default;
SceneBroadPhase& SceneBroadPhase::operator=(SceneBroadPhase&&) noexcept = default;

void SceneBroadPhase::update(const std::vector<Vec3>& positions_t1) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  if (positions_t1.size() != state_->scene.positions_t0.size())
    throw std::invalid_argument("exactccd SceneBroadPhase::update: positions_t1 has " +
                                std::to_string(positions_t1.size()) + " vertices but positions_t0 has " +
                                std::to_string(state_->scene.positions_t0.size()));
  scene::require_finite_positions(positions_t1, "positions_t1");
  state_->scene.positions_t1 = positions_t1;
  state_->refresh();
}

const Scene& SceneBroadPhase::scene() const { return state_->scene; }

const std::vector<std::array<int, 2>>& SceneBroadPhase::edges() const { return state_->prim.edges; }

const SceneCandidates& SceneBroadPhase::candidates() const { return state_->prim.candidates; }

}  // namespace exactccd
