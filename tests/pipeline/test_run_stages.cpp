// The one policy of the filtered method (pipeline/run_stages.hpp): stages run in order until one
// answers the question; each query is counted once, at the stage that decides its answer (or
// the counter its outcome names, or not at all by the list when the stage counts for itself);
// a collision whose TOI is asked but not certified is counted as toi_refined as well, and only
// the later stages narrow it; a list where no stage decides is an error, never an answer.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "pipeline/run_stages.hpp"

namespace exactccd::pipeline {
namespace {

/// A scripted stage: returns `outcome`, records that it ran and what Work::collides was then.
struct Scripted {
  static constexpr Counter counter = &StageCounters::interval;
  Outcome outcome;
  std::vector<int>* log;
  int id;
  Outcome operator()(Work<VertexFaceQuery>& work) const {
    log->push_back(work.collides ? -id : id);
    return outcome;
  }
};
/// The same, counted at another counter.
struct ScriptedExact : Scripted {
  static constexpr Counter counter = &StageCounters::exact;
};
/// The same, counting for itself (a nested list).
struct ScriptedSelfCounting : Scripted {
  static constexpr Counter counter = nullptr;
};

const VertexFaceQuery kQuery{};
const TimeInterval kToi{0.25, 0.25};

TEST(RunStages, TheFirstDecidingStageAnswersAndIsCounted) {
  std::vector<int> log;
  StageCounters counters;
  Work<VertexFaceQuery> work(kQuery, Question{{}, true}, &counters);
  const auto answer = run_stages(work, Scripted{Outcome::undecided(), &log, 1}, ScriptedExact{Outcome::collides(kToi), &log, 2},
                                 Scripted{Outcome::separate(), &log, 3});
  ASSERT_TRUE(answer);
  EXPECT_EQ(*answer, kToi);
  EXPECT_EQ(log, (std::vector<int>{1, 2}));  // stage 3 never runs
  EXPECT_EQ(counters.exact, 1u);
  EXPECT_EQ(counters.interval, 0u);
  EXPECT_EQ(counters.total(), 1u);
}

TEST(RunStages, SeparateIsNoCollisionAndAnswerAloneGivesThePlaceholder) {
  std::vector<int> log;
  StageCounters counters;
  Work<VertexFaceQuery> apart(kQuery, Question{}, &counters);
  EXPECT_FALSE(run_stages(apart, Scripted{Outcome::separate(), &log, 1}));
  Work<VertexFaceQuery> hit(kQuery, Question{}, &counters);  // the TOI not asked
  const auto answer = run_stages(hit, Scripted{Outcome::collides(), &log, 1});
  ASSERT_TRUE(answer);
  EXPECT_EQ(*answer, kCollisionWithoutToi);
  EXPECT_EQ(counters.interval, 2u);
  EXPECT_EQ(counters.toi_refined, 0u);
}

TEST(RunStages, ACollisionWithoutItsToiIsNarrowedByTheLaterStages) {
  std::vector<int> log;
  StageCounters counters;
  Work<VertexFaceQuery> work(kQuery, Question{{}, true}, &counters);
  const auto answer = run_stages(work, Scripted{Outcome::collides(), &log, 1}, Scripted{Outcome::undecided(), &log, 2},
                                 ScriptedExact{Outcome::collides(kToi), &log, 3});
  ASSERT_TRUE(answer);
  EXPECT_EQ(*answer, kToi);
  // The later stages see Work::collides (negative ids in the log).
  EXPECT_EQ(log, (std::vector<int>{1, -2, -3}));
  // Counted once, at the stage that decided the answer, and as toi_refined; not at stage 3.
  EXPECT_EQ(counters.interval, 1u);
  EXPECT_EQ(counters.toi_refined, 1u);
  EXPECT_EQ(counters.exact, 0u);
}

TEST(RunStages, TheOutcomeNamesItsCounterAndSelfCountingStagesAreNotCounted) {
  std::vector<int> log;
  StageCounters counters;
  Outcome with_gmp = Outcome::separate();
  with_gmp.counted_as = &StageCounters::integer;
  Work<VertexFaceQuery> named(kQuery, Question{}, &counters);
  EXPECT_FALSE(run_stages(named, Scripted{with_gmp, &log, 1}));
  EXPECT_EQ(counters.integer, 1u);
  EXPECT_EQ(counters.interval, 0u);
  Work<VertexFaceQuery> nested(kQuery, Question{}, &counters);
  EXPECT_FALSE(run_stages(nested, ScriptedSelfCounting{Outcome::separate(), &log, 2}));
  EXPECT_EQ(counters.total(), 1u);
  Work<VertexFaceQuery> uncounted(kQuery, Question{}, nullptr);  // counters may be null
  EXPECT_FALSE(run_stages(uncounted, Scripted{Outcome::separate(), &log, 3}));
}

TEST(RunStages, NoDecidingStageIsAnErrorNotAnAnswer) {
  std::vector<int> log;
  Work<VertexFaceQuery> work(kQuery, Question{}, nullptr);
  EXPECT_THROW(run_stages(work, Scripted{Outcome::undecided(), &log, 1}), std::logic_error);
  Work<VertexFaceQuery> toi(kQuery, Question{{}, true}, nullptr);  // a collision whose TOI nobody finds
  EXPECT_THROW(run_stages(toi, Scripted{Outcome::collides(), &log, 1}), std::logic_error);
}

}  // namespace
}  // namespace exactccd::pipeline
