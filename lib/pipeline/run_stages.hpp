// The whole policy of the filtered method (docs/design.md, 5.0), as CGAL's Filtered_predicate:
// try the stages in order, cheapest first, until one decides; the last one always does.
//
// A stage is a type with
//   static constexpr Counter counter;                  // where a query it decides is counted
//   template <class Query, class Findings> Outcome operator()(Work<Query, Findings>&) const;
// and may have a block form too (block.hpp: the same stage on blocks of lanes).
// Counting: each query is counted once, at the stage that decides its answer (or at the
// counter its Outcome names); a stage whose counter is nullptr counts for itself (a nested
// stage list). When the answer is a collision but the TOI is asked and not yet certified, the
// query is also counted as toi_refined and the later stages run only to narrow the TOI
// (Work::collides tells them).
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "pipeline/outcome.hpp"

namespace exactccd::pipeline {

/// The answer returned for a collision when the TOI was not asked (only its presence matters).
inline constexpr TimeInterval kCollisionWithoutToi{0.0, 0.0};

/// Adds one to counters->*counter (either may be null: nothing counted).
inline void count(StageCounters* counters, Counter counter) {
  if (counters && counter) ++(counters->*counter);
}

/// The result of a stage list so far.
class StageRun {
 public:
  /// Takes a stage's outcome for a query whose state is (question, counters, collides: an
  /// earlier stage proved a collision; set here when this outcome does and the TOI is still
  /// to be narrowed); true when the question is now answered (result() holds it).
  bool take(const Outcome& outcome, Counter own_counter, const Question& question, StageCounters* counters,
            bool& collides) {
    if (outcome.answer == Outcome::Answer::undecided) return false;
    if (!collides) count(counters, outcome.counted_as ? outcome.counted_as : own_counter);
    if (outcome.answer == Outcome::Answer::separate) return finish(std::nullopt);
    if (outcome.toi || !question.want_toi) return finish(outcome.toi ? *outcome.toi : kCollisionWithoutToi);
    if (!collides) count(counters, &StageCounters::toi_refined);
    collides = true;  // the later stages narrow the TOI
    return false;
  }

  /// take() for a query on its way through the stages.
  template <class Query, class Findings>
  bool take(const Outcome& outcome, Counter own_counter, Work<Query, Findings>& work) {
    return take(outcome, own_counter, work.question, work.counters, work.collides);
  }

  /// True when a stage answered the question.
  bool done() const { return done_; }

  /// The answer: the TOI (or kCollisionWithoutToi), nullopt for no collision.
  std::optional<TimeInterval> result() const {
    if (!done_) throw std::logic_error("exactccd: no stage decided the query");  // the last stage always decides
    return result_;
  }

 private:
  bool finish(std::optional<TimeInterval> result) {
    result_ = result;
    done_ = true;
    return true;
  }

  std::optional<TimeInterval> result_;
  bool done_ = false;
};

/// A question's stages, in order: the one description its per-query path (run) and its block
/// path (block.hpp, run_block) both follow.
template <class... Stage>
class StageList {
 public:
  /// The number of stages.
  static constexpr std::size_t size = sizeof...(Stage);
  /// The type of stage I.
  template <std::size_t I>
  using StageAt = std::tuple_element_t<I, std::tuple<Stage...>>;

  /// The list of these stages.
  constexpr explicit StageList(Stage... stage) : stages_(std::move(stage)...) {}

  /// Stage I.
  template <std::size_t I>
  const StageAt<I>& at() const {
    return std::get<I>(stages_);
  }

  /// Runs stages First, First + 1, ... on `work` until one answers its question (counted in
  /// work.counters); `run` starts at the first, a block's lanes resume where their block
  /// stages stopped (block.hpp), never again at a stage they passed.
  template <std::size_t First = 0, class Query, class Findings>
  void take_from(StageRun& run, Work<Query, Findings>& work) const {
    if constexpr (First < size) {
      if (!run.take(at<First>()(work), StageAt<First>::counter, work)) take_from<First + 1>(run, work);
    }
  }

  /// The answer of the stages from First on: the TOI when asked (else kCollisionWithoutToi) for
  /// a collision, nullopt for none; the last stage must decide.
  template <std::size_t First = 0, class Query, class Findings>
  std::optional<TimeInterval> run(Work<Query, Findings>& work) const {
    StageRun run;
    take_from<First>(run, work);
    return run.result();
  }

  /// The answer of a nested list (one whose last stage may leave the query undecided: the
  /// contact probe's, contact_probe.hpp) as an Outcome: collides with the TOI (or
  /// kCollisionWithoutToi), separate, or undecided when no stage answered.
  template <class Query, class Findings>
  Outcome run_nested(Work<Query, Findings>& work) const {
    StageRun run;
    take_from<0>(run, work);
    if (!run.done()) return Outcome::undecided();
    const std::optional<TimeInterval> answer = run.result();
    return answer ? Outcome::collides(answer) : Outcome::separate();
  }

 private:
  std::tuple<Stage...> stages_;
};

/// Runs the stages on `work` in order until one answers its question (StageList::run).
template <class Query, class Findings, class... Stage>
std::optional<TimeInterval> run_stages(Work<Query, Findings>& work, const Stage&... stage) {
  return StageList<Stage...>(stage...).run(work);
}

/// Runs the stages of a nested list (StageList::run_nested).
template <class Query, class Findings, class... Stage>
Outcome run_nested_stages(Work<Query, Findings>& work, const Stage&... stage) {
  return StageList<Stage...>(stage...).run_nested(work);
}

}  // namespace exactccd::pipeline
