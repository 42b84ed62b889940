// The exact minimum-separation path: GMP rationals for the terms of contact/separation_terms.hpp,
// CGAL's Algebraic_kernel_d_1 for their roots and for exact signs at those roots
// (exact_separation.cpp), and the stage that runs it last in the minimum-separation question's
// stage list.
#pragma once

#include <optional>

#include "exact/rational_query.hpp"
#include "exactccd/rational.hpp"
#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::separation {

/// The earliest t in [0, tmax] with dist(A(t), B(t)) <= d, exactly (d = params.min_distance,
/// tmax = params.tmax, validated by the caller), in the tightest double interval, or nullopt;
/// for a rational query of any kind (instantiated for every kind of the minimum-separation
/// question). Also for d = 0 (an independent computation of the contact answer: the tests
/// compare it with exact::toi). With `use`, only the feature pairs f with use[f]: the same
/// answer whenever every pair left out holds nowhere in [0, tmax] (S of docs/design.md 4b.2 is
/// the same set; the filtered method leaves out the pairs a separating direction keeps apart,
/// feature_separated).
template <class RationalQuery>
std::optional<TimeInterval> exact_toi(const RationalQuery& q, const RationalCcdParams& params,
                                      const kinds::FeatureMask& use = kinds::kAllFeatures);

/// The exact path as the minimum-separation question's last stage (any kind, any d and tmax):
/// always decides. Without the feature pairs the earlier stages proved apart (findings.use of
/// SeparationFindings, from separation_walk.hpp's stage).
struct ExactSeparationStage {
  static constexpr pipeline::Counter counter = &StageCounters::exact;  ///< counted as
  /// The exact answer and TOI.
  template <class Query, class Findings>
  pipeline::Outcome operator()(const pipeline::Work<Query, Findings>& work) const {
    const CcdParams& p = work.question.params;
    const auto toi = exact_toi(exact::to_rational(work.query()),
                               RationalCcdParams{mpq_class(p.min_distance), mpq_class(p.tmax)}, work.findings.use);
    return toi ? pipeline::Outcome::collides(toi) : pipeline::Outcome::separate();
  }
};

}  // namespace exactccd::separation
