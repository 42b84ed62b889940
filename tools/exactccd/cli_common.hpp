// Shared pieces of the exactccd subcommands: option parsing helpers, loading benchmark files,
// running one method over a dataset.
#pragma once

#include <chrono>
#include <functional>
#include <utility>
#include <optional>
#include <stdexcept>
#include <cstdint>
#include <string>
#include <vector>

#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"
#include "io/benchmark_csv.hpp"
#include "io/input_file.hpp"
#include "kinds/primitive_kinds.hpp"
#include "options.hpp"
#include "scene/parallel.hpp"
#include "methods/methods.hpp"

namespace exactccd::cli {

/// Exit codes of every subcommand.
enum ExitCode : int {
  kExitOk = 0,           ///< ran (whatever it found)
  kExitInternal = 1,     ///< unexpected internal error
  kExitUsage = 2,        ///< bad command line or malformed input file
};

/// A command-line or input error: printed as "exactccd: <message>", exit code 2 (io::UsageError,
/// which the tools library's writers and readers throw too).
using UsageError = io::UsageError;

/// A primitive kind at run time: the position of its description in
/// kinds::for_each_kind (lib/kinds/primitive_kinds.hpp: vf, ee, pe, pp, ee2, pe2,
/// pp2), from which every name below is derived.
struct QueryKind {
  std::size_t index = 0;
  friend bool operator==(QueryKind a, QueryKind b) { return a.index == b.index; }
  friend bool operator!=(QueryKind a, QueryKind b) { return a.index != b.index; }
};

/// The run-time kind of a kind's description.
template <class Kind>
QueryKind query_kind() {
  std::size_t i = 0, found = 0;
  kinds::for_each_kind([&](auto k) {
    if (std::is_same_v<decltype(k), Kind>) found = i;
    ++i;
  });
  return QueryKind{found};
}

/// f(Kind{}) for the kind's description (every kind's call must return the same type).
template <class F>
auto visit_kind(QueryKind kind, F&& f) {
  using R = decltype(f(kinds::VertexFace{}));
  if constexpr (std::is_void_v<R>) {
    std::size_t i = 0;
    kinds::for_each_kind([&](auto k) {
      if (i++ == kind.index) f(k);
    });
  } else {
    std::optional<R> out;
    std::size_t i = 0;
    kinds::for_each_kind([&](auto k) {
      if (i++ == kind.index) out.emplace(f(k));
    });
    if (!out) throw std::logic_error("visit_kind: no kind at index " + std::to_string(kind.index));
    return std::move(*out);
  }
}

/// True for the kinds of the contact question of the benchmark (vertex-face, edge-edge): those
/// with a volume, the baselines, families and plug-ins.
template <class Kind>
constexpr bool is_contact_kind = std::is_same_v<Kind, kinds::VertexFace> || std::is_same_v<Kind, kinds::EdgeEdge>;
/// True when the run-time kind is vertex-face or edge-edge (is_contact_kind).
bool is_contact_kind_at(QueryKind k);

/// Every kind, in for_each_kind order.
std::vector<QueryKind> all_kinds();
/// A kind's --kind value ("vf", "ee", ...).
std::string kind_name(QueryKind k);
/// A kind's long name ("vertex-face", ...), as in file names.
std::string kind_long_name(QueryKind k);
/// A --kind value: a short or a long name of a kind.
QueryKind parse_kind(const std::string& s);
/// The `--kind` option (every kind's short and long names), with the given help.
OptionSpec kind_option(const std::string& help);
/// The kind given by `--kind`, if any.
std::optional<QueryKind> kind_of(const ParsedOptions& options);

/// The kind whose long name ("vertex-face", "edge-edge", ...) occurs in a path, if any; when
/// several occur, the one nearest the end of the path (the file name over its folders). The
/// Scalable CCD dataset's short names count too, as the end of the file name's stem not
/// preceded by a letter: "queries/227vf.csv" is vertex-face, "227ee.csv" edge-edge
/// ("coffee.csv" is neither).
std::optional<QueryKind> kind_from_path(const std::string& path);

/// Every method (tools::Method: the library's exact methods and the baselines), baselines
/// first: naive, naive-tolerance, mpfr24, mpfr53, mpfr113, mpfr256, filtered, exact (their
/// names on the command line).
const std::vector<tools::Method>& all_methods();
tools::Method parse_method(const std::string& s);
std::string method_name(tools::Method m);
/// The names of all_methods(), in that order.
std::vector<std::string> all_method_names();

/// A loaded benchmark file.
struct Dataset {
  std::string name;     ///< file name or bundled dataset name
  std::string path;
  QueryKind kind;
  io::BenchmarkQueries queries;
  /// Each query in doubles when all its coordinates are exact doubles.
  std::vector<std::optional<std::array<Vec3, 8>>> doubles;
  /// Where queries.truth comes from: empty for the CSV's truth column, else the JSON file.
  std::string truth_path;
  /// False when the file has no truth column and no truth file was required (queries.truth is
  /// then all false and must not be compared with).
  bool has_truth = true;
};

/// Where the truth of a CSV without a truth column (the Scalable CCD dataset's 6-column query
/// files) comes from.
struct TruthSource {
  /// A JSON array of booleans (--truth FILE.json); empty: the file found by name,
  /// DIR/queries/NAME.csv -> DIR/mma_bool/NAME_mma_bool.json, when it exists.
  std::string json;
  /// Whether a file without truth column needs a truth file (false for --answers and compare).
  bool required = true;
};

/// The truth file found by name for a query CSV: ../mma_bool/STEM_mma_bool.json beside the
/// file's folder ("queries/227vf.csv" -> "mma_bool/227vf_mma_bool.json").
std::string truth_path_by_name(const std::string& csv_path);

/// Reads and parses a benchmark CSV. Throws UsageError when the kind is neither given nor in
/// the path, io::InputError when the file is missing, a directory, unreadable or holds no
/// query (an empty file is an error, never an empty answer), io::ParseError ("file:line:
/// reason") when it is malformed. kind: explicit, or inferred from the path. A file whose
/// first row has no truth column (2 * dimension fields: the Scalable CCD dataset's query
/// files) takes its truth from `truth` (io::read_truth_json_file; its count must be the
/// file's query count); without a truth file it is a UsageError unless !truth.required.
/// truth.json given for a file with a truth column is a UsageError.
Dataset load_dataset(const std::string& path, std::optional<QueryKind> kind, const TruthSource& truth = {});

/// Throws io::ParseError naming the file and the row's line when `method` works in doubles (a
/// baseline) and a coordinate of d rounds beyond the largest double (the baseline cannot take
/// the query; the exact methods can). No-op for the exact methods.
void require_double_range(const Dataset& d, tools::Method method);

/// Prints `check --answers`' lines for `answers`: "0" for no collision, "1" with want_toi
/// "1 LO HI" (17 significant digits: read back as the same doubles).
void print_answers(const std::vector<std::optional<TimeInterval>>& answers, bool want_toi);

/// The stage counts of a check report, in report order: each counter's name and value.
using StageCounts = std::vector<std::pair<const char*, std::uint64_t>>;

/// The linear filtered method's stages as check reports them.
StageCounts linear_stage_counts(const StageCounters& s);

/// One file's result in a check report (check, check --motion rigid).
struct CheckRecord {
  std::string file;               ///< the file as printed
  std::string kind;               ///< its kind's short name
  const char* motion = nullptr;   ///< "rigid", or nullptr for linear motion (no "motion" key)
  std::string method;             ///< the method's name
  std::size_t queries = 0, positives = 0, fp = 0, fn = 0;
  double us_per_query = 0;
  StageCounts stages;             ///< the method's stages, in report order
};

/// Appends rec to the items of a --json report ("  {...}", after ",\n" unless the first).
void append_json_record(std::string& items, const CheckRecord& rec);

/// Prints the header of the text report. For the default question (d = 0, tmax = 1) the counts
/// against the truth column are "positives", "FP" and "FN"; for another one they are named for
/// what they count, "truth_1", "yes_truth_0" and "no_truth_1": the bundled files' truth column is
/// contact over [0, 1], so a query that comes within d without touching is a right answer
/// counted in yes_truth_0, not a false positive.
void print_check_header(const CcdParams& params);

/// Prints rec's row of the text report (the columns of print_check_header(params)) and, with
/// `stages_line`, its stage counts below it.
void print_check_row(const CheckRecord& rec, bool stages_line, const CcdParams& params = {});

/// The answer of one method on query i: the TOI when it collides. Rational queries that are
/// not exact doubles run the exact path (the baselines round them to the nearest doubles).
/// `params`: the minimum separation and time limit (only the exact methods answer other
/// questions than the default one, and the only ones for kinds other than vf and ee: see
/// require_method_answers).
std::optional<TimeInterval> run_query(const Dataset& d, std::size_t i, tools::Method method,
                                      StageCounters* counters, bool want_toi, const CcdParams& params = {});

/// run_query for queries [begin, end) of d into out[0, end - begin), counted in `counters`: by
/// the library's batch entry point (answer_batch: the stage lists on blocks of queries) for the
/// filtered method's queries in doubles, query by query for the others.
void run_query_range(const Dataset& d, std::size_t begin, std::size_t end, tools::Method method,
                     StageCounters& counters, bool want_toi, const CcdParams& params, std::optional<TimeInterval>* out);

/// Throws UsageError when `method` (a baseline) cannot answer the kind or the question: the
/// baselines answer only vertex-face and edge-edge with the default CcdParams.
void require_method_answers(tools::Method method, QueryKind kind, const CcdParams& params);

/// The `--min-distance D` and `--tmax T` options (D >= 0 and T in (0, 1], nearest doubles).
std::vector<OptionSpec> separation_option_specs();
/// The CcdParams given by --min-distance and --tmax.
CcdParams separation_params(const ParsedOptions& options);

/// Seconds since an arbitrary epoch (steady clock).
inline double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// s as a JSON string literal (quotes, backslashes and control characters escaped).
std::string json_string(const std::string& s);

/// The largest --threads of any subcommand: a documented range (1..kMaxThreads), not a
/// resource the run may fail to get (fewer threads are used when the system gives fewer).
constexpr long long kMaxThreads = scene::kMaxThreads;  // the library's pool's limit
/// The largest N of --shard I/N.
constexpr long long kMaxShards = 1000000;

/// The `--threads N` option: 1..kMaxThreads, the given default ("" for none) and help.
OptionSpec threads_option(const std::string& default_value, const std::string& help);

/// Options shared by batch commands: `--threads N` and `--shard I/N`.
struct BatchOptions {
  unsigned threads = 1;
  std::size_t shard_index = 0, shard_count = 1;

  /// The half-open range of the global query indices [0, total) this shard owns: contiguous
  /// blocks, so that concatenating the outputs of shards 0..N-1 gives the whole run's output.
  std::pair<std::size_t, std::size_t> shard_range(std::size_t total) const;
};

/// `threads`, or fewer when the system refuses to start that many threads now (a limit on the
/// user's processes, RLIMIT_NPROC, counts threads): at most `threads`, at least 1. oneTBB cannot
/// recover from a worker thread it fails to start (its private_server.cpp: it throws from the
/// thread that asked for workers, or terminates from a worker that was waking others), so the
/// command line first starts, holds and joins as many threads as oneTBB would (its default
/// concurrency, at most `threads`), and asks for no more threads than it could start. The
/// answers are the same on any number of threads.
unsigned startable_threads(unsigned threads);

/// The option specs of the batch options (--threads, default 1, and --shard).
std::vector<OptionSpec> batch_option_specs();

/// The batch options given (defaults when absent).
BatchOptions batch_options(const ParsedOptions& options);

/// Runs task(i) for i in [begin, end) on up to `threads` threads (oneTBB: never more than there
/// are indices, fewer when the machine has fewer; same results); shows a progress bar on stderr
/// when stderr is a terminal and the run takes more than two seconds. Exceptions are rethrown.
void parallel_for(std::size_t begin, std::size_t end, unsigned threads, const std::function<void(std::size_t)>& task,
                  const char* label);

}  // namespace exactccd::cli
