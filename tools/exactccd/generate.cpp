// exactccd generate: writes the project's own query sets in the benchmark CSV format.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "cli_common.hpp"
#include "fuzz/catalogue.hpp"
#include "fuzz/families.hpp"
#include "output_file.hpp"
#include "rigid_cli.hpp"
#include "scenes/procedural_scenes.hpp"
#include "scenes/sim_queries.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

namespace fs = std::filesystem;

/// The largest --resolution: a bound on the scenes' size (the pile at 1000 has 3 million bodies).
constexpr long long kMaxResolution = 1000;
/// The largest --max-queries.
constexpr long long kMaxQueriesPerFile = 1000000000;
/// The most family instances per direction and (family, k).
constexpr long long kMaxFamilyInstances = 100000;

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "generate";
    c.usage =
        "usage: exactccd generate catalogue --out DIR\n"
        "       exactccd generate sim --scene cloth|strip|fold|pile [--resolution N] [--seed S]\n"
        "                             [--max-queries M] [--truth exact|filtered] --out DIR\n"
        "       exactccd generate families [--seed S] [--instances N] [--k-step K] [--wide] --out DIR\n"
        "       exactccd generate scene --scene NAME [--resolution N] [--seed S] --out DIR\n"
        "       exactccd generate rigid [--seed S] [--max-queries M] --out DIR\n";
    c.description =
        "Writes query sets in the benchmark CSV format (8 rows per query, exact rationals, truth column).\n"
        "\n"
        "  catalogue   the hand-derived degenerate catalogue (fuzz/catalogue.cpp) with its scaled and\n"
        "              translated copies: DIR/catalogue-vertex-face.csv and DIR/catalogue-edge-edge.csv;\n"
        "              the truth column is the hand-derived answer\n"
        "  families    instances of every degenerate family (fuzz/families.hpp) for k = 0, K, 2K, ...\n"
        "              <= 60 and unperturbed, N per direction and (family, k) (default 1, K = 4):\n"
        "              DIR/families-vertex-face.csv and DIR/families-edge-edge.csv; the truth column is\n"
        "              the answer known by construction where the family knows it (else the exact\n"
        "              reference, Method::exact); every constructed answer and time of impact is\n"
        "              checked against Method::exact, and a disagreement is an internal error (exit 1,\n"
        "              naming the instance, nothing written); with --wide, each instance placed\n"
        "              in every wide style instead (families::make_wide: per-axis power-of-two\n"
        "              scales from the subnormal to the overflow end, translations, shears, all\n"
        "              exact) in DIR/families-wide-vertex-face.csv and families-wide-edge-edge.csv\n"
        "  rigid       rigid queries (--motion rigid files): the degenerate rigid families (d = 0; truth\n"
        "              by construction, checked against Method::exact) and the candidates of tumbling\n"
        "              bodies (a box onto a plane, interlocked rings; truth Method::exact, at most M per\n"
        "              file): DIR/rigid-families-*.csv, DIR/rigid-sim-<scene>-*.csv\n"
        "  scene       one time step of a procedural scene as two meshes, DIR/T0.obj (t = 0) and\n"
        "              DIR/T1.obj (t = 1), for exactccd scene\n"
        "  sim         simulation-like queries: the broad-phase candidates of one time step of a\n"
        "              procedural scene (lib/scenes/procedural_scenes.hpp), written to\n"
        "              DIR/sim-<scene>-vertex-face.csv and DIR/sim-<scene>-edge-edge.csv; the truth\n"
        "              column is the exact answer of the reference path (Method::exact) unless\n"
        "              --truth filtered\n"
        "\n"
        "Files are written to temporaries renamed when complete: a failed run leaves no half-written\n"
        "file.\n";
    c.options = {
        required(text_option("--out", "DIR", "", "output directory (created if missing)")),
        text_option("--scene", "NAME", "",
                    "cloth (cloth draped over a sphere), strip (tightening helical ribbon),\n"
                    "fold (sheet folding onto itself), pile (boxes and tetrahedra falling\n"
                    "onto the ground and each other)"),
        integer_option("--resolution", "N", 2, kMaxResolution, "24", "scene resolution"),
        unsigned64_option("--seed", "S", "1", "random seed of the scene's noise; same seed, same file"),
        integer_option("--instances", "N", 1, kMaxFamilyInstances, "1",
                       "families: instances per direction and (family, k)"),
        integer_option("--k-step", "K", 1, 60, "4", "families: the step K between perturbation exponents"),
        flag_option("--wide", "families: wide-exponent placements (every style) instead of the plain ones"),
        integer_option("--max-queries", "M", 0, kMaxQueriesPerFile, "1000",
                       "keep at most M queries per file (0 = all): every\n"
                       "colliding candidate (evenly spaced ones if more than M collide), then\n"
                       "evenly spaced non-colliding ones, in candidate order"),
        choice_option("--truth", "METHOD", {"exact", "filtered"}, "exact",
                      "how sim computes the truth column: exact (the reference path, rational\n"
                      "arithmetic and CGAL's algebraic kernel, ~0.1 ms per query, independent\n"
                      "of the filtered method that benchmarks measure) or filtered (opt-in for\n"
                      "large sets: exact too, about a microsecond per query, but then the truth\n"
                      "comes from the method under test); every candidate is answered, also the\n"
                      "ones not kept"),
    };
    c.epilogue = "exit codes: 0 written, 2 bad usage or unwritable output, 1 internal error.\n";
    return c;
  }();
  return spec;
}

template <class E>
io::BenchmarkQueries to_benchmark(const std::vector<E>& entries) {
  io::BenchmarkQueries q;
  for (const E& e : entries) {
    q.rows.push_back(rows(e.query));
    q.truth.push_back(e.collides);
  }
  return q;
}

/// Writes to a temporary file and renames it: a failed run leaves no half-written file.
void write_atomically(const fs::path& path, const io::BenchmarkQueries& q,
                      const std::string& note = "") {
  AtomicOutputFile out(path.string());
  io::write_benchmark_csv(out.stream(), q);
  out.commit();
  std::size_t positives = 0;
  for (bool t : q.truth) positives += t;
  std::printf("%s: %zu queries, %zu positives%s\n", path.string().c_str(), q.size(), positives,
              note.c_str());
}

/// Answers every query exactly (collides(q)), keeps those scene::select_queries picks
/// (max_queries 0: all) in their order, and converts them exactly to rationals (a double is
/// m 2^e: mpq_class holds it as the reduced m 2^max(e,0) / 2^max(-e,0)). `positives_all`
/// receives the number of colliding queries among all of them.
template <class Query, class Collides>
io::BenchmarkQueries answer_and_select(const std::vector<Query>& queries, std::size_t max_queries,
                                       Collides&& collides, std::size_t* positives_all = nullptr) {
  std::vector<bool> truth(queries.size());
  std::size_t positives = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const bool c = collides(queries[i]);
    truth[i] = c;
    positives += c;
  }
  if (positives_all) *positives_all = positives;
  io::BenchmarkQueries out;
  for (std::size_t i : scene::select_queries(truth, max_queries)) {
    std::array<RationalVec3, 8> r;
    const auto d = rows(queries[i]);
    for (int j = 0; j < 8; ++j) r[j] = {mpq_class(d[j].x), mpq_class(d[j].y), mpq_class(d[j].z)};
    out.rows.push_back(r);
    out.truth.push_back(truth[i]);
  }
  return out;
}

/// The eight points of a double query as exact rationals.
template <class Query>
std::array<RationalVec3, 8> rational_rows(const Query& q) {
  std::array<RationalVec3, 8> r;
  const auto d = rows(q);
  for (std::size_t j = 0; j < 8; ++j) r[j] = {mpq_class(d[j].x), mpq_class(d[j].y), mpq_class(d[j].z)};
  return r;
}

/// The truth of a family instance: its answer by construction where the family knows it,
/// else the exact reference (Method::exact). A constructed answer or time of impact that
/// Method::exact contradicts is a bug in the construction or in the exact path: thrown as an
/// internal error (exit 1) naming the instance, before anything is written.
bool family_truth(const families::Instance& inst, const std::string& where) {
  const auto [exact, toi] = std::visit(
      [](const auto& q) { return std::pair{ccd(q, Method::exact), exactccd::toi(q, Method::exact)}; }, inst.query);
  if (const std::optional<std::string> why = families::disagreement(inst, exact, toi))
    throw std::runtime_error("generate families: " + where + ": the construction and Method::exact disagree: " + *why);
  return inst.expected.value_or(exact);
}

}  // namespace

int run_generate(int argc, char** argv) {
  const ParsedOptions options = parse_options(command(), argc, argv);
  if (options.help()) {
    std::cout << help_text(command());
    return kExitOk;
  }
  const std::string out = options.text("--out");
  const std::string scene_name = options.has("--scene") ? options.text("--scene") : "";
  const int resolution = static_cast<int>(options.integer("--resolution"));
  const std::uint64_t seed = options.unsigned64("--seed");
  const auto max_queries = static_cast<std::size_t>(options.integer("--max-queries"));
  const int family_instances = static_cast<int>(options.integer("--instances"));
  const int k_step = static_cast<int>(options.integer("--k-step"));
  const std::string truth_name = options.text("--truth");
  const bool wide = options.flag("--wide");
  if (options.positionals().size() > 1)
    throw UsageError("generate: unexpected argument '" + options.positionals()[1] + "'");
  const std::string what = options.positionals().empty() ? "" : options.positionals()[0];
  if (what != "catalogue" && what != "sim" && what != "families" && what != "scene" && what != "rigid")
    throw UsageError("generate: expected catalogue, sim, families, scene or rigid (see exactccd generate --help)");
  if (what == "rigid") return generate_rigid(seed, max_queries, 2, out);
  if (what == "scene") return generate_scene(scene_name, resolution, seed, out);
  if (what == "catalogue") {
    prepare_output_directory(out);
    write_atomically(fs::path(out) / "catalogue-vertex-face.csv", to_benchmark(catalogue::vertex_face_cases()));
    write_atomically(fs::path(out) / "catalogue-edge-edge.csv", to_benchmark(catalogue::edge_edge_cases()));
    return kExitOk;
  }
  if (what == "families") {
    std::map<std::string_view, io::BenchmarkQueries> by_kind;  // by the kind's name
    std::size_t constructed = 0, total = 0;
    std::mt19937_64 rng(seed);
    for (const families::Family& f : families::all_families())
      for (int k = families::kUnperturbed; k <= 60; k = (k < 0 ? 0 : k + k_step))
        for (int i = 0; i < 2 * family_instances; ++i) {
          const bool toward = i % 2 == 0;
          const std::string where = f.name + " k=" + std::to_string(k) + (toward ? " toward" : " away") +
                                    " instance " + std::to_string(i / 2);
          const auto add = [&](const families::Instance& inst, const std::string& placement) {
            io::BenchmarkQueries& queries = by_kind[f.kind];
            queries.truth.push_back(family_truth(inst, where + placement));
            queries.rows.push_back(std::visit([](const auto& q) { return rational_rows(q); }, inst.query));
            constructed += inst.expected.has_value();
            ++total;
          };
          if (!wide) {
            add(f.make(k, toward, rng), "");
            continue;
          }
          for (int style = 0; style < families::kWideStyleCount; ++style) {
            const auto w = static_cast<families::WideStyle>(style);
            if (const auto inst = families::make_wide(f, k, toward, w, rng))
              add(*inst, std::string(" wide ") + families::wide_style_name(w));
          }
        }
    prepare_output_directory(out);
    const std::string note = " (truth: " + std::to_string(constructed) + " of " + std::to_string(total) +
                             " by construction, checked against Method::exact; the others by Method::exact)";
    const std::string prefix = wide ? "families-wide-" : "families-";
    for (QueryKind k : all_kinds()) {  // one file per kind that has families, named by the kind
      const auto it = by_kind.find(kind_long_name(k));
      if (it != by_kind.end()) write_atomically(fs::path(out) / (prefix + std::string(it->first) + ".csv"), it->second, note);
    }
    return kExitOk;
  }
  if (scene_name.empty()) throw UsageError("generate sim: --scene cloth|strip|fold|pile is required");
  prepare_output_directory(out);  // an unwritable DIR fails before the work
  const Method truth_method = truth_name == "exact" ? Method::exact : Method::filtered;
  scene::MovingMesh mesh;
  try {
    mesh = scene::procedural_scene(scene_name, resolution, seed);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("generate sim: ") + e.what());
  }
  const scene::StepQueries q = scene::step_queries(mesh);
  std::fprintf(stderr, "scene %s: %zu vertices, %zu triangles, %zu VF and %zu EE candidates\n",
               scene_name.c_str(), mesh.positions_t0.size(), mesh.triangles.size(), q.vertex_face.size(),
               q.edge_edge.size());
  std::size_t vf_positives = 0, ee_positives = 0;
  const auto vf = answer_and_select(
      q.vertex_face, max_queries, [&](const VertexFaceQuery& x) { return vertex_face_ccd(x, truth_method); },
      &vf_positives);
  const auto ee = answer_and_select(
      q.edge_edge, max_queries, [&](const EdgeEdgeQuery& x) { return edge_edge_ccd(x, truth_method); },
      &ee_positives);
  const auto note = [&](std::size_t candidates, std::size_t positives) {
    return " (truth: " + truth_name + "; the step: " + std::to_string(candidates) + " candidates, " +
           std::to_string(positives) + " collide)";
  };
  write_atomically(fs::path(out) / ("sim-" + scene_name + "-vertex-face.csv"), vf,
                   note(q.vertex_face.size(), vf_positives));
  write_atomically(fs::path(out) / ("sim-" + scene_name + "-edge-edge.csv"), ee,
                   note(q.edge_edge.size(), ee_positives));
  return kExitOk;
}

}  // namespace exactccd::cli
