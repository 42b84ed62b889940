// Shared pieces of the exactccd subcommands: option parsing helpers, loading benchmark files,
// running one method over a dataset.
#pragma once

#include <chrono>
#include <functional>
#include <utility>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "exactccd/exactccd.hpp"
#include "io/benchmark_csv.hpp"

namespace exactccd::cli {

/// Exit codes of every subcommand.
enum ExitCode : int {
  kExitOk = 0,           ///< ran (whatever it found)
  kExitInternal = 1,     ///< unexpected internal error
  kExitUsage = 2,        ///< bad command line or malformed input file
};

/// A command-line or input error: printed as "exactccd: <message>", exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class QueryKind { vertex_face, edge_edge };

/// "vf" / "ee" (also "vertex-face" / "edge-edge").
QueryKind parse_kind(const std::string& s);
std::string kind_name(QueryKind k);  ///< "vf" or "ee"

/// The kind named by a path containing "vertex-face" or "edge-edge", if any; when both occur,
/// the one nearer the end of the path (the file name over its folders).
std::optional<QueryKind> kind_from_path(const std::string& path);

/// Every method, baselines first: naive, naive-tolerance, mpfr24, mpfr53, mpfr113, mpfr256,
/// filtered, exact (their names on the command line).
const std::vector<Method>& all_methods();
Method parse_method(const std::string& s);
std::string method_name(Method m);

/// A loaded benchmark file.
struct Dataset {
  std::string name;     ///< file name or bundled dataset name
  std::string path;
  QueryKind kind;
  io::BenchmarkQueries queries;
  /// Each query in doubles when all its coordinates are exact doubles.
  std::vector<std::optional<std::array<Vec3, 8>>> doubles;
};

/// Reads and parses a benchmark CSV (throws UsageError on a missing file, io::ParseError on a
/// malformed one). kind: explicit, or inferred from the path.
Dataset load_dataset(const std::string& path, std::optional<QueryKind> kind);

/// The answer of one method on query i: the TOI when it collides. Rational queries that are
/// not exact doubles run the exact path (the baselines round them to the nearest doubles).
std::optional<TimeInterval> run_query(const Dataset& d, std::size_t i, Method method,
                                      StageCounters* counters, bool want_toi);

/// Seconds since an arbitrary epoch (steady clock).
inline double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// s as a JSON string literal (quotes, backslashes and control characters escaped).
std::string json_string(const std::string& s);

/// Value of option `--name VALUE` at argv[i] (advances i), or UsageError when missing.
std::string option_value(int argc, char** argv, int& i);

/// Options shared by batch commands: `--threads N` and `--shard I/N`.
struct BatchOptions {
  unsigned threads = 1;
  std::size_t shard_index = 0, shard_count = 1;

  /// Consumes argv[i] (and its value) when it is a batch option; returns whether it was.
  bool parse(int argc, char** argv, int& i);

  /// The half-open range of the global query indices [0, total) this shard owns: contiguous
  /// blocks, so that concatenating the outputs of shards 0..N-1 gives the whole run's output.
  std::pair<std::size_t, std::size_t> shard_range(std::size_t total) const;
};

/// Help text of the batch options.
constexpr const char* kBatchOptionsHelp =
    "  --threads N         answer queries on N threads (results identical to one thread)\n"
    "  --shard I/N         only the I-th of N contiguous blocks of all queries (0 <= I < N), for\n"
    "                      splitting a run across cluster jobs; concatenating the outputs of\n"
    "                      shards 0..N-1 gives the output of the whole run\n";

/// Runs task(i) for i in [begin, end) on `threads` threads; shows a progress bar on stderr when
/// stderr is a terminal and the run takes more than two seconds. Exceptions are rethrown.
void parallel_for(std::size_t begin, std::size_t end, unsigned threads,
                  const std::function<void(std::size_t)>& task, const char* label);

}  // namespace exactccd::cli
