// The interval stage when V is not identically zero but its roots cannot be isolated or
// decided directly, and V factors visibly (docs/design.md, 5.2, items 5 and 6). The candidates
// are then the roots of the two factors, each examined with what its factor makes exactly zero,
// in increasing order; the first contact is the answer (its TOI narrowed on its factor).
//  - factored_strategy: three of the four points share one coordinate for all t (two
//    components of a point-on-segment cross product C are exactly zero polynomials, as on a
//    grid line): V = +-(W - X)_k C_k, a linear factor times the third component of C. At a root
//    of C_k the rule's segment test has a sign known to be zero, which decides contacts exactly
//    on an edge's line.
//  - parallel_factor_strategy (edge-edge): the edge directions agree exactly in two coordinates
//    up to one sign s (db_j = s da_j: parallel grid lines of a folding sheet moving alike):
//    w = Delta (da x e_k) and V = -Delta F with Delta = db_k - s da_k linear and
//    F = r . (da x e_k) quadratic. At a root of Delta the edges are parallel (w = 0, known
//    exactly), which decides the common roots of V and w that plain isolation of V cannot.
#pragma once

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <optional>

#include "filter/interval/in_plane_over_cell.hpp"
#include "filter/interval/isolation.hpp"
#include "filter/root_cells.hpp"
#include "filter/interval/narrowing.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::filter::interval {

/// A candidate root of one of V's two factors: factor 0 (linear) or factor 1 (quadratic).
struct FactorCandidate {
  RootCell cell;
  int factor;
};
using FactorCandidates = boost::container::small_vector<FactorCandidate, 3>;

/// The candidates of both factors' root cells, sorted by their lower ends.
inline FactorCandidates sorted_candidates(const RootCells& first, const RootCells& second) {
  FactorCandidates candidates;
  for (const RootCell& c : first) candidates.push_back({c, 0});
  for (const RootCell& c : second) candidates.push_back({c, 1});
  std::sort(candidates.begin(), candidates.end(),
            [](const FactorCandidate& a, const FactorCandidate& b) { return a.cell.lo < b.cell.lo; });
  return candidates;
}

/// The cells a (sorted before b) and b are disjoint, so that their roots are ordered.
inline bool ordered(const RootCell& a, const RootCell& b) {
  return a.hi < b.lo || (a.hi == b.lo && !(a.is_point() && b.is_point()));
}

/// The first candidate, in order, where `verdict(candidate)` (the rule there) is certain
/// contact: a collision, its TOI from `narrow_toi(candidate)` (true when narrowed to adjacent
/// doubles); undecided at the first uncertain candidate (it blocks the rest); else separate.
template <class Verdict, class NarrowToi>
pipeline::Outcome first_contact(FactorCandidates& candidates, bool want_toi, Verdict&& verdict, NarrowToi&& narrow_toi) {
  for (FactorCandidate& c : candidates) {
    const contact::Truth v = verdict(c);
    if (v == contact::Truth::unknown) return pipeline::Outcome::undecided();
    if (v == contact::Truth::no) continue;
    pipeline::Outcome result = pipeline::Outcome::collides();
    if (want_toi && narrow_toi(c)) result.toi = TimeInterval{c.cell.lo, c.cell.hi};
    return result;
  }
  return pipeline::Outcome::separate();
}

/// A point-on-segment test of the rule (a point X against a segment [u, v]) and the fourth
/// point W of the query: rows of the query's row order (t0 rows; t1 is row + 4).
struct SegmentTest {
  int index;  ///< P.on_edge(index) (vertex-face) or P.endpoint_on_edge(index) (edge-edge)
  int x, w;   ///< rows of X and W
};
// Vertex-face rows p, a, b, c: p on edge (a, b), (b, c), (c, a); W the opposite vertex.
inline constexpr std::array<SegmentTest, 3> kVertexFaceTests{{{0, 0, 3}, {1, 0, 1}, {2, 0, 2}}};
// Edge-edge rows a0, a1, b0, b1: a0 and a1 on edge b, b0 and b1 on edge a; W the other
// endpoint of X's own edge.
inline constexpr std::array<SegmentTest, 4> kEdgeEdgeTests{{{0, 0, 1}, {1, 1, 0}, {2, 2, 3}, {3, 3, 2}}};

/// The rule's segment test `i` (see SegmentTest).
template <class Polys>
const auto& segment_test(const Polys& P, int i) {
  if constexpr (contact::is_vertex_face_polys<Polys>::value)
    return P.on_edge(i);
  else
    return P.endpoint_on_edge(i);
}

/// Coordinate k of v.
template <class T>
const T& coordinate(const Vec3T<T>& v, int k) {
  return k == 0 ? v.x : k == 1 ? v.y : v.z;
}

/// The index of the only component of the cross product that is not exactly zero, or -1.
inline int only_nonzero_component(const std::array<const contact::Poly<Interval, 2>*, 3>& component) {
  int k = -1, zeros = 0;
  for (int j = 0; j < 3; ++j) {
    if (exactly_zero(*component[j]))
      ++zeros;
    else
      k = j;
  }
  return zeros == 2 ? k : -1;
}

/// V = +-f g with f = (W - X)_k linear and g = C_k of `test`: the roots of both, in order. A
/// contact's root cell not narrowed to adjacent doubles here is handed over in `toi_cell`: the
/// candidates' cells are disjoint and in order (checked below) and every root of V is one of
/// them, so every other candidate that may hold is after it (later_from = +inf).
template <class Polys, class Rows>
pipeline::Outcome factored_by_test(const Polys& P, const Rows& r, const SegmentTest& test, bool want_toi,
                                   bool& applies, std::optional<RuleRootCell>& toi_cell) {
  const auto& cross = segment_test(P, test.index).cross;
  const int k = only_nonzero_component({&cross.x, &cross.y, &cross.z});
  applies = false;
  if (k < 0) return pipeline::Outcome::undecided();
  const Interval w0 = coordinate(r[test.w], k), w1 = coordinate(r[test.w + 4], k);
  const Interval x0 = coordinate(r[test.x], k), x1 = coordinate(r[test.x + 4], k);
  const contact::Poly<Interval, 1> f = contact::linear_motion(w0 - x0, w1 - x1);  // as relative_motion
  const contact::Poly<Interval, 2>& g = coordinate(cross, k);
  RootCells f_cells, g_cells;
  if (exactly_zero(f) || isolate_roots(f, f_cells) == Isolation::failed || isolate_roots(g, g_cells) == Isolation::failed)
    return pipeline::Outcome::undecided();  // V = 0 for all t, or not isolable: not this case
  applies = true;
  FactorCandidates candidates = sorted_candidates(f_cells, g_cells);
  for (std::size_t i = 1; i < candidates.size(); ++i)  // overlapping cells: a common root, or too close
    if (!ordered(candidates[i - 1].cell, candidates[i].cell)) return pipeline::Outcome::undecided();
  return first_contact(
      candidates, want_toi,
      [&](FactorCandidate& c) {
        return c.factor == 1 ? in_plane_verdict(P, g, true, c.cell) : in_plane_verdict(P, f, false, c.cell);
      },
      [&](FactorCandidate& c) {
        if ((c.factor == 1 ? narrow(g, c.cell, kAllHalvings) : narrow(f, c.cell, kAllHalvings)) == Narrowing::done)
          return true;
        // g = C_k is the in-plane polynomial of index first_degenerate + 4 test + k
        // (contact::for_each_degenerate_poly); f is coordinate k of the motion X -> W.
        const RulePoly poly = c.factor == 1
            ? RulePoly{contact::first_degenerate_poly(P) + 4 * test.index + k}
            : RulePoly{-1, test.x, test.w, k};
        toi_cell = RuleRootCell{c.cell.lo, c.cell.hi, c.cell.sign_at_lo, poly, kInf};
        return false;
      });
}

/// The stage with the factorisation of the first segment test that has one (file comment); a
/// collision's root cell may be handed over in `toi_cell` (factored_by_test).
template <class Polys, class IntervalQuery>
pipeline::Outcome factored_strategy(const Polys& P, const IntervalQuery& q, bool want_toi,
                                    std::optional<RuleRootCell>& toi_cell) {
  const auto r = rows(q);
  const auto tests = [] {
    if constexpr (contact::is_vertex_face_polys<Polys>::value) return kVertexFaceTests; else return kEdgeEdgeTests;
  }();
  for (const SegmentTest& test : tests) {
    bool applies = false;
    const pipeline::Outcome o = factored_by_test(P, r, test, want_toi, applies, toi_cell);
    if (applies) return o;
  }
  return pipeline::Outcome::undecided();
}

/// Sign oracle at a root t* of a factor of V that makes several rule polynomials vanish (their
/// exact values are multiples of the factor): 0 for those, certified interval signs over the
/// cell (which holds t*) for the others.
struct FactorRootOracle {
  Interval t;
  std::array<const void*, 3> zero_at_candidate;
  template <int D>
  int operator()(const contact::Poly<Interval, D>& p) const {
    for (const void* z : zero_at_candidate)
      if (static_cast<const void*>(&p) == z) return 0;
    return IntervalSignOracle{t}(p);
  }
};

/// Edge-edge, parallel factor: (b1 - b0)_j = s (a1 - a0)_j exactly at both ends (then as
/// polynomials in t): the same input doubles (b0 = a0 and b1 = a1 for s = +1, swapped for
/// s = -1), or differences that are exact (point intervals) and equal up to s.
template <class Rows>
bool same_direction_component(const Rows& r, int j, double s) {
  for (const int o : {0, 4}) {
    const double a0 = coordinate(r[o], j).inf(), a1 = coordinate(r[o + 1], j).inf();
    const double b0 = coordinate(r[o + 2], j).inf(), b1 = coordinate(r[o + 3], j).inf();
    if (s > 0 ? (a0 == b0 && a1 == b1) : (a0 == b1 && a1 == b0)) continue;
    const Interval a = coordinate(r[o + 1], j) - coordinate(r[o], j), b = coordinate(r[o + 3], j) - coordinate(r[o + 2], j);
    if (!(a.inf() == a.sup() && b.inf() == b.sup() && b.inf() == s * a.inf())) return false;
  }
  return true;
}

/// Orders the candidates of Delta (factor 0) and F (factor 1): overlapping cells are narrowed
/// by certified bisection of their own factor until disjoint; the same exact point for both (a
/// common root) is one candidate, Delta's (its oracle knows more). False when still overlapping
/// after the budget.
template <class Linear, class Quadratic>
bool order_by_narrowing(FactorCandidates& candidates, const Linear& delta, const Quadratic& F) {
  const auto narrow_one = [&](FactorCandidate& c) { return c.factor == 0 ? narrowed(delta, c.cell, 1) : narrowed(F, c.cell, 1); };
  for (int round = 0;; ++round) {
    std::sort(candidates.begin(), candidates.end(),
              [](const FactorCandidate& a, const FactorCandidate& b) { return a.cell.lo < b.cell.lo; });
    std::size_t clash = 0;
    bool merged = false;
    for (std::size_t n = 1; n < candidates.size() && clash == 0 && !merged; ++n) {
      const RootCell &a = candidates[n - 1].cell, &b = candidates[n].cell;
      if (a.is_point() && b.is_point() && a.lo == b.lo) {
        candidates.erase(candidates.begin() + static_cast<std::ptrdiff_t>(candidates[n - 1].factor == 0 ? n : n - 1));
        merged = true;  // changed: sort and scan again
      } else if (!ordered(a, b)) {
        clash = n;
      }
    }
    if (merged) continue;
    if (clash == 0) return true;
    if (round == 64) return false;
    const bool left = narrow_one(candidates[clash - 1]), right = narrow_one(candidates[clash]);
    if (!left && !right) return false;
  }
}

/// The rule at a root of Delta, where w = 0 exactly: retried on a narrower cell while uncertain.
template <class Polys, class Linear>
contact::Truth verdict_at_parallel_root(const Polys& P, const Linear& delta, RootCell& cell) {
  const auto& w = P.direction_cross();
  for (int attempt = 0; attempt < 3; ++attempt) {
    const contact::Truth t = contact::in_plane_contact(P, FactorRootOracle{Interval(cell.lo, cell.hi), {&w.x, &w.y, &w.z}});
    if (t != contact::Truth::unknown || cell.is_point()) return t;
    if (!narrowed(delta, cell, attempt == 0 ? kToiHalvings : kAllHalvings)) return contact::Truth::unknown;
  }
  return contact::Truth::unknown;
}

/// The parallel factorisation for the coordinate k and sign s (file comment): the roots of
/// Delta and of F in order.
template <class Polys, class Rows>
pipeline::Outcome parallel_factor_roots(const Polys& P, const Rows& r, int k, double s, bool want_toi) {
  using Linear = contact::Poly<Interval, 1>;
  const contact::PolyVec3<Interval, 1> da = contact::relative_motion(r, 0, 1), db = contact::relative_motion(r, 2, 3),
                                       rv = contact::relative_motion(r, 0, 2);
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const Linear &da_k = coordinate(da, k), &db_k = coordinate(db, k);
  const Linear delta{{db_k.c[0] - Interval(s) * da_k.c[0], db_k.c[1] - Interval(s) * da_k.c[1]}};
  // (i, j, k) cyclic: e_i x e_k = -e_j and e_j x e_k = e_i, so da x e_k = da_j e_i - da_i e_j
  // and F = r . (da x e_k) = r_i da_j - r_j da_i.
  const contact::Poly<Interval, 2> F = coordinate(rv, i) * coordinate(da, j) - coordinate(rv, j) * coordinate(da, i);
  RootCells delta_cells, f_cells;
  if (exactly_zero(delta) || exactly_zero(F) || isolate_roots(delta, delta_cells) == Isolation::failed ||
      isolate_roots(F, f_cells) == Isolation::failed)
    return pipeline::Outcome::undecided();  // V = 0 for all t (not this case), or not isolable
  FactorCandidates candidates = sorted_candidates(delta_cells, f_cells);
  if (!order_by_narrowing(candidates, delta, F)) return pipeline::Outcome::undecided();
  return first_contact(
      candidates, want_toi,
      [&](FactorCandidate& c) {
        return c.factor == 0 ? verdict_at_parallel_root(P, delta, c.cell) : in_plane_verdict(P, F, false, c.cell);
      },
      [&](FactorCandidate& c) {
        return (c.factor == 0 ? narrow(delta, c.cell, kAllHalvings) : narrow(F, c.cell, kAllHalvings)) == Narrowing::done;
      });
}

/// Edge-edge with edge directions equal (or opposite) in two coordinates: see the file comment.
template <class Polys, class IntervalQuery>
pipeline::Outcome parallel_factor_strategy(const Polys& P, const IntervalQuery& q, bool want_toi) {
  if constexpr (contact::is_vertex_face_polys<Polys>::value) {
    return pipeline::Outcome::undecided();
  } else {
    const auto r = rows(q);
    for (int k = 0; k < 3; ++k)
      for (const double s : {1.0, -1.0})
        if (same_direction_component(r, (k + 1) % 3, s) && same_direction_component(r, (k + 2) % 3, s))
          return parallel_factor_roots(P, r, k, s, want_toi);
    return pipeline::Outcome::undecided();
  }
}

}  // namespace exactccd::filter::interval
