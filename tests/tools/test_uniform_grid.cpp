// The uniform grid broad phase of the benchmarks (tools/lib/broad_phase/uniform_grid.hpp): the
// same vertex-face and edge-edge candidates as the library's trees (scene_primitives), each
// once, on procedural cloth, fold, pile and strip scenes and on random and degenerate scenes
// (touching and repeated boxes on a grid), at several cell sides.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "broad_phase/uniform_grid.hpp"
#include "exactccd/exactccd.hpp"
#include "scene/scene_primitives.hpp"
#include "scenes/procedural_scenes.hpp"
#include "tests/scene_support.hpp"

namespace exactccd {
namespace {

void expect_same_candidates(const Scene& s, const std::string& what) {
  const scene::ScenePrimitives prim = scene::scene_primitives(s, {}, 1);
  const std::vector<scene::Box> boxes = scene::vertex_boxes(s.positions_t0, s.positions_t1, {});
  const double extent = tools::UniformGrid::mean_edge_extent(boxes, prim.edges);
  for (const double factor : {0.25, 1.0, 4.0}) {
    const tools::UniformGrid grid(boxes, s.triangles, prim.edges, prim.vertices, factor * extent);
    std::vector<std::array<int, 2>> vf, ee;
    const std::size_t found = grid.pairs([&](const scene::FoundPair& p) {
      (p.kind == CollisionKind::vertex_face ? vf : ee).push_back(p.ij);
    });
    EXPECT_EQ(found, vf.size() + ee.size());
    std::sort(vf.begin(), vf.end());  // duplicates kept: each pair must come once
    std::sort(ee.begin(), ee.end());
    EXPECT_EQ(vf, prim.candidates.vertex_face) << what << ", cell factor " << factor;
    EXPECT_EQ(ee, prim.candidates.edge_edge) << what << ", cell factor " << factor;
  }
}

TEST(UniformGrid, ProceduralScenesGiveTheTreesCandidates) {
  for (const std::string name : {"cloth", "fold", "pile", "strip"})
    for (const int resolution : {8, 16, 32}) {
      const scene::MovingMesh m = scene::procedural_scene(name, resolution, 1);
      expect_same_candidates(Scene{m.positions_t0, m.positions_t1, m.triangles, {}, {}},
                             name + " " + std::to_string(resolution));
    }
}

TEST(UniformGrid, RandomAndDegenerateScenesGiveTheTreesCandidates) {
  std::mt19937_64 rng(23);
  for (int n = 0; n < 60; ++n) {
    Scene s = testing::random_scene(rng, 40, 30, 0, 0, n % 2 == 1);
    expect_same_candidates(s, "scene " + std::to_string(n));
  }
}

}  // namespace
}  // namespace exactccd
