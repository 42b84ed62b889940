// The block protocol (pipeline/block.hpp): a stage list run on a block of lanes gives every lane
// the answer and the counts that the same list gives the query alone; the block stages see only
// the lanes still open, packed; each open lane's per-query stages start at the first stage
// without a block form, with what the block stages handed over, and never run a stage the lane
// passed; the lanes' order and a block's stale lanes do not matter.
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "pipeline/block.hpp"
#include "pipeline/run_stages.hpp"

namespace exactccd::pipeline {
namespace {

/// What the scripted stages hand over: which block stage saw the lane last, and the lane's id.
struct Seen {
  int by = 0;
  int id = -1;
};

/// A query's script: its id (p_t0.x) and, per stage, what that stage decides: 0 undecided,
/// 1 separate, 2 collides without a TOI (the block stages: p_t0.y, p_t0.z, a_t0.y; the last
/// stage: a_t0.x, where 2 and 3 are a collision with the TOI [id / 64, id / 64]).
VertexFaceQuery scripted(int id, int first, int second, int third, int last) {
  VertexFaceQuery q{};
  q.p_t0 = {static_cast<double>(id), static_cast<double>(first), static_cast<double>(second)};
  q.a_t0 = {static_cast<double>(last), static_cast<double>(third), 0};
  return q;
}

/// The block stage `entry`'s script entry of q.
double entry_of(const VertexFaceQuery& q, int entry) { return entry == 1 ? q.p_t0.y : entry == 2 ? q.p_t0.z : q.a_t0.y; }

Outcome outcome_of(double code, double id) {
  if (code == 1) return Outcome::separate();
  if (code == 2) return Outcome::collides();
  if (code == 3) return Outcome::collides(TimeInterval{id / 64, id / 64});
  return Outcome::undecided();
}

/// Records what ran: (stage, id) per call, block stages the ids of the lanes they saw.
struct Log {
  std::vector<std::pair<int, int>> per_query;
  std::vector<std::vector<int>> block_lanes[3];
};

/// A stage with a block form deciding by the script's entry `entry` (1 to 3; never a certified
/// TOI, as LaneDecisions has none); it hands over by = entry.
template <int Entry>
struct ScriptedBlockStage {
  static constexpr Counter counter = Entry == 1 ? &StageCounters::volume_exclusion : &StageCounters::interval;
  Log* log;
  template <class Findings>
  Outcome operator()(Work<VertexFaceQuery, Findings>& work) const {
    log->per_query.emplace_back(Entry, static_cast<int>(work.query().p_t0.x));
    work.findings.by = Entry;
    work.findings.id = static_cast<int>(work.query().p_t0.x);
    return outcome_of(entry_of(work.query(), Entry), 0);
  }
  template <class Findings>
  LaneDecisions block(const QueryLanes<VertexFaceQuery>& lanes, const Question&, std::array<Findings, kLanes>& found) const {
    LaneDecisions d;
    std::vector<int>& seen = log->block_lanes[Entry - 1].emplace_back();
    for (std::size_t i = 0; i < lanes.size; ++i) {
      const VertexFaceQuery q = lanes.query(i);
      seen.push_back(static_cast<int>(q.p_t0.x));
      if (Entry > 1) {
        EXPECT_EQ(found[i].by, Entry - 1) << "lane " << i << ": the previous block stage's handover is missing";
        EXPECT_EQ(found[i].id, seen.back()) << "lane " << i << ": the handover of another lane";
      }
      found[i].by = Entry;
      found[i].id = static_cast<int>(q.p_t0.x);
      const double code = entry_of(q, Entry);
      if (code == 1) d.separate |= LaneMask{1} << i;
      if (code == 2) d.collides |= LaneMask{1} << i;
    }
    return d;
  }
};

/// A per-query stage deciding by the script's third entry; it checks the handover.
struct ScriptedLastStage {
  static constexpr Counter counter = &StageCounters::exact;
  Log* log;
  template <class Findings>
  Outcome operator()(Work<VertexFaceQuery, Findings>& work) const {
    const int id = static_cast<int>(work.query().p_t0.x);
    log->per_query.emplace_back(4, id);
    EXPECT_EQ(work.findings.by, 3) << "lane " << id << ": the block stages' handover is missing";
    EXPECT_EQ(work.findings.id, id) << "the handover of another lane";
    const double code = work.query().a_t0.x;
    return outcome_of(code <= 1 ? 1 : 3, id);  // always decides (a collision with its TOI)
  }
};

using List = StageList<ScriptedBlockStage<1>, ScriptedBlockStage<2>, ScriptedBlockStage<3>, ScriptedLastStage>;

/// The list, logging into `log`.
List list_logging(Log& log) {
  return List{ScriptedBlockStage<1>{&log}, ScriptedBlockStage<2>{&log}, ScriptedBlockStage<3>{&log},
              ScriptedLastStage{&log}};
}

/// Every script (the block stages' entries from 0..2, the last stage's from 0..3), as queries.
std::vector<VertexFaceQuery> every_script() {
  std::vector<VertexFaceQuery> all;
  for (int a = 0; a <= 2; ++a)
    for (int b = 0; b <= 2; ++b)
      for (int c = 0; c <= 2; ++c)
        for (int d = 0; d <= 3; ++d) all.push_back(scripted(static_cast<int>(all.size()), a, b, c, d));
  return all;
}

TEST(Block, EveryLaneGetsTheAnswerAndCountsOfTheQueryAlone) {
  const std::vector<VertexFaceQuery> all = every_script();
  for (const bool want_toi : {false, true}) {
    const Question question{{}, want_toi};
    Log alone_log, block_log;
    const List alone_list = list_logging(alone_log), block_list = list_logging(block_log);
    StageCounters alone_counts, block_counts;
    std::vector<std::optional<TimeInterval>> alone(all.size()), blocked(all.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
      Work<VertexFaceQuery, Seen> work{all[i], question, &alone_counts};
      alone[i] = alone_list.run(work);
    }
    run_batch<Seen>(block_list, all.data(), all.size(), question, &block_counts,
                    [&](std::size_t i, const std::optional<TimeInterval>& a) { blocked[i] = a; });
    for (std::size_t i = 0; i < all.size(); ++i) {
      ASSERT_EQ(blocked[i].has_value(), alone[i].has_value()) << "query " << i;
      if (alone[i]) {
        EXPECT_EQ(*blocked[i], *alone[i]) << "query " << i;
      }
    }
    EXPECT_EQ(block_counts.volume_exclusion, alone_counts.volume_exclusion);
    EXPECT_EQ(block_counts.interval, alone_counts.interval);
    EXPECT_EQ(block_counts.exact, alone_counts.exact);
    EXPECT_EQ(block_counts.toi_refined, alone_counts.toi_refined);
    // In the block run only the last stage runs per query, once per lane the block stages left
    // open: a lane never goes through a stage it passed.
    std::vector<int> last_stage_ids;
    for (const auto& [stage, id] : block_log.per_query) {
      EXPECT_EQ(stage, 4) << "a block stage ran again per query, for query " << id;
      last_stage_ids.push_back(id);
    }
    std::vector<int> expected_ids;
    for (const auto& [stage, id] : alone_log.per_query)
      if (stage == 4) expected_ids.push_back(id);
    EXPECT_EQ(last_stage_ids, expected_ids);
  }
}

TEST(Block, TheLaterBlockStagesSeeOnlyTheOpenLanesPacked) {
  // 16 lanes: the first stage separates the even ones, the second sees the 8 odd ones packed and
  // separates those of id 1 mod 4, the third sees ids 3, 7, 11, 15 and separates them.
  Log log;
  const List list = list_logging(log);
  QueryLanes<VertexFaceQuery> lanes;
  for (int i = 0; i < 16; ++i) lanes.push(scripted(i, i % 2 == 0 ? 1 : 0, i % 4 == 1 ? 1 : 0, 1, 1));
  std::array<std::optional<TimeInterval>, kLanes> got{};
  std::array<bool, kLanes> seen{};
  run_block<Seen>(list, lanes, Question{}, nullptr, [&](std::size_t i, const std::optional<TimeInterval>& a) {
    got[i] = a;
    seen[i] = true;
  });
  ASSERT_EQ(log.block_lanes[0].size(), 1u);
  ASSERT_EQ(log.block_lanes[1].size(), 1u);
  ASSERT_EQ(log.block_lanes[2].size(), 1u);
  EXPECT_EQ(log.block_lanes[0][0].size(), 16u);
  EXPECT_EQ(log.block_lanes[1][0], (std::vector<int>{1, 3, 5, 7, 9, 11, 13, 15}));
  EXPECT_EQ(log.block_lanes[2][0], (std::vector<int>{3, 7, 11, 15}));
  EXPECT_TRUE(log.per_query.empty());
  for (std::size_t i = 0; i < 16; ++i) {
    EXPECT_TRUE(seen[i]);
    EXPECT_FALSE(got[i].has_value());
  }
}

TEST(Block, StaleLanesDoNotCount) {
  // A full block, then a block of 3 over it: the 13 lanes beyond are not answered nor counted.
  Log log;
  const List list = list_logging(log);
  QueryLanes<VertexFaceQuery> lanes;
  for (int i = 0; i < 16; ++i) lanes.push(scripted(i, 1, 0, 0, 0));
  run_block<Seen>(list, lanes, Question{}, nullptr, [](std::size_t, const std::optional<TimeInterval>&) {});
  lanes.size = 0;
  for (int i = 0; i < 3; ++i) lanes.push(scripted(100 + i, 0, 0, 0, 3));
  StageCounters counts;
  std::size_t answered = 0;
  run_block<Seen>(list, lanes, Question{{}, true}, &counts, [&](std::size_t i, const std::optional<TimeInterval>& a) {
    ++answered;
    ASSERT_TRUE(a.has_value());
    EXPECT_EQ(a->lo, (100.0 + static_cast<double>(i)) / 64);
  });
  EXPECT_EQ(answered, 3u);
  EXPECT_EQ(counts.total(), 3u);
  EXPECT_EQ(counts.exact, 3u);
}

/// A per-query stage that always decides (separate), recording the queries it sees.
struct PlainStage {
  static constexpr Counter counter = &StageCounters::exact;
  std::vector<int>* seen;
  template <class Findings>
  Outcome operator()(Work<VertexFaceQuery, Findings>& work) const {
    seen->push_back(static_cast<int>(work.query().p_t0.x));
    return Outcome::separate();
  }
};

// A list without block stages runs query by query, in order.
TEST(Block, AListWithoutBlockStagesRunsQueryByQuery) {
  EXPECT_EQ((block_prefix_length<StageList<PlainStage>, VertexFaceQuery, Seen>()), 0u);
  EXPECT_EQ((block_prefix_length<List, VertexFaceQuery, Seen>()), 3u);
  std::vector<int> seen;
  const StageList<PlainStage> list{PlainStage{&seen}};
  const std::vector<VertexFaceQuery> all = every_script();
  std::vector<int> answered;
  run_batch<Seen>(list, all.data(), all.size(), Question{}, nullptr,
                  [&](std::size_t i, const std::optional<TimeInterval>& a) {
                    EXPECT_FALSE(a.has_value());
                    answered.push_back(static_cast<int>(i));
                  });
  ASSERT_EQ(answered.size(), all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(answered[i], static_cast<int>(i));
    EXPECT_EQ(seen[i], static_cast<int>(i));
  }
}

}  // namespace
}  // namespace exactccd::pipeline
