// The interval stage of the rigid contact question (d = 0; docs/design.md, 9.4). On the
// normalized query (rigid_unit_scaling.hpp), in interval arithmetic (interval_frame.hpp):
//  1. the volume polynomial V (degree 5, V's sign on [0, 1]) in the Bernstein basis; where its
//     value at t = 0 or 1 is uncertain, its exact sign there (sign_at.hpp);
//  2. its roots in [0, 1] isolated by Descartes' rule (numeric/bernstein_isolation.hpp): cells
//     holding exactly one simple root, and exact zeros at dyadic points; a cell that cannot be
//     settled (a multiple root: a tangential contact; V identically zero: motion in one plane)
//     leaves the query to the exact path;
//  3. by section 9.3 (the candidates are V's roots), the earliest contact is the first root at
//     which the in-plane rule holds: at each root cell in time order the rule is evaluated on
//     the positions' enclosures over the cell (the terms' signs certain over the cell are their
//     signs at the root; V itself is 0 there), the cell halved by V's certain sign at its
//     midpoint while the rule is uncertain (up to 24 times);
//  4. the first root where it certainly holds is the TOI, every earlier one certainly failing;
//     it is narrowed to adjacent doubles by V's exact signs at doubles (intervals, else
//     double-double, else GMP: sign_at.hpp; numeric/root_narrowing.hpp). No root where it holds
//     (or none up to tmax): no collision. Anything uncertain: undecided.
#pragma once

#include "exactccd/rigid.hpp"
#include "exactccd/stats.hpp"
#include "pipeline/outcome.hpp"
#include "rigid/interval_frame.hpp"

namespace exactccd::rigid {

/// The walk on a normalized query for [0, tmax], with its interval frame (built on the same
/// query). Needs upward rounding (CGAL::Protect_FPU_rounding<true>) held by the caller. Without
/// want_toi and with tmax = 1, a collision's TOI is any enclosure of the earliest time. Sets
/// `used_gmp` when an exact sign needed GMP (never clears it).
pipeline::Outcome contact_walk(const RigidVertexFaceQuery& normalized_query,
                               const IntervalFrame<RigidVertexFaceQuery>& frame, double tmax, bool want_toi,
                               bool& used_gmp);
/// See contact_walk(const RigidVertexFaceQuery&, const IntervalFrame<RigidVertexFaceQuery>&, double, bool, bool&).
pipeline::Outcome contact_walk(const RigidEdgeEdgeQuery& normalized_query, const IntervalFrame<RigidEdgeEdgeQuery>& frame,
                               double tmax, bool want_toi, bool& used_gmp);

/// The walk in the rigid contact question's stage list (and the contact probe's), on the Work's
/// normalized query and the interval frame it shares with the later stages. Counted as
/// `interval`, or `integer` when GMP was used (findings.used_gmp, which it sets).
template <class Query>
struct ContactWalkStage {
  static constexpr pipeline::Counter counter = &StageCounters::interval;  ///< counted as
  SharedIntervalFrame<Query>* frame;  ///< the query's interval frame, shared with later stages
  /// The walk over [0, tmax].
  template <class Findings>
  pipeline::Outcome operator()(pipeline::Work<Query, Findings>& work) const {
    const CGAL::Protect_FPU_rounding<true> upward;  // the walk switches back where it needs
    const pipeline::Outcome o = contact_walk(work.query(), frame->of(work.query()), work.question.params.tmax,
                                             work.question.want_toi, work.findings.used_gmp);
    return pipeline::counted_with_gmp(o, work.findings);
  }
};

}  // namespace exactccd::rigid
