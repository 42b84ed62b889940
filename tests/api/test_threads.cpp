// Queries from many threads at once give the answers of a serial run; the floating-point
// rounding mode is the same after the calls as before.
#include <gtest/gtest.h>

#include <cfenv>
#include <thread>
#include <vector>

#include "tests/test_support.hpp"
#include "methods/methods.hpp"

namespace exactccd {
namespace {

struct Answer {
  bool collides;
  TimeInterval toi;
  bool operator==(const Answer& o) const { return collides == o.collides && toi == o.toi; }
};

template <class Query, class Toi>
std::vector<Answer> answer_all(const std::vector<Query>& qs, Toi&& toi, std::size_t begin,
                               std::size_t stride) {
  std::vector<Answer> out(qs.size());
  for (std::size_t i = begin; i < qs.size(); i += stride) {
    const auto t = toi(qs[i]);
    out[i] = {t.has_value(), t.value_or(TimeInterval{-1, -1})};
  }
  return out;
}

template <class Query>
std::vector<Query> test_queries(std::uint64_t seed, const char* sample_file, bool vf) {
  std::vector<Query> qs = testing::degenerate_queries<Query>(seed, 1500);
  if (const auto sample = testing::load_sample(sample_file))
    for (const auto& r : sample->rows)
      if (const auto d = io::exact_double_rows(r)) qs.push_back(from_rows<Query>(*d));
  (void)vf;
  return qs;
}

template <class Query, class Toi>
void check_threads_match_serial(const std::vector<Query>& qs, Toi toi) {
  const std::vector<Answer> serial = answer_all(qs, toi, 0, 1);
  constexpr std::size_t kThreads = 8;
  std::vector<std::vector<Answer>> parts(kThreads);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] { parts[t] = answer_all(qs, toi, t, kThreads); });
  for (auto& th : threads) th.join();
  for (std::size_t i = 0; i < qs.size(); ++i)
    ASSERT_EQ(parts[i % kThreads][i], serial[i]) << "query " << i;
}

TEST(Threads, VertexFaceEightThreadsMatchSerial) {
  check_threads_match_serial(test_queries<VertexFaceQuery>(11, "unit-tests/vertex-face/data_0_1.csv", true),
                             [](const VertexFaceQuery& q) { return vertex_face_toi(q); });
}

TEST(Threads, EdgeEdgeEightThreadsMatchSerial) {
  check_threads_match_serial(test_queries<EdgeEdgeQuery>(12, "unit-tests/edge-edge/data_0_1.csv", false),
                             [](const EdgeEdgeQuery& q) { return edge_edge_toi(q); });
}

TEST(Threads, ExactMethodIsThreadSafeToo) {
  const auto qs = testing::degenerate_queries<EdgeEdgeQuery>(13, 200);
  check_threads_match_serial(qs, [](const EdgeEdgeQuery& q) { return edge_edge_toi(q, Method::exact); });
}

TEST(RoundingMode, RestoredAfterEveryMethod) {
  ASSERT_EQ(std::fegetround(), FE_TONEAREST);
  for (const auto& q : testing::degenerate_queries<VertexFaceQuery>(14, 300))
    for (tools::Method m : {tools::Method::filtered, tools::Method::exact, tools::Method::naive}) {
      tools::toi(q, m);
      ASSERT_EQ(std::fegetround(), FE_TONEAREST);
    }
}

}  // namespace
}  // namespace exactccd
