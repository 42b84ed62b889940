// Tight Inclusion (Wang et al. 2021; Continuous-Collision-Detection/Tight-Inclusion) against
// exactccd's filtered method and the textbook double-precision cubic, on the same vertex-face
// and edge-edge query files, timed in one run, interleaved (as `exactccd bench`). The harness's
// own source only: nothing in this repository builds or links it, nor Tight Inclusion (the
// figures were taken with it built by hand beside the repository against Tight Inclusion
// ca9a8c2, docs/performance.md, "Tight Inclusion").
//
// Tight Inclusion is called as its own benchmark program (app/main.cpp) calls it: err = (-1,
// -1, -1) (computed per query), minimum separation 0, tolerance 1e-6, t_max 1, at most 10^6
// iterations, breadth-first.
//
// Usage: tight_inclusion_bench REPETITIONS NAME=FILE.csv[,FILE.csv...]...
// Prints one markdown row per NAME: queries, mean ns per query (per file: the median over the
// repetitions of the file's mean; per NAME: the files' figures weighted by their query counts,
// as `exactccd bench`), the median of the queries' own times (each query timed alone once,
// after the repetitions), and FP / FN against each file's truth column for each method.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <tight_inclusion/ccd.hpp>

#include "exactccd/ccd.hpp"
#include "io/benchmark_csv.hpp"
#include "methods/methods.hpp"

namespace {

using exactccd::EdgeEdgeQuery;
using exactccd::VertexFaceQuery;

struct File {
  std::string path;
  bool vertex_face = true;
  std::vector<std::array<exactccd::Vec3, 8>> rows;
  std::vector<bool> truth;
};

enum MethodIndex { kNaive, kFiltered, kTightInclusion, kMethods };
const char* const kNames[kMethods] = {"naive", "filtered", "tight-inclusion"};

ticcd::Vector3 v(const exactccd::Vec3& p) { return {p.x, p.y, p.z}; }

bool tight_inclusion(const std::array<exactccd::Vec3, 8>& r, bool vertex_face) {
  const ticcd::Array3 err(-1, -1, -1);
  double toi = 0, output_tolerance = 0;
  constexpr double ms = 0, tolerance = 1e-6, t_max = 1;
  constexpr long max_itr = 1000000;
  if (vertex_face)
    return ticcd::vertexFaceCCD(v(r[0]), v(r[1]), v(r[2]), v(r[3]), v(r[4]), v(r[5]), v(r[6]), v(r[7]), err, ms,
                                toi, tolerance, t_max, max_itr, output_tolerance);
  return ticcd::edgeEdgeCCD(v(r[0]), v(r[1]), v(r[2]), v(r[3]), v(r[4]), v(r[5]), v(r[6]), v(r[7]), err, ms, toi,
                            tolerance, t_max, max_itr, output_tolerance);
}

bool answer(int method, const std::array<exactccd::Vec3, 8>& r, bool vertex_face) {
  if (method == kTightInclusion) return tight_inclusion(r, vertex_face);
  const auto m = method == kNaive ? exactccd::tools::Method::naive : exactccd::tools::Method::filtered;
  if (vertex_face)
    return exactccd::tools::ccd(VertexFaceQuery{r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]}, m);
  return exactccd::tools::ccd(EdgeEdgeQuery{r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]}, m);
}

File load(const std::string& path) {
  File f;
  f.path = path;
  const std::size_t vf = path.rfind("vertex-face"), ee = path.rfind("edge-edge");
  if (vf == std::string::npos && ee == std::string::npos) throw std::runtime_error(path + ": not vertex-face or edge-edge");
  f.vertex_face = ee == std::string::npos || (vf != std::string::npos && vf > ee);
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  const exactccd::io::BenchmarkQueries q = exactccd::io::read_benchmark_csv(in, path);
  for (std::size_t i = 0; i < q.size(); ++i) {
    const auto d = exactccd::io::exact_double_rows(q.rows[i]);
    if (!d) throw std::runtime_error(path + ": query " + std::to_string(i) + " is not in doubles");
    f.rows.push_back(*d);
    f.truth.push_back(q.truth[i]);
  }
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: tight_inclusion_bench REPETITIONS NAME=FILE.csv[,FILE.csv...]...\n";
    return 2;
  }
  const int repetitions = std::atoi(argv[1]);
  std::printf("| dataset | queries | naive ns | filtered ns | Tight Inclusion ns | Tight Inclusion / filtered | "
              "median ns: naive / filtered / Tight Inclusion | naive FP / FN | filtered FP / FN | Tight Inclusion FP / FN "
              "|\n|---|---|---|---|---|---|---|---|---|---|\n");
  for (int a = 2; a < argc; ++a) {
    const std::string arg = argv[a];
    const std::string name = arg.substr(0, arg.find('='));
    std::vector<File> files;
    for (std::size_t at = arg.find('=') + 1; at != std::string::npos && at < arg.size();) {
      const std::size_t comma = arg.find(',', at);
      files.push_back(load(arg.substr(at, comma == std::string::npos ? std::string::npos : comma - at)));
      at = comma == std::string::npos ? comma : comma + 1;
    }
    std::size_t queries = 0;
    std::array<double, kMethods> weighted{};
    std::array<std::size_t, kMethods> fp{}, fn{};
    std::array<std::vector<double>, kMethods> single;  // every query's own time, every file
    for (const File& f : files) {
      std::array<std::vector<double>, kMethods> ns;
      std::array<std::vector<char>, kMethods> answers;
      for (int rep = 0; rep < repetitions; ++rep)
        for (int k = 0; k < kMethods; ++k) {
          const int m = (k + rep) % kMethods;  // rotate the order: no method always runs first
          std::vector<char>& got = answers[m];
          got.assign(f.rows.size(), 0);
          const auto start = std::chrono::steady_clock::now();
          for (std::size_t i = 0; i < f.rows.size(); ++i) got[i] = answer(m, f.rows[i], f.vertex_face);
          const auto stop = std::chrono::steady_clock::now();
          ns[m].push_back(std::chrono::duration<double, std::nano>(stop - start).count() / f.rows.size());
        }
      for (int m = 0; m < kMethods; ++m)  // each query timed alone once, for the medians
        for (const auto& r : f.rows) {
          const auto start = std::chrono::steady_clock::now();
          const bool got = answer(m, r, f.vertex_face);
          const auto stop = std::chrono::steady_clock::now();
          single[m].push_back(std::chrono::duration<double, std::nano>(stop - start).count());
          (void)got;
        }
      for (int m = 0; m < kMethods; ++m) {  // the answers of the last repetition (all are the same)
        std::sort(ns[m].begin(), ns[m].end());
        weighted[m] += ns[m][ns[m].size() / 2] * f.rows.size();
        for (std::size_t i = 0; i < f.rows.size(); ++i) {
          fp[m] += answers[m][i] && !f.truth[i];
          fn[m] += !answers[m][i] && f.truth[i];
        }
      }
      queries += f.rows.size();
    }
    for (double& w : weighted) w /= static_cast<double>(queries);
    std::array<double, kMethods> median{};
    for (int m = 0; m < kMethods; ++m) {
      std::sort(single[m].begin(), single[m].end());
      median[m] = single[m][single[m].size() / 2];
    }
    std::printf("| %s | %zu | %.0f | %.0f | %.0f | %.2f | %.0f / %.0f / %.0f | %zu / %zu | %zu / %zu | %zu / %zu |\n",
                name.c_str(), queries, weighted[kNaive], weighted[kFiltered], weighted[kTightInclusion],
                weighted[kTightInclusion] / weighted[kFiltered], median[kNaive], median[kFiltered],
                median[kTightInclusion], fp[kNaive], fn[kNaive], fp[kFiltered], fn[kFiltered],
                fp[kTightInclusion], fn[kTightInclusion]);
    std::fflush(stdout);
  }
  return 0;
}
