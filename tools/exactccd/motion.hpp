// The motion models of the command line (issue 28): `check`, `bench` and `generate` take
// `--motion linear|rigid` and run one code path each (check.cpp, bench.cpp, generate.cpp), a
// template over a motion traits type that holds what differs between the models. A third
// motion model is one more traits type, added to the list of motions.hpp.
//
// A motion traits type M (LinearMotion in linear_motion.hpp, RigidMotion in rigid_motion.hpp)
// provides:
//
//   static constexpr const char* name;  // its --motion value
//   using Dataset;  // a loaded query file: path, kind (QueryKind), queries (size(), truth)
//   static Dataset load(const std::string& path, const std::optional<QueryKind>& kind,
//                       const TruthSource& truth);  // the reader; errors name the file and line
//   static void check_method(tools::Method);  // UsageError for a method it has not (check)
//   static TruthSource truth_source(const ParsedOptions&, std::size_t files, bool answers);
//   static void require_answers(const Dataset&, tools::Method, const CcdParams&);  // the method
//                                            // answers the question on every query, else throws
//   static std::optional<TimeInterval> answer(const Dataset&, std::size_t i, tools::Method,
//                                             StageCounters*, bool want_toi, const CcdParams&);
//                                            // query i through the library's public entry point
//   static const char* const record_motion;  // check --json's "motion" value (nullptr: no key)
//   static StageCounts stage_counts(const StageCounters&);  // the stages a report prints
//   static std::vector<std::string> bundled_files(const std::filesystem::path& data);
//                                            // bench without files (data: data_dir.hpp)
//   class BenchCase;   // one dataset in bench: BenchCase(const Dataset&, const BenchSettings&),
//                      //   box_size(i), reference(params, contact_question), arms(params)
//   class BenchTable;  // bench's report: BenchTable(const BenchSettings&) (checks the options
//                      //   the model takes), header(), add(case, d, reference, runs), finish()
//   static const std::vector<GenerateSet>& generate_sets();  // what generate writes
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cli_common.hpp"

namespace exactccd::cli {

/// The options of `bench` every motion model reads.
struct BenchSettings {
  std::optional<QueryKind> kind;       ///< --kind
  int repetitions = 5;                 ///< --repetitions
  std::vector<tools::Method> methods;  ///< --methods
  std::string json;                    ///< --json FILE ("-": stdout; empty: none)
  std::vector<double> distances;       ///< --min-distances
  bool relative = false;               ///< --relative
  double tmax = 1;                     ///< --tmax
  std::vector<std::string> files;      ///< the files given (empty: the model's bundled files)
  std::string data_dir;                ///< --data-dir ("": the environment, else beside the program)
};

/// One timed arm of a benchmark: answers every query of a dataset into `answers` (sized to the
/// dataset), counting the deciding stages in `counters`. Timed as a whole, once per repetition.
using BenchArm = std::function<void(std::vector<bool>& answers, StageCounters& counters)>;

/// An arm's time per query at every repetition, and its first repetition's answers and stages.
struct ArmRun {
  std::vector<double> ns_per_query;
  std::vector<bool> answers;
  StageCounters stages;
};

/// A query set `generate` writes: its name on the command line and the function that writes it
/// (reading the options it takes; files under --out).
struct GenerateSet {
  const char* name;
  void (*write)(const ParsedOptions& options);
};

/// The mean of a non-empty list.
double mean(const std::vector<double>& v);
/// The median of a non-empty list (the mean of the middle two for an even count).
double median(std::vector<double> v);

}  // namespace exactccd::cli
