// The exact path of the rigid motion model (docs/design.md, 9.3): GMP integers for the rule's
// polynomials in B's frame (rigid_frame.hpp), divided by the positive factors |qA|^2, |qB|^2
// wherever they divide, CGAL's Algebraic_kernel_d_1 for their roots in [0, tmax] and the exact
// signs there, the tightest double enclosure of the earliest time, and the stage that runs it
// last in both rigid questions' stage lists (questions/rigid_methods.cpp). Never wrong, never
// gives up; slow (milliseconds). The filtered stages defer to it when a sign is uncertain.
#pragma once

#include <optional>

#include "exact/rational_query.hpp"
#include "exactccd/rational.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/stats.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::rigid {

using RationalRigidVertexFaceQuery = RigidVertexFaceQueryT<mpq_class>;  ///< rigid vertex-face in rationals
using RationalRigidEdgeEdgeQuery = RigidEdgeEdgeQueryT<mpq_class>;      ///< rigid edge-edge in rationals

/// The earliest t in [0, params.tmax] with distance <= params.min_distance, exactly, in the
/// tightest double interval, or nullopt: by the contact rule (docs/design.md, 2) when d = 0, by
/// the feature-pair terms (4b.1) when d > 0. The query must be valid (its quaternion paths do
/// not vanish in [0, 1]; checked by the caller), d >= 0, tmax in (0, 1].
std::optional<TimeInterval> exact_toi(const RationalRigidVertexFaceQuery& q, const RationalCcdParams& params);
/// See exact_toi(const RationalRigidVertexFaceQuery&, const RationalCcdParams&).
std::optional<TimeInterval> exact_toi(const RationalRigidEdgeEdgeQuery& q, const RationalCcdParams& params);

/// The same question answered by the feature-pair terms for every d, d = 0 included (an
/// independent computation of the contact answer: the tests compare the two).
std::optional<TimeInterval> exact_separation_toi(const RationalRigidVertexFaceQuery& q, const RationalCcdParams& params);
/// See exact_separation_toi(const RationalRigidVertexFaceQuery&, const RationalCcdParams&).
std::optional<TimeInterval> exact_separation_toi(const RationalRigidEdgeEdgeQuery& q, const RationalCcdParams& params);

/// The degrees of the polynomials the exact path isolates and evaluates, after the division by
/// |qA|^2 and |qB|^2 (docs/design.md, 9.2): the volume, then the largest in-plane polynomial's,
/// then the largest feature-pair term's (f or g) for the given d. -1 for a zero polynomial.
struct ReducedDegrees {
  int volume = -1;    ///< V (vertex-face and edge-edge: 5 for generic motions)
  int in_plane = -1;  ///< the largest of the in-plane rule's polynomials
  int term = -1;      ///< the largest of the feature-pair terms' polynomials
};
/// See ReducedDegrees.
ReducedDegrees reduced_degrees(const RationalRigidVertexFaceQuery& q, const mpq_class& d);
/// See ReducedDegrees.
ReducedDegrees reduced_degrees(const RationalRigidEdgeEdgeQuery& q, const mpq_class& d);

/// The exact path's answer to the Work's question (on its query, normalized or not: the same
/// answer) as an Outcome.
template <class Query, class Findings>
pipeline::Outcome exact_outcome(const pipeline::Work<Query, Findings>& work) {
  const CcdParams& p = work.question.params;
  const auto t = exact_toi(exact::to_rational(work.query()), RationalCcdParams{p.min_distance, p.tmax});
  return t ? pipeline::Outcome::collides(t) : pipeline::Outcome::separate();
}

/// The exact path as the last stage of both rigid questions: always decides.
struct ExactRigidStage {
  static constexpr pipeline::Counter counter = &StageCounters::exact;  ///< counted as
  /// The exact answer, with the TOI.
  template <class Query, class Findings>
  pipeline::Outcome operator()(const pipeline::Work<Query, Findings>& work) const {
    return exact_outcome(work);
  }
};

}  // namespace exactccd::rigid
