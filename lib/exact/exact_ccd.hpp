// The exact path of the contact question: GMP rationals for the polynomials of the contact
// rule, CGAL's Algebraic_kernel_d_1 for their real roots in [0, 1] and for exact signs at those
// roots (exact_ccd.cpp), and the stage that runs it last in the contact question's stage list.
// Never wrong, never gives up; slow (tens of microseconds per query). The filters of later
// stages defer to it whenever a sign is uncertain.
#pragma once

#include <optional>

#include "exact/rational_query.hpp"
#include "exactccd/rational.hpp"
#include "exactccd/types.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::exact {

/// Exact vertex-face CCD: true iff p(t) is in the closed triangle for some t in [0, 1].
bool ccd(const RationalVertexFaceQuery& q);

/// Exact edge-edge CCD: true iff the closed segments meet for some t in [0, 1].
bool ccd(const RationalEdgeEdgeQuery& q);

/// Earliest contact time of a vertex-face query, enclosed in the tightest double interval.
std::optional<TimeInterval> toi(const RationalVertexFaceQuery& q);

/// Earliest contact time of an edge-edge query, enclosed in the tightest double interval.
std::optional<TimeInterval> toi(const RationalEdgeEdgeQuery& q);

/// The exact path as the contact question's last stage (vertex-face and edge-edge, d = 0, over
/// [0, 1]): always decides.
struct ExactContactStage {
  static constexpr pipeline::Counter counter = &StageCounters::exact;  ///< counted as
  /// The exact answer, with the TOI when asked.
  template <class Query, class Findings>
  pipeline::Outcome operator()(const pipeline::Work<Query, Findings>& work) const {
    const auto rational = to_rational(work.query());
    if (!work.question.want_toi) return ccd(rational) ? pipeline::Outcome::collides() : pipeline::Outcome::separate();
    const auto t = toi(rational);
    return t ? pipeline::Outcome::collides(t) : pipeline::Outcome::separate();
  }
};

}  // namespace exactccd::exact
