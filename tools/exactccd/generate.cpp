// exactccd generate: writes the project's own query sets, one code path for every motion model
// (motions.hpp): each model lists the sets it writes (LinearMotion::generate_sets, ...).
#include <iostream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "motions.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

/// The largest --resolution: a bound on the scenes' size (the pile at 1000 has 3 million bodies).
constexpr long long kMaxResolution = 1000;
/// The largest --max-queries.
constexpr long long kMaxQueriesPerFile = 1000000000;
/// The most family instances per direction and (family, k).
constexpr long long kMaxFamilyInstances = 100000;

const char* const kUsage =
    "usage: exactccd generate SET... [--motion linear|rigid] [options] --out DIR\n"
    "       exactccd generate catalogue --out DIR\n"
    "       exactccd generate sim --scene cloth|strip|fold|pile [--resolution N] [--seed S]\n"
    "                             [--max-queries M] [--truth exact|filtered] --out DIR\n"
    "       exactccd generate families [--seed S] [--instances N] [--k-step K] [--wide] --out DIR\n"
    "       exactccd generate scene --scene NAME [--resolution N] [--seed S] --out DIR\n"
    "       exactccd generate families sim --motion rigid [--seed S] [--max-queries M] --out DIR\n";

const char* const kDescription =
    "Writes query sets: each SET given, in order, into DIR. --motion linear (the default): the benchmark\n"
    "CSV format (8 rows per query, exact rationals, truth column); --motion rigid: rigid query files\n"
    "(check --motion rigid). Sets of linear motion:\n"
    "\n"
    "  catalogue   the hand-derived degenerate catalogue (tools/lib/generators/catalogue.cpp) with its scaled and\n"
    "              translated copies: DIR/catalogue-vertex-face.csv and DIR/catalogue-edge-edge.csv;\n"
    "              the truth column is the hand-derived answer\n"
    "  families    instances of every degenerate family (tools/lib/generators/families.hpp) for k = 0, K, 2K, ...\n"
    "              <= 60 and unperturbed, N per direction and (family, k) (default 1, K = 4):\n"
    "              DIR/families-vertex-face.csv and DIR/families-edge-edge.csv; the truth column is\n"
    "              the answer known by construction where the family knows it (else the exact\n"
    "              reference, Method::exact); every constructed answer and time of impact is\n"
    "              checked against Method::exact, and a disagreement is an internal error (exit 1,\n"
    "              naming the instance, nothing written); with --wide, each instance placed\n"
    "              in every wide style instead (families::make_wide: per-axis power-of-two\n"
    "              scales from the subnormal to the overflow end, translations, shears, all\n"
    "              exact) in DIR/families-wide-vertex-face.csv and families-wide-edge-edge.csv\n"
    "  scene       one time step of a procedural scene as two meshes, DIR/T0.obj (t = 0) and\n"
    "              DIR/T1.obj (t = 1), for exactccd scene\n"
    "  sim         simulation-like queries: the broad-phase candidates of one time step of a\n"
    "              procedural scene (tools/lib/scenes/procedural_scenes.hpp), written to\n"
    "              DIR/sim-<scene>-vertex-face.csv and DIR/sim-<scene>-edge-edge.csv; the truth\n"
    "              column is the exact answer of the reference path (Method::exact) unless\n"
    "              --truth filtered\n"
    "\n"
    "Sets of rigid motion (the files of data/rigid):\n"
    "\n"
    "  families    the degenerate rigid families (tools/lib/generators/rigid_families.hpp) at d = 0, k = unperturbed,\n"
    "              0, 4, ..., 52, both directions (truth by construction, checked against\n"
    "              Method::exact): DIR/rigid-families-vertex-face.csv and rigid-families-edge-edge.csv\n"
    "  sim         the candidates of tumbling bodies (tools/lib/scenes/rigid_sim.hpp: a box onto a\n"
    "              plane, interlocked rings; --scene box|rings for one), truth Method::exact, at most\n"
    "              M per file: DIR/rigid-sim-<scene>-vertex-face.csv and rigid-sim-<scene>-edge-edge.csv\n"
    "\n"
    "Files are written to temporaries renamed when complete: a failed run leaves no half-written\n"
    "file.\n";

std::vector<OptionSpec> generate_options() {
  return {
      required(text_option("--out", "DIR", "", "output directory (created if missing)")),
      motion_option("linear: the benchmark CSV sets and scenes; rigid: the rigid query sets\n"
                    "(see above)"),
      text_option("--scene", "NAME", "",
                  "cloth (cloth draped over a sphere), strip (tightening helical ribbon),\n"
                  "fold (sheet folding onto itself), pile (boxes and tetrahedra falling\n"
                  "onto the ground and each other); --motion rigid: box or rings (default both)"),
      integer_option("--resolution", "N", 2, kMaxResolution, "24", "scene resolution"),
      unsigned64_option("--seed", "S", "1", "random seed of the scene's noise and of the families; same seed,\n"
                                            "same file"),
      integer_option("--instances", "N", 1, kMaxFamilyInstances, "1",
                     "families (linear): instances per direction and (family, k)"),
      integer_option("--k-step", "K", 1, 60, "4", "families (linear): the step K between perturbation exponents"),
      flag_option("--wide", "families (linear): wide-exponent placements (every style) instead of\n"
                            "the plain ones"),
      integer_option("--max-queries", "M", 0, kMaxQueriesPerFile, "1000",
                     "sim: keep at most M queries per file (0 = all): every\n"
                     "colliding candidate (evenly spaced ones if more than M collide), then\n"
                     "evenly spaced non-colliding ones, in candidate order"),
      choice_option("--truth", "METHOD", {"exact", "filtered"}, "exact",
                    "how sim (linear) computes the truth column: exact (the reference path,\n"
                    "rational arithmetic and CGAL's algebraic kernel, ~0.1 ms per query,\n"
                    "independent of the filtered method that benchmarks measure) or filtered\n"
                    "(opt-in for large sets: exact too, about a microsecond per query, but then\n"
                    "the truth comes from the method under test); every candidate is answered,\n"
                    "also the ones not kept"),
      threads_option("2", "sim: answer the candidates on N threads (the same files)"),
  };
}

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "generate";
    c.usage = kUsage;
    c.description = kDescription;
    c.options = generate_options();
    c.epilogue = "exit codes: 0 written, 2 bad usage or unwritable output, 1 internal error.\n";
    return c;
  }();
  return spec;
}

/// The sets named on the command line, each one the model writes (checked before any is written).
template <class Motion>
std::vector<const GenerateSet*> chosen_sets(const std::vector<std::string>& names) {
  const std::vector<GenerateSet>& sets = Motion::generate_sets();
  std::string expected;
  for (std::size_t i = 0; i < sets.size(); ++i)
    expected += std::string(i == 0 ? "" : i + 1 == sets.size() ? " or " : ", ") + sets[i].name;
  if (names.empty())
    throw UsageError(subcommand_name<Motion>("generate") + ": expected " + expected +
                     " (see exactccd generate --help)");
  std::vector<const GenerateSet*> chosen;
  for (const std::string& name : names) {
    const GenerateSet* set = nullptr;
    for (const GenerateSet& s : sets)
      if (name == s.name) set = &s;
    if (!set)
      throw UsageError(subcommand_name<Motion>("generate") + ": unknown set '" + name + "' (expected " +
                       expected + "; see exactccd generate --help)");
    chosen.push_back(set);
  }
  return chosen;
}

}  // namespace

int run_generate(int argc, char** argv) {
  const ParsedOptions options = parse_options(command(), argc, argv);
  if (options.help()) {
    std::cout << help_text(command());
    return kExitOk;
  }
  return visit_motion(options, [&](auto motion) {
    for (const GenerateSet* set : chosen_sets<decltype(motion)>(options.positionals())) set->write(options);
    return kExitOk;
  });
}

}  // namespace exactccd::cli
