// The cost of a query with its certified TOI, query by query (issue 30, item 2): each query of
// the given benchmark CSV files answered by Method::filtered with the TOI (the tightest double
// interval), and by the textbook cubic (baseline::naive_toi), each `repetitions` times in turn;
// the minimum time per query (robust on a shared, loaded machine: a preempted run only raises
// the others' maximum). Prints, per d, the sums over all queries and over those that collide,
// the median of the colliding ones and the costliest queries (file and index).
//
//   build/toi_bench [--repetitions R] [--min-distances D1,D2,...] [--top N] FILE.csv...
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "baseline/naive_ccd.hpp"
#include "exactccd/exactccd.hpp"
#include "io/benchmark_csv.hpp"

namespace {

using namespace exactccd;

/// One query of a file: its rows in doubles and its kind (from the file name).
struct Query {
  std::string file;
  std::size_t index;
  std::array<Vec3, 8> rows;
  bool vertex_face;
};

std::vector<Query> read_queries(const std::vector<std::string>& paths) {
  std::vector<Query> out;
  for (const std::string& path : paths) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    const io::BenchmarkQueries q = io::read_benchmark_csv(in, path);
    const bool vf = path.find("vertex-face") != std::string::npos;
    for (std::size_t i = 0; i < q.rows.size(); ++i) out.push_back({path, i, io::nearest_double_rows(q.rows[i]), vf});
  }
  return out;
}

template <class F>
double seconds(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The filtered method's answer with its TOI, and the cubic's, for one query.
std::optional<TimeInterval> filtered_toi(const Query& q, const CcdParams& params) {
  if (q.vertex_face) return answer_query(from_rows<VertexFaceQuery>(q.rows), params, Method::filtered, true, nullptr);
  return answer_query(from_rows<EdgeEdgeQuery>(q.rows), params, Method::filtered, true, nullptr);
}
bool naive_collides(const Query& q) {
  if (q.vertex_face) return baseline::naive_toi(from_rows<VertexFaceQuery>(q.rows)).has_value();
  return baseline::naive_toi(from_rows<EdgeEdgeQuery>(q.rows)).has_value();
}

/// Per query: the minimum seconds of each method over the repetitions, and the answer.
struct Timing {
  double filtered = 1e30, naive = 1e30;
  bool collides = false, naive_collides = false;
};

void report(const std::vector<Query>& queries, double d, int repetitions, std::size_t top) {
  std::vector<Timing> t(queries.size());
  const CcdParams params{d, 1.0};
  for (int r = 0; r < repetitions; ++r)
    for (std::size_t i = 0; i < queries.size(); ++i) {
      t[i].filtered = std::min(t[i].filtered, seconds([&] { t[i].collides = filtered_toi(queries[i], params).has_value(); }));
      t[i].naive = std::min(t[i].naive, seconds([&] { t[i].naive_collides = naive_collides(queries[i]); }));
    }
  double all = 0, colliding = 0, naive = 0;
  std::size_t naive_hits = 0;
  std::vector<double> colliding_times;
  for (const Timing& x : t) {
    all += x.filtered;
    naive += x.naive;
    naive_hits += x.naive_collides;
    if (x.collides) colliding += x.filtered, colliding_times.push_back(x.filtered);
  }
  std::sort(colliding_times.begin(), colliding_times.end());
  const double median = colliding_times.empty() ? 0 : colliding_times[colliding_times.size() / 2];
  std::printf("d = %g: %zu queries, %zu collide; filtered with TOI %.1f us (colliding %.1f us, median %.2f us); "
              "naive cubic (contact only) %.1f us, %zu hits (minimum of %d runs per query)\n",
              d, queries.size(), colliding_times.size(), all * 1e6, colliding * 1e6, median * 1e6, naive * 1e6, naive_hits,
              repetitions);
  std::vector<std::size_t> order(queries.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return t[a].filtered > t[b].filtered; });
  for (std::size_t k = 0; k < std::min(top, order.size()); ++k)
    std::printf("  %8.2f us  %s query %zu%s\n", t[order[k]].filtered * 1e6, queries[order[k]].file.c_str(),
                queries[order[k]].index, t[order[k]].collides ? " (collides)" : "");
}

std::vector<double> parse_list(const char* text) {
  std::vector<double> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) out.push_back(std::stod(item));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  int repetitions = 20;
  std::size_t top = 5;
  std::vector<double> distances{0.0};
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const bool has_value = i + 1 < argc;
    if (!std::strcmp(argv[i], "--repetitions") && has_value)
      repetitions = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--min-distances") && has_value)
      distances = parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--top") && has_value)
      top = static_cast<std::size_t>(std::max(0, std::atoi(argv[++i])));
    else
      files.push_back(argv[i]);
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: toi_bench [--repetitions R] [--min-distances D1,D2,...] [--top N] FILE.csv...\n");
    return 2;
  }
  try {
    const std::vector<Query> queries = read_queries(files);
    for (const double d : distances) report(queries, d, repetitions, top);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "toi_bench: %s\n", e.what());
    return 2;
  }
  return 0;
}
