// The one policy of the filtered method (pipeline/run_stages.hpp): stages run in order until one
// answers the question; each query is counted once, at the stage that decides its answer (or
// the counter its outcome names, or not at all by the list when the stage counts for itself);
// a collision whose TOI is asked but not certified is counted as toi_refined as well, and only
// the later stages narrow it; a list where no stage decides is an error, never an answer.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "pipeline/contact_probe.hpp"
#include "pipeline/run_stages.hpp"

namespace exactccd::pipeline {
namespace {

/// A scripted stage: returns `outcome`, records that it ran and what Work::collides was then.
struct Scripted {
  static constexpr Counter counter = &StageCounters::interval;
  Outcome outcome;
  std::vector<int>* log;
  int id;
  Outcome operator()(Work<VertexFaceQuery, GmpUse>& work) const {
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
  Work<VertexFaceQuery, GmpUse> work(kQuery, Question{{}, true}, &counters);
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
  Work<VertexFaceQuery, GmpUse> apart(kQuery, Question{}, &counters);
  EXPECT_FALSE(run_stages(apart, Scripted{Outcome::separate(), &log, 1}));
  Work<VertexFaceQuery, GmpUse> hit(kQuery, Question{}, &counters);  // the TOI not asked
  const auto answer = run_stages(hit, Scripted{Outcome::collides(), &log, 1});
  ASSERT_TRUE(answer);
  EXPECT_EQ(*answer, kCollisionWithoutToi);
  EXPECT_EQ(counters.interval, 2u);
  EXPECT_EQ(counters.toi_refined, 0u);
}

TEST(RunStages, ACollisionWithoutItsToiIsNarrowedByTheLaterStages) {
  std::vector<int> log;
  StageCounters counters;
  Work<VertexFaceQuery, GmpUse> work(kQuery, Question{{}, true}, &counters);
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
  Work<VertexFaceQuery, GmpUse> named(kQuery, Question{}, &counters);
  EXPECT_FALSE(run_stages(named, Scripted{with_gmp, &log, 1}));
  EXPECT_EQ(counters.integer, 1u);
  EXPECT_EQ(counters.interval, 0u);
  Work<VertexFaceQuery, GmpUse> nested(kQuery, Question{}, &counters);
  EXPECT_FALSE(run_stages(nested, ScriptedSelfCounting{Outcome::separate(), &log, 2}));
  EXPECT_EQ(counters.total(), 1u);
  Work<VertexFaceQuery, GmpUse> uncounted(kQuery, Question{}, nullptr);  // counters may be null
  EXPECT_FALSE(run_stages(uncounted, Scripted{Outcome::separate(), &log, 3}));
}

TEST(RunStages, NoDecidingStageIsAnErrorNotAnAnswer) {
  std::vector<int> log;
  Work<VertexFaceQuery, GmpUse> work(kQuery, Question{}, nullptr);
  EXPECT_THROW(run_stages(work, Scripted{Outcome::undecided(), &log, 1}), std::logic_error);
  Work<VertexFaceQuery, GmpUse> toi(kQuery, Question{{}, true}, nullptr);  // a collision whose TOI nobody finds
  EXPECT_THROW(run_stages(toi, Scripted{Outcome::collides(), &log, 1}), std::logic_error);
}

TEST(RunNestedStages, ANestedListMayLeaveTheQueryUndecided) {
  std::vector<int> log;
  StageCounters counters;
  Work<VertexFaceQuery, GmpUse> work(kQuery, Question{}, &counters);
  EXPECT_EQ(run_nested_stages(work, Scripted{Outcome::undecided(), &log, 1}).answer, Outcome::Answer::undecided);
  EXPECT_EQ(counters.total(), 0u);
  Work<VertexFaceQuery, GmpUse> hit(kQuery, Question{}, &counters);
  const Outcome o = run_nested_stages(hit, Scripted{Outcome::undecided(), &log, 2}, Scripted{Outcome::collides(kToi), &log, 3});
  ASSERT_EQ(o.answer, Outcome::Answer::collides);
  EXPECT_EQ(*o.toi, kToi);
  EXPECT_EQ(counters.interval, 1u);
  Work<VertexFaceQuery, GmpUse> apart(kQuery, Question{}, &counters);
  EXPECT_EQ(run_nested_stages(apart, Scripted{Outcome::separate(), &log, 4}).answer, Outcome::Answer::separate);
}

/// A scripted contact question for the probe: answers `touch`, counted at the interval counter
/// when it decides, with `gmp` in the findings it hands back; records the question it was asked.
struct ScriptedContact {
  Outcome touch;
  bool gmp = false;
  Question* asked = nullptr;
  Outcome operator()(const VertexFaceQuery&, const Question& question, StageCounters* counters, GmpUse& found) const {
    *asked = question;
    found.used_gmp = gmp;
    if (touch.answer != Outcome::Answer::undecided && counters) ++counters->interval;
    return touch;
  }
};

TEST(ContactProbe, ACollisionEnclosesTheEarliestTimeAndIsCountedWhereTheContactQuestionDecided) {
  StageCounters counters;
  Question asked;
  Work<VertexFaceQuery, GmpUse> work(kQuery, Question{{0.125, 0.5}, false}, &counters);
  const Outcome o = contact_probe(ScriptedContact{Outcome::collides(TimeInterval{0.25, 0.375}), false, &asked})(work);
  ASSERT_EQ(o.answer, Outcome::Answer::collides);
  EXPECT_EQ(*o.toi, (TimeInterval{0.0, 0.375}));  // touching at t0 is within d at t0: [0, hi] holds the earliest time
  EXPECT_EQ(asked.params.min_distance, 0.0);     // the contact question, over the same [0, tmax], answer alone
  EXPECT_EQ(asked.params.tmax, 0.5);
  EXPECT_FALSE(asked.want_toi);
  EXPECT_EQ(counters.interval, 1u);
  EXPECT_FALSE(work.findings.used_gmp);
}

TEST(ContactProbe, OtherwiseItCountsNothingAndHandsOverGmpUse) {
  StageCounters counters;
  Question asked;
  for (const Outcome& touch : {Outcome::separate(), Outcome::undecided()}) {
    Work<VertexFaceQuery, GmpUse> work(kQuery, Question{{0.125, 1.0}, false}, &counters);
    EXPECT_EQ(contact_probe(ScriptedContact{touch, true, &asked})(work).answer, Outcome::Answer::undecided);
    EXPECT_TRUE(work.findings.used_gmp);
    Work<VertexFaceQuery, GmpUse> without(kQuery, Question{{0.125, 1.0}, false}, &counters);
    (void)contact_probe(ScriptedContact{touch, false, &asked})(without);
    EXPECT_FALSE(without.findings.used_gmp);
  }
  EXPECT_EQ(counters.total(), 0u);
  Work<VertexFaceQuery, GmpUse> toi(kQuery, Question{{0.125, 1.0}, true}, &counters);  // the TOI asked: no probe
  asked = Question{{-1.0, -1.0}, true};
  EXPECT_EQ(contact_probe(ScriptedContact{Outcome::collides(kToi), false, &asked})(toi).answer, Outcome::Answer::undecided);
  EXPECT_EQ(asked.params.tmax, -1.0);  // not asked
}

}  // namespace
}  // namespace exactccd::pipeline
