// exactccd::ExactNarrowPhaseCCD (include/exactccd/ipc_toolkit.hpp), the IPC Toolkit's narrow
// phase answered by exactccd. The toolkit is not on this machine (nor in CI: it is no Debian
// package), so this test compiles the adapter against tests/api/ipc_toolkit_shape/, a stand-in
// header with an interface of the same shape as the toolkit's ipc::NarrowPhaseCCD (same
// virtual signatures, copied from ipc-sim/ipc-toolkit's src/ipc/ccd/narrow_phase_ccd.hpp), and
// calls the adapter through that base class, as the toolkit does.
//
// Checked: on the bundled data of every kind (data/*/ *.csv), the answer equals the library's
// own entry point's, and toi is what the header promises, verified by exact properties through
// the library (no collision within [0, toi] when toi > 0, a collision within [0, next double
// after toi]), at several min_distance and tmax (passed through); the edge cases of the rule
// (a collision at t = 0, a time of impact that is a double, one that is not, tmax < 1, no
// collision, 2D points); the same answers from several threads sharing one const object.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include "exactccd/ccd.hpp"
#include "exactccd/ipc_toolkit.hpp"
#include "io/benchmark_csv.hpp"
#include "kinds/primitive_kinds.hpp"

namespace {

using exactccd::CcdParams;
using exactccd::ExactNarrowPhaseCCD;
using exactccd::TimeInterval;

/// One call's outcome.
struct Outcome {
  bool collides = false;
  double toi = -1;
  bool operator==(const Outcome& o) const {
    return collides == o.collides && (toi == o.toi || (std::isnan(toi) && std::isnan(o.toi)));
  }
};

Eigen::Vector3d e3(const exactccd::Vec3& v) { return {v.x, v.y, v.z}; }
Eigen::Vector3d e3(const exactccd::Vec2& v) { return {v.x, v.y, 0.0}; }  // the plane z = 0
ipc::VectorMax3d e2(const exactccd::Vec2& v) {
  ipc::VectorMax3d out(2);
  out << v.x, v.y;
  return out;
}
ipc::VectorMax3d em(const exactccd::Vec3& v) {
  ipc::VectorMax3d out(3);
  out << v.x, v.y, v.z;
  return out;
}

/// The adapter's answer to query q of kind Kind, called through the toolkit's interface.
/// Edge-edge in the plane has no method in the toolkit: it is asked as 3D edges at z = 0 (the
/// library's 2D kinds are exactly that question).
template <class Kind>
Outcome ask(const ipc::NarrowPhaseCCD& ccd, const typename Kind::template Query<double>& q, const CcdParams& p) {
  const auto r = rows(q);
  Outcome o;
  if constexpr (std::is_same_v<Kind, exactccd::kinds::VertexFace>) {
    o.collides = ccd.point_triangle_ccd(e3(r[0]), e3(r[1]), e3(r[2]), e3(r[3]), e3(r[4]), e3(r[5]), e3(r[6]),
                                        e3(r[7]), o.toi, p.min_distance, p.tmax);
  } else if constexpr (Kind::points == 4) {  // edge-edge, 3D or in the plane
    o.collides = ccd.edge_edge_ccd(e3(r[0]), e3(r[1]), e3(r[2]), e3(r[3]), e3(r[4]), e3(r[5]), e3(r[6]),
                                   e3(r[7]), o.toi, p.min_distance, p.tmax);
  } else if constexpr (Kind::points == 3) {
    const auto v = [&](int i) { if constexpr (Kind::dimension == 2) return e2(r[i]); else return em(r[i]); };
    o.collides = ccd.point_edge_ccd(v(0), v(1), v(2), v(3), v(4), v(5), o.toi, p.min_distance, p.tmax);
  } else {
    const auto v = [&](int i) { if constexpr (Kind::dimension == 2) return e2(r[i]); else return em(r[i]); };
    o.collides = ccd.point_point_ccd(v(0), v(1), v(2), v(3), o.toi, p.min_distance, p.tmax);
  }
  return o;
}

/// Checks `got` against the library's own entry point for the same question, and its toi by
/// exact properties: with a collision, the pair does not collide within [0, toi] when toi > 0
/// and collides within [0, next double after toi] (so toi is the largest double before the
/// time of impact, or 0), and toi >= the double just below lo; without, toi == tmax.
template <class Query>
void check(const Query& q, const CcdParams& p, const Outcome& got, const std::string& where) {
  const std::optional<TimeInterval> t = exactccd::toi(q, p);
  ASSERT_EQ(got.collides, t.has_value()) << where;
  if (!t) {
    EXPECT_EQ(got.toi, p.tmax) << where;
    return;
  }
  EXPECT_GE(got.toi, 0.0) << where;
  EXPECT_GE(got.toi, std::nextafter(t->lo, -1.0)) << where << " lo " << t->lo;
  EXPECT_LE(got.toi, t->lo) << where;
  if (got.toi > 0) {
    EXPECT_FALSE(exactccd::ccd(q, CcdParams{p.min_distance, got.toi})) << where << " toi " << got.toi;
  }
  const double next = std::nextafter(got.toi, 2.0);
  EXPECT_TRUE(exactccd::ccd(q, CcdParams{p.min_distance, std::min(next, 1.0)}))
      << where << " toi " << got.toi << " [" << t->lo << ", " << t->hi << "]";
}

/// Every bundled query file and its kind's name.
std::vector<std::filesystem::path> bundled_files() {
  std::vector<std::filesystem::path> files;
  for (const char* dir : {"catalogue", "families", "sim", "kinds"})
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(EXACTCCD_SOURCE_DIR) / "data" / dir))
      if (entry.path().extension() == ".csv") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

/// The double queries of kind Kind in `file` (queries with a coordinate that is not a double
/// are skipped: the toolkit takes doubles).
template <class Kind>
std::vector<typename Kind::template Query<double>> load(const std::filesystem::path& file) {
  std::ifstream in(file);
  const exactccd::io::BenchmarkQueries queries =
      exactccd::io::read_benchmark_csv(in, file.string(), exactccd::io::layout_of<Kind>());
  std::vector<typename Kind::template Query<double>> out;
  for (const auto& r : queries.rows)
    if (const auto d = exactccd::io::exact_double_rows(r))
      out.push_back(exactccd::io::query_from_rows<typename Kind::template Query<double>>(*d));
  return out;
}

/// Calls f.template operator()<Kind>(file) with the kind of `file` (from its name, longest
/// kind name first, as the CLI does); returns false when no kind matches.
template <class F>
bool with_kind_of(const std::filesystem::path& file, F&& f) {
  const std::string stem = file.stem().string();
  std::size_t best = 0;
  bool found = false;
  exactccd::kinds::for_each_kind([&](auto kind) {
    const std::string name(decltype(kind)::name);
    if (stem.size() >= name.size() && stem.compare(stem.size() - name.size(), name.size(), name) == 0 &&
        name.size() > best) {
      best = name.size();
      found = true;
    }
  });
  exactccd::kinds::for_each_kind([&](auto kind) {
    using Kind = decltype(kind);
    if (found && std::string(Kind::name).size() == best &&
        stem.compare(stem.size() - best, best, std::string(Kind::name)) == 0)
      f(kind);
  });
  return found;
}

/// The questions asked of every file: contact over the step and over its first quarter; and of
/// the simulation-like files (data/sim, data/kinds) also two minimum separations, one with
/// tmax < 1 (at d > 0 the degenerate catalogue's and families' extreme magnitudes make the
/// exact path the common one: minutes of test time for no other code).
const std::vector<CcdParams> kContactQuestions = {{0.0, 1.0}, {0.0, 0.25}};
const std::vector<CcdParams> kSeparationQuestions = {{1e-3, 1.0}, {1e-2, 0.5}};

TEST(IpcToolkitAdapter, AnswersAndToiOfEveryKindOnTheBundledData) {
  const ExactNarrowPhaseCCD adapter;
  const ipc::NarrowPhaseCCD& ccd = adapter;
  std::set<std::string> kinds_seen;
  std::size_t queries = 0, collisions = 0;
  for (const auto& file : bundled_files()) {
    const bool known = with_kind_of(file, [&](auto kind) {
      using Kind = decltype(kind);
      kinds_seen.insert(std::string(Kind::name));
      const auto qs = load<Kind>(file);
      std::vector<CcdParams> questions = kContactQuestions;
      const std::string dir = file.parent_path().filename().string();
      if (dir == "sim" || dir == "kinds")
        questions.insert(questions.end(), kSeparationQuestions.begin(), kSeparationQuestions.end());
      for (const CcdParams& p : questions)
        for (std::size_t i = 0; i < qs.size(); ++i) {
          const Outcome got = ask<Kind>(ccd, qs[i], p);
          collisions += got.collides;
          check(qs[i], p, got,
                file.filename().string() + " query " + std::to_string(i) + " d " + std::to_string(p.min_distance) +
                    " tmax " + std::to_string(p.tmax));
        }
      queries += qs.size();
    });
    EXPECT_TRUE(known) << file;
  }
  EXPECT_EQ(kinds_seen.size(), 7u);  // every kind of the library
  EXPECT_GT(queries, 5000u);
  EXPECT_GT(collisions, 500u);
}

TEST(IpcToolkitAdapter, ToiAtTheEdgesOfTheRule) {
  const ExactNarrowPhaseCCD adapter;
  const ipc::NarrowPhaseCCD& ccd = adapter;
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const auto P = [](double z) { return Eigen::Vector3d(0.25, 0.25, z); };  // above the triangle's inside
  double toi = -1;
  // A vertex falling through the triangle from z = 1 to z = -1: contact at t = 1/2, a double
  // (lo == hi): toi is the double just below 1/2.
  EXPECT_TRUE(ccd.point_triangle_ccd(P(1), a, b, c, P(-1), a, b, c, toi));
  EXPECT_EQ(toi, std::nextafter(0.5, 0.0));
  // From z = 1 to z = -2: contact at t = 1/3, not a double (lo < hi): toi = lo, the largest
  // double below 1/3.
  EXPECT_TRUE(ccd.point_triangle_ccd(P(1), a, b, c, P(-2), a, b, c, toi));
  EXPECT_EQ(toi, 1.0 / 3.0);  // the nearest double to 1/3, 0x1.5555555555555p-2, is below it
  EXPECT_FALSE(exactccd::vertex_face_ccd(exactccd::VertexFaceQuery{{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                                                   {0.25, 0.25, -2}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                         CcdParams{0.0, toi}));
  // Starting in contact (lo == 0): toi = 0, true, also when moving apart.
  EXPECT_TRUE(ccd.point_triangle_ccd(P(0), a, b, c, P(1), a, b, c, toi));
  EXPECT_EQ(toi, 0.0);
  // Starting within min_distance: toi = 0.
  EXPECT_TRUE(ccd.point_triangle_ccd(P(0.1), a, b, c, P(1), a, b, c, toi, 0.25));
  EXPECT_EQ(toi, 0.0);
  // tmax < 1: the contact at 1/2 is beyond tmax = 0.4: no collision, toi = tmax; at tmax = 0.5
  // it counts (closed interval) and toi is below it.
  EXPECT_FALSE(ccd.point_triangle_ccd(P(1), a, b, c, P(-1), a, b, c, toi, 0.0, 0.4));
  EXPECT_EQ(toi, 0.4);
  EXPECT_TRUE(ccd.point_triangle_ccd(P(1), a, b, c, P(-1), a, b, c, toi, 0.0, 0.5));
  EXPECT_EQ(toi, std::nextafter(0.5, 0.0));
  // min_distance passed through: within 0.5 of the plane at t = 1/4 (a double).
  EXPECT_TRUE(ccd.point_triangle_ccd(P(1), a, b, c, P(-1), a, b, c, toi, 0.5));
  EXPECT_EQ(toi, std::nextafter(0.25, 0.0));
  // Two particles in the plane (VectorMax3d of size 2) meeting at t = 3/4 within 0.5.
  ipc::VectorMax3d p0(2), q0(2), p1(2), q1(2);
  p0 << 0, 0;
  q0 << 2, 0;
  p1 << 0, 0;
  q1 << 0, 0;
  EXPECT_TRUE(ccd.point_point_ccd(p0, q0, p1, q1, toi, 0.5));
  EXPECT_EQ(toi, std::nextafter(0.75, 0.0));
  // No collision: false, toi = tmax.
  EXPECT_FALSE(ccd.point_point_ccd(p0, q0, p0, q0, toi, 0.5));
  EXPECT_EQ(toi, 1.0);
  // Mixed sizes and bad parameters are refused.
  ipc::VectorMax3d r3(3);
  r3 << 0, 0, 0;
  EXPECT_THROW(ccd.point_point_ccd(p0, q0, r3, q1, toi), std::invalid_argument);
  EXPECT_THROW(ccd.point_point_ccd(p0, q0, p1, q1, toi, -1.0), std::invalid_argument);
  EXPECT_THROW(ccd.point_point_ccd(p0, q0, p1, q1, toi, 0.0, 1.5), std::invalid_argument);
  EXPECT_EQ(adapter.conservative_rescaling, 1.0);
}

TEST(IpcToolkitAdapter, SameAnswersFromSeveralThreadsSharingOneObject) {
  const ExactNarrowPhaseCCD adapter;
  const ipc::NarrowPhaseCCD& ccd = adapter;
  using Kind = exactccd::kinds::EdgeEdge;
  std::vector<Kind::Query<double>> qs;
  for (const char* f : {"sim/sim-cloth-edge-edge.csv", "sim/sim-fold-edge-edge.csv", "families/families-edge-edge.csv"}) {
    const auto more = load<Kind>(std::filesystem::path(EXACTCCD_SOURCE_DIR) / "data" / f);
    qs.insert(qs.end(), more.begin(), more.end());
  }
  const CcdParams p{1e-3, 1.0};
  std::vector<Outcome> serial(qs.size());
  for (std::size_t i = 0; i < qs.size(); ++i) serial[i] = ask<Kind>(ccd, qs[i], p);
  constexpr int kThreads = 4;
  std::vector<std::vector<Outcome>> parallel(kThreads, std::vector<Outcome>(qs.size()));
  std::vector<std::thread> pool;
  for (int w = 0; w < kThreads; ++w)
    pool.emplace_back([&, w] {
      for (int pass = 0; pass < 2; ++pass)  // every thread does every query, twice, at once
        for (std::size_t i = 0; i < qs.size(); ++i) parallel[w][i] = ask<Kind>(ccd, qs[(i + w * 97) % qs.size()], p);
    });
  for (auto& t : pool) t.join();
  for (int w = 0; w < kThreads; ++w)
    for (std::size_t i = 0; i < qs.size(); ++i)
      ASSERT_TRUE(parallel[w][i] == serial[(i + w * 97) % qs.size()]) << "thread " << w << " query " << i;
}

}  // namespace
