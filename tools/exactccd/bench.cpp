// exactccd bench: the methods on the same loaded queries, several repetitions, interleaved; one
// code path for every motion model (motions.hpp), whose arms and table differ.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <vector>

#include "cli_common.hpp"
#include "io/data_dir.hpp"
#include "motions.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

/// The most repetitions: a bound on the run time, not on anything's size.
constexpr long long kMaxRepetitions = 100000;

/// What bench does (its --help).
constexpr const char* kDescription =
    "Runs every method on the same loaded queries and reports, per dataset and method: mean and\n"
    "median time per query in ns, false positives and false negatives against the file's published\n"
    "truth column (for every method, the exact ones included), the queries that reached the exact\n"
    "CGAL fallback, and the share decided by each filter stage. Per dataset, truth!=exact counts the\n"
    "queries whose published truth disagrees with the exact reference (Method::exact); when it is\n"
    "not 0 the FP/FN figures are against a wrong truth, and a note says so on stderr.\n"
    "\n"
    "Without files it runs the bundled datasets: the shared benchmark's unit-tests (when present)\n"
    "and the simulation-like sets under data/sim (dataset names starting with \"sim\").\n"
    "Each file given is one dataset.\n"
    "\n"
    "The bundled data folder: --data-dir DIR, else the environment variable EXACTCCD_DATA_DIR,\n"
    "else share/exactccd/data relative to the program (<prefix>/bin/../share/exactccd/data when\n"
    "installed; in a build tree a link to the checkout's data/). The shared benchmark sample (not\n"
    "installed): EXACTCCD_SAMPLE_QUERIES_DIR, else share/exactccd/sample-queries beside data/.\n"
    "\n"
    "Timing: each repetition times the whole dataset for each method in turn (methods interleaved\n"
    "within a repetition, so drift affects them alike); time per query = elapsed / queries.\n"
    "mean_ns and median_ns are the mean and median of that figure over the repetitions.\n"
    "\n"
    "Minimum separation: --min-distances D1,D2,... runs every method at each d (with --relative,\n"
    "d is that fraction of each query's bounding-box size: the largest extent of its points at\n"
    "t0 and t1); FP and FN at d > 0 or tmax < 1 are against Method::exact at the same question\n"
    "(the file's truth column is the contact question's). Only filtered and exact answer them.\n"
    "gmp_cgal: queries of the filtered method decided with GMP integers or CGAL (integer + exact).\n"
    "\n"
    "--motion rigid: the rigid filtered method on rigid query files (default: data/rigid) against the\n"
    "linear filtered method on the same bodies' linearised queries (every vertex's positions at t0\n"
    "and t1 as a linear query), per file and d: mean and median ns per query of each, the ratio of\n"
    "the means, FP/FN of the rigid method (against the truth column at d = 0 and tmax = 1, else\n"
    "against the rigid Method::exact; with --methods containing exact, always against it),\n"
    "gmp_cgal and the stages of the first repetition.\n";

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "bench";
    c.usage = "usage: exactccd bench [options] [FILE.csv...]";
    c.description = kDescription;
    c.options = {
        kind_option("query kind of the files (default: inferred from the path)"),
        motion_option("linear: benchmark CSV files, every method of --methods; rigid: rigid\n"
                      "query files, the rigid filtered method against the linear filtered\n"
                      "method on the linearised queries (see above)"),
        integer_option("--repetitions", "N", 1, kMaxRepetitions, "5", "repetitions per dataset and method"),
        choice_list_option("--methods", "LIST", all_method_names(), "naive,filtered,exact",
                           "the methods to run"),
        text_option("--min-distances", "LIST", "0", "comma-separated minimum separations d >= 0"),
        flag_option("--relative", "each d of --min-distances is a fraction of the query's box size"),
        real_option("--tmax", "T", std::numeric_limits<double>::denorm_min(), 1.0, "1",
                    "only times t in [0, T] count (the nearest double to T)"),
        text_option("--data-dir", "DIR", "",
                    "the bundled data folder, for a run without files (default: the environment\n"
                    "variable EXACTCCD_DATA_DIR, else found relative to the program)"),
        text_option("--json", "FILE", "",
                    "also write the results as a JSON array ('-' for stdout; the table then\n"
                    "goes to stderr): per (dataset, method) the table's figures,\n"
                    "\"fp_fn_against\": \"file truth column\" and \"truth_disagrees_with_exact\";\n"
                    "written to a temporary renamed when complete"),
    };
    c.epilogue = "exit codes: 0 ran, 2 bad usage or malformed input, 1 internal error.\n";
    return c;
  }();
  return spec;
}

/// The comma-separated list of --min-distances (each a finite number >= 0).
std::vector<double> parse_distances(const std::string& list) {
  std::vector<double> out;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t end = std::min(list.find(',', start), list.size());
    const std::string item = list.substr(start, end - start);
    char* stop = nullptr;
    const double d = std::strtod(item.c_str(), &stop);
    if (item.empty() || *stop != '\0' || !std::isfinite(d) || d < 0)
      throw UsageError("bench: --min-distances: '" + item + "' is not a finite number >= 0");
    out.push_back(d);
    start = end + 1;
  }
  return out;
}

BenchSettings bench_settings(const ParsedOptions& options) {
  BenchSettings s;
  s.kind = kind_of(options);
  s.repetitions = static_cast<int>(options.integer("--repetitions"));
  for (const std::string& m : options.list("--methods")) s.methods.push_back(parse_method(m));
  s.json = options.has("--json") ? options.text("--json") : "";
  s.distances = parse_distances(options.text("--min-distances"));
  s.relative = options.flag("--relative");
  s.tmax = options.real("--tmax");
  s.files = options.positionals();
  s.data_dir = options.has("--data-dir") ? options.text("--data-dir") : "";
  return s;
}

/// The files given, else the model's bundled ones, read (and every method's limits checked at
/// every d) before anything is printed.
template <class Motion>
std::vector<typename Motion::Dataset> load_files(const BenchSettings& s) {
  const std::string name = subcommand_name<Motion>("bench");
  const std::vector<std::string> files =
      s.files.empty() ? Motion::bundled_files(io::bundled_data_dir(s.data_dir, name)) : s.files;
  if (files.empty())
    throw UsageError(name + ": no dataset given and no bundled dataset found");
  std::vector<typename Motion::Dataset> datasets;
  for (const std::string& f : files) {
    datasets.push_back(Motion::load(f, s.kind, {}));
    for (const tools::Method m : s.methods)
      for (const double d : s.distances) Motion::require_answers(datasets.back(), m, CcdParams{d, s.tmax});
  }
  return datasets;
}

/// Times every arm on n queries, `repetitions` times, the arms interleaved within a repetition
/// (so that drift affects them alike); keeps each arm's first answers and stage counts.
std::vector<ArmRun> time_arms(const std::vector<BenchArm>& arms, std::size_t n, int repetitions) {
  std::vector<ArmRun> runs(arms.size());
  for (int rep = 0; rep < repetitions; ++rep)
    for (std::size_t a = 0; a < arms.size(); ++a) {
      std::vector<bool> answers(n);
      StageCounters counters;
      const double start = now_seconds();
      arms[a](answers, counters);
      runs[a].ns_per_query.push_back(1e9 * (now_seconds() - start) / static_cast<double>(n));
      if (rep == 0) {
        runs[a].answers = std::move(answers);
        runs[a].stages = counters;
      }
    }
  return runs;
}

/// bench for one motion model: per dataset and d, each query's question (d absolute, or relative
/// to its box), the reference answers, the arms timed, a report.
template <class Motion>
int bench(const BenchSettings& s) {
  typename Motion::BenchTable table(s);
  const std::vector<typename Motion::Dataset> datasets = load_files<Motion>(s);
  table.header();
  for (const auto& d : datasets) {
    const typename Motion::BenchCase c(d, s);
    const std::size_t n = d.queries.size();
    for (const double distance : s.distances) {
      std::vector<CcdParams> params(n);  // each query's question, set before timing
      for (std::size_t i = 0; i < n; ++i) params[i] = {s.relative ? distance * c.box_size(i) : distance, s.tmax};
      const std::vector<bool> reference = c.reference(params, CcdParams{distance, s.tmax}.contact_over_whole_step());
      table.add(c, distance, reference, time_arms(c.arms(params), n, s.repetitions));
    }
  }
  table.finish();
  return kExitOk;
}

}  // namespace

double mean(const std::vector<double>& v) {
  double s = 0;
  for (const double x : v) s += x;
  return s / static_cast<double>(v.size());
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

int run_bench(int argc, char** argv) {
  const ParsedOptions options = parse_options(command(), argc, argv);
  if (options.help()) {
    std::cout << help_text(command());
    return kExitOk;
  }
  const BenchSettings settings = bench_settings(options);
  return visit_motion(options, [&](auto motion) { return bench<decltype(motion)>(settings); });
}

}  // namespace exactccd::cli
