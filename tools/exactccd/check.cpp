// exactccd check: the oracle on benchmark CSV files.
#include <cstdio>
#include <iostream>
#include <vector>

#include "cli_common.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

constexpr const char* kHelp = R"(usage: exactccd check [options] FILE.csv...

Answers every query of benchmark CSV files (Wang et al. 2021 format: 8 rows per query,
x_num,x_den,y_num,y_den,z_num,z_den,truth) and compares with the truth column.

options:
  --kind vf|ee        query kind (default: inferred from 'vertex-face' / 'edge-edge' in the path)
  --method NAME       filtered (default; exact), exact (CGAL reference; slow), naive (textbook
                      doubles; NOT robust)
  --answers           print only one line per query, 0 or 1, in file order
  --stats             also print how many queries each stage of the filtered method decided
  -h, --help          this help

output: per file, queries, truth positives, false positives, false negatives and the mean time
per query; then the totals.
exit codes: 0 ran (whatever it found), 2 bad usage or malformed input (file:line on stderr),
1 internal error.
)";

struct Totals {
  std::size_t queries = 0, positives = 0, fp = 0, fn = 0;
  double seconds = 0;
};

}  // namespace

int run_check(int argc, char** argv) {
  std::optional<QueryKind> kind;
  Method method = Method::filtered;
  bool answers = false, stats = false;
  std::vector<std::string> files;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      std::cout << kHelp;
      return kExitOk;
    } else if (a == "--kind") {
      kind = parse_kind(option_value(argc, argv, i));
    } else if (a == "--method") {
      method = parse_method(option_value(argc, argv, i));
    } else if (a == "--answers") {
      answers = true;
    } else if (a == "--stats") {
      stats = true;
    } else if (!a.empty() && a[0] == '-') {
      throw UsageError("check: unknown option '" + a + "' (see exactccd check --help)");
    } else {
      files.push_back(a);
    }
  }
  if (files.empty()) throw UsageError("check: no input file (see exactccd check --help)");

  // Parse everything first: a malformed file fails before anything is printed.
  std::vector<Dataset> datasets;
  for (const std::string& f : files) datasets.push_back(load_dataset(f, kind));

  Totals total;
  if (!answers)
    std::printf("%-60s %4s %8s %9s %6s %6s %12s\n", "file", "kind", "queries", "positives", "FP",
                "FN", "us/query");
  for (const Dataset& d : datasets) {
    StageCounters counters;
    std::vector<bool> result(d.queries.size());
    const double start = now_seconds();
    for (std::size_t i = 0; i < d.queries.size(); ++i)
      result[i] = run_query(d, i, method, &counters, false).has_value();
    const double seconds = now_seconds() - start;
    Totals t;
    t.queries = d.queries.size();
    t.seconds = seconds;
    for (std::size_t i = 0; i < t.queries; ++i) {
      t.positives += d.queries.truth[i];
      t.fp += result[i] && !d.queries.truth[i];
      t.fn += !result[i] && d.queries.truth[i];
    }
    if (answers) {
      for (bool r : result) std::fputs(r ? "1\n" : "0\n", stdout);
    } else {
      std::printf("%-60s %4s %8zu %9zu %6zu %6zu %12.3f\n", d.name.c_str(), kind_name(d.kind).c_str(),
                  t.queries, t.positives, t.fp, t.fn, t.queries ? 1e6 * seconds / t.queries : 0.0);
      if (stats && method == Method::filtered)
        std::printf("  stages: volume_exclusion %llu, interval %llu, integer %llu, exact %llu\n",
                    static_cast<unsigned long long>(counters.volume_exclusion),
                    static_cast<unsigned long long>(counters.interval),
                    static_cast<unsigned long long>(counters.integer),
                    static_cast<unsigned long long>(counters.exact));
    }
    total.queries += t.queries;
    total.positives += t.positives;
    total.fp += t.fp;
    total.fn += t.fn;
    total.seconds += t.seconds;
  }
  if (!answers)
    std::printf("%-60s %4s %8zu %9zu %6zu %6zu %12.3f\n", "total", "", total.queries, total.positives,
                total.fp, total.fn, total.queries ? 1e6 * total.seconds / total.queries : 0.0);
  return kExitOk;
}

}  // namespace exactccd::cli
