// exactccd scene: scene-level CCD of one time step given as two mesh files; and the OBJ writer
// of `exactccd generate scene`.
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "cli_common.hpp"
#include "exactccd/scene.hpp"
#include "io/mesh_file.hpp"
#include "io/obj.hpp"
#include "scene/parallel.hpp"
#include "io/output_file.hpp"
#include "scenes/procedural_scenes.hpp"
#include "scene/scene_primitives.hpp"
#include "numeric/simd_level.hpp"
#include "scene/step_stats.hpp"
#include "scene/streamed_step.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

namespace fs = std::filesystem;

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "scene";
    c.usage = "usage: exactccd scene T0.obj T1.obj [--min-distance D] [--tmax T] [--json] [--stats] [--threads N]";
    c.description =
        "One time step of a triangle mesh whose vertices move linearly from their positions in T0.obj\n"
        "(t = 0) to those in T1.obj (t = 1); both files must have the same vertex count and faces.\n"
        "Every vertex-face and edge-edge pair is decided exactly (pairs sharing a vertex are not\n"
        "tested), with the tightest double enclosure of its time of impact.\n"
        "\n"
        "Prints the vertex and triangle counts, the broad-phase candidate pairs, the colliding\n"
        "vertex-face pairs (vertex, triangle) and edge-edge pairs (a0 a1, b0 b1: each edge ascending,\n"
        "pairs ordered) with their times of impact, the earliest time of impact, the largest collision-\n"
        "free step (1 when collision-free, else the largest double below the earliest TOI's lower\n"
        "bound) and whether the mesh is free of self-intersections at t = 0 and at t = 1 (the exact\n"
        "static check of exactccd::intersection_free). Indices are 0-based, in OBJ order (a polygon\n"
        "is fan-triangulated into consecutive triangles). With --min-distance D and --tmax T a pair\n"
        "collides when it comes within distance D at some t in [0, T] (exactly), and the largest\n"
        "collision-free step is T when no pair does.\n"
        "\n"
        "Input: OBJ (.obj), PLY (.ply: ASCII or binary, either byte order, float or double x y z,\n"
        "list faces), OFF (.off, ASCII) and STL (.stl, ASCII or binary; corners with exactly equal\n"
        "coordinates are merged into one vertex), read strictly (docs/formats.md); float\n"
        "coordinates are taken exactly. A file whose content does not match its extension is an\n"
        "error. Indices are in file order (PLY, OFF: 0-based as in the file; STL: order of first\n"
        "appearance).\n";
    c.options = {
        flag_option("--json",
                    "print one JSON object instead: vertices, triangles, candidates, vf_pairs\n"
                    "([vertex, triangle] lists), ee_pairs ([a0, a1, b0, b1] lists), earliest_toi\n"
                    "([lo, hi] or null), max_safe_step, end_intersection_free (both ends),\n"
                    "t0_intersection_free, t1_intersection_free"),
        flag_option("--stats",
                    "also print where the step's time went: reading the files, the set-up (topology,\n"
                    "boxes, trees), the streamed broad and narrow phase (wall time, and the CPU time\n"
                    "of the tree traversal and of the narrow phase, summed over the threads), each intersection-free check; the\n"
                    "candidates per kind; the peak memory of the process (text: after the summary\n"
                    "lines; --json: a \"stats\" member)"),
        threads_option("", "broad and narrow phase on N threads (default: all cores; same results)"),
    };
    for (OptionSpec& o : separation_option_specs()) c.options.push_back(o);
    c.epilogue =
        "exit codes: 0 ran (whatever it found), 2 bad usage or malformed or mismatched files, 1 internal\n"
        "error.\n";
    return c;
  }();
  return spec;
}

/// The scene of two mesh files, or UsageError when they are not the same mesh.
Scene scene_of(const std::string& path0, const io::ObjMesh& m0, const std::string& path1, const io::ObjMesh& m1) {
  if (m0.vertices.size() != m1.vertices.size())
    throw UsageError("scene: mismatched files: " + path0 + " has " + std::to_string(m0.vertices.size()) +
                     " vertices but " + path1 + " has " + std::to_string(m1.vertices.size()));
  if (m0.triangles.size() != m1.triangles.size())
    throw UsageError("scene: mismatched files: " + path0 + " has " + std::to_string(m0.triangles.size()) +
                     " triangles but " + path1 + " has " + std::to_string(m1.triangles.size()));
  for (std::size_t i = 0; i < m0.triangles.size(); ++i)
    if (m0.triangles[i] != m1.triangles[i])
      throw UsageError("scene: mismatched files: triangle " + std::to_string(i) + " (0-based) differs between " +
                       path0 + " and " + path1);
  Scene s;
  s.positions_t0 = m0.vertices;
  s.positions_t1 = m1.vertices;
  s.triangles = m0.triangles;
  return s;
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string interval(const TimeInterval& t) { return "[" + number(t.lo) + ", " + number(t.hi) + "]"; }

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// The peak resident memory of this process so far (getrusage's ru_maxrss, KiB on Linux), MiB.
double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// What --stats prints.
struct StatsLine {
  scene::StepStats step;
  double read_seconds = 0, free0_seconds = 0, free1_seconds = 0, total_seconds = 0, peak_mib = 0;
};

/// intersection_free of the scene's triangles at these positions; its wall time in `seconds`.
bool timed_intersection_free(const std::vector<Vec3>& positions, const Scene& s, unsigned threads, double& seconds) {
  const auto start = Clock::now();
  const bool free = intersection_free(positions, s.triangles, threads);
  seconds = seconds_since(start);
  return free;
}

std::string fixed(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

std::string stats_text(const StatsLine& s) {
  const scene::StepStats& t = s.step;
  std::ostringstream out;
  out << "time read files           " << fixed(s.read_seconds, 3) << " s\n"
      << "time set-up               " << fixed(t.setup_seconds, 3) << " s (validation, topology, boxes, trees)\n"
      << "time broad+narrow phase   " << fixed(t.stream_seconds, 3) << " s wall, " << t.workers
      << " workers (CPU time: traversal " << fixed(t.traversal_thread_seconds, 3) << " s, narrow phase "
      << fixed(t.narrow_thread_seconds, 3) << " s)\n"
      << "time intersection-free    " << fixed(s.free0_seconds, 3) << " s at t0, " << fixed(s.free1_seconds, 3)
      << " s at t1\n"
      << "time total                " << fixed(s.total_seconds, 3) << " s\n"
      << "candidates per kind       " << t.candidates[0] << " vf, " << t.candidates[1] << " ee, " << t.candidates[2]
      << " pe, " << t.candidates[3] << " pp\n"
      << "peak memory               " << fixed(s.peak_mib, 1) << " MiB (peak resident set of the process)\n"
      << "simd level                " << numeric::simd_level_text() << " (the batched stages')\n";
  return out.str();
}

std::string stats_json(const StatsLine& s) {
  const scene::StepStats& t = s.step;
  std::ostringstream out;
  out << "{\"read_s\": " << fixed(s.read_seconds, 6) << ", \"setup_s\": " << fixed(t.setup_seconds, 6)
      << ", \"stream_s\": " << fixed(t.stream_seconds, 6) << ", \"workers\": " << t.workers
      << ", \"traversal_cpu_s\": " << fixed(t.traversal_thread_seconds, 6)
      << ", \"narrow_cpu_s\": " << fixed(t.narrow_thread_seconds, 6)
      << ", \"intersection_free_t0_s\": " << fixed(s.free0_seconds, 6)
      << ", \"intersection_free_t1_s\": " << fixed(s.free1_seconds, 6) << ", \"total_s\": " << fixed(s.total_seconds, 6)
      << ", \"candidates\": {\"vf\": " << t.candidates[0] << ", \"ee\": " << t.candidates[1]
      << ", \"pe\": " << t.candidates[2] << ", \"pp\": " << t.candidates[3]
      << "}, \"peak_rss_mib\": " << fixed(s.peak_mib, 1) << ", \"simd\": \""
      << numeric::simd_level_name(numeric::simd_level()) << "\"}";
  return out.str();
}

/// What one `exactccd scene` run found, and its --stats.
struct SceneRun {
  std::vector<Collision> collisions;
  std::optional<TimeInterval> earliest;
  double step = 0;
  bool free0 = false, free1 = false;
  StatsLine stats;
};

/// The broad-phase candidates the output counts: vertex-face and edge-edge (as streamed).
std::size_t candidates_of(const SceneRun& run) { return run.stats.step.candidates[0] + run.stats.step.candidates[1]; }

std::string json_report(const Scene& s, const SceneRun& run, bool with_stats) {
  std::string vf_list, ee_list;
  for (const Collision& c : run.collisions) {
    if (c.kind == CollisionKind::vertex_face)
      vf_list += (vf_list.empty() ? "[" : ", [") + std::to_string(c.vertex) + ", " + std::to_string(c.triangle) + "]";
    else
      ee_list += (ee_list.empty() ? "[" : ", [") + std::to_string(c.edge_a[0]) + ", " + std::to_string(c.edge_a[1]) +
                 ", " + std::to_string(c.edge_b[0]) + ", " + std::to_string(c.edge_b[1]) + "]";
  }
  const auto boolean = [](bool b) { return b ? "true" : "false"; };
  std::ostringstream out;
  out << "{\"vertices\": " << s.positions_t0.size() << ", \"triangles\": " << s.triangles.size()
      << ", \"candidates\": " << candidates_of(run) << ",\n \"vf_pairs\": [" << vf_list << "],\n \"ee_pairs\": ["
      << ee_list << "],\n \"earliest_toi\": " << (run.earliest ? interval(*run.earliest) : "null")
      << ", \"max_safe_step\": " << number(run.step) << ",\n \"end_intersection_free\": "
      << boolean(run.free0 && run.free1) << ", \"t0_intersection_free\": " << boolean(run.free0)
      << ", \"t1_intersection_free\": " << boolean(run.free1);
  if (with_stats) out << ",\n \"stats\": " << stats_json(run.stats);
  out << "}\n";
  return out.str();
}

std::string text_report(const Scene& s, const SceneRun& run, bool with_stats) {
  std::size_t vf = 0;
  for (const Collision& c : run.collisions) vf += c.kind == CollisionKind::vertex_face;
  const auto yes = [](bool b) { return b ? "yes" : "no"; };
  std::ostringstream out;
  out << "vertices                  " << s.positions_t0.size() << "\n"
      << "triangles                 " << s.triangles.size() << "\n"
      << "candidates                " << candidates_of(run) << " (" << run.stats.step.candidates[0] << " vf, "
      << run.stats.step.candidates[1] << " ee)\n"
      << "colliding vf pairs        " << vf << "\n"
      << "colliding ee pairs        " << run.collisions.size() - vf << "\n"
      << "earliest toi              " << (run.earliest ? interval(*run.earliest) : "none") << "\n"
      << "max safe step             " << number(run.step) << "\n"
      << "intersection-free at t0   " << yes(run.free0) << "\n"
      << "intersection-free at t1   " << yes(run.free1) << "\n";
  if (with_stats) out << stats_text(run.stats);
  for (const Collision& c : run.collisions) {
    if (c.kind == CollisionKind::vertex_face)
      out << "vf " << c.vertex << " " << c.triangle;
    else
      out << "ee " << c.edge_a[0] << " " << c.edge_a[1] << " " << c.edge_b[0] << " " << c.edge_b[1];
    out << " toi " << interval(c.toi) << "\n";
  }
  return out.str();
}

}  // namespace

int run_scene(int argc, char** argv) {
  const ParsedOptions options = parse_options(command(), argc, argv);
  if (options.help()) {
    std::cout << help_text(command());
    return kExitOk;
  }
  const bool json = options.flag("--json");
  SceneOptions scene_options;
  const unsigned threads = options.has("--threads") ? static_cast<unsigned>(options.integer("--threads")) : 0u;
  scene_options.threads = startable_threads(scene::resolve_threads(threads));  // 0: every hardware thread
  const CcdParams params = separation_params(options);
  scene_options.min_distance = params.min_distance;
  scene_options.tmax = params.tmax;
  const std::vector<std::string>& files = options.positionals();
  if (files.size() != 2) throw UsageError("scene: expected two files, T0 T1 (.obj, .ply, .off or .stl; see exactccd scene --help)");
  const auto start = Clock::now();
  const io::TriangleMesh m0 = io::read_mesh(files[0]), m1 = io::read_mesh(files[1]);
  const double read_seconds = seconds_since(start);
  const Scene s = scene_of(files[0], m0, files[1], m1);
  try {
    validate(s);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("scene: ") + e.what());
  }
  // One streamed pass (scene/streamed_step.hpp): the candidates are counted, not stored.
  SceneRun run;
  run.collisions = scene::find_collisions(s, scene_options, &run.stats.step);
  run.earliest = earliest_toi(run.collisions);
  run.step = max_collision_free_step(run.earliest, params.tmax);
  run.free0 = timed_intersection_free(s.positions_t0, s, scene_options.threads, run.stats.free0_seconds);
  run.free1 = timed_intersection_free(s.positions_t1, s, scene_options.threads, run.stats.free1_seconds);
  run.stats.read_seconds = read_seconds;
  run.stats.total_seconds = seconds_since(start);
  run.stats.peak_mib = peak_rss_mib();
  const bool stats = options.flag("--stats");
  const std::string out = json ? json_report(s, run, stats) : text_report(s, run, stats);
  std::cout << out;
  return kExitOk;
}

int generate_scene(const std::string& scene_name, int resolution, std::uint64_t seed, const std::string& out) {
  if (scene_name.empty()) throw UsageError("generate scene: --scene NAME is required (see exactccd generate --help)");
  scene::MovingMesh mesh;
  try {
    mesh = scene::procedural_scene(scene_name, resolution, seed);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("generate scene: ") + e.what());
  }
  io::prepare_output_directory(out);
  const std::string comment = "exactccd generate scene --scene " + scene_name + " --resolution " +
                              std::to_string(resolution) + " --seed " + std::to_string(seed);
  // Both files go to temporaries first, renamed once both are written: no half-written pair.
  const char* const names[] = {"T0.obj", "T1.obj"};
  const std::vector<Vec3>* const positions[] = {&mesh.positions_t0, &mesh.positions_t1};
  io::AtomicOutputFile t0((fs::path(out) / names[0]).string()), t1((fs::path(out) / names[1]).string());
  io::AtomicOutputFile* const files[] = {&t0, &t1};
  for (int i = 0; i < 2; ++i)
    io::write_obj(files[i]->stream(), *positions[i], mesh.triangles, comment + " (" + names[i] + ")");
  t0.commit();
  t1.commit();
  std::printf("%s: %zu vertices, %zu triangles (T0.obj, T1.obj)\n", out.c_str(), mesh.positions_t0.size(),
              mesh.triangles.size());
  return kExitOk;
}

}  // namespace exactccd::cli
