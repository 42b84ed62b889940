// The whole policy of the filtered method (docs/design.md, 5.0), as CGAL's Filtered_predicate:
// try the stages in order, cheapest first, until one decides; the last one always does.
//
// A stage is a type with
//   static constexpr Counter counter;                  // where a query it decides is counted
//   template <class Query> Outcome operator()(Work<Query>&) const;
// Counting: each query is counted once, at the stage that decides its answer (or at the
// counter its Outcome names); a stage whose counter is nullptr counts for itself (a nested
// stage list). When the answer is a collision but the TOI is asked and not yet certified, the
// query is also counted as toi_refined and the later stages run only to narrow the TOI
// (Work::collides tells them).
#pragma once

#include <optional>
#include <stdexcept>

#include "pipeline/outcome.hpp"

namespace exactccd::pipeline {

/// The answer returned for a collision when the TOI was not asked (only its presence matters).
inline constexpr TimeInterval kCollisionWithoutToi{0.0, 0.0};

/// The result of a stage list so far.
class StageRun {
 public:
  /// Takes a stage's outcome; true when the question is now answered (result() holds it).
  template <class Query>
  bool take(const Outcome& outcome, Counter own_counter, Work<Query>& work) {
    if (outcome.answer == Outcome::Answer::undecided) return false;
    if (!work.collides) count(work.counters, outcome.counted_as ? outcome.counted_as : own_counter);
    if (outcome.answer == Outcome::Answer::separate) return finish(std::nullopt);
    if (outcome.toi || !work.question.want_toi) return finish(outcome.toi ? *outcome.toi : kCollisionWithoutToi);
    if (!work.collides) count(work.counters, &StageCounters::toi_refined);
    work.collides = true;  // the later stages narrow the TOI
    return false;
  }

  /// True when a stage answered the question.
  bool done() const { return done_; }

  /// The answer: the TOI (or kCollisionWithoutToi), nullopt for no collision.
  std::optional<TimeInterval> result() const {
    if (!done_) throw std::logic_error("exactccd: no stage decided the query");  // the last stage always decides
    return result_;
  }

 private:
  static void count(StageCounters* counters, Counter counter) {
    if (counters && counter) ++(counters->*counter);
  }
  bool finish(std::optional<TimeInterval> result) {
    result_ = result;
    done_ = true;
    return true;
  }

  std::optional<TimeInterval> result_;
  bool done_ = false;
};

/// Runs the stages on `work` in order until one answers its question (counted in
/// work.counters), and returns the answer: the TOI when asked (else kCollisionWithoutToi) for a
/// collision, nullopt for none.
template <class Query, class... Stage>
std::optional<TimeInterval> run_stages(Work<Query>& work, const Stage&... stage) {
  StageRun run;
  (run.take(stage(work), Stage::counter, work) || ...);
  return run.result();
}

/// Runs the stages of a nested list (one whose last stage may leave the query undecided: the
/// contact probe's, contact_probe.hpp) as run_stages, and returns the answer as an Outcome:
/// collides with the TOI (or kCollisionWithoutToi), separate, or undecided when no stage answered.
template <class Query, class... Stage>
Outcome run_nested_stages(Work<Query>& work, const Stage&... stage) {
  StageRun run;
  (run.take(stage(work), Stage::counter, work) || ...);
  if (!run.done()) return Outcome::undecided();
  const std::optional<TimeInterval> answer = run.result();
  return answer ? Outcome::collides(answer) : Outcome::separate();
}

}  // namespace exactccd::pipeline
