// The two methods of the library for linear motion as stage lists of the one protocol
// (pipeline/outcome.hpp, docs/design.md 4b.3 and 5): every question's stage order reads in one
// function here, or in contact_question.cpp for the contact question of vertex-face and
// edge-edge queries.
// Included by the entry point (api/entry_point.cpp), which instantiates them for every kind.
#pragma once

#include <cstddef>
#include <optional>
#include <type_traits>

#include "contact/separation_terms.hpp"
#include "exact/exact_ccd.hpp"
#include "exactccd/stats.hpp"
#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"
#include "pipeline/block.hpp"
#include "pipeline/contact_probe.hpp"
#include "pipeline/outcome.hpp"
#include "pipeline/run_stages.hpp"
#include "questions/contact_question.hpp"
#include "separation/exact_separation.hpp"
#include "separation/separating_direction.hpp"
#include "separation/separation_walk.hpp"

namespace exactccd::questions {

using pipeline::Counter;
using pipeline::Outcome;
using pipeline::Work;

/// The kinds whose contact question has stages of its own (kinds::HasContactStages: the volume
/// filter and the contact rule of lib/contact): vertex-face and edge-edge.
template <class Query>
inline constexpr bool has_contact_stages = kinds::HasContactStages<kinds::kind_of<Query>>::value;

/// The contact (d = 0) question of a query of a kind without contact stages as the query of
/// its ContactKind (kinds/primitive_kinds.hpp: its points, in the order of contact_points; a
/// point is a zero-length edge, a 2D query lies in the plane z = 0) with the same answer and TOI.
template <class Query>
auto as_contact_query(const Query& q) {
  using Kind = kinds::kind_of<Query>;
  using ContactKind = typename Kind::ContactKind;
  static_assert(kinds::HasContactStages<ContactKind>::value, "a kind's contact question needs contact stages");
  constexpr int P = Kind::points;
  constexpr int C = ContactKind::points;
  const auto x = contact::points3<double>(q);  // 2D points at z = 0
  std::array<Vec3, 2 * C> e;
  for (int at = 0; at < 2; ++at)
    for (int i = 0; i < C; ++i) e[at * C + i] = x[at * P + Kind::contact_points[i]];
  return from_rows<typename ContactKind::template Query<double>>(e);
}

/// The contact question of a query of any kind: its own contact stages, or those of the query of
/// its ContactKind it is (as_contact_query).
template <class Query>
std::optional<TimeInterval> contact_of_any_kind(const Query& q, const Question& question, StageCounters* counters) {
  if constexpr (has_contact_stages<Query>)
    return contact_question(q, question, counters);
  else
    return contact_question(as_contact_query(q), question, counters);
}

/// The contact question of the kinds without contact stages after their separating direction:
/// the contact stages of the query of their ContactKind they are (counted there).
struct ContactOfEmbeddingStage {
  static constexpr Counter counter = nullptr;  ///< counts for itself, at the contact stage deciding
  /// The contact stages' answer.
  template <class Query, class Findings>
  Outcome operator()(const Work<Query, Findings>& work) const {
    const auto toi = contact_question(as_contact_query(work.query()), work.question, work.counters);
    return toi ? Outcome::collides(toi) : Outcome::separate();
  }
};

/// The contact question of a query of any kind (contact_of_any_kind) for the minimum-separation
/// question's contact probe (pipeline/contact_probe.hpp): it always decides, and hands over
/// GMP use through the counters.
struct ContactOfAnyKind {
  /// The contact question's answer as an Outcome.
  template <class Query>
  Outcome operator()(const Query& q, const Question& question, StageCounters* counters, pipeline::GmpUse&) const {
    const auto toi = contact_of_any_kind(q, question, counters);
    return toi ? Outcome::collides(toi) : Outcome::separate();
  }
};

/// The minimum-separation question's stage order (any kind, d > 0). SeparationFindings
/// (separation_walk.hpp) in this list: used_gmp is written by the contact probe (GMP or CGAL in
/// the contact question it asked) and by SeparationWalkStage (an exact sign in integers, the
/// exact plane test), and read by SeparationWalkStage when it decides (counted `integer`); use
/// is written by SeparationWalkStage (the feature pairs no direction keeps apart) and read by
/// ExactSeparationStage (the exact path leaves the others out).
inline constexpr pipeline::StageList kSeparationStages{
    separation::SeparatingDirectionStage{},                  // a direction keeps them > d apart
    pipeline::ContactProbeStage<ContactOfAnyKind>{},         // answer alone: touching is within d
    separation::SeparationWalkStage{},                       // the terms over time cells, intervals
    separation::ExactSeparationStage{}};                     // CGAL's algebraic kernel: always decides

/// The contact question of the kinds without contact stages (no handover between the two).
inline constexpr pipeline::StageList kEmbeddedContactStages{separation::SeparatingDirectionStage{},
                                                            ContactOfEmbeddingStage{}};

/// A query of any kind by the filtered method (the question validated by the entry point):
/// certified floating-point stages first, the exact path last, each query counted at the stage
/// deciding it (in `counters`, may be null). The contact question's own findings are its list's
/// (contact_question.cpp).
template <class Query>
std::optional<TimeInterval> filtered_method(const Query& q, const Question& question, StageCounters* counters) {
  if (question.params.contact_only()) {
    if constexpr (has_contact_stages<Query>) {
      return contact_question(q, question, counters);
    } else {
      Work<Query, pipeline::GmpUse> work{q, question, counters};
      return kEmbeddedContactStages.run(work);
    }
  }
  Work<Query, separation::SeparationFindings> work{q, question, counters};  // the minimum-separation question
  return kSeparationStages.run(work);
}

/// filtered_method for queries[0, count) into answers[0, count): the same stage lists, run on
/// blocks of queries where a list has block stages for the kind (pipeline::run_batch).
template <class Query>
void filtered_batch(const Query* queries, std::size_t count, const Question& question, StageCounters* counters,
                    std::optional<TimeInterval>* answers) {
  const auto into = [&](std::size_t i, const std::optional<TimeInterval>& answer) { answers[i] = answer; };
  if (question.params.contact_only()) {
    if constexpr (has_contact_stages<Query>)
      return contact_question(queries, count, question, counters, answers);
    else
      return pipeline::run_batch<pipeline::GmpUse>(kEmbeddedContactStages, queries, count, question, counters, into);
  }
  pipeline::run_batch<separation::SeparationFindings>(kSeparationStages, queries, count, question, counters, into);
}

/// A query of any kind by the exact method (GMP and CGAL throughout; not counted): the contact
/// rule for vertex-face and edge-edge at d = 0 (the reference of the contact question), the
/// minimum-separation terms otherwise (at d = 0 an independent derivation).
template <class Query>
std::optional<TimeInterval> exact_method(const Query& q, const Question& question) {
  if constexpr (has_contact_stages<Query>) {
    if (question.params.contact_only()) {
      Work<Query, pipeline::GmpUse> work{q, {question.params, question.want_toi || !question.params.whole_step()}, nullptr};
      return pipeline::cut(run_stages(work, exact::ExactContactStage{}), question.params.tmax);
    }
  }
  Work<Query, separation::SeparationFindings> work{q, question, nullptr};  // use: every feature pair
  return run_stages(work, separation::ExactSeparationStage{});
}

}  // namespace exactccd::questions
