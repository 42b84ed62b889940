// Linear motion on the command line (motion.hpp's traits): every vertex on a straight line from
// t0 to t1, in the benchmark CSV files of io/benchmark_csv.hpp (every kind), answered by the
// library's methods and the tools' baselines.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "motion.hpp"
#include "io/output_file.hpp"

namespace exactccd::cli {

/// The linear motion model (motion.hpp).
struct LinearMotion {
  static constexpr const char* name = "linear";
  using Dataset = cli::Dataset;

  /// load_dataset (cli_common.hpp).
  static Dataset load(const std::string& path, const std::optional<QueryKind>& kind, const TruthSource& truth) {
    return load_dataset(path, kind, truth);
  }
  /// Every method answers linear queries: no-op.
  static void check_method(tools::Method) {}
  /// --truth FILE.json (one FILE.csv only); a truth file is required unless `answers`.
  static TruthSource truth_source(const ParsedOptions& options, std::size_t files, bool answers);
  /// A baseline answers only vf and ee at the contact question, and only coordinates in the
  /// double range (require_method_answers, require_double_range).
  static void require_answers(const Dataset& d, tools::Method method, const CcdParams& params);
  /// run_query (cli_common.hpp).
  static std::optional<TimeInterval> answer(const Dataset& d, std::size_t i, tools::Method method,
                                            StageCounters* counters, bool want_toi, const CcdParams& params) {
    return run_query(d, i, method, counters, want_toi, params);
  }
  /// run_query_range (cli_common.hpp): the filtered method through the batch entry point.
  static void answer_range(const Dataset& d, std::size_t begin, std::size_t end, tools::Method method,
                           StageCounters& counters, bool want_toi, const CcdParams& params,
                           std::optional<TimeInterval>* out) {
    run_query_range(d, begin, end, method, counters, want_toi, params, out);
  }
  /// No "motion" key in check --json (the records of linear files predate the key).
  static constexpr const char* record_motion = nullptr;
  /// Every stage of the linear filtered method.
  static StageCounts stage_counts(const StageCounters& s) { return linear_stage_counts(s); }

  /// The shared benchmark's unit-tests (when present: shared_sample_dir, data_dir.hpp), then
  /// the bundled data's sim/ (`data`: bundled_data_dir).
  static std::vector<std::string> bundled_files(const std::filesystem::path& data);
  class BenchCase;
  class BenchTable;

  /// catalogue, families, sim, scene.
  static const std::vector<GenerateSet>& generate_sets();
};

/// One linear dataset in bench: every method of --methods is an arm; FP and FN against the
/// file's truth column at the contact question, else against Method::exact.
class LinearMotion::BenchCase {
 public:
  /// Counts (and notes on stderr) the queries whose truth column disagrees with Method::exact.
  BenchCase(const Dataset& d, const BenchSettings& s);
  /// The dataset.
  const Dataset& dataset() const { return d_; }
  /// Its name in the table: "unit-tests/vertex-face/data_0_0", or the file's stem.
  const std::string& name() const { return name_; }
  /// The number of queries whose truth column disagrees with Method::exact.
  std::size_t truth_disagrees_with_exact() const { return truth_disagrees_; }
  /// The largest extent of query i's bounding box (its points at t0 and t1).
  double box_size(std::size_t i) const;
  /// The truth column at the contact question, else Method::exact at each query's params.
  std::vector<bool> reference(const std::vector<CcdParams>& params, bool contact_question) const;
  /// One arm per method, each query asked its params.
  std::vector<BenchArm> arms(const std::vector<CcdParams>& params) const;

 private:
  const Dataset& d_;
  const BenchSettings& s_;
  std::string name_;
  std::size_t truth_disagrees_ = 0;
};

/// bench's table of linear datasets: one row per (dataset, d, method); --json writes them too.
class LinearMotion::BenchTable {
 public:
  /// Opens the --json file now (an unwritable one fails before the run).
  explicit BenchTable(const BenchSettings& s);
  /// Prints the header.
  void header();
  /// Prints the rows of one (dataset, d): FP and FN of each arm against `reference`.
  void add(const BenchCase& c, double distance, const std::vector<bool>& reference, const std::vector<ArmRun>& runs);
  /// Writes --json.
  void finish();

  /// One row: a method on a dataset at one d.
  struct Row {
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

 private:
  const BenchSettings& s_;
  FILE* table_;  ///< stdout, or stderr when --json - takes stdout
  std::optional<io::AtomicOutputFile> json_file_;
  std::vector<Row> rows_;
};

}  // namespace exactccd::cli
