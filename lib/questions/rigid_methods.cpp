// The filtered and exact methods for rigid queries as stage lists of the one protocol
// (pipeline/outcome.hpp, run_stages.hpp; docs/design.md 9.4), in the shape of the linear lists
// (methods.hpp): the contact question (d = 0) and the minimum-separation question (d > 0), each
// in one function below. Each stage sits next to the algorithm it runs:
//   rigid::RigidUnitScalingStage     the query and d scaled exactly by powers of two into the
//                                    Work's replacement (rigid_unit_scaling.hpp); where a scaling
//                                    is inexact, the exact path answers at once (`exact`)
//   rigid::DirectionStage            a certified separating direction over the step
//                                    (direction_stage.hpp, `separating_direction`)
//   rigid::ContactWalkStage          V's roots and the in-plane rule in intervals (contact_walk.hpp)
//   rigid::CoplanarWalkStage         edge-edge motion in one plane: the plane's candidates
//                                    (coplanar_walk.hpp)
//   pipeline::ContactProbeStage      d > 0, the answer alone: the two contact walks first
//                                    (touching in [0, tmax] is being within d; contact_probe.hpp)
//   rigid::RigidSeparationWalkStage  the feature-pair terms over time cells (rigid_separation_walk.hpp)
//   rigid::ExactRigidStage           the exact path (exact_rigid.hpp, `exact`): always decides
// The walks are counted `interval`, or `integer` when GMP was used on the way.
//
// Findings in these lists: pipeline::GmpUse alone; used_gmp is written by the contact walk, the
// coplanar walk, the separation walk (an exact sign in GMP) and the contact probe (its nested
// list's), and read by each walk when it decides (counted `integer`: pipeline::counted_with_gmp).
// No other field is used: the separation walk leaves out the feature pairs a direction keeps
// apart itself, and the exact path takes every pair. Besides the Work, the walks share the
// query's interval frame (rigid::SharedIntervalFrame: built by the first of them that runs, on
// the normalized query).
#include "questions/rigid_methods.hpp"

#include "pipeline/contact_probe.hpp"
#include "pipeline/run_stages.hpp"
#include "rigid/contact_walk.hpp"
#include "rigid/coplanar_walk.hpp"
#include "rigid/direction_stage.hpp"
#include "rigid/exact_rigid.hpp"
#include "rigid/interval_frame.hpp"
#include "rigid/rigid_separation_walk.hpp"
#include "rigid/rigid_unit_scaling.hpp"

namespace exactccd::questions {
namespace {

using pipeline::Outcome;
using pipeline::Question;
using pipeline::Work;

/// The rigid contact question of the contact probe, on the normalized query: the two contact
/// walks alone, a nested list that may leave the query undecided (the separation walk and the
/// exact path answer it then), sharing the query's interval frame with the stages after it.
template <class Query>
struct ContactWalks {
  rigid::SharedIntervalFrame<Query>* frame;  ///< the query's interval frame
  /// The walks' answer, with what they learned in `found`.
  Outcome operator()(const Query& q, const Question& question, StageCounters* counters, pipeline::GmpUse& found) const {
    Work<Query, pipeline::GmpUse> work{q, question, counters};
    const Outcome o = pipeline::run_nested_stages(work, rigid::ContactWalkStage<Query>{frame}, rigid::CoplanarWalkStage{});
    found = work.findings;
    return o;
  }
};

template <class Query>
std::optional<TimeInterval> filtered(const Query& q, const Question& question, StageCounters* counters) {
  Work<Query, pipeline::GmpUse> work{q, question, counters};
  rigid::SharedIntervalFrame<Query> frame;
  if (question.params.contact_only())
    return run_stages(work,
                      rigid::RigidUnitScalingStage{},          // lengths and quaternions scaled towards 1
                      rigid::DirectionStage{},                 // a direction keeps them apart over the step
                      rigid::ContactWalkStage<Query>{&frame},  // V's roots and the in-plane rule in intervals
                      rigid::CoplanarWalkStage{},              // edges moving in one plane: the plane's candidates
                      rigid::ExactRigidStage{});               // CGAL's algebraic kernel: always decides
  return run_stages(work,  // the minimum-separation question
                    rigid::RigidUnitScalingStage{},                        // lengths, d and quaternions scaled
                    rigid::DirectionStage{},                               // a direction keeps them > d apart
                    pipeline::contact_probe(ContactWalks<Query>{&frame}),  // answer alone: touching is within d
                    rigid::RigidSeparationWalkStage<Query>{&frame},        // the terms over time cells, intervals
                    rigid::ExactRigidStage{});                             // CGAL's algebraic kernel: always decides
}

template <class Query>
std::optional<TimeInterval> exact(const Query& q, const Question& question) {
  Work<Query, pipeline::GmpUse> work{q, question, nullptr};
  return run_stages(work, rigid::ExactRigidStage{});
}

}  // namespace

std::optional<TimeInterval> filtered_method(const RigidVertexFaceQuery& q, const Question& question,
                                            StageCounters* counters) {
  return filtered(q, question, counters);
}
std::optional<TimeInterval> filtered_method(const RigidEdgeEdgeQuery& q, const Question& question,
                                            StageCounters* counters) {
  return filtered(q, question, counters);
}
std::optional<TimeInterval> exact_method(const RigidVertexFaceQuery& q, const Question& question) {
  return exact(q, question);
}
std::optional<TimeInterval> exact_method(const RigidEdgeEdgeQuery& q, const Question& question) {
  return exact(q, question);
}

}  // namespace exactccd::questions
