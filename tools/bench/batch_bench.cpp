// The candidate API as a simulator calls it, against the textbook cubic over the same queries
// (issue 30's table): exactccd::find_collisions and earliest_toi over a CandidateSet, one
// thread, each query with its own four vertices, and baseline::naive_toi in a plain loop over
// the same queries, timed in turn in one process (interleaved rounds, medians).
//
// Workloads (vertex-face and edge-edge together):
//   sim     the bundled data/sim files (simulation-like queries, 17% collide at d = 0)
//   cloth   the broad-phase candidates of one step of the procedural cloth-on-sphere scene
//   fold    the same for the folding sheet (both as `exactccd generate` makes their steps)
//   funnel  the shared Scalable CCD cloth-funnel step's queries (published near-contact queries;
//           skipped when ../shared/data is absent)
// at d = 0 and d = 1e-3 (absolute; the naive cubic answers the contact question only, so its
// loop is the same at both d: the ratio is the cost of the exact answer against the cubic's).
//
//   build/batch_bench [--rounds N] [--only WORKLOAD] [--distance D] [--data-dir DIR] [--funnel DIR]
// (the data folder: --data-dir, else EXACTCCD_DATA_DIR, else the build tree's share/exactccd/data,
// as for the exactccd program)
// prints one row per workload and d: queries, colliding share, the median ns per query of each
// method and the ratios find_collisions / naive and earliest_toi / naive.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "baseline/naive_ccd.hpp"
#include "exactccd/exactccd.hpp"
#include "io/benchmark_csv.hpp"
#include "io/data_dir.hpp"
#include "scene/scene_primitives.hpp"
#include "scenes/procedural_scenes.hpp"

namespace {

using namespace exactccd;
namespace fs = std::filesystem;

/// A workload: the queries as the naive loop takes them, and the same queries as a candidate
/// list over positions where each query owns its four vertices.
struct Workload {
  std::string name;
  std::vector<VertexFaceQuery> vf;
  std::vector<EdgeEdgeQuery> ee;
  std::vector<Vec3> x0, x1;
  CandidateSet candidates;

  std::size_t size() const { return vf.size() + ee.size(); }
};

/// Appends a query's eight points (t0 rows, then t1 rows) as four new vertices; returns the
/// index of the first.
int own_vertices(Workload& w, const std::array<Vec3, 8>& r) {
  const int base = static_cast<int>(w.x0.size());
  for (int i = 0; i < 4; ++i) {
    w.x0.push_back(r[i]);
    w.x1.push_back(r[4 + i]);
  }
  return base;
}

void add_vertex_face(Workload& w, const VertexFaceQuery& q) {
  w.vf.push_back(q);
  const int b = own_vertices(w, rows(q));
  w.candidates.vertex_face.push_back({b, b + 1, b + 2, b + 3});
}

void add_edge_edge(Workload& w, const EdgeEdgeQuery& q) {
  w.ee.push_back(q);
  const int b = own_vertices(w, rows(q));
  w.candidates.edge_edge.push_back({b, b + 1, b + 2, b + 3});
}

/// Every query of a benchmark CSV file (rounded to doubles), by the kind its name says.
void add_file(Workload& w, const fs::path& path, io::QueryLayout layout) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  const io::BenchmarkQueries q = io::read_benchmark_csv(in, path.string(), layout);
  const std::string name = path.filename().string();
  const bool vf = name.find("vertex-face") != std::string::npos || name.find("vf") != std::string::npos;
  for (const auto& r : q.rows) {
    const auto d = io::nearest_double_rows(r);
    if (vf)
      add_vertex_face(w, from_rows<VertexFaceQuery>(d));
    else
      add_edge_edge(w, from_rows<EdgeEdgeQuery>(d));
  }
}

Workload sim_workload(const fs::path& data) {
  Workload w{"sim", {}, {}, {}, {}, {}};
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(data / "sim"))
    if (e.path().extension() == ".csv") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) add_file(w, f, {});
  return w;
}

/// One step of a procedural scene: its broad-phase candidates as queries.
Workload scene_workload(const std::string& name, int resolution) {
  Workload w{name, {}, {}, {}, {}, {}};
  const scene::MovingMesh mesh = scene::procedural_scene(name, resolution, 7);
  const Scene s{mesh.positions_t0, mesh.positions_t1, mesh.triangles, {}, {}};
  const scene::ScenePrimitives prim = scene::scene_primitives(s);
  for (const auto& [v, t] : prim.candidates.vertex_face) add_vertex_face(w, scene::vertex_face_query(s, v, t));
  for (const auto& [i, j] : prim.candidates.edge_edge)
    add_edge_edge(w, scene::edge_edge_query(s, prim.edges[i], prim.edges[j]));
  return w;
}

std::optional<Workload> funnel_workload(const fs::path& dir) {
  const fs::path q = dir / "cloth-funnel" / "queries";
  if (!fs::exists(q / "227vf.csv")) return std::nullopt;
  Workload w{"funnel", {}, {}, {}, {}, {}};
  add_file(w, q / "227vf.csv", {8, 3, false});
  add_file(w, q / "227ee.csv", {8, 3, false});
  return w;
}

template <class F>
double seconds(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// The naive cubic over every query; the number that collide (kept so the loop is not elided).
std::size_t naive_loop(const Workload& w) {
  std::size_t hits = 0;
  for (const auto& q : w.vf) hits += baseline::naive_toi(q).has_value();
  for (const auto& q : w.ee) hits += baseline::naive_toi(q).has_value();
  return hits;
}

/// Times the three methods in turn, `rounds` times, and prints the row.
void measure(const Workload& w, double d, int rounds) {
  const SceneOptions options{1, d, 1.0, nullptr};
  std::vector<double> naive, find, earliest;
  std::size_t collide = 0, naive_hits = 0;
  bool any = false;
  for (int r = 0; r < rounds; ++r) {
    naive.push_back(seconds([&] { naive_hits = naive_loop(w); }));
    find.push_back(seconds([&] { collide = find_collisions(w.x0, w.x1, w.candidates, options).size(); }));
    earliest.push_back(seconds([&] { any = earliest_toi(w.x0, w.x1, w.candidates, options).has_value(); }));
  }
  const double n = static_cast<double>(w.size());
  const double tn = median(naive), tf = median(find), te = median(earliest);
  std::printf("%-7s %-6g %8zu %6.1f%% %9.1f %9.1f %9.1f %8.2fx %8.2fx   (naive hits %zu, earliest %s)\n",
              w.name.c_str(), d, w.size(), 100.0 * static_cast<double>(collide) / n, 1e9 * tn / n, 1e9 * tf / n,
              1e9 * te / n, tf / tn, te / tn, naive_hits, any ? "found" : "none");
}

}  // namespace

int main(int argc, char** argv) {
  int rounds = 7;
  std::string data;  // empty: found like the exactccd program's (tools/lib/io/data_dir.hpp)
  fs::path funnel = EXACTCCD_SCALABLE_SAMPLE_DIR;
  std::string only;
  std::vector<double> distances{0.0, 1e-3};
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--rounds")) rounds = std::max(1, std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--only")) only = argv[i + 1];
    else if (!std::strcmp(argv[i], "--distance")) distances = {std::atof(argv[i + 1])};
    else if (!std::strcmp(argv[i], "--data-dir") || !std::strcmp(argv[i], "--data")) data = argv[i + 1];
    else if (!std::strcmp(argv[i], "--funnel")) funnel = argv[i + 1];
    else {
      std::fprintf(stderr, "usage: batch_bench [--rounds N] [--only WORKLOAD] [--distance D] [--data-dir DIR] [--funnel DIR]\n");
      return 2;
    }
  }
  fs::path data_dir;
  try {
    data_dir = exactccd::io::bundled_data_dir(data, "batch_bench");
  } catch (const exactccd::io::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  std::vector<Workload> workloads;
  workloads.push_back(sim_workload(data_dir));
  workloads.push_back(scene_workload("cloth", 64));
  workloads.push_back(scene_workload("fold", 64));
  if (auto f = funnel_workload(funnel))
    workloads.push_back(std::move(*f));
  else
    std::printf("funnel: skipped, no %s/cloth-funnel/queries\n", funnel.string().c_str());
  std::printf("%-7s %-6s %8s %7s %9s %9s %9s %9s %9s   (ns/query, medians of %d rounds, 1 thread)\n", "work",
              "d", "queries", "collide", "naive", "find", "earliest", "find/nv", "toi/nv", rounds);
  for (const double d : distances)
    for (const auto& w : workloads)
      if (only.empty() || only == w.name) measure(w, d, rounds);
}
