#include "cli_common.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <exception>
#include <fstream>
#include <mutex>
#include <thread>

namespace exactccd::cli {

QueryKind parse_kind(const std::string& s) {
  if (s == "vf" || s == "vertex-face") return QueryKind::vertex_face;
  if (s == "ee" || s == "edge-edge") return QueryKind::edge_edge;
  throw UsageError("unknown kind '" + s + "' (expected vf or ee)");
}

std::string kind_name(QueryKind k) { return k == QueryKind::vertex_face ? "vf" : "ee"; }

std::optional<QueryKind> kind_from_path(const std::string& path) {
  // The occurrence nearest the file name wins: "edge-edge/run-vertex-face.csv" is vertex-face.
  const auto vf = path.rfind("vertex-face"), ee = path.rfind("edge-edge");
  if (vf == std::string::npos && ee == std::string::npos) return std::nullopt;
  if (ee == std::string::npos || (vf != std::string::npos && vf > ee)) return QueryKind::vertex_face;
  return QueryKind::edge_edge;
}

const std::vector<Method>& all_methods() {
  static const std::vector<Method> methods = {
      Method::naive,        Method::naive_tolerance, Method::naive_mpfr24,  Method::naive_mpfr53,
      Method::naive_mpfr113, Method::naive_mpfr256,  Method::filtered,      Method::exact};
  return methods;
}

std::string method_name(Method m) {
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

Method parse_method(const std::string& s) {
  for (Method m : all_methods())
    if (method_name(m) == s) return m;
  throw UsageError("unknown method '" + s +
                   "' (expected filtered, exact, naive, naive-tolerance, mpfr24, mpfr53, mpfr113 or mpfr256)");
}

Dataset load_dataset(const std::string& path, std::optional<QueryKind> kind) {
  if (!kind) kind = kind_from_path(path);
  if (!kind)
    throw UsageError("cannot infer the query kind of '" + path +
                     "' (no 'vertex-face' or 'edge-edge' in the path): pass --kind vf|ee");
  std::ifstream in(path);
  if (!in) throw UsageError("cannot open '" + path + "'");
  Dataset d;
  d.path = path;
  d.name = path;
  d.kind = *kind;
  d.queries = io::read_benchmark_csv(in, path);
  d.doubles.reserve(d.queries.size());
  for (const auto& rows : d.queries.rows) d.doubles.push_back(io::exact_double_rows(rows));
  return d;
}

namespace {

std::optional<TimeInterval> collides_placeholder(bool collides) {
  return collides ? std::optional<TimeInterval>(TimeInterval{}) : std::nullopt;
}

}  // namespace

std::optional<TimeInterval> run_query(const Dataset& d, std::size_t i, Method method,
                                      StageCounters* counters, bool want_toi) {
  const bool vf = d.kind == QueryKind::vertex_face;
  const auto& exact_rows = d.doubles[i];
  if (!exact_rows && is_exact_method(method)) {  // not doubles: the rational exact path
    if (counters) ++counters->exact;
    const auto& r = d.queries.rows[i];
    if (vf) {
      const auto q = from_rows<RationalVertexFaceQuery>(r);
      return want_toi ? vertex_face_toi(q) : collides_placeholder(vertex_face_ccd(q));
    }
    const auto q = from_rows<RationalEdgeEdgeQuery>(r);
    return want_toi ? edge_edge_toi(q) : collides_placeholder(edge_edge_ccd(q));
  }
  const std::array<Vec3, 8> rows = exact_rows ? *exact_rows : io::nearest_double_rows(d.queries.rows[i]);
  StageCounters unused;
  StageCounters& c = counters ? *counters : unused;
  if (vf) {
    const auto q = from_rows<VertexFaceQuery>(rows);
    return want_toi ? vertex_face_toi(q, method, c) : collides_placeholder(vertex_face_ccd(q, method, c));
  }
  const auto q = from_rows<EdgeEdgeQuery>(rows);
  return want_toi ? edge_edge_toi(q, method, c) : collides_placeholder(edge_edge_ccd(q, method, c));
}

bool BatchOptions::parse(int argc, char** argv, int& i) {
  const std::string a = argv[i];
  if (a == "--threads") {
    const std::string v = option_value(argc, argv, i);
    try {
      const int n = std::stoi(v);
      if (n < 1) throw std::invalid_argument(v);
      threads = static_cast<unsigned>(n);
    } catch (const std::exception&) {
      throw UsageError("--threads needs a positive integer, not '" + v + "'");
    }
    return true;
  }
  if (a == "--shard") {
    const std::string v = option_value(argc, argv, i);
    const auto slash = v.find('/');
    try {
      if (slash == std::string::npos) throw std::invalid_argument(v);
      const long index = std::stol(v.substr(0, slash)), count = std::stol(v.substr(slash + 1));
      if (count < 1 || index < 0 || index >= count) throw std::invalid_argument(v);
      shard_index = static_cast<std::size_t>(index);
      shard_count = static_cast<std::size_t>(count);
    } catch (const std::exception&) {
      throw UsageError("--shard needs I/N with 0 <= I < N, not '" + v + "'");
    }
    return true;
  }
  return false;
}

std::pair<std::size_t, std::size_t> BatchOptions::shard_range(std::size_t total) const {
  return {total * shard_index / shard_count, total * (shard_index + 1) / shard_count};
}

void parallel_for(std::size_t begin, std::size_t end, unsigned threads,
                  const std::function<void(std::size_t)>& task, const char* label) {
  std::atomic<std::size_t> next{begin}, done{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto run_one = [&](std::size_t i) {
    try {
      task(i);
    } catch (...) {
      std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = end;  // stop handing out work
    }
    done.fetch_add(1);
  };
  const auto worker = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < end;) run_one(i);
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
  // The calling thread works too, and draws the progress bar between queries.
  const bool tty = isatty(fileno(stderr)) != 0;
  const double start = now_seconds();
  double last_draw = start;
  bool drawn = false;
  const std::size_t total = end > begin ? end - begin : 0;
  const auto draw = [&](std::size_t finished) {
    constexpr int kWidth = 40;
    const int filled = total ? static_cast<int>(kWidth * finished / total) : kWidth;
    std::fprintf(stderr, "\r%s [%s%s] %zu/%zu", label, std::string(filled, '=').c_str(),
                 std::string(kWidth - filled, ' ').c_str(), finished, total);
    std::fflush(stderr);
    drawn = true;
  };
  for (std::size_t i; (i = next.fetch_add(1)) < end;) {
    run_one(i);
    if (tty) {
      const double now = now_seconds();
      if (now - start > 2.0 && now - last_draw > 0.2) {
        draw(done.load());
        last_draw = now;
      }
    }
  }
  for (auto& t : pool) t.join();
  if (drawn) {
    draw(done.load());
    std::fputc('\n', stderr);
  }
  if (failure) std::rethrow_exception(failure);
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

std::string option_value(int argc, char** argv, int& i) {
  if (i + 1 >= argc) throw UsageError(std::string("option ") + argv[i] + " needs a value");
  return argv[++i];
}

}  // namespace exactccd::cli
