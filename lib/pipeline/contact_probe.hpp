// The contact probe: a stage of the minimum-separation question (d > 0) that asks the contact
// question (d = 0) first, for the answer alone. Touching within [0, tmax] is being within d,
// and the contact stages decide most touching pairs far more cheaply than the separation walk.
// One stage for both motion models: each gives its contact question (questions/methods.hpp for
// linear motion, questions/rigid_methods.cpp for rigid motion).
#pragma once

#include <utility>

#include "exactccd/stats.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::pipeline {

/// The probe over `contact`, a callable `Outcome contact(const Query&, const Question&,
/// StageCounters*, GmpUse&)` answering the contact question of the query (counted in the
/// counters it is given; whether it used GMP or CGAL in the GmpUse; undecided allowed).
/// A collision is counted at the contact stage that found it (its TOI t0 bounds the earliest
/// time within d from above: [0, hi] encloses it); otherwise nothing is counted, and GMP or CGAL
/// use is handed over (findings.used_gmp: the deciding stage then counts as `integer`; the
/// linear fixed-width integer stage allocates nothing and does not count).
template <class Contact>
struct ContactProbeStage {
  static constexpr Counter counter = nullptr;  ///< counts for itself (above)
  Contact contact;                             ///< the motion model's contact question
  /// The probe, for the answer alone (undecided when the TOI is asked).
  template <class Query, class Findings>
  Outcome operator()(Work<Query, Findings>& work) const {
    if (work.question.want_toi) return Outcome::undecided();
    StageCounters probe;
    GmpUse found;
    const Outcome touch = contact(work.query(), Question{{0.0, work.question.params.tmax}, false}, &probe, found);
    if (touch.answer == Outcome::Answer::collides) {
      if (work.counters) *work.counters += probe;
      return Outcome::collides(TimeInterval{0.0, touch.toi->hi});
    }
    work.findings.used_gmp = work.findings.used_gmp || found.used_gmp || probe.integer + probe.exact > 0;
    return Outcome::undecided();
  }
};

/// The probe over the contact question `contact` (ContactProbeStage).
template <class Contact>
ContactProbeStage<Contact> contact_probe(Contact contact) {
  return {std::move(contact)};
}

}  // namespace exactccd::pipeline
