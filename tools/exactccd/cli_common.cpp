#include "cli_common.hpp"

#include <cctype>
#include <filesystem>

#include "io/truth_json.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <exception>
#include <future>
#include <mutex>
#include <system_error>
#include <thread>
#include <tuple>

#include <tbb/info.h>

#include "io/input_file.hpp"
#include "scene/parallel.hpp"

namespace exactccd::cli {

std::vector<QueryKind> all_kinds() {
  std::vector<QueryKind> out;
  std::size_t i = 0;
  kinds::for_each_kind([&](auto) { out.push_back(QueryKind{i++}); });
  return out;
}

bool is_contact_kind_at(QueryKind k) {
  return visit_kind(k, [](auto kind) { return is_contact_kind<decltype(kind)>; });
}

std::string kind_name(QueryKind k) {
  return visit_kind(k, [](auto kind) { return std::string(decltype(kind)::short_name); });
}

std::string kind_long_name(QueryKind k) {
  return visit_kind(k, [](auto kind) { return std::string(decltype(kind)::name); });
}

namespace {

/// "vf|ee" from the kinds' short names.
std::string short_names(const char* separator) {
  std::string out;
  for (QueryKind k : all_kinds()) out += (out.empty() ? "" : separator) + kind_name(k);
  return out;
}

}  // namespace

QueryKind parse_kind(const std::string& s) {
  for (QueryKind k : all_kinds())
    if (s == kind_name(k) || s == kind_long_name(k)) return k;
  throw UsageError("unknown kind '" + s + "' (expected " + short_names(" or ") + ")");
}

OptionSpec kind_option(const std::string& help) {
  std::vector<std::string> choices;
  for (QueryKind k : all_kinds()) choices.push_back(kind_name(k));
  for (QueryKind k : all_kinds()) choices.push_back(kind_long_name(k));
  return choice_option("--kind", short_names("|"), choices, "", help);
}

std::optional<QueryKind> kind_of(const ParsedOptions& options) {
  if (!options.has("--kind")) return std::nullopt;
  return parse_kind(options.text("--kind"));
}

std::optional<QueryKind> kind_from_path(const std::string& path) {
  // The occurrence nearest the file name wins: "edge-edge/run-vertex-face.csv" is vertex-face.
  std::optional<QueryKind> best;
  std::size_t best_at = 0;
  for (QueryKind k : all_kinds()) {
    // The same start: the longer name ("edge-edge-2d" over "edge-edge").
    const std::size_t at = path.rfind(kind_long_name(k));
    if (at != std::string::npos &&
        (!best || at > best_at || (at == best_at && kind_long_name(k).size() > kind_long_name(*best).size()))) {
      best = k;
      best_at = at;
    }
  }
  // The dataset's short names: the file name's stem ends in vf or ee, not after a letter.
  const std::string stem = std::filesystem::path(path).stem().string();
  if (stem.size() >= 2 && (stem.size() == 2 || !std::isalpha(static_cast<unsigned char>(stem[stem.size() - 3])))) {
    const std::string suffix = stem.substr(stem.size() - 2);
    const std::optional<QueryKind> k = suffix == "vf"   ? std::optional<QueryKind>(query_kind<kinds::VertexFace>())
                                       : suffix == "ee" ? std::optional<QueryKind>(query_kind<kinds::EdgeEdge>())
                                                        : std::nullopt;
    const std::size_t at = path.size() - std::filesystem::path(path).filename().string().size() + stem.size() - 2;
    if (k && (!best || at > best_at)) best = k;
  }
  return best;
}

std::string truth_path_by_name(const std::string& csv_path) {
  const std::filesystem::path p(csv_path);
  return (p.parent_path().parent_path() / "mma_bool" / (p.stem().string() + "_mma_bool.json")).string();
}

const std::vector<tools::Method>& all_methods() {
  using tools::Method;
  static const std::vector<Method> methods = {
      Method::naive,        Method::naive_tolerance, Method::naive_mpfr24,  Method::naive_mpfr53,
      Method::naive_mpfr113, Method::naive_mpfr256,  Method::filtered,      Method::exact};
  return methods;
}

std::string method_name(tools::Method m) {
  using tools::Method;
  switch (m) {
    case Method::filtered: return "filtered";
    case Method::exact: return "exact";
    case Method::naive: return "naive";
    case Method::naive_tolerance: return "naive-tolerance";
    case Method::naive_mpfr24: return "mpfr24";
    case Method::naive_mpfr53: return "mpfr53";
    case Method::naive_mpfr113: return "mpfr113";
    case Method::naive_mpfr256: return "mpfr256";
  }
  return "?";
}

std::vector<std::string> all_method_names() {
  std::vector<std::string> names;
  for (tools::Method m : all_methods()) names.push_back(method_name(m));
  return names;
}

tools::Method parse_method(const std::string& s) {
  for (tools::Method m : all_methods())
    if (method_name(m) == s) return m;
  throw UsageError("unknown method '" + s +
                   "' (expected filtered, exact, naive, naive-tolerance, mpfr24, mpfr53, mpfr113 or mpfr256)");
}

Dataset load_dataset(const std::string& path, std::optional<QueryKind> kind, const TruthSource& truth) {
  if (!kind) kind = kind_from_path(path);
  if (!kind) {
    std::string names;
    for (QueryKind k : all_kinds()) names += (names.empty() ? "'" : " or '") + kind_long_name(k) + "'";
    throw UsageError("cannot infer the query kind of '" + path + "' (no " + names +
                     " in the path): pass --kind " + short_names("|"));
  }
  io::QueryLayout layout = visit_kind(*kind, [](auto k) { return io::layout_of<decltype(k)>(); });
  {
    io::InputFile peek(path);
    layout.truth_column = io::first_row_columns(peek.stream()) != 2 * layout.dimension;
    peek.check_read();
  }
  io::InputFile file(path);
  Dataset d;
  d.path = path;
  d.name = path;
  d.kind = *kind;
  d.queries = io::read_benchmark_csv(file.stream(), path, layout);
  file.check_read();
  if (d.queries.size() == 0) throw io::InputError(path, "no queries (an empty benchmark file)");
  if (layout.truth_column && !truth.json.empty())
    throw UsageError("--truth " + truth.json + ": " + path + " has its own truth column");
  if (!layout.truth_column) {
    const std::string by_name = truth_path_by_name(path);
    std::error_code ec;
    d.truth_path = !truth.json.empty() ? truth.json : std::filesystem::is_regular_file(by_name, ec) ? by_name : "";
    if (d.truth_path.empty()) {
      if (truth.required)
        throw UsageError(path + " has no truth column (" + std::to_string(layout.columns()) +
                         " columns) and no truth file (looked for " + by_name +
                         "): pass --truth FILE.json, or --answers to print the answers only");
      d.has_truth = false;
    } else {
      const std::vector<bool> t = io::read_truth_json_file(d.truth_path);
      if (t.size() != d.queries.size())
        throw io::InputError(d.truth_path, std::to_string(t.size()) + " truth values but " + path + " has " +
                                               std::to_string(d.queries.size()) + " queries");
      d.queries.truth = t;
    }
  }
  d.doubles.reserve(d.queries.size());
  for (const auto& rows : d.queries.rows) d.doubles.push_back(io::exact_double_rows(rows));
  return d;
}

void require_double_range(const Dataset& d, tools::Method method) {
  if (tools::is_exact_method(method)) return;
  for (std::size_t i = 0; i < d.queries.size(); ++i) {
    if (d.doubles[i]) continue;  // exact doubles: finite
    for (std::size_t row = 0; row < 8; ++row) {
      const RationalVec3& p = d.queries.rows[i][row];
      for (const mpq_class* c : {&p.x, &p.y, &p.z}) {
        if (std::isfinite(io::nearest_double(*c))) continue;
        const std::size_t line = d.queries.lines.empty() ? 0 : d.queries.lines[i][row];
        throw io::ParseError(d.path, line,
                             "a coordinate rounds beyond the largest double (DBL_MAX); the baseline method " +
                                 method_name(method) +
                                 " works in doubles and cannot take it (the filtered and exact methods can)");
      }
    }
  }
}

namespace {

std::optional<TimeInterval> collides_placeholder(bool collides) {
  return collides ? std::optional<TimeInterval>(TimeInterval{}) : std::nullopt;
}

}  // namespace

void print_answers(const std::vector<std::optional<TimeInterval>>& answers, bool want_toi) {
  for (const auto& r : answers) {
    if (!r)
      std::fputs("0\n", stdout);
    else if (want_toi)
      std::printf("1 %.17g %.17g\n", r->lo, r->hi);
    else
      std::fputs("1\n", stdout);
  }
}

std::optional<TimeInterval> run_query(const Dataset& d, std::size_t i, tools::Method method,
                                      StageCounters* counters, bool want_toi, const CcdParams& params) {
  return visit_kind(d.kind, [&](auto kind) -> std::optional<TimeInterval> {
    using Kind = decltype(kind);
    using RationalQuery = typename Kind::template Query<mpq_class>;
    using DoubleQuery = typename Kind::template Query<double>;
    const bool contact_question = params.contact_over_whole_step();
    const auto& exact_rows = d.doubles[i];
    if (!exact_rows && tools::is_exact_method(method)) {  // not doubles: the rational exact path
      if (counters) ++counters->exact;
      const auto q = io::query_at<RationalQuery>(d.queries, i);
      if constexpr (is_contact_kind<Kind>)
        if (contact_question) return want_toi ? toi(q) : collides_placeholder(ccd(q));
      return toi(q, RationalCcdParams{mpq_class(params.min_distance), mpq_class(params.tmax)});
    }
    const std::array<Vec3, 8> rows = exact_rows ? *exact_rows : io::nearest_double_rows(d.queries.rows[i]);
    StageCounters unused;
    StageCounters& c = counters ? *counters : unused;
    if constexpr (is_contact_kind<Kind>) {
      if (contact_question) {
        const auto q = io::query_from_rows<DoubleQuery>(rows);
        return want_toi ? tools::toi(q, method, c) : collides_placeholder(tools::ccd(q, method, c));
      }
    }
    if (!tools::is_exact_method(method)) throw std::logic_error("run_query: a baseline for " + kind_name(d.kind));
    const auto q = io::query_from_rows<DoubleQuery>(rows);
    const Method m = method == tools::Method::exact ? Method::exact : Method::filtered;
    return want_toi ? toi(q, params, m, c) : collides_placeholder(ccd(q, params, m, c));
  });
}

void run_query_range(const Dataset& d, std::size_t begin, std::size_t end, tools::Method method,
                     StageCounters& counters, bool want_toi, const CcdParams& params, std::optional<TimeInterval>* out) {
  if (method != tools::Method::filtered) {
    for (std::size_t i = begin; i < end; ++i) out[i - begin] = run_query(d, i, method, &counters, want_toi, params);
    return;
  }
  visit_kind(d.kind, [&](auto kind) {
    using DoubleQuery = typename decltype(kind)::template Query<double>;
    std::vector<DoubleQuery> queries;  // the queries in doubles, to the batch entry point
    std::vector<std::size_t> at;       // where each one's answer goes
    for (std::size_t i = begin; i < end; ++i) {
      if (!d.doubles[i]) {  // not doubles: run_query's rational path
        out[i - begin] = run_query(d, i, method, &counters, want_toi, params);
        continue;
      }
      queries.push_back(io::query_from_rows<DoubleQuery>(*d.doubles[i]));
      at.push_back(i - begin);
    }
    std::vector<std::optional<TimeInterval>> answers(queries.size());
    answer_batch(queries.data(), queries.size(), params, Method::filtered, want_toi, answers.data(), &counters);
    for (std::size_t k = 0; k < at.size(); ++k) out[at[k]] = answers[k];
  });
}

void require_method_answers(tools::Method method, QueryKind kind, const CcdParams& params) {
  if (tools::is_exact_method(method)) return;
  if (!is_contact_kind_at(kind))
    throw UsageError("the baseline method " + method_name(method) + " answers only vf and ee queries, not " +
                     kind_name(kind) + " (use filtered or exact)");
  if (!params.contact_over_whole_step())
    throw UsageError("the baseline method " + method_name(method) +
                     " answers only the contact question (no --min-distance, --tmax 1)");
}

std::vector<OptionSpec> separation_option_specs() {
  constexpr double kSmallest = std::numeric_limits<double>::denorm_min();
  return {real_option("--min-distance", "D", 0.0, std::numeric_limits<double>::max(), "0",
                      "a collision is a distance <= D between the primitives (the nearest double to D)"),
          real_option("--tmax", "T", kSmallest, 1.0, "1", "only times t in [0, T] count (the nearest double to T)")};
}

CcdParams separation_params(const ParsedOptions& options) {
  return CcdParams{options.real("--min-distance"), options.real("--tmax")};
}

OptionSpec threads_option(const std::string& default_value, const std::string& help) {
  // The library's range (SceneOptions::threads, the C API, the Python module): 0 is every
  // hardware thread.
  return integer_option("--threads", "N", 0, kMaxThreads, default_value, help + " (0: every hardware thread)");
}

std::vector<OptionSpec> batch_option_specs() {
  return {threads_option("1", "answer queries on N threads (results identical to one thread)"),
          shard_option("--shard", kMaxShards,
                       "only the I-th of N contiguous blocks of all queries, for splitting a run\n"
                       "across cluster jobs; concatenating the outputs of shards 0..N-1 gives\n"
                       "the output of the whole run")};
}

unsigned startable_threads(unsigned threads) {
  const unsigned wanted = std::min<unsigned>(threads, std::max(1, tbb::info::default_concurrency()));
  std::promise<void> release;
  const std::shared_future<void> released = release.get_future().share();
  std::vector<std::thread> held;  // alive together: the system counts them at once
  held.reserve(wanted);
  for (unsigned i = 1; i < wanted; ++i) {
    try {
      held.emplace_back([released] { released.wait(); });
    } catch (const std::system_error&) {
      break;  // refused (EAGAIN): the ones started so far, and the calling thread
    }
  }
  release.set_value();
  for (std::thread& t : held) t.join();
  return held.size() + 1 == wanted ? threads : static_cast<unsigned>(held.size() + 1);
}

BatchOptions batch_options(const ParsedOptions& options) {
  BatchOptions b;
  b.threads = startable_threads(scene::resolve_threads(static_cast<unsigned>(options.integer("--threads"))));
  std::tie(b.shard_index, b.shard_count) = options.shard("--shard");
  return b;
}

std::pair<std::size_t, std::size_t> BatchOptions::shard_range(std::size_t total) const {
  return {total * shard_index / shard_count, total * (shard_index + 1) / shard_count};
}

void parallel_for(std::size_t begin, std::size_t end, unsigned threads, const std::function<void(std::size_t)>& task,
                  const char* label) {
  // The library's loop (scene::call_chunks: oneTBB on at most `threads` threads, the first
  // exception stops the loop and is rethrown), one index per chunk; the calling thread (worker
  // 0: the arena's reserved slot) also draws the progress bar between its indices.
  const std::size_t total = end > begin ? end - begin : 0;
  std::atomic<std::size_t> done{0};
  const bool tty = isatty(fileno(stderr)) != 0;
  const double start = now_seconds();
  double last_draw = start;
  bool drawn = false;
  const auto draw = [&](std::size_t finished) {
    constexpr int kWidth = 40;
    const int filled = total ? static_cast<int>(kWidth * finished / total) : kWidth;
    std::fprintf(stderr, "\r%s [%s%s] %zu/%zu", label, std::string(filled, '=').c_str(),
                 std::string(kWidth - filled, ' ').c_str(), finished, total);
    std::fflush(stderr);
    drawn = true;
  };
  scene::call_chunks(total, std::max(1u, threads), 1, [&](std::size_t b, std::size_t e, unsigned worker) {
    for (std::size_t i = b; i < e; ++i) task(begin + i);
    done.fetch_add(e - b);
    if (worker == 0 && tty) {
      const double now = now_seconds();
      if (now - start > 2.0 && now - last_draw > 0.2) {
        draw(done.load());
        last_draw = now;
      }
    }
    return true;
  });
  if (drawn) {
    draw(done.load());
    std::fputc('\n', stderr);
  }
}

StageCounts linear_stage_counts(const StageCounters& s) {
  return {{"volume_exclusion", s.volume_exclusion}, {"static_predicates", s.static_predicates},
          {"separating_direction", s.separating_direction}, {"interval", s.interval},
          {"fixed_integer", s.fixed_integer}, {"integer", s.integer}, {"exact", s.exact}};
}

void append_json_record(std::string& items, const CheckRecord& rec) {
  char buf[512];
  std::string item = std::string(items.empty() ? "" : ",\n") + "  {\"file\": " + json_string(rec.file) +
                     ", \"kind\": \"" + rec.kind + "\"";
  if (rec.motion) item += std::string(", \"motion\": \"") + rec.motion + "\"";
  std::snprintf(buf, sizeof buf,
                ", \"method\": \"%s\", \"queries\": %zu, \"positives\": %zu, \"fp\": %zu, \"fn\": %zu, "
                "\"us_per_query\": %.3f, \"stages\": {",
                rec.method.c_str(), rec.queries, rec.positives, rec.fp, rec.fn, rec.us_per_query);
  item += buf;
  for (std::size_t k = 0; k < rec.stages.size(); ++k)
    item += std::string(k ? ", " : "") + "\"" + rec.stages[k].first + "\": " + std::to_string(rec.stages[k].second);
  items += item + "}}";
}

namespace {
/// Whether the report answers the default question (contact over [0, 1]).
bool default_question(const CcdParams& params) { return params.contact_over_whole_step(); }
}  // namespace

void print_check_header(const CcdParams& params) {
  if (default_question(params)) {
    std::printf("%-60s %4s %8s %9s %6s %6s %12s\n", "file", "kind", "queries", "positives", "FP", "FN", "us/query");
  } else {
    std::printf("%-60s %4s %8s %9s %11s %10s %12s\n", "file", "kind", "queries", "truth_1", "yes_truth_0", "no_truth_1",
                "us/query");
  }
}

void print_check_row(const CheckRecord& rec, bool stages_line, const CcdParams& params) {
  const int fp_width = default_question(params) ? 6 : 11, fn_width = default_question(params) ? 6 : 10;
  std::printf("%-60s %4s %8zu %9zu %*zu %*zu %12.3f\n", rec.file.c_str(), rec.kind.c_str(), rec.queries,
              rec.positives, fp_width, rec.fp, fn_width, rec.fn, rec.us_per_query);
  if (!stages_line) return;
  std::string line = "  stages: ";
  for (std::size_t k = 0; k < rec.stages.size(); ++k)
    line += std::string(k ? ", " : "") + rec.stages[k].first + " " + std::to_string(rec.stages[k].second);
  std::printf("%s\n", line.c_str());
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace exactccd::cli
