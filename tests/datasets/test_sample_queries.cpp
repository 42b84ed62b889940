// The shared unit-test subset of the public CCD benchmark (Wang et al. 2021): every method that
// claims exactness must give 0 false positives and 0 false negatives against its ground truth.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"
#include "io/benchmark_csv.hpp"

namespace exactccd {
namespace {

namespace fs = std::filesystem;

struct SampleFile {
  const char* relative_path;
  bool vertex_face;
  std::size_t queries;
  std::size_t positives;
};

// Counts from the data's README.
constexpr SampleFile kFiles[] = {
    {"unit-tests/vertex-face/data_0_0.csv", true, 125, 35},
    {"unit-tests/vertex-face/data_0_1.csv", true, 125, 89},
    {"unit-tests/edge-edge/data_0_0.csv", false, 54, 21},
    {"unit-tests/edge-edge/data_0_1.csv", false, 20, 15},
};

void PrintTo(const SampleFile& f, std::ostream* os) { *os << f.relative_path; }

class SampleQueries : public ::testing::TestWithParam<SampleFile> {
 protected:
  io::BenchmarkQueries load() {
    const fs::path path = fs::path(EXACTCCD_SAMPLE_QUERIES_DIR) / GetParam().relative_path;
    std::ifstream in(path);
    if (!in) return {};
    return io::read_benchmark_csv(in, path.string());
  }
  bool available() const {
    return fs::exists(fs::path(EXACTCCD_SAMPLE_QUERIES_DIR) / GetParam().relative_path);
  }
};

std::string describe(const std::array<RationalVec3, 8>& rows) {
  std::string s;
  for (const auto& p : rows) s += "  " + p.x.get_str() + " " + p.y.get_str() + " " + p.z.get_str() + "\n";
  return s;
}

TEST_P(SampleQueries, ExactRationalPathMatchesGroundTruth) {
  if (!available())
    GTEST_SKIP() << "sample queries not found under " << EXACTCCD_SAMPLE_QUERIES_DIR
                 << " (set -DEXACTCCD_SAMPLE_QUERIES_DIR)";
  const io::BenchmarkQueries q = load();
  ASSERT_EQ(q.size(), GetParam().queries);
  std::size_t positives = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    positives += q.truth[i];
    const bool got = GetParam().vertex_face ? vertex_face_ccd(from_rows<RationalVertexFaceQuery>(q.rows[i]))
                                            : edge_edge_ccd(from_rows<RationalEdgeEdgeQuery>(q.rows[i]));
    EXPECT_EQ(got, q.truth[i]) << (got ? "false positive" : "false negative") << " at query " << i
                               << ":\n" << describe(q.rows[i]);
  }
  EXPECT_EQ(positives, GetParam().positives);
}

TEST_P(SampleQueries, DoubleApiMatchesGroundTruthForEveryExactMethod) {
  if (!available())
    GTEST_SKIP() << "sample queries not found under " << EXACTCCD_SAMPLE_QUERIES_DIR;
  const io::BenchmarkQueries q = load();
  for (std::size_t i = 0; i < q.size(); ++i) {
    const auto rows = io::exact_double_rows(q.rows[i]);
    ASSERT_TRUE(rows.has_value()) << "query " << i << " is not in doubles";
    for (Method m : {Method::filtered, Method::exact}) {
      const bool got = GetParam().vertex_face ? vertex_face_ccd(from_rows<VertexFaceQuery>(*rows), m)
                                              : edge_edge_ccd(from_rows<EdgeEdgeQuery>(*rows), m);
      EXPECT_EQ(got, q.truth[i]) << "method " << static_cast<int>(m) << ", query " << i << ":\n"
                                 << describe(q.rows[i]);
    }
  }
}

TEST_P(SampleQueries, ToiAgreesWithCollisionAndIsTight) {
  if (!available())
    GTEST_SKIP() << "sample queries not found under " << EXACTCCD_SAMPLE_QUERIES_DIR;
  const io::BenchmarkQueries q = load();
  for (std::size_t i = 0; i < q.size(); ++i) {
    const std::optional<TimeInterval> toi =
        GetParam().vertex_face ? vertex_face_toi(from_rows<RationalVertexFaceQuery>(q.rows[i]))
                               : edge_edge_toi(from_rows<RationalEdgeEdgeQuery>(q.rows[i]));
    EXPECT_EQ(toi.has_value(), q.truth[i]) << "query " << i;
    if (!toi) continue;
    EXPECT_LE(0.0, toi->lo);
    EXPECT_LE(toi->hi, 1.0);
    EXPECT_TRUE(toi->lo == toi->hi || std::nextafter(toi->lo, 2.0) == toi->hi)
        << "query " << i << ": [" << toi->lo << ", " << toi->hi << "] is not tight";
  }
}

INSTANTIATE_TEST_SUITE_P(UnitTests, SampleQueries, ::testing::ValuesIn(kFiles),
                         [](const ::testing::TestParamInfo<SampleFile>& info) {
                           std::string n = std::string(info.param.vertex_face ? "vf_" : "ee_") +
                                           std::to_string(info.index);
                           return n;
                         });

}  // namespace
}  // namespace exactccd
