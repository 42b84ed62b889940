// The first real case of the mesh readers: the Scalable CCD dataset's cloth-funnel step
// 227 -> 228 (EXACTCCD_SCALABLE_SAMPLE_DIR, see its README.md). The exact scene CCD of the two
// binary PLY frames must report exactly the colliding pairs of the dataset's truth: the
// queries of boxes/227vf.json and boxes/227ee.json (primitive ids: vertices, then the unique
// edges ordered by (larger, smaller) vertex index, then the faces) whose mma_bool is true.
// Skipped when the folder is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "exactccd/scene.hpp"
#include "io/mesh_file.hpp"
#include "io/truth_json.hpp"

namespace exactccd {
namespace {

namespace fs = std::filesystem;

const fs::path kScene = fs::path(EXACTCCD_SCALABLE_SAMPLE_DIR) / "cloth-funnel";

/// The [id, id] pairs of a boxes file (a JSON array of two-integer arrays).
std::vector<std::array<long, 2>> read_boxes(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  for (char& c : text)
    if (c == '[' || c == ']' || c == ',') c = ' ';
  std::istringstream numbers(text);
  std::vector<std::array<long, 2>> out;
  for (long a, b; numbers >> a >> b;) out.push_back({a, b});
  return out;
}

TEST(ScalableSample, ClothFunnelSceneCcdReportsExactlyTheTruePairs) {
  if (!fs::is_directory(kScene))
    GTEST_SKIP() << "the Scalable CCD sample is absent: " << kScene.string()
                 << " (set the CMake cache variable EXACTCCD_SCALABLE_SAMPLE_DIR to the scalable-ccd-sample folder)";
  const io::TriangleMesh m0 = io::read_mesh((kScene / "frames/227.ply").string());
  const io::TriangleMesh m1 = io::read_mesh((kScene / "frames/228.ply").string());
  ASSERT_EQ(m0.vertices.size(), 9450u);
  ASSERT_EQ(m0.triangles.size(), 18484u);
  ASSERT_EQ(m1.triangles, m0.triangles);

  // The dataset's edge numbering.
  std::vector<std::array<int, 2>> edges;  // (larger, smaller)
  for (const auto& t : m0.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      edges.push_back({std::max(a, b), std::min(a, b)});
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const long nv = static_cast<long>(m0.vertices.size()), ne = static_cast<long>(edges.size());
  const auto edge = [&](long id) {
    const long e = id - nv;
    EXPECT_TRUE(e >= 0 && e < ne) << id;
    const auto& x = edges.at(static_cast<std::size_t>(e));
    return std::array<int, 2>{x[1], x[0]};  // ascending
  };

  std::set<std::pair<int, int>> want_vf, got_vf;
  std::set<std::array<int, 4>> want_ee, got_ee;
  const auto vf_boxes = read_boxes(kScene / "boxes/227vf.json");
  const std::vector<bool> vf_truth = io::read_truth_json_file((kScene / "mma_bool/227vf_mma_bool.json").string());
  ASSERT_EQ(vf_boxes.size(), vf_truth.size());
  for (std::size_t i = 0; i < vf_boxes.size(); ++i) {
    const long v = vf_boxes[i][0], f = vf_boxes[i][1] - nv - ne;
    ASSERT_TRUE(v >= 0 && v < nv && f >= 0 && f < static_cast<long>(m0.triangles.size())) << i;
    if (vf_truth[i]) want_vf.insert({static_cast<int>(v), static_cast<int>(f)});
  }
  const auto ee_boxes = read_boxes(kScene / "boxes/227ee.json");
  const std::vector<bool> ee_truth = io::read_truth_json_file((kScene / "mma_bool/227ee_mma_bool.json").string());
  ASSERT_EQ(ee_boxes.size(), ee_truth.size());
  for (std::size_t i = 0; i < ee_boxes.size(); ++i) {
    std::array<int, 2> a = edge(ee_boxes[i][0]), b = edge(ee_boxes[i][1]);
    if (b < a) std::swap(a, b);
    if (ee_truth[i]) want_ee.insert({a[0], a[1], b[0], b[1]});
  }
  EXPECT_EQ(want_vf.size(), 27u);
  EXPECT_EQ(want_ee.size(), 107u);

  Scene s;
  s.positions_t0 = m0.vertices;
  s.positions_t1 = m1.vertices;
  s.triangles = m0.triangles;
  for (const Collision& c : find_collisions(s, SceneOptions{})) {
    if (c.kind == CollisionKind::vertex_face)
      got_vf.insert({c.vertex, c.triangle});
    else if (c.kind == CollisionKind::edge_edge)
      got_ee.insert({c.edge_a[0], c.edge_a[1], c.edge_b[0], c.edge_b[1]});
  }
  EXPECT_EQ(got_vf, want_vf);
  EXPECT_EQ(got_ee, want_ee);
}

}  // namespace
}  // namespace exactccd
