// Stage 2: the contact rule in interval arithmetic (docs/design.md, "Interval stage").
//
// Soundness rests on the inclusion property of interval arithmetic: every interval computed
// here contains the exact real value of the quantity it stands for. CGAL::Interval_nt<false>
// needs the FPU rounding towards +infinity, which Protect_FPU_rounding sets for this stage and
// restores on every exit (also by exception).
//
// 1. V's monomial coefficients -> Bernstein coefficients on [0, 1]; de Casteljau halving
//    (divisions by 2 are exact) gives the Bernstein coefficients on dyadic sub-intervals.
//    A cell whose coefficients all have one certain strict sign holds no root. A cell whose
//    coefficients have certain strict signs with exactly one sign change holds exactly one
//    root, and it is simple (Descartes' rule of signs in the Bernstein basis: the number of
//    roots in the open cell, with multiplicity, is the number of sign changes minus an even
//    number). Anything else is halved, up to a depth limit; then the stage gives up. An
//    interval that is exactly [0, 0] encloses only 0: the value is certainly zero. Such
//    exact zeros at t = 0, t = 1 or a cell's midpoint are roots known exactly (common with
//    small-integer or dyadic input, where interval arithmetic happens to be exact); zero
//    coefficients are skipped when counting sign changes.
// 2. Cells come out in increasing t. Over a root cell T every other term of the rule is
//    enclosed over T, first from the points' relative positions over T (interval/values.hpp),
//    then from its polynomial by interval Horner: an interval that excludes 0 gives the term's
//    sign at the root, an exact [0, 0] means the term vanishes identically, anything else is
//    uncertain. Uncertain: shrink T by certified bisection of V and retry.
// 3. The earliest root where the rule holds is the TOI (the candidate argument of
//    exact_ccd.cpp). It is narrowed by certified bisection to two consecutive doubles.
// 4. Coplanar for all t (V's coefficients exactly [0, 0]): the candidates are 0, 1 and the
//    roots of the in-plane polynomials the rule can consult (pruned as in the integer stage),
//    isolated the same way (Bernstein of degree 2 or 4). At a candidate root of q, q's sign is
//    0 and every other sign comes from the cell as above (narrowed by bisection of q). The
//    answer is certain when every candidate is decided; the TOI only when the earliest
//    contact is an exact point and no undecided or contacting cell starts before it; when it is
//    a root cell, that cell is handed over (findings.rule_toi_cell) to be narrowed exactly.
// 5. V not identically zero but uncertain in item 2: if the in-plane rule is certainly false over
//    all of [0, 1], no collision (whatever V's roots). Else, with a visible factorisation: when three
//    of the four points share one coordinate for all t (two components of a point-on-segment
//    cross product are exactly zero), V is a linear factor times the third component C_k, and
//    the candidates are the roots of the two factors (factored_strategy). At a root of C_k the
//    rule's segment test has a sign known to be zero, which decides contacts exactly on an
//    edge's line; a contact found there has a certified TOI (narrowed on its factor), or its
//    root cell is handed over (findings.rule_toi_cell) to be narrowed exactly.
// 6. Edge-edge, V uncertain and not factored as in 5: when the edge directions da, db agree
//    exactly in two coordinates up to one sign s (db_j = s da_j as exact polynomials: parallel
//    grid lines of a folding sheet moving alike), w = Delta (da x e_k) and V = -Delta F with
//    Delta = db_k - s da_k linear and F = r . (da x e_k) quadratic (parallel_factor_strategy).
//    The candidates are the roots of Delta and of F; at a root of Delta the edges are parallel
//    (w = 0, known exactly), which decides the common roots of V and w that item 2 cannot.
#include "filter/interval_stage.hpp"

#include "filter/interval/coplanar_roots.hpp"
#include "filter/interval/factored_roots.hpp"
#include "filter/interval/moving_roots.hpp"
#include "filter/static_stage.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd::filter {
namespace {

using interval::Interval;
using pipeline::Outcome;

template <class IntervalQuery, class Query>
IntervalQuery to_interval_query(const Query& q) {
  std::array<Vec3T<Interval>, 8> r;
  const auto d = rows(q);
  for (std::size_t i = 0; i < d.size(); ++i)
    r[i] = {Interval(d[i].x), Interval(d[i].y), Interval(d[i].z)};
  return from_rows<IntervalQuery>(r);
}

/// Exact facts at t = 0 and t = 1 of a double query, for moving_strategy. CGAL's static filters
/// assume round-to-nearest: it is set for each call (this stage otherwise rounds upwards).
template <class Query>
struct ExactEnds {
  const Query& q;
  int volume_sign(int end) const {
    CGAL::Protect_FPU_rounding<true> to_nearest(CGAL_FE_TONEAREST);
    return volume_sign_at_end(q, end);
  }
  bool contact(int end) const {
    CGAL::Protect_FPU_rounding<true> to_nearest(CGAL_FE_TONEAREST);
    return contact_at_end(q, end);
  }
};

/// The stage on one query: the strategies of the file comment, in order.
template <class IntervalQuery, class Query>
Outcome run_interval_stage(const IntervalQuery& q, const Query& double_query, bool want_toi,
                           RootCells& findings) {
  const auto P = contact::polynomials(q);
  if (interval::exactly_zero(P.volume())) return interval::coplanar_strategy(P, want_toi, findings.rule_toi_cell);
  const Outcome moving = interval::moving_strategy(P, ExactEnds<Query>{double_query}, want_toi, findings.toi_cell);
  // A collision whose TOI cell was handed over (toi_cell) needs nothing more here.
  const bool collides = moving.answer == Outcome::Answer::collides;
  const bool toi_missing = want_toi && collides && !moving.toi && !findings.toi_cell;
  if (moving.answer != Outcome::Answer::undecided && !toi_missing) return moving;
  // Contact needs V(t) = 0 and the in-plane rule at the same t: a rule certainly false at every
  // t of [0, 1] (its deciding sign certified over the whole interval) excludes contact wherever
  // V's roots are. Decides nearly coplanar motion (resting contact, V within rounding of 0 for
  // all t, roots not isolable) when the point stays clearly outside the triangle's edge.
  if (!collides && interval::rule_over_unit_interval(P) == contact::Truth::no) return Outcome::separate();
  // Undecided, or a collision whose TOI could not be narrowed on V (V's sign is uncertain near
  // a root it shares with a factor's): the factored view may decide or narrow on the factor.
  const Outcome factored = interval::factored_strategy(P, q, want_toi, findings.rule_toi_cell);
  const bool factored_toi = factored.toi || findings.rule_toi_cell;  // certified, or its cell handed over
  if (factored.answer != Outcome::Answer::undecided && !(toi_missing && !factored_toi)) return factored;
  // Edge directions equal (or opposite) in two coordinates: V = -Delta F, w = Delta (da x e_k).
  const Outcome parallel = interval::parallel_factor_strategy(P, q, want_toi);
  if (parallel.answer == Outcome::Answer::undecided || (toi_missing && !parallel.toi)) return moving;
  return parallel;
}

template <class Query>
Outcome interval_stage_of(const Query& q, bool want_toi, RootCells& findings) {
  CGAL::Protect_FPU_rounding<true> rounding_towards_infinity;
  using IntervalQuery = typename kinds::kind_of<Query>::template Query<Interval>;
  return run_interval_stage(to_interval_query<IntervalQuery>(q), q, want_toi, findings);
}

}  // namespace

Outcome interval_stage(const VertexFaceQuery& q, bool want_toi, RootCells& findings) {
  return interval_stage_of(q, want_toi, findings);
}
Outcome interval_stage(const EdgeEdgeQuery& q, bool want_toi, RootCells& findings) {
  return interval_stage_of(q, want_toi, findings);
}

}  // namespace exactccd::filter
