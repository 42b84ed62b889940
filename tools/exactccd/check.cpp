// exactccd check: the oracle on benchmark CSV files.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "rigid_cli.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "check";
    c.usage = "usage: exactccd check [options] FILE.csv...";
    c.description =
        "Answers every query of benchmark CSV files (Wang et al. 2021 format: 8 rows per query,\n"
        "x_num,x_den,y_num,y_den,z_num,z_den,truth) and compares with the truth column. Other kinds:\n"
        "point-edge 6 rows (p_t0, a_t0, b_t0, p_t1, a_t1, b_t1), point-point 4 rows (p_t0, q_t0, p_t1,\n"
        "q_t1); the 2D kinds have the rows of their 3D counterpart with 5 columns each\n"
        "(x_num,x_den,y_num,y_den,truth). With --min-distance D and --tmax T a query collides iff the\n"
        "primitives come within distance D at some t in [0, T] (exactly; the truth column must be\n"
        "that question's).\n"
        "\n"
        "The Scalable CCD dataset's query files (6 columns x_num, x_den, y_num, y_den, z_num, z_den,\n"
        "no truth column; kind 'vf' or 'ee' at the end of the file name, e.g. 227vf.csv) take their\n"
        "truth from a JSON array of booleans: --truth FILE.json, or found by name\n"
        "(DIR/queries/227vf.csv -> DIR/mma_bool/227vf_mma_bool.json). Without one such a file is an\n"
        "error, except with --answers (which needs no truth).\n"
        "\n"
        "--motion rigid: rigid bodies (--kind vf|ee; see --motion below): vertex p of body A against\n"
        "triangle (a, b, c) of body B, or edge (a0, a1) of A against edge (b0, b1) of B, each body moving\n"
        "from pose (c0, q0) to (c1, q1) (c and the quaternion q interpolated linearly; docs/design.md 9);\n"
        "methods filtered and exact.\n";
    c.options = {
        kind_option("query kind (default: inferred from 'vertex-face' / 'edge-edge' in the path)"),
        motion_option(),
        choice_option("--method", "NAME", all_method_names(), "filtered",
                      "filtered (exact), exact (CGAL reference; slow); baselines, NOT robust:\n"
                      "naive (textbook doubles), naive-tolerance (Bridson-style tolerance),\n"
                      "mpfr24, mpfr53, mpfr113, mpfr256 (textbook in MPFR)"),
        flag_option("--answers", "print only one line per query, 0 or 1, in file order"),
        text_option("--truth", "FILE.json", "",
                    "the truth of a query file without truth column (one FILE.csv only): a JSON\n"
                    "array of booleans, one per query (default: found by name, see above)"),
        flag_option("--toi", "compute times of impact; with --answers each line is 0, or 1 LO HI: the\n"
                             "tightest doubles around the earliest time (17 significant digits)"),
        flag_option("--stats", "also print how many queries each stage of the filtered method decided"),
        flag_option("--json", "print a JSON array instead of the table: one object per file with keys\n"
                              "file, kind, method, queries, positives, fp, fn, us_per_query, stages"),
    };
    for (OptionSpec& o : separation_option_specs()) c.options.push_back(o);
    for (OptionSpec& o : batch_option_specs()) c.options.push_back(o);
    c.epilogue =
        "\noutput: per file, queries, truth positives, false positives, false negatives and the mean time\n"
        "per query (wall-clock time / queries, so with --threads it is the throughput); then the totals.\n"
        "With --min-distance D > 0 or --tmax T < 1 those three counts are named for what they count,\n"
        "truth_1, yes_truth_0 and no_truth_1 (the answer to the question D, T against the truth column):\n"
        "the bundled files' truth column is contact over [0, 1], so a query that comes within D without\n"
        "touching is a right answer counted in yes_truth_0, not a false positive.\n"
        "input: docs/formats.md, \"Input files\" (empty files, numerators or denominators over 4096\n"
        "bits and, for the baselines, coordinates beyond the double range are errors).\n"
        "exit codes: 0 ran (whatever it found), 2 bad usage or malformed input (file:line on stderr),\n"
        "1 internal error.\n";
    return c;
  }();
  return spec;
}

struct Totals {
  std::size_t queries = 0, positives = 0, fp = 0, fn = 0;
  double seconds = 0;
};

}  // namespace

int run_check(int argc, char** argv) {
  const ParsedOptions options = parse_options(command(), argc, argv);
  if (options.help()) {
    std::cout << help_text(command());
    return kExitOk;
  }
  if (rigid_motion(options)) return run_rigid_check(options);
  const std::optional<QueryKind> kind = kind_of(options);
  const tools::Method method = parse_method(options.text("--method"));
  const bool answers = options.flag("--answers"), stats = options.flag("--stats"), json = options.flag("--json");
  const bool want_toi = options.flag("--toi");
  const CcdParams params = separation_params(options);
  const BatchOptions batch = batch_options(options);
  const std::vector<std::string>& files = options.positionals();
  if (files.empty()) throw UsageError("check: no input file (see exactccd check --help)");
  if (json && answers) throw UsageError("check: --json and --answers exclude each other");

  // Parse everything first: a malformed file fails before anything is printed.
  TruthSource truth;
  truth.json = options.has("--truth") ? options.text("--truth") : "";
  truth.required = !answers;
  if (!truth.json.empty() && files.size() != 1)
    throw UsageError("check: --truth FILE.json goes with one FILE.csv (" + std::to_string(files.size()) + " given)");
  std::vector<Dataset> datasets;
  for (const std::string& f : files) {
    datasets.push_back(load_dataset(f, kind, truth));
    require_method_answers(method, datasets.back().kind, params);
    require_double_range(datasets.back(), method);
  }

  std::size_t all_queries = 0;
  for (const Dataset& d : datasets) all_queries += d.queries.size();
  const auto [shard_begin, shard_end] = batch.shard_range(all_queries);

  Totals total;
  const bool table = !answers && !json;
  std::string json_items;
  if (table) print_check_header(params);
  std::size_t offset = 0;  // global index of the dataset's first query
  for (const Dataset& d : datasets) {
    const std::size_t n = d.queries.size();
    const std::size_t begin = std::clamp(shard_begin, offset, offset + n) - offset;
    const std::size_t end = std::clamp(shard_end, offset, offset + n) - offset;
    offset += n;
    if (begin == end) continue;
    std::vector<StageCounters> counters(end - begin);  // one per query: no shared counter
    std::vector<std::optional<TimeInterval>> result(end - begin);
    const double start = now_seconds();
    parallel_for(begin, end, batch.threads, [&](std::size_t i) {
      result[i - begin] = run_query(d, i, method, &counters[i - begin], want_toi, params);
    }, "check");
    const double seconds = now_seconds() - start;
    StageCounters stages;
    for (const StageCounters& c : counters) stages += c;
    Totals t;
    t.queries = end - begin;
    t.seconds = seconds;
    for (std::size_t i = begin; i < end; ++i) {
      const bool r = result[i - begin].has_value();
      t.positives += d.queries.truth[i];
      t.fp += r && !d.queries.truth[i];
      t.fn += !r && d.queries.truth[i];
    }
    const CheckRecord record{d.name, kind_name(d.kind), nullptr, method_name(method), t.queries, t.positives, t.fp, t.fn,
                             t.queries ? 1e6 * seconds / t.queries : 0.0, linear_stage_counts(stages)};
    if (answers)
      print_answers(result, want_toi);
    else if (json)
      append_json_record(json_items, record);
    else
      print_check_row(record, stats && method == tools::Method::filtered, params);
    total.queries += t.queries;
    total.positives += t.positives;
    total.fp += t.fp;
    total.fn += t.fn;
    total.seconds += t.seconds;
  }
  if (json) std::printf("[\n%s\n]\n", json_items.c_str());
  if (table) {
    const CheckRecord sum{"total", "", nullptr, "", total.queries, total.positives, total.fp, total.fn,
                          total.queries ? 1e6 * total.seconds / total.queries : 0.0, {}};
    print_check_row(sum, false, params);
  }
  return kExitOk;
}

}  // namespace exactccd::cli
