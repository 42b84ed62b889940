// exactccd fuzz-against: another CCD code, loaded as a plug-in (include/exactccd/plugin.h),
// against the exact answers of any question (a minimum distance d and a time limit tmax) for
// every kind, on degenerate families and random degenerate queries. Every disagreement is
// shrunk and written as a benchmark CSV that `exactccd check` replays; times of impact after
// the exact one, or more than a factor early, are counted and written too.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <tuple>

#include "fuzz_against.hpp"
#include "fuzz_against_plugin.hpp"
#include "fuzz_against_queries.hpp"
#include "fuzz_against_report.hpp"
#include "io/output_file.hpp"
#include "partial.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

using namespace fuzz;

constexpr const char* kDescription = R"(Tests another CCD code against the exact answers. PLUGIN.so is a shared library exporting, for
the kind K (vf, ee, pe, pp, ee2, pe2, pp2),
  int exactccd_plugin_K_query(const double* q, double min_distance, double tmax, double* toi)
(include/exactccd/plugin.h: the kind's points at t = 0 then t = 1 in benchmark row order, x y z
each, x y in the plane; 1 = within min_distance at some t in [0, tmax], with its time of impact
in *toi; 0 = not; anything else counts as an error); for vf and ee at d = 0 and tmax = 1 the
contact-only exactccd_plugin_vf / exactccd_plugin_ee (and their _toi variants) also do.

Query i of the run is
  i even:      a family of the kind, cycling over every family, k = -1 (unperturbed), 0..60 and
               both directions (toward/away from "collides"), each instance randomly placed
               (the separation families in turn, each k in a scrambled order: a short run
               reaches every family and both large and ulp-sized perturbations);
  i = 1 mod 4: a random instance of a random family, k, direction and placement;
  i = 3 mod 4: plain random queries, cycling over the groups random_near (points on a grid of
               the scale of d, with degenerate edits) and for vf and ee the fuzzers' decoder on
               random bytes (integer grids, random doubles, family instances, catalogue cases).
The families: for --min-distance 0 with vf and ee the degenerate contact families
(tools/lib/generators/families.hpp: perturbations of 2^-k of contact through a vertex, an edge, coplanar
sliding, ...); otherwise the minimum-separation families (tools/lib/generators/separation_families.hpp): for
each feature pair (point-triangle, point-edge, point-point, edge-edge crossing, parallel, end to
end; the plane's kinds too) a configuration whose exact minimum distance over [0, tmax] is d
itself, passing, approaching, leaving or sliding at d, its contact at tmax, inside or at 0, and
its gap or contact time perturbed by 2^-k (relative, at least one ulp); scales of 2^-60..2^60.
The truth is the exact answer of the reference path (Method::exact: rational arithmetic and
CGAL's algebraic kernel, not the filtered front end). Prints per group the queries, collisions,
false positives and negatives, errors, times of impact after the exact one (unsafe) and more
than --early-factor times early, and for the families the k at which the plug-in disagreed.

Every disagreement is shrunk, then written to DIR:
  NNNNNN-GROUP-FP|FN-KIND.csv: the shrunk query (query index NNNNNN of the run), benchmark
      format, truth = the exact answer of the run's question, coordinates exact rationals;
  disagreements-KIND.csv: all of them, in run order; disagreements-KIND.txt: one line per
      disagreement (file, group, k and direction, how it was shrunk) and the query in hex floats;
  unsafe-toi-KIND.csv/.txt, early-toi-KIND.csv/.txt: the collisions with an unsafe or early
      time of impact (when the plug-in reports times).
Replay: exactccd check --kind K --min-distance D --tmax T DIR/disagreements-KIND.csv (0 FP, 0
FN: the truth column is exact). Files of the same kind from an earlier run in DIR are replaced.
Shrinking: a family instance is replaced by the least degenerate instance of the same family,
direction and placement that still disagrees the same way (the smallest k >= 0, else the
unperturbed one); the .txt lists every k at which that placement disagrees. Other queries:
each coordinate is simplified (0, its value at the other time, an integer, fewer significand
bits) while the same disagreement persists (and, for vf and ee, the same exact degeneracies).

)";

/// The most queries of a run: each holds about half a kilobyte until the end (5 GB at the limit).
constexpr long long kMaxFuzzQueries = 10000000;
/// The largest --min-distance: the families put points above d (docs/fuzzing.md).
constexpr double kMaxMinDistance = 0x1p1000;

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "fuzz-against";
    c.usage = "usage: exactccd fuzz-against PLUGIN.so --kind K (--out DIR | --partial OUT [--shard I/N]) [options]";
    c.description = kDescription;
    c.options = {
        required(kind_option("query kind")),
        integer_option("--queries", "N", 1, kMaxFuzzQueries, "10000", "number of queries"),
        unsigned64_option("--seed", "S", "1", "seed; a run is reproducible and independent of --threads"),
        text_option("--out", "DIR", "", "where to write the disagreements (created if missing)"),
        threads_option("1", "query on N threads (the plug-in must then be thread-safe)"),
        flag_option("--no-shrink", "write the disagreements as found"),
        real_option("--early-factor", "F", 1.0, 1e300, "2",
                    "count a time of impact T as early when F T is before the exact time"),
        shard_option("--shard", kMaxShards,
                     "only the I-th of N contiguous blocks of the queries 0..Q-1 (a cluster job);\n"
                     "needs --partial"),
        text_option("--partial", "OUT", "",
                    "write this run's or shard's partial results to OUT instead of the report and\n"
                    "DIR (then no --out): `exactccd merge --out DIR` of the N shards' files prints\n"
                    "the report and writes DIR, byte-identical to one run"),
    };
    for (OptionSpec o : separation_option_specs()) {
      if (o.name == "--min-distance") o.help += ";\nat most 2^1000 (the families put points above D)";
      c.options.push_back(o);
    }
    c.epilogue =
        "exit codes: 0 ran (whatever it found), 2 bad usage, an unwritable DIR, or a plug-in that cannot\n"
        "be loaded or lacks the kind's symbol, 1 internal error.\n";
    return c;
  }();
  return spec;
}

/// The run's settings as partial-file settings (every shard of one run has the same).
std::vector<std::pair<std::string, std::string>> partial_settings(const FuzzRun& run, const FuzzKind& kind,
                                                                  bool reports_toi) {
  return {{"plugin", run.plugin_path},
          {"kind", kind.short_name},
          {"queries", std::to_string(run.queries)},
          {"seed", std::to_string(run.seed)},
          {"shrink", run.shrinking ? "1" : "0"},
          {"toi", reports_toi ? "1" : "0"},
          {"min-distance", hex_double(run.params.min_distance)},
          {"tmax", hex_double(run.params.tmax)},
          {"early-factor", hex_double(run.early_factor)}};
}

/// A run (or one shard of it): the report, or with run.partial_path the partial results.
int run_kind(const FuzzRun& run, const FuzzKind& kind) {
  const Plugin plugin(run.plugin_path, kind, run.params);
  if (run.partial_path.empty()) io::prepare_output_directory(run.out_dir);  // fail before the work
  const Groups groups = make_groups(kind, run.params);
  const std::size_t begin = run.queries * run.shard_index / run.shard_count;
  const std::size_t end = run.queries * (run.shard_index + 1) / run.shard_count;
  const double start = now_seconds();
  const FuzzTally tally = fuzz_queries(run, kind, plugin, groups, begin, end);
  // The time goes to stderr: stdout is the report, the same for a run, its shards merged, and
  // any --threads.
  std::fprintf(stderr, "fuzz-against: %zu queries in %.1f s\n", end - begin, now_seconds() - start);
  if (run.partial_path.empty()) {
    report_fuzz({run, kind, groups.names(), plugin.symbol(), plugin.reports_toi()}, tally);
    return kExitOk;
  }
  Partial p;
  p.command = "fuzz-against";
  p.settings = partial_settings(run, kind, plugin.reports_toi());
  p.settings.emplace_back("symbol", plugin.symbol());
  p.shard_index = run.shard_index;
  p.shard_count = run.shard_count;
  p.begin = begin;
  p.end = end;
  p.total = run.queries;
  add_records(tally, p);
  write_partial(run.partial_path, p);
  return kExitOk;
}

/// The run the options ask for; throws UsageError on inconsistent options.
FuzzRun run_of(const ParsedOptions& options) {
  FuzzRun run;
  run.queries = static_cast<std::size_t>(options.integer("--queries"));
  run.seed = options.unsigned64("--seed");
  run.out_dir = options.has("--out") ? options.text("--out") : "";
  run.partial_path = options.has("--partial") ? options.text("--partial") : "";
  std::tie(run.shard_index, run.shard_count) = options.shard("--shard");
  if (options.has("--shard") && run.partial_path.empty())
    throw UsageError("fuzz-against: --shard needs --partial FILE (the shards are merged by exactccd merge --out DIR)");
  if (run.partial_path.empty() == run.out_dir.empty())
    throw UsageError("fuzz-against: give exactly one of --out DIR and --partial FILE");
  run.threads = startable_threads(scene::resolve_threads(static_cast<unsigned>(options.integer("--threads"))));
  run.shrinking = !options.flag("--no-shrink");
  run.params = separation_params(options);
  run.early_factor = options.real("--early-factor");
  if (run.params.min_distance > kMaxMinDistance)
    throw UsageError("fuzz-against: --min-distance above 2^1000 is not supported (the families put points above d)");
  if (options.positionals().empty()) throw UsageError("fuzz-against: no plug-in (see exactccd fuzz-against --help)");
  if (options.positionals().size() > 1)
    throw UsageError("fuzz-against: one plug-in at a time ('" + options.positionals()[0] + "' and '" +
                     options.positionals()[1] + "')");
  run.plugin_path = options.positionals()[0];
  return run;
}

double real_setting(const Partial& merged, const std::string& key, const std::string& source) {
  return parse_double(merged.setting(key, source), source, 1);
}

}  // namespace

int run_fuzz_against(int argc, char** argv) {
  const ParsedOptions options = parse_options(command(), argc, argv);
  if (options.help()) {
    std::cout << help_text(command());
    return kExitOk;
  }
  const std::optional<QueryKind> kind = kind_of(options);
  return run_kind(run_of(options), fuzz_kind(*kind));
}

int merge_fuzz_against(const Partial& merged, const std::string& source, const std::string& out_dir) {
  if (out_dir.empty()) throw UsageError("merge: fuzz-against partials need --out DIR (where the run writes its files)");
  FuzzRun run;
  run.plugin_path = merged.setting("plugin", source);
  run.queries = parse_count(merged.setting("queries", source), source, 1);
  run.seed = parse_count(merged.setting("seed", source), source, 1);
  run.shrinking = merged.setting("shrink", source) == "1";
  run.params = {real_setting(merged, "min-distance", source), real_setting(merged, "tmax", source)};
  run.early_factor = real_setting(merged, "early-factor", source);
  run.out_dir = out_dir;
  const bool reports_toi = merged.setting("toi", source) == "1";
  if (run.queries != merged.total)
    throw io::ParseError(source, 1, "the run has " + std::to_string(run.queries) + " queries but the shards cover " +
                                        std::to_string(merged.total));
  const std::string& kind_text = merged.setting("kind", source);
  QueryKind kind;
  try {
    kind = parse_kind(kind_text);
  } catch (const UsageError&) {
    throw io::ParseError(source, 1, "fuzz-against has no kind '" + kind_text + "'");
  }
  const FuzzKind& k = fuzz_kind(kind);
  const Groups groups = make_groups(k, run.params);
  report_fuzz({run, k, groups.names(), merged.setting("symbol", source), reports_toi},
              tally_from_records(merged, groups.list.size()));
  return kExitOk;
}

}  // namespace exactccd::cli
