// The exact paths as the last stage of each question (they always decide): CGAL's algebraic
// kernel on the contact rule (exact/exact_ccd.cpp) and on the minimum-separation terms
// (separation/exact_separation.cpp), from the query's doubles read exactly as rationals.
#pragma once

#include "exact/exact_ccd.hpp"
#include "exact/rational_query.hpp"
#include "pipeline/outcome.hpp"
#include "separation/exact_separation.hpp"

namespace exactccd::pipeline {

/// The contact question's last stage (vertex-face and edge-edge, d = 0, over [0, 1]).
struct ExactContactStage {
  static constexpr Counter counter = &StageCounters::exact;  ///< counted as
  /// The exact answer, with the TOI when asked.
  template <class Query>
  Outcome operator()(const Work<Query>& work) const {
    const auto rational = exact::to_rational(work.query());
    if (!work.question.want_toi) return exact::ccd(rational) ? Outcome::collides() : Outcome::separate();
    const auto toi = exact::toi(rational);
    return toi ? Outcome::collides(toi) : Outcome::separate();
  }
};

/// The minimum-separation question's last stage (any kind, any d and tmax), without the feature
/// pairs the earlier stages proved apart (findings.use).
struct ExactSeparationStage {
  static constexpr Counter counter = &StageCounters::exact;  ///< counted as
  /// The exact answer and TOI.
  template <class Query>
  Outcome operator()(const Work<Query>& work) const {
    const CcdParams& p = work.question.params;
    const auto toi = separation::exact_toi(exact::to_rational(work.query()),
                                           RationalCcdParams{mpq_class(p.min_distance), mpq_class(p.tmax)}, work.findings.use);
    return toi ? Outcome::collides(toi) : Outcome::separate();
  }
};

}  // namespace exactccd::pipeline
