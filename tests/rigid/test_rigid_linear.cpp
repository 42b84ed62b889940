// The regression anchor of docs/design.md 9.2: with equal constant rotations the rigid question
// is the linear one. Every query of the bundled vertex-face and edge-edge data (catalogue,
// degenerate families, simulation-like sets) as rigid queries under three exact constant
// rotations (rigid_linear_support.hpp), by both rigid methods, against the linear method on the
// same motion: the same answers and the same TOIs, bit for bit; at d = 0 over [0, 1] for every
// query, and with d > 0 and tmax < 1 for every fifth.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "exactccd/ccd.hpp"
#include "exactccd/rational.hpp"
#include "exactccd/rigid.hpp"
#include "io/benchmark_csv.hpp"
#include "rigid_linear_support.hpp"

namespace exactccd {
namespace {

using namespace rigid_test;

/// The linear query's answer: the double API's filtered method when its rows are doubles, the
/// rational API otherwise (both exact).
template <class LinearQuery, class RationalQuery>
std::optional<TimeInterval> linear_toi(const std::array<RationalVec3, 8>& rows, const CcdParams& p) {
  if (const auto d = io::exact_double_rows(rows)) return toi(from_rows<LinearQuery>(*d), p);
  return toi(from_rows<RationalQuery>(rows), RationalCcdParams{p.min_distance, p.tmax});
}

/// A power of two near `fraction` of the rows' largest extent (exact, so d is the same number
/// for both questions).
double distance_for(const std::array<Vec3, 8>& rows, double fraction) {
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const Vec3& v : rows) {
    const double c[3] = {v.x, v.y, v.z};
    for (int k = 0; k < 3; ++k) lo[k] = std::fmin(lo[k], c[k]), hi[k] = std::fmax(hi[k], c[k]);
  }
  double extent = 0;
  for (int k = 0; k < 3; ++k) extent = std::fmax(extent, hi[k] - lo[k]);
  if (!(extent > 0 && std::isfinite(extent))) return 0x1p-10;
  int e = 0;
  std::frexp(extent * fraction, &e);
  return std::ldexp(1.0, std::max(e, -1000));
}

template <class RigidQuery, class LinearQuery, class RationalQuery>
void anchor(const std::string& kind) {
  const auto queries = bundled_rows(kind);
  ASSERT_GT(queries.size(), 1000u) << "the bundled data of " << kind;
  std::size_t compared = 0, collisions = 0;
  const std::vector<std::pair<int, bool>> variants{{0, false}, {1, true}, {2, true}};  // rotation, translate B
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const auto& [name, rows] = queries[i];
    for (const auto& [rotation, translate_b] : variants) {
      const auto c = anchor_case<RigidQuery>(name, rows, exact_rotations()[rotation], translate_b);
      std::vector<CcdParams> questions{CcdParams{}};
      if (i % 5 == 0) questions.push_back(CcdParams{distance_for(rows, 1.0 / 256), 0.75});
      for (const CcdParams& p : questions) {
        const auto want = linear_toi<LinearQuery, RationalQuery>(c.linear, p);
        for (const Method m : {Method::filtered, Method::exact}) {
          const auto got = toi(c.rigid, p, m);
          ASSERT_EQ(got.has_value(), want.has_value())
              << c.name << " d " << p.min_distance << " tmax " << p.tmax << " method " << int(m);
          if (got) {
            EXPECT_EQ(got->lo, want->lo) << c.name << " d " << p.min_distance << " method " << int(m);
            EXPECT_EQ(got->hi, want->hi) << c.name << " d " << p.min_distance << " method " << int(m);
          }
          EXPECT_EQ(ccd(c.rigid, p, m), want.has_value()) << c.name;
          ++compared;
        }
        collisions += want.has_value();
      }
    }
  }
  EXPECT_GT(collisions, compared / 40);  // the data hold many collisions (and many misses)
}

TEST(RigidLinear, ConstantEqualRotationsGiveTheLinearAnswersVertexFace) {
  anchor<RigidVertexFaceQuery, VertexFaceQuery, RationalVertexFaceQuery>("vertex-face");
}

TEST(RigidLinear, ConstantEqualRotationsGiveTheLinearAnswersEdgeEdge) {
  anchor<RigidEdgeEdgeQuery, EdgeEdgeQuery, RationalEdgeEdgeQuery>("edge-edge");
}

}  // namespace
}  // namespace exactccd
