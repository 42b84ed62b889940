// exactccd scene: scene-level CCD of one time step given as two mesh files; and the OBJ writer
// of `exactccd generate scene`.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "cli_common.hpp"
#include "exactccd/scene.hpp"
#include "io/mesh_file.hpp"
#include "io/obj.hpp"
#include "output_file.hpp"
#include "scene/procedural_scenes.hpp"
#include "scene/scene_primitives.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

namespace fs = std::filesystem;

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "scene";
    c.usage = "usage: exactccd scene T0.obj T1.obj [--min-distance D] [--tmax T] [--json] [--threads N]";
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
        threads_option("", "narrow phase on N threads (default: all cores; same results)"),
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

}  // namespace

int run_scene(int argc, char** argv) {
  const ParsedOptions options = parse_options(command(), argc, argv);
  if (options.help()) {
    std::cout << help_text(command());
    return kExitOk;
  }
  const bool json = options.flag("--json");
  SceneOptions scene_options;
  if (options.has("--threads")) scene_options.threads = static_cast<unsigned>(options.integer("--threads"));
  const CcdParams params = separation_params(options);
  scene_options.min_distance = params.min_distance;
  scene_options.tmax = params.tmax;
  const std::vector<std::string>& files = options.positionals();
  if (files.size() != 2) throw UsageError("scene: expected two files, T0 T1 (.obj, .ply, .off or .stl; see exactccd scene --help)");
  const io::TriangleMesh m0 = io::read_mesh(files[0]), m1 = io::read_mesh(files[1]);
  const Scene s = scene_of(files[0], m0, files[1], m1);
  try {
    validate(s);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("scene: ") + e.what());
  }
  const scene::ScenePrimitives prim = scene::scene_primitives(s, params);
  const std::size_t candidates = prim.candidates.vertex_face.size() + prim.candidates.edge_edge.size();
  const std::vector<Collision> collisions = find_collisions(s, scene_options);
  const std::optional<TimeInterval> earliest = earliest_toi(collisions);
  const double step = max_collision_free_step(earliest, params.tmax);
  const bool free0 = intersection_free(s.positions_t0, s.triangles);
  const bool free1 = intersection_free(s.positions_t1, s.triangles);
  std::size_t vf = 0;
  for (const Collision& c : collisions) vf += c.kind == CollisionKind::vertex_face;
  std::ostringstream out;
  if (json) {
    std::string vf_list, ee_list;
    for (const Collision& c : collisions) {
      if (c.kind == CollisionKind::vertex_face)
        vf_list += (vf_list.empty() ? "[" : ", [") + std::to_string(c.vertex) + ", " + std::to_string(c.triangle) + "]";
      else
        ee_list += (ee_list.empty() ? "[" : ", [") + std::to_string(c.edge_a[0]) + ", " + std::to_string(c.edge_a[1]) +
                   ", " + std::to_string(c.edge_b[0]) + ", " + std::to_string(c.edge_b[1]) + "]";
    }
    const auto boolean = [](bool b) { return b ? "true" : "false"; };
    out << "{\"vertices\": " << s.positions_t0.size() << ", \"triangles\": " << s.triangles.size()
        << ", \"candidates\": " << candidates << ",\n \"vf_pairs\": [" << vf_list << "],\n \"ee_pairs\": ["
        << ee_list << "],\n \"earliest_toi\": " << (earliest ? interval(*earliest) : "null")
        << ", \"max_safe_step\": " << number(step) << ",\n \"end_intersection_free\": " << boolean(free0 && free1)
        << ", \"t0_intersection_free\": " << boolean(free0) << ", \"t1_intersection_free\": " << boolean(free1)
        << "}\n";
  } else {
    const auto yes = [](bool b) { return b ? "yes" : "no"; };
    out << "vertices                  " << s.positions_t0.size() << "\n"
        << "triangles                 " << s.triangles.size() << "\n"
        << "candidates                " << candidates << " (" << prim.candidates.vertex_face.size() << " vf, "
        << prim.candidates.edge_edge.size() << " ee)\n"
        << "colliding vf pairs        " << vf << "\n"
        << "colliding ee pairs        " << collisions.size() - vf << "\n"
        << "earliest toi              " << (earliest ? interval(*earliest) : "none") << "\n"
        << "max safe step             " << number(step) << "\n"
        << "intersection-free at t0   " << yes(free0) << "\n"
        << "intersection-free at t1   " << yes(free1) << "\n";
    for (const Collision& c : collisions) {
      if (c.kind == CollisionKind::vertex_face)
        out << "vf " << c.vertex << " " << c.triangle;
      else
        out << "ee " << c.edge_a[0] << " " << c.edge_a[1] << " " << c.edge_b[0] << " " << c.edge_b[1];
      out << " toi " << interval(c.toi) << "\n";
    }
  }
  std::cout << out.str();
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
  prepare_output_directory(out);
  const std::string comment = "exactccd generate scene --scene " + scene_name + " --resolution " +
                              std::to_string(resolution) + " --seed " + std::to_string(seed);
  // Both files go to temporaries first, renamed once both are written: no half-written pair.
  const char* const names[] = {"T0.obj", "T1.obj"};
  const std::vector<Vec3>* const positions[] = {&mesh.positions_t0, &mesh.positions_t1};
  AtomicOutputFile t0((fs::path(out) / names[0]).string()), t1((fs::path(out) / names[1]).string());
  AtomicOutputFile* const files[] = {&t0, &t1};
  for (int i = 0; i < 2; ++i)
    io::write_obj(files[i]->stream(), *positions[i], mesh.triangles, comment + " (" + names[i] + ")");
  t0.commit();
  t1.commit();
  std::printf("%s: %zu vertices, %zu triangles (T0.obj, T1.obj)\n", out.c_str(), mesh.positions_t0.size(),
              mesh.triangles.size());
  return kExitOk;
}

}  // namespace exactccd::cli
