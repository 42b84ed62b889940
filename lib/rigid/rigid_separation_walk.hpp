// The interval stage of the rigid minimum-separation question (d > 0; docs/design.md, 9.4):
// the walk of rigid_separation_walk.cpp and its stage.
#pragma once

#include "exactccd/rigid.hpp"
#include "exactccd/stats.hpp"
#include "pipeline/outcome.hpp"
#include "rigid/direction_stage.hpp"
#include "rigid/interval_frame.hpp"

namespace exactccd::rigid {

/// The walk on a normalized query with the scaled d > 0, over [0, tmax], with the query's
/// direction and interval frames. Needs upward rounding held by the caller. Sets `used_gmp` when
/// an exact sign needed GMP (never clears it).
pipeline::Outcome rigid_separation_walk(const RigidVertexFaceQuery& normalized_query,
                                  const DirectionFrame<RigidVertexFaceQuery>& directions,
                                  const IntervalFrame<RigidVertexFaceQuery>& frame, double d, double tmax, bool want_toi,
                                  bool& used_gmp);
/// See rigid_separation_walk(const RigidVertexFaceQuery&, ...).
pipeline::Outcome rigid_separation_walk(const RigidEdgeEdgeQuery& normalized_query,
                                  const DirectionFrame<RigidEdgeEdgeQuery>& directions,
                                  const IntervalFrame<RigidEdgeEdgeQuery>& frame, double d, double tmax, bool want_toi,
                                  bool& used_gmp);

/// The walk in the rigid minimum-separation question's stage list, on the Work's normalized query
/// and scaled d, with the interval frame shared with the contact probe before it. Counted as
/// `interval`, or `integer` when GMP was used (findings.used_gmp: by it, or by the contact probe).
template <class Query>
struct RigidSeparationWalkStage {
  static constexpr pipeline::Counter counter = &StageCounters::interval;  ///< counted as
  SharedIntervalFrame<Query>* frame;  ///< the query's interval frame, shared with earlier stages
  /// The walk over [0, tmax].
  template <class Findings>
  pipeline::Outcome operator()(pipeline::Work<Query, Findings>& work) const {
    const Query& q = work.query();
    const DirectionFrame<Query> directions(q);  // in round-to-nearest (the pairs kept apart are left out)
    const CGAL::Protect_FPU_rounding<true> upward;  // the walk switches back where it needs
    const pipeline::Outcome o = rigid_separation_walk(q, directions, frame->of(q), work.question.params.min_distance,
                                                work.question.params.tmax, work.question.want_toi, work.findings.used_gmp);
    return pipeline::counted_with_gmp(o, work.findings);
  }
};

}  // namespace exactccd::rigid
