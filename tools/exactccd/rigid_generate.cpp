// exactccd generate rigid: the rigid query sets (issue 24) in the format of io/rigid_csv.hpp.
#include <cstdio>
#include <filesystem>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "exactccd/rigid.hpp"
#include "fuzz/rigid_families.hpp"
#include "io/rigid_csv.hpp"
#include "output_file.hpp"
#include "rigid/rigid_layout.hpp"
#include "rigid_cli.hpp"
#include "scenes/rigid_sim.hpp"
#include "scenes/sim_queries.hpp"  // select_queries

namespace exactccd::cli {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const io::RigidQueries& q, const std::vector<std::string>& comments) {
  std::ostringstream text;
  io::write_rigid_csv(text, q, comments);
  write_file_atomically(path.string(), text.str());
  std::size_t positives = 0;
  for (const bool t : q.truth) positives += t;
  std::printf("%s: %zu queries, %zu positives\n", path.string().c_str(), q.size(), positives);
}

/// Every query answered by Method::exact on `threads` threads; then select_queries' choice.
template <class Query>
void add_selected(const std::vector<Query>& queries, std::size_t max_queries, unsigned threads, io::RigidQueries& out,
                  std::size_t& positives_all) {
  std::vector<char> collides(queries.size());
  parallel_for(0, queries.size(), threads, [&](std::size_t i) {
    collides[i] = ccd(queries[i], CcdParams{}, Method::exact);
  }, "generate rigid");
  std::vector<bool> truth(collides.begin(), collides.end());
  for (const bool t : truth) positives_all += t;
  for (const std::size_t i : scene::select_queries(truth, max_queries)) {
    out.numbers.push_back(rigid::to_numbers(queries[i]));
    out.truth.push_back(truth[i]);
    out.lines.push_back(0);
  }
}

}  // namespace

int generate_rigid(std::uint64_t seed, std::size_t max_queries, unsigned threads, const std::string& out) {
  prepare_output_directory(out);
  // The degenerate families at d = 0 (the file format has no d): truth by construction, checked
  // against Method::exact.
  io::RigidQueries families_of[2];
  std::mt19937_64 rng(seed);
  for (const rigid_families::Family& f : rigid_families::all_families())
    for (int k = -1; k <= 52; k = k < 0 ? 0 : k + 4)
      for (const bool toward : {true, false}) {
        if (k < 0 && !toward) continue;
        const rigid_families::Instance inst = rigid_families::make(f, k, toward, rng);
        if (inst.min_distance != 0) continue;
        const bool exact = std::visit([](const auto& q) { return ccd(q, CcdParams{}, Method::exact); }, inst.query);
        if (inst.expected && *inst.expected != exact)
          throw std::runtime_error("generate rigid: " + f.name + " k=" + std::to_string(k) +
                                   ": the construction and Method::exact disagree");
        io::RigidQueries& q = families_of[f.vertex_face ? 0 : 1];
        q.numbers.push_back(std::visit([](const auto& x) { return rigid::to_numbers(x); }, inst.query));
        q.truth.push_back(exact);
        q.lines.push_back(0);
      }
  const std::vector<std::string> family_note{
      "Degenerate rigid families (fuzz/rigid_families.hpp) at k = unperturbed, 0, 4, ..., 52, both directions,",
      "placed by exact common changes of frame; truth by construction, checked against Method::exact.",
      "Regenerate: exactccd generate rigid --seed " + std::to_string(seed) + " --max-queries " + std::to_string(max_queries) + " --out DIR"};
  write(fs::path(out) / "rigid-families-vertex-face.csv", families_of[0], family_note);
  write(fs::path(out) / "rigid-families-edge-edge.csv", families_of[1], family_note);
  // The tumbling bodies: every step's candidates answered by Method::exact.
  for (const rigid_sim::Scene& scene : rigid_sim::all_scenes()) {
    std::vector<RigidVertexFaceQuery> vf;
    std::vector<RigidEdgeEdgeQuery> ee;
    for (std::size_t step = 0; step + 1 < scene.poses.size(); ++step) {
      const rigid_sim::StepQueries s = rigid_sim::step_queries(scene, step);
      vf.insert(vf.end(), s.vertex_face.begin(), s.vertex_face.end());
      ee.insert(ee.end(), s.edge_edge.begin(), s.edge_edge.end());
    }
    std::fprintf(stderr, "scene %s: %zu VF and %zu EE candidates over %zu steps\n", scene.name.c_str(), vf.size(),
                 ee.size(), scene.poses.size() - 1);
    io::RigidQueries qvf, qee;
    std::size_t pvf = 0, pee = 0;
    add_selected(vf, max_queries, threads, qvf, pvf);
    add_selected(ee, max_queries, threads, qee, pee);
    const auto note = [&](std::size_t all, std::size_t positives) {
      return std::vector<std::string>{
          "Tumbling rigid bodies (lib/scene/rigid_sim.hpp, scene '" + scene.name + "'): candidates of " +
              std::to_string(scene.poses.size() - 1) + " steps from certified swept boxes: " + std::to_string(all) +
              " candidates, " + std::to_string(positives) + " collide (truth: Method::exact);",
          "kept: every colliding one, then evenly spaced others, at most " + std::to_string(max_queries) + ".",
          "Regenerate: exactccd generate rigid --seed " + std::to_string(seed) + " --max-queries " + std::to_string(max_queries) + " --out DIR"};
    };
    write(fs::path(out) / ("rigid-sim-" + scene.name + "-vertex-face.csv"), qvf, note(vf.size(), pvf));
    write(fs::path(out) / ("rigid-sim-" + scene.name + "-edge-edge.csv"), qee, note(ee.size(), pee));
  }
  return kExitOk;
}

}  // namespace exactccd::cli
