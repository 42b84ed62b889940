// exactccd bench: every method on the same loaded queries, several repetitions.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <filesystem>
#include <optional>
#include <iostream>
#include <vector>

#include "cli_common.hpp"
#include "output_file.hpp"
#include "rigid_cli.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

namespace fs = std::filesystem;

/// The most repetitions: a bound on the run time, not on anything's size.
constexpr long long kMaxRepetitions = 100000;

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "bench";
    c.usage = "usage: exactccd bench [options] [FILE.csv...]";
    c.description =
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
    c.options = {
        kind_option("query kind of the files (default: inferred from the path)"),
        motion_option(),
        integer_option("--repetitions", "N", 1, kMaxRepetitions, "5", "repetitions per dataset and method"),
        choice_list_option("--methods", "LIST", all_method_names(), "naive,filtered,exact",
                           "the methods to run"),
        text_option("--min-distances", "LIST", "0", "comma-separated minimum separations d >= 0"),
        flag_option("--relative", "each d of --min-distances is a fraction of the query's box size"),
        real_option("--tmax", "T", std::numeric_limits<double>::denorm_min(), 1.0, "1",
                    "only times t in [0, T] count (the nearest double to T)"),
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

struct Result {
  std::string dataset, kind, method;
  double min_distance = 0;  ///< d, or the fraction of the box size when relative
  bool relative = false;
  double tmax = 1;
  std::size_t queries = 0, fp = 0, fn = 0;
  std::size_t truth_disagrees_with_exact = 0;  ///< the dataset's truth column vs Method::exact
  double mean_ns = 0, median_ns = 0;
  StageCounters stages;
  std::uint64_t exact_fallbacks = 0;
};

/// The largest extent of a query's bounding box over all its points at t0 and t1.
double box_size(const std::array<Vec3, 8>& rows, int count) {
  double size = 0;
  for (int axis = 0; axis < 3; ++axis) {
    double lo = 0, hi = 0;
    for (int k = 0; k < count; ++k) {
      const double c = axis == 0 ? rows[k].x : axis == 1 ? rows[k].y : rows[k].z;
      lo = k == 0 ? c : std::min(lo, c);
      hi = k == 0 ? c : std::max(hi, c);
    }
    size = std::max(size, hi - lo);
  }
  return size;
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

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

std::vector<std::string> bundled_files() {
  std::vector<std::string> files;
  const fs::path sample = fs::path(EXACTCCD_SAMPLE_QUERIES_DIR) / "unit-tests";
  for (const char* f : {"vertex-face/data_0_0.csv", "vertex-face/data_0_1.csv",
                        "edge-edge/data_0_0.csv", "edge-edge/data_0_1.csv"})
    if (fs::exists(sample / f)) files.push_back((sample / f).string());
  const fs::path sim = fs::path(EXACTCCD_DATA_DIR) / "sim";
  if (fs::is_directory(sim)) {
    std::vector<std::string> sims;
    for (const auto& e : fs::directory_iterator(sim))
      if (e.path().extension() == ".csv") sims.push_back(e.path().string());
    std::sort(sims.begin(), sims.end());
    files.insert(files.end(), sims.begin(), sims.end());
  }
  return files;
}

/// A short dataset name: "unit-tests/vertex-face/data_0_0" or the file's stem for others.
std::string dataset_name(const std::string& path) {
  const fs::path p(path);
  const std::string parent = p.parent_path().filename().string();
  if (parent == "vertex-face" || parent == "edge-edge")
    return p.parent_path().parent_path().filename().string() + "/" + parent + "/" + p.stem().string();
  return p.stem().string();
}

void write_json(std::ostream& out, const std::vector<Result>& results) {
  out << "[\n";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const Result& r = results[i];
    out << "  {\"dataset\": " << json_string(r.dataset) << ", \"kind\": \"" << r.kind << "\", \"method\": \""
        << r.method << "\", \"min_distance\": " << r.min_distance << ", \"relative\": "
        << (r.relative ? "true" : "false") << ", \"tmax\": " << r.tmax << ", \"queries\": " << r.queries << ", \"mean_ns\": " << r.mean_ns
        << ", \"median_ns\": " << r.median_ns << ", \"fp\": " << r.fp << ", \"fn\": " << r.fn
        << ", \"fp_fn_against\": \""
        << (r.min_distance == 0 && r.tmax == 1 ? "file truth column" : "Method::exact at the same d and tmax")
        << "\", \"truth_disagrees_with_exact\": "
        << r.truth_disagrees_with_exact
        << ", \"exact_fallbacks\": " << r.exact_fallbacks << ", \"stages\": {\"volume_exclusion\": "
        << r.stages.volume_exclusion << ", \"static_predicates\": " << r.stages.static_predicates
        << ", \"separating_direction\": " << r.stages.separating_direction << ", \"interval\": " << r.stages.interval
        << ", \"fixed_integer\": " << r.stages.fixed_integer << ", \"integer\": " << r.stages.integer << ", \"exact\": " << r.stages.exact << "}}"
        << (i + 1 < results.size() ? "," : "") << "\n";
  }
  out << "]\n";
}

}  // namespace

int run_bench(int argc, char** argv) {
  const ParsedOptions options = parse_options(command(), argc, argv);
  if (options.help()) {
    std::cout << help_text(command());
    return kExitOk;
  }
  const std::optional<QueryKind> kind = kind_of(options);
  const int repetitions = static_cast<int>(options.integer("--repetitions"));
  std::vector<tools::Method> methods;
  for (const std::string& m : options.list("--methods")) methods.push_back(parse_method(m));
  const std::string json = options.has("--json") ? options.text("--json") : "";
  const std::vector<double> distances = parse_distances(options.text("--min-distances"));
  const bool relative = options.flag("--relative");
  const double tmax = options.real("--tmax");
  if (rigid_motion(options)) return run_rigid_bench(options, distances, relative, tmax);
  std::vector<std::string> files = options.positionals();
  // An unwritable --json FILE fails now, not after the whole run.
  std::optional<AtomicOutputFile> json_file;
  if (!json.empty() && json != "-") json_file.emplace(json);
  if (files.empty()) files = bundled_files();
  if (files.empty()) throw UsageError("bench: no dataset given and no bundled dataset found");

  std::vector<Dataset> datasets;
  for (const std::string& f : files) {
    datasets.push_back(load_dataset(f, kind));
    datasets.back().name = dataset_name(f);
    for (tools::Method m : methods) {
      require_double_range(datasets.back(), m);
      for (double d : distances) require_method_answers(m, datasets.back().kind, CcdParams{d, tmax});
    }
  }

  FILE* table = json == "-" ? stderr : stdout;
  std::fprintf(table, "FP and FN: against each file's truth column; truth!=exact: queries whose truth column "
                      "disagrees with Method::exact\n");
  std::fprintf(table, "%-34s %4s %-9s %9s %8s %10s %10s %6s %6s %12s %9s %8s  %s\n", "dataset", "kind", "method",
               relative ? "d/box" : "d", "queries", "mean_ns", "median_ns", "FP", "FN", "truth!=exact", "exact_fb",
               "gmp_cgal", "stages (vol/static/sep/int/fixed/gmp/exact)");
  std::vector<Result> results;
  for (const Dataset& d : datasets) {
    const std::size_t n = d.queries.size();
    // FP and FN are counted against the file's published truth column; the exact reference
    // (Method::exact) says how far that column can be trusted.
    std::size_t truth_disagrees_with_exact = 0;
    for (std::size_t i = 0; i < n; ++i)
      truth_disagrees_with_exact +=
          run_query(d, i, tools::Method::exact, nullptr, false).has_value() != d.queries.truth[i];
    if (truth_disagrees_with_exact > 0)
      std::fprintf(stderr, "exactccd bench: %s: the truth column disagrees with Method::exact on %zu of %zu "
                           "queries: its FP and FN are against that column\n",
                   d.path.c_str(), truth_disagrees_with_exact, n);
    const int points = d.queries.layout.rows;
    for (const double distance : distances) {
      // Each query's question, set before timing.
      std::vector<CcdParams> params(n);
      for (std::size_t i = 0; i < n; ++i) {
        const double size = relative ? box_size(d.doubles[i] ? *d.doubles[i] : io::nearest_double_rows(d.queries.rows[i]), points) : 1.0;
        params[i] = CcdParams{relative ? distance * size : distance, tmax};
      }
      const bool contact_question = distance == 0 && tmax == 1;
      std::vector<bool> reference = d.queries.truth;
      if (!contact_question)
        for (std::size_t i = 0; i < n; ++i)
          reference[i] = run_query(d, i, tools::Method::exact, nullptr, false, params[i]).has_value();
      std::vector<std::vector<double>> per_query_ns(methods.size());
      std::vector<Result> rows(methods.size());
      for (int rep = 0; rep < repetitions; ++rep) {
        for (std::size_t m = 0; m < methods.size(); ++m) {
          StageCounters counters;
          std::vector<bool> answer(n);
          const double start = now_seconds();
          for (std::size_t i = 0; i < n; ++i)
            answer[i] = run_query(d, i, methods[m], &counters, false, params[i]).has_value();
          const double elapsed = now_seconds() - start;
          per_query_ns[m].push_back(n ? 1e9 * elapsed / n : 0);
          if (rep == 0) {
            Result& r = rows[m];
            r.dataset = d.name;
            r.kind = kind_name(d.kind);
            r.method = method_name(methods[m]);
            r.min_distance = distance;
            r.relative = relative;
            r.tmax = tmax;
            r.queries = n;
            r.truth_disagrees_with_exact = truth_disagrees_with_exact;
            for (std::size_t i = 0; i < n; ++i) {
              r.fp += answer[i] && !reference[i];
              r.fn += !answer[i] && reference[i];
            }
            r.stages = counters;
            r.exact_fallbacks = methods[m] == tools::Method::exact ? n : methods[m] == tools::Method::filtered ? counters.exact : 0;
          }
        }
      }
      for (std::size_t m = 0; m < methods.size(); ++m) {
        Result& r = rows[m];
        double sum = 0;
        for (double x : per_query_ns[m]) sum += x;
        r.mean_ns = sum / per_query_ns[m].size();
        r.median_ns = median(per_query_ns[m]);
        std::string stages = "-";
        std::string gmp_cgal = "-";
        if (methods[m] == tools::Method::filtered && n) {
          char buf[160];
          std::snprintf(buf, sizeof buf, "%.1f%% / %.1f%% / %.1f%% / %.1f%% / %.2f%% / %.2f%% / %.3f%%",
                        100.0 * r.stages.volume_exclusion / n, 100.0 * r.stages.static_predicates / n,
                        100.0 * r.stages.separating_direction / n, 100.0 * r.stages.interval / n,
                        100.0 * r.stages.fixed_integer / n, 100.0 * r.stages.integer / n,
                        100.0 * r.stages.exact / n);
          stages = buf;
          gmp_cgal = std::to_string(r.stages.integer + r.stages.exact);
        }
        std::fprintf(table, "%-34s %4s %-9s %9.3g %8zu %10.1f %10.1f %6zu %6zu %12zu %9llu %8s  %s\n",
                     r.dataset.c_str(), r.kind.c_str(), r.method.c_str(), r.min_distance, r.queries, r.mean_ns,
                     r.median_ns, r.fp, r.fn, r.truth_disagrees_with_exact,
                     static_cast<unsigned long long>(r.exact_fallbacks), gmp_cgal.c_str(), stages.c_str());
        results.push_back(r);
      }
    }
  }
  if (!json.empty()) {
    if (json == "-") {
      write_json(std::cout, results);
    } else {
      write_json(json_file->stream(), results);
      json_file->commit();
    }
  }
  return kExitOk;
}

}  // namespace exactccd::cli
