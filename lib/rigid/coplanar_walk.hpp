// The rigid edge-edge contact question (d = 0) when the motion stays in planes orthogonal to a
// coordinate axis of B's frame (docs/design.md, 9.4, step 3a): the contact walk's volume then
// vanishes identically and its roots say nothing, so the candidates are those of the plane.
//
// Certificate. On the scaled frame in intervals (rigid_frame.hpp: D(t) times the positions in
// B's frame), the k-th coordinate polynomials of the four points differ by polynomials whose
// interval coefficients are all exactly [0, 0]: each interval holds the exact coefficient, so
// the exact differences vanish identically, and dividing by D(t) > 0, the four true positions
// have the same k-th coordinate at every t: they lie in one plane orthogonal to e_k (which may
// move along e_k). The projection along e_k is injective on that plane, so the closed edges meet
// at t iff their projections meet, and the contact rule (its in-plane part, V being 0) says so.
//
// Candidates. Let o_i(t) be the k-th component of the rule's cross (rel(u, p) x rel(u, v)) of
// endpoint p against the other edge [u, v] (contact_polynomials.hpp, endpoint_on_edge(i)): with
// both vectors in the plane it is the 2D orientation of (u, v, p) times D(t)^2 > 0. Claim: the
// earliest contact t* in [0, 1] is 0 or a root of some o_i. Proof: let t* > 0 and suppose every
// o_i(t*) != 0. The edges meet at t*; were B's endpoints strictly on one side of A's line (o of
// b0 and b1 of one sign) they could not, so o(b0), o(b1) have opposite signs, and likewise
// o(a0), o(a1). The o_i are continuous, so these strict signs hold on a neighbourhood of t*,
// where two segments whose endpoints are strictly on opposite sides of each other's lines cross:
// contact before t*, a contradiction.
//
// The walk: every o_i's roots in [0, 1] are isolated (numeric/bernstein_isolation.hpp, degree 10; a
// successful isolation also shows o_i is not identically zero, so its roots are finitely many and
// all listed); the rule is evaluated at t = 0 and at each root cell with signs certified over the
// cell, the defining o_i counted as zero (contact/interval_oracle.hpp's IntervalSignOracle: the
// other signs certain over the cell are their signs at the root), the cell halved by o_i's certain
// sign at its midpoint while the rule is uncertain. Then, over [0, tmax]: every candidate certainly
// not in contact is no collision (the claim); without want_toi, a candidate certainly in contact
// whose cell lies in [0, tmax] is a collision (any enclosure of the earliest time is asked for: [0,
// that cell's hi]). Otherwise each candidate not certainly out of contact is narrowed to the
// tightest double cell around its root by its orientation's exact signs at doubles (sign_at.hpp:
// double-double, else GMP rationals; numeric/root_narrowing.hpp); the candidate certainly in
// contact that starts first is the earliest contact when every other such candidate starts at or
// after its end (its root is then no earlier): its cell is the TOI, a collision iff within tmax.
// Anything else: undecided (the exact path).
#pragma once

#include <type_traits>

#include "exactccd/rigid.hpp"
#include "exactccd/stats.hpp"
#include "numeric/interval.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::rigid {

/// The walk on a normalized edge-edge query for [0, tmax] (file comment); undecided unless the
/// plane certificate holds. Needs upward rounding (CGAL::Protect_FPU_rounding<true>) held by the
/// caller. Sets `used_gmp` when an exact sign needed GMP (never clears it).
pipeline::Outcome coplanar_walk(const RigidEdgeEdgeQuery& normalized_query, double tmax, bool want_toi, bool& used_gmp);

/// The walk in the rigid contact question's stage list (and the contact probe's), after the
/// contact walk: edge-edge queries only (vertex-face: undecided). Counted as `interval`, or
/// `integer` when GMP was used (findings.used_gmp, by it or the contact walk).
struct CoplanarWalkStage {
  static constexpr pipeline::Counter counter = &StageCounters::interval;  ///< counted as
  /// The walk over [0, tmax] on the Work's normalized query.
  template <class Query, class Findings>
  pipeline::Outcome operator()(pipeline::Work<Query, Findings>& work) const {
    if constexpr (std::is_same_v<Query, RigidEdgeEdgeQuery>) {
      const CGAL::Protect_FPU_rounding<true> upward;  // the walk switches back where it needs
      const pipeline::Outcome o =
          coplanar_walk(work.query(), work.question.params.tmax, work.question.want_toi, work.findings.used_gmp);
      return pipeline::counted_with_gmp(o, work.findings);
    } else {
      return pipeline::Outcome::undecided();  // the walk is for two edges moving in one plane
    }
  }
};

}  // namespace exactccd::rigid
