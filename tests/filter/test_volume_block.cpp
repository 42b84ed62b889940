// Stage 1 of the contact question on a block of queries (filter/volume_block.hpp) against the
// per-query stage 1, query by query, at every SIMD level this CPU has: every intermediate value
// (the underflow threshold, the four group sums and their permanents) bit for bit, the verdict
// and the handover (out of range: the retry's cue), on
// every vertex-face and edge-edge query of the bundled data, of tests/data and of the shared
// sample (skipped with a note where absent), the wide-exponent families (subnormals next to
// 2^1000) and random queries over the whole exponent range (underflowing and overflowing
// products), in blocks of 0, 1, 3, 5, 7, 9, 15 and 16 lanes (the vector widths 2, 4, 8 plus and
// minus one), each block filled over the lanes of the previous one (stale lanes must not count).
// Both answers must occur in every source. Also: the level the environment variable
// EXACTCCD_SIMD forces (CTest runs this file, the candidate API's tests and the scene
// environment tests once per level: tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "filter/volume_block.hpp"
#include "filter/volume_exclusion.hpp"
#include "generators/families.hpp"
#include "io/benchmark_csv.hpp"
#include "pipeline/block.hpp"

namespace exactccd {
namespace {

namespace fs = std::filesystem;
using numeric::SimdLevel;
using Rows = std::array<Vec3, 8>;

/// Queries of both kinds from one source.
struct Cases {
  std::vector<Rows> vertex_face, edge_edge;
};

/// Every query of a benchmark file whose name says its kind (vertex-face or edge-edge).
void add_file(const fs::path& path, Cases& out) {
  const std::string name = path.filename().string();
  const bool vf = name.find("vertex-face") != std::string::npos, ee = name.find("edge-edge") != std::string::npos;
  if (path.extension() != ".csv" || !(vf || ee) || name.find("2d") != std::string::npos ||
      name.find("malformed") != std::string::npos || name.find("rigid") != std::string::npos)
    return;
  std::ifstream in(path);
  const io::BenchmarkQueries q = io::read_benchmark_csv(in, path.string());
  for (const auto& r : q.rows)
    if (const auto rows = io::exact_double_rows(r)) (vf ? out.vertex_face : out.edge_edge).push_back(*rows);
}

Cases bundled_cases() {
  Cases c;
  const fs::path root(EXACTCCD_SOURCE_DIR);
  for (const fs::path& dir : {root / "data" / "sim", root / "data" / "catalogue", root / "data" / "families", root / "tests" / "data"})
    for (const auto& e : fs::directory_iterator(dir)) add_file(e.path(), c);
  return c;
}

Cases shared_cases() {
  Cases c;
  const fs::path sample = fs::path(EXACTCCD_SAMPLE_QUERIES_DIR) / "unit-tests";
  if (!fs::exists(sample)) return c;
  for (const auto& e : fs::recursive_directory_iterator(sample)) {
    if (!e.is_regular_file()) continue;
    // The sample's files are named data_*.csv inside a folder named by the kind.
    const std::string kind = e.path().parent_path().filename().string();
    std::ifstream in(e.path());
    const io::BenchmarkQueries q = io::read_benchmark_csv(in, e.path().string());
    for (const auto& r : q.rows)
      if (const auto rows = io::exact_double_rows(r)) (kind == "vertex-face" ? c.vertex_face : c.edge_edge).push_back(*rows);
  }
  return c;
}

Cases wide_cases() {
  Cases c;
  std::mt19937_64 rng(2030);
  for (const families::Family& f : families::all_families())
    for (int style = 0; style < families::kWideStyleCount; ++style)
      for (int k : {0, 20, 52})
        for (bool toward : {true, false})
          if (const auto inst = families::make_wide(f, k, toward, static_cast<families::WideStyle>(style), rng))
            std::visit(
                [&](const auto& q) {
                  using Query = std::decay_t<decltype(q)>;
                  if constexpr (std::is_same_v<Query, VertexFaceQuery>) c.vertex_face.push_back(rows(q));
                  if constexpr (std::is_same_v<Query, EdgeEdgeQuery>) c.edge_edge.push_back(rows(q));
                },
                inst->query);
  return c;
}

/// Random queries at scales 2^-1074 .. 2^1023: products underflow or overflow in some lanes;
/// some with a static point or two equal points (V near or exactly zero).
Cases random_cases() {
  Cases c;
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1074, 1023);
  for (int n = 0; n < 4000; ++n) {
    Rows r;
    const int e = n % 2 == 0 ? exponent(rng) : 0;
    for (Vec3& p : r) p = {std::ldexp(unit(rng), e), std::ldexp(unit(rng), e), std::ldexp(unit(rng), e)};
    if (n % 5 == 1) r[7] = r[3];      // a static fourth point
    if (n % 7 == 2) r[6] = r[5];      // two points equal at t1
    if (n % 11 == 3) r[1].x = 0x1p1023; // one huge coordinate next to small ones
    (n % 3 == 0 ? c.edge_edge : c.vertex_face).push_back(r);
  }
  return c;
}

/// The bits of a double (equal bits: the same value, the same zero, the same NaN).
std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

/// What a source's blocks decided: lanes excluded, lanes out of range.
struct Counts {
  std::size_t excluded = 0, out_of_range = 0;
};

/// Lane `lane` of a block against the per-query stage on the same query: every intermediate
/// value (the threshold, the four group sums and permanents) bit for bit, then the verdict and
/// the handover. False (with a failure reported) when they differ.
template <class Query>
bool lane_matches(const Rows& rows, const filter::VolumeGroupLanes& g, const filter::VolumeLaneVerdicts& v,
                  std::size_t lane, const std::string& where) {
  const filter::VolumeGroups want = filter::volume_groups(from_rows<Query>(rows));
  bool same = bits(g.threshold[lane]) == bits(want.threshold);
  for (std::size_t m = 0; m < 4; ++m)
    same = same && bits(g.sum[m][lane]) == bits(want.sum[m]) && bits(g.permanent[m][lane]) == bits(want.permanent[m]);
  const filter::Exclusion e = filter::volume_exclusion(from_rows<Query>(rows));
  const bool excluded = (v.excluded >> lane & 1u) != 0, out_of_range = (v.out_of_range >> lane & 1u) != 0;
  if (same && excluded == (e == filter::Exclusion::excluded) && out_of_range == (e == filter::Exclusion::out_of_range))
    return true;
  ADD_FAILURE() << where << ", lane " << lane << ": " << (same ? "the verdict" : "an intermediate value")
                << " differs from the per-query stage's";
  return false;
}

/// Checks queries of one kind in blocks of `lanes` at `level` against the per-query stage 1
/// (lane_matches), each block written over the previous one.
template <class Query>
Counts check_blocks(const std::vector<Rows>& queries, std::size_t lanes, SimdLevel level, const std::string& where) {
  pipeline::QueryLanes<Query> block;
  Counts counts;
  for (std::size_t first = 0; first < queries.size() || first == 0; first += lanes == 0 ? queries.size() + 1 : lanes) {
    block.size = 0;
    const std::size_t end = std::min(queries.size(), first + lanes);
    for (std::size_t i = first; i < end; ++i) block.push(queries[i]);
    filter::VolumeGroupLanes groups;
    filter::volume_groups_block(block, level, groups);
    const filter::VolumeLaneVerdicts v = filter::volume_exclusion_block(block, level);
    EXPECT_EQ(v.excluded >> block.size, 0u) << where << ": a lane beyond the block's size, at query " << first;
    EXPECT_EQ(v.out_of_range >> block.size, 0u) << where << ": a lane beyond the block's size, at query " << first;
    const std::string at = where + ", " + std::to_string(lanes) + " lanes, " + numeric::simd_level_name(level);
    for (std::size_t i = first; i < end; ++i) {
      if (!lane_matches<Query>(queries[i], groups, v, i - first, at + ", query " + std::to_string(i)))
        return counts;  // one report per source and size
      counts.excluded += (v.excluded >> (i - first) & 1u);
      counts.out_of_range += (v.out_of_range >> (i - first) & 1u);
    }
  }
  return counts;
}

/// Checks both kinds of `cases` at `level` in every block size; both answers must occur (and,
/// where `out_of_range_occurs`, the handover too).
void check_cases(const Cases& cases, SimdLevel level, const std::string& where, bool out_of_range_occurs = false) {
  for (const std::size_t lanes : {0, 1, 3, 5, 7, 9, 15, 16}) {
    const Counts vf = check_blocks<VertexFaceQuery>(cases.vertex_face, lanes, level, where + " vertex-face");
    const Counts ee = check_blocks<EdgeEdgeQuery>(cases.edge_edge, lanes, level, where + " edge-edge");
    if (lanes == 0) continue;
    EXPECT_GT(vf.excluded, 0u) << where;
    EXPECT_LT(vf.excluded, cases.vertex_face.size()) << where;
    EXPECT_GT(ee.excluded, 0u) << where;
    EXPECT_LT(ee.excluded, cases.edge_edge.size()) << where;
    if (out_of_range_occurs) {
      EXPECT_GT(vf.out_of_range + ee.out_of_range, 0u) << where;
    }
  }
}

class EveryLevel : public testing::TestWithParam<SimdLevel> {
 protected:
  void SetUp() override {
    if (GetParam() > numeric::detected_simd_level())
      GTEST_SKIP() << "this CPU has no " << numeric::simd_level_name(GetParam());
  }
};

TEST_P(EveryLevel, EqualsTheScalarStageOnBundledData) { check_cases(bundled_cases(), GetParam(), "bundled"); }

TEST_P(EveryLevel, EqualsTheScalarStageOnTheSharedSample) {
  const Cases c = shared_cases();
  if (c.vertex_face.empty()) GTEST_SKIP() << "shared sample not found under " << EXACTCCD_SAMPLE_QUERIES_DIR;
  check_cases(c, GetParam(), "shared sample");
}

TEST_P(EveryLevel, EqualsTheScalarStageOnWideFamilies) {
  check_cases(wide_cases(), GetParam(), "wide families", true);
}

TEST_P(EveryLevel, EqualsTheScalarStageOnRandomQueriesOfEveryScale) {
  check_cases(random_cases(), GetParam(), "random", true);
}

INSTANTIATE_TEST_SUITE_P(Simd, EveryLevel, testing::Values(SimdLevel::sse2, SimdLevel::avx2, SimdLevel::avx512),
                         [](const testing::TestParamInfo<SimdLevel>& info) {
                           return std::string(numeric::simd_level_name(info.param));
                         });

// The level in use: EXACTCCD_SIMD names a level at most the CPU's (CTest's forced runs), or is
// absent (the detected level).
TEST(SimdLevel, IsTheDetectedOneOrTheOneForced) {
  const char* asked = std::getenv("EXACTCCD_SIMD");
  std::cout << "[ note     ] level in use: " << numeric::simd_level_text() << "\n";
  if (asked == nullptr) {
    EXPECT_EQ(numeric::simd_level(), numeric::detected_simd_level());
    return;
  }
  const auto wanted = numeric::simd_level_named(asked);
  ASSERT_TRUE(wanted.has_value()) << asked;
  if (*wanted > numeric::detected_simd_level()) GTEST_SKIP() << "this CPU has no " << asked;
  EXPECT_EQ(numeric::simd_level(), *wanted);
}

TEST(SimdLevel, NamesReadBack) {
  for (const SimdLevel level : {SimdLevel::sse2, SimdLevel::avx2, SimdLevel::avx512})
    EXPECT_EQ(numeric::simd_level_named(numeric::simd_level_name(level)), level);
  EXPECT_FALSE(numeric::simd_level_named("avx").has_value());
}

}  // namespace
}  // namespace exactccd
