// exactccd check: the oracle on query files, one code path for every motion model (motions.hpp).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "motions.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

/// What check does (its --help).
constexpr const char* kDescription =
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

/// What check prints, and its exit codes (its --help).
constexpr const char* kEpilogue =
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

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "check";
    c.usage = "usage: exactccd check [options] FILE.csv...";
    c.description = kDescription;
    c.options = {
        kind_option("query kind (default: inferred from 'vertex-face' / 'edge-edge' in the path)"),
        motion_option(
            "linear: every vertex on a straight line (benchmark CSV files); rigid:\n"
            "rigid bodies turning and moving (files of one query per line, 41\n"
            "comma-separated numbers: cA0 (3), qA0 (4: w x y z), cA1 (3), qA1 (4),\n"
            "cB0, qB0, cB1, qB1, the body points (vf: p of A, a b c of B; ee: a0 a1\n"
            "of A, b0 b1 of B), the truth 0 or 1; '#' starts a comment line)"),
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
    c.epilogue = kEpilogue;
    return c;
  }();
  return spec;
}

/// What check was asked, whatever the motion model.
struct CheckSettings {
  std::optional<QueryKind> kind;
  tools::Method method = tools::Method::filtered;
  bool answers = false, stats = false, json = false, want_toi = false;
  CcdParams params;
  BatchOptions batch;
  std::vector<std::string> files;
};

CheckSettings check_settings(const ParsedOptions& options) {
  CheckSettings s;
  s.kind = kind_of(options);
  s.method = parse_method(options.text("--method"));
  s.answers = options.flag("--answers"), s.stats = options.flag("--stats"), s.json = options.flag("--json");
  s.want_toi = options.flag("--toi");
  s.params = separation_params(options);
  s.batch = batch_options(options);
  s.files = options.positionals();
  return s;
}

struct Totals {
  std::size_t queries = 0, positives = 0, fp = 0, fn = 0;
  double seconds = 0;
  Totals& operator+=(const Totals& t) {
    queries += t.queries, positives += t.positives, fp += t.fp, fn += t.fn;
    seconds += t.seconds;
    return *this;
  }
  /// The mean time per query in microseconds (0 without queries).
  double us_per_query() const { return queries ? 1e6 * seconds / static_cast<double>(queries) : 0.0; }
};

/// Every file read (and the method's limits checked on it) before anything is printed: a
/// malformed file fails with no output.
template <class Motion>
std::vector<typename Motion::Dataset> load_files(const ParsedOptions& options, const CheckSettings& s) {
  const TruthSource truth = Motion::truth_source(options, s.files.size(), s.answers);
  std::vector<typename Motion::Dataset> datasets;
  for (const std::string& f : s.files) {
    datasets.push_back(Motion::load(f, s.kind, truth));
    Motion::require_answers(datasets.back(), s.method, s.params);
  }
  return datasets;
}

/// Answers queries [begin, end) of a file (on --threads threads) and reports them: its answers,
/// its JSON record (appended to json_items) or its table row.
template <class Motion>
Totals check_file(const typename Motion::Dataset& d, std::size_t begin, std::size_t end, const CheckSettings& s,
                  std::string& json_items) {
  constexpr std::size_t chunk = 64;  // queries answered together (answer_range: blocks of lanes)
  const std::size_t chunks = (end - begin + chunk - 1) / chunk;
  std::vector<StageCounters> counters(chunks);  // one per chunk: no shared counter
  std::vector<std::optional<TimeInterval>> result(end - begin);
  const double start = now_seconds();
  parallel_for(0, chunks, s.batch.threads, [&](std::size_t c) {
    const std::size_t first = begin + c * chunk, last = std::min(end, first + chunk);
    Motion::answer_range(d, first, last, s.method, counters[c], s.want_toi, s.params, result.data() + (first - begin));
  }, "check");
  Totals t;
  t.seconds = now_seconds() - start;
  t.queries = end - begin;
  StageCounters stages;
  for (const StageCounters& c : counters) stages += c;
  for (std::size_t i = begin; i < end; ++i) {
    const bool r = result[i - begin].has_value(), truth = d.queries.truth[i];
    t.positives += truth;
    t.fp += r && !truth;
    t.fn += !r && truth;
  }
  const CheckRecord record{d.path, kind_name(d.kind), Motion::record_motion, method_name(s.method), t.queries,
                           t.positives, t.fp, t.fn, t.us_per_query(), Motion::stage_counts(stages)};
  if (s.answers)
    print_answers(result, s.want_toi);
  else if (s.json)
    append_json_record(json_items, record);
  else
    print_check_row(record, s.stats && s.method == tools::Method::filtered, s.params);
  return t;
}

/// check for one motion model: the files of this shard (--shard), file by file.
template <class Motion>
int check(const ParsedOptions& options, const CheckSettings& s) {
  Motion::check_method(s.method);
  if (s.files.empty()) throw UsageError("check: no input file (see exactccd check --help)");
  if (s.json && s.answers) throw UsageError("check: --json and --answers exclude each other");
  const std::vector<typename Motion::Dataset> datasets = load_files<Motion>(options, s);
  std::size_t all_queries = 0;
  for (const auto& d : datasets) all_queries += d.queries.size();
  const auto [shard_begin, shard_end] = s.batch.shard_range(all_queries);
  const bool table = !s.answers && !s.json;
  if (table) print_check_header(s.params);
  Totals total;
  std::string json_items;
  std::size_t offset = 0;  // global index of the file's first query
  for (const auto& d : datasets) {
    const std::size_t n = d.queries.size();
    const std::size_t begin = std::clamp(shard_begin, offset, offset + n) - offset;
    const std::size_t end = std::clamp(shard_end, offset, offset + n) - offset;
    offset += n;
    if (begin != end) total += check_file<Motion>(d, begin, end, s, json_items);
  }
  if (s.json) std::printf("[\n%s\n]\n", json_items.c_str());
  if (table) {
    const CheckRecord sum{"total", "", nullptr, "", total.queries, total.positives, total.fp, total.fn,
                          total.us_per_query(), {}};
    print_check_row(sum, false, s.params);
  }
  return kExitOk;
}

}  // namespace

int run_check(int argc, char** argv) {
  const ParsedOptions options = parse_options(command(), argc, argv);
  if (options.help()) {
    std::cout << help_text(command());
    return kExitOk;
  }
  const CheckSettings settings = check_settings(options);
  return visit_motion(options, [&](auto motion) { return check<decltype(motion)>(options, settings); });
}

}  // namespace exactccd::cli
