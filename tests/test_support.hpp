// Shared helpers of the test suites: the shared benchmark sample, and deterministic random
// queries biased to degeneracies (small integer grids, repeated vertices, coplanar motion).
#pragma once

#include <array>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "exactccd/exactccd.hpp"
#include "io/benchmark_csv.hpp"

namespace exactccd::testing {

/// The shared sample file (unit-tests/vertex-face/... etc.) in doubles, or nullopt when the
/// shared data is absent.
inline std::optional<io::BenchmarkQueries> load_sample(const std::string& relative_path) {
  const std::filesystem::path path =
      std::filesystem::path(EXACTCCD_SAMPLE_QUERIES_DIR) / relative_path;
  std::ifstream in(path);
  if (!in) return std::nullopt;
  return io::read_benchmark_csv(in, path.string());
}

/// Eight points in benchmark row order drawn from a small grid, with repeated vertices and
/// coplanar motion mixed in: the inputs where floating-point CCD goes wrong.
inline std::array<Vec3, 8> degenerate_rows(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> coord(-2, 2), choice(0, 9);
  const double scale = 0.125;
  std::array<Vec3, 8> r;
  for (auto& p : r) p = {coord(rng) * scale, coord(rng) * scale, coord(rng) * scale};
  const int c = choice(rng);
  if (c == 0)  // everything in the plane z = 0 for all t
    for (auto& p : r) p.z = 0;
  if (c == 1) r[5] = r[4];  // two vertices coincide at t1
  if (c == 2) {             // a static triangle / edge
    r[5] = r[1];
    r[6] = r[2];
    r[7] = r[3];
  }
  if (c == 3) r[4] = r[0];  // a vertex that does not move
  return r;
}

template <class Query>
std::vector<Query> degenerate_queries(std::uint64_t seed, std::size_t n) {
  std::mt19937_64 rng(seed);
  std::vector<Query> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(from_rows<Query>(degenerate_rows(rng)));
  return out;
}

}  // namespace exactccd::testing
