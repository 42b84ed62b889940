// The strategies of the interval stage (docs/design.md, 5.2), each a complete argument on its
// own: the moving case (V not identically zero: V's roots, the rule over each root cell), the
// coplanar case (V identically zero: the in-plane polynomials' roots), the rule certain over
// all of [0, 1], and the factored view of V. interval_stage.cpp applies them in order.
// Every function runs under the stage's upward rounding (Interval_nt<false>).
#pragma once

#include <algorithm>
#include <array>
#include <optional>

#include "contact/contact_rule.hpp"
#include "filter/interval_isolation.hpp"
#include "filter/interval_stage.hpp"
#include "filter/interval_values.hpp"
#include "filter/toi_narrowing.hpp"

namespace exactccd::filter::interval {

// Halvings spent narrowing a TOI cell in intervals before handing it to the double-double /
// exact narrowing (toi_in_cell): interval signs of V fail a few bits short of adjacent doubles
// for most roots (design.md, 5.2), so a long interval bisection mostly wastes time; 16 still
// finds exact dyadic roots of small-integer input (t = 1/2, 3/8, ...) here.
inline constexpr int kToiHalvings = 16;
enum class CellVerdict { contact, no_contact, uncertain };

/// The in-plane rule over a root cell of `defining`. Unless `defining` is one of the rule's own
/// polynomials (whose zero the oracle must know), first from the terms' values over the cell,
/// over the cell narrowed by 16 halvings and over the cell narrowed to consecutive doubles
/// (interval_values.hpp); then from the polynomials, narrowing the cell (16 halvings, then to
/// consecutive doubles) and retrying while that makes progress.
template <class Polys, int D>
CellVerdict in_plane_verdict(const Polys& P, const contact::Poly<Interval, D>& defining, bool defining_is_rule_poly,
                             RootCell& cell) {
  if (!defining_is_rule_poly) {
    // First from the terms' values over the cell (interval_values.hpp: no polynomial built),
    // and when those are uncertain, over the cell narrowed by 16 halvings, then to consecutive
    // doubles (the values' enclosure tightens with the cell). Only then are the rule's
    // polynomials built (below).
    contact::Truth t = in_plane_rule_over(P, cell);
    for (const int halvings : {16, 1100}) {
      if (t != contact::Truth::unknown || cell.is_point()) break;
      const RootCell before = cell;
      narrow(defining, cell, halvings);
      if (cell.lo == before.lo && cell.hi == before.hi) break;
      t = in_plane_rule_over(P, cell);
    }
    if (t == contact::Truth::yes) return CellVerdict::contact;
    if (t == contact::Truth::no) return CellVerdict::no_contact;
  }
  for (int attempt = 0; attempt < 3; ++attempt) {
    const IntervalSignOracle oracle{Interval(cell.lo, cell.hi), defining_is_rule_poly ? &defining : nullptr};
    const contact::Truth t = contact::in_plane_contact(P, oracle);
    if (t == contact::Truth::yes) return CellVerdict::contact;
    if (t == contact::Truth::no) return CellVerdict::no_contact;
    if (cell.is_point()) return CellVerdict::uncertain;
    const RootCell before = cell;
    narrow(defining, cell, attempt == 0 ? 16 : 1100);
    if (cell.lo == before.lo && cell.hi == before.hi) return CellVerdict::uncertain;
  }
  return CellVerdict::uncertain;
}

/// The stage when V is not identically zero: the roots of V in increasing order. At t = 0 and
/// t = 1 the configuration is static: where intervals are uncertain there, `ends` gives V's
/// exact sign and the exact contact (CGAL's static predicates, static_stage.hpp).
template <class Polys, class Ends>
StageResult moving_strategy(const Polys& P, const Ends& ends, bool want_toi) {
  RootCells cells;
  if (isolate_roots(P.volume(), cells, true, [&](int end) { return ends.volume_sign(end); }) ==
          Isolation::failed ||
      cells.size() > 3)
    return {};
  if (cells.empty()) return {Verdict::no_collision, std::nullopt};
  bool earlier_uncertain = false;
  for (RootCell cell : cells) {
    CellVerdict v = in_plane_verdict(P, P.volume(), false, cell);
    if (v == CellVerdict::uncertain && cell.is_point() && (cell.lo == 0.0 || cell.lo == 1.0))
      v = ends.contact(cell.lo == 0.0 ? 0 : 1) ? CellVerdict::contact : CellVerdict::no_contact;
    if (v == CellVerdict::uncertain) {
      earlier_uncertain = true;
      continue;
    }
    if (v == CellVerdict::no_contact) continue;
    StageResult r{Verdict::collision};
    // The TOI is this root only if no earlier root is uncertain; narrowing may still fail
    // (V's sign uncertain close to the root), then a later stage narrows this cell exactly.
    if (want_toi && !earlier_uncertain) {
      if (narrow(P.volume(), cell, kToiHalvings) == Narrowing::done)
        r.toi = TimeInterval{cell.lo, cell.hi};
      else if (!cell.is_point())
        r.toi_cell = VolumeRootCell{cell.lo, cell.hi, cell.sign_at_lo};
    }
    return r;
  }
  if (earlier_uncertain) return {};
  return {Verdict::no_collision, std::nullopt};
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

template <class Polys>
const auto& segment_test(const Polys& P, int i) {
  if constexpr (contact::is_vertex_face_polys<Polys>::value)
    return P.on_edge(i);
  else
    return P.endpoint_on_edge(i);
}

/// The stage when V is not identically zero but factors visibly (file comment, item 5).
/// V = +-(W - X) . C with C = (X - u) x (v - u) the cross product of a point-on-segment test
/// (the volume of the four points, with X as base point). When two components of C are exactly
/// zero polynomials (X, u, v share one coordinate for all t, as on a grid line), then
/// V = +-(W - X)_k C_k exactly, and V's roots in [0, 1] are those of the linear factor
/// f = (W - X)_k and of C_k. At a root of C_k, X is on the line uv, and C_k's sign is zero by
/// construction: the rule's segment test decides there, where the barycentric numerators or
/// segment parameters are exactly zero and uncertain in intervals.
template <class Polys, class IntervalQuery>
StageResult factored_strategy(const Polys& P, const IntervalQuery& q, bool want_toi) {
  constexpr bool vertex_face = contact::is_vertex_face_polys<Polys>::value;
  const auto r = rows(q);
  const auto tests = [] {
    if constexpr (vertex_face) return kVertexFaceTests; else return kEdgeEdgeTests;
  }();
  for (const SegmentTest& test : tests) {
    const auto& cross = segment_test(P, test.index).cross;
    const std::array<const contact::Poly<Interval, 2>*, 3> component{&cross.x, &cross.y, &cross.z};
    int k = -1, zeros = 0;
    for (int j = 0; j < 3; ++j) {
      if (exactly_zero(*component[j]))
        ++zeros;
      else
        k = j;
    }
    if (zeros != 2) continue;
    const auto coordinate = [k](const Vec3T<Interval>& v) { return k == 0 ? v.x : k == 1 ? v.y : v.z; };
    const Interval w0 = coordinate(r[test.w]), w1 = coordinate(r[test.w + 4]);
    const Interval x0 = coordinate(r[test.x]), x1 = coordinate(r[test.x + 4]);
    const contact::Poly<Interval, 1> f = contact::linear_motion(w0 - x0, w1 - x1);  // as relative_motion
    const contact::Poly<Interval, 2>& g = *component[k];
    if (exactly_zero(f)) continue;  // V = 0 for all t: not this stage's case
    RootCells f_cells, g_cells;
    if (isolate_roots(f, f_cells) == Isolation::failed || isolate_roots(g, g_cells) == Isolation::failed) continue;
    // The candidates in increasing order; overlapping cells of the two factors cannot be
    // ordered here (a common root, or roots too close): leave the query to a later stage.
    struct Candidate {
      RootCell cell;
      bool of_g;
    };
    boost::container::small_vector<Candidate, 3> candidates;
    for (const RootCell& c : f_cells) candidates.push_back({c, false});
    for (const RootCell& c : g_cells) candidates.push_back({c, true});
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate& a, const Candidate& b) { return a.cell.lo < b.cell.lo; });
    bool ordered = true;
    for (std::size_t i = 1; i < candidates.size(); ++i) {
      const RootCell &a = candidates[i - 1].cell, &b = candidates[i].cell;
      ordered = ordered && (a.hi < b.lo || (a.hi == b.lo && !(a.is_point() && b.is_point())));
    }
    if (!ordered) return {};
    for (Candidate& c : candidates) {
      const CellVerdict v = c.of_g ? in_plane_verdict(P, g, true, c.cell) : in_plane_verdict(P, f, false, c.cell);
      if (v == CellVerdict::uncertain) return {};  // the earliest undecided candidate blocks the rest
      if (v == CellVerdict::no_contact) continue;
      StageResult result{Verdict::collision, std::nullopt};
      if (want_toi) {
        const Narrowing n = c.of_g ? narrow(g, c.cell, 1100) : narrow(f, c.cell, 1100);
        if (n == Narrowing::done) result.toi = TimeInterval{c.cell.lo, c.cell.hi};
      }
      return result;
    }
    return {Verdict::no_collision, std::nullopt};
  }
  return {};
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

/// Edge-edge when the edge directions differ in one coordinate only (file comment, item 6):
/// db_j = s da_j exactly for the two coordinates j != k (s = +1 or -1; parallel grid lines of a
/// folding sheet). Then db = s da + Delta e_k with Delta = db_k - s da_k, so
/// w = da x db = Delta (da x e_k), and V = da . (r x db) = -r . w = -Delta F with
/// F = r . (da x e_k) (r = b0 - a0): V's roots in [0, 1] are those of the linear Delta and of
/// the quadratic F. At a root of Delta all of w vanishes (the edges are parallel there) and the
/// oracle knows it, so the rule takes its degenerate branch with certain signs, where the plain
/// isolation of V could not tell w(t*) = 0 from a tiny nonzero value (a common root of V and w).
template <class Polys, class IntervalQuery>
StageResult parallel_factor_strategy(const Polys& P, const IntervalQuery& q, bool want_toi) {
  if constexpr (contact::is_vertex_face_polys<Polys>::value) {
    return {};
  } else {
    const auto r = rows(q);
    using Linear = contact::Poly<Interval, 1>;
    const contact::PolyVec3<Interval, 1> da = contact::relative_motion(r, 0, 1), db = contact::relative_motion(r, 2, 3),
                                         rv = contact::relative_motion(r, 0, 2);
    const auto component = [](const contact::PolyVec3<Interval, 1>& v, int j) -> const Linear& {
      return j == 0 ? v.x : j == 1 ? v.y : v.z;
    };
    // (b1 - b0)_j = s (a1 - a0)_j exactly at both ends (then as polynomials in t): the same
    // input doubles (b0 = a0 and b1 = a1 for s = +1, swapped for s = -1), or differences that
    // are exact (point intervals) and equal up to s.
    const auto coordinate = [](const Vec3T<Interval>& v, int j) { return j == 0 ? v.x : j == 1 ? v.y : v.z; };
    const auto same_at_end = [&](int j, double s, int end) {
      const int o = 4 * end;
      const double a0 = coordinate(r[o], j).inf(), a1 = coordinate(r[o + 1], j).inf();
      const double b0 = coordinate(r[o + 2], j).inf(), b1 = coordinate(r[o + 3], j).inf();
      if (s > 0 ? (a0 == b0 && a1 == b1) : (a0 == b1 && a1 == b0)) return true;
      const Interval a = coordinate(r[o + 1], j) - coordinate(r[o], j), b = coordinate(r[o + 3], j) - coordinate(r[o + 2], j);
      return a.inf() == a.sup() && b.inf() == b.sup() && b.inf() == s * a.inf();
    };
    const auto same_component = [&](int j, double s) { return same_at_end(j, s, 0) && same_at_end(j, s, 1); };
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      for (const double s : {1.0, -1.0}) {
        if (!same_component(i, s) || !same_component(j, s)) continue;
        const Linear &da_k = component(da, k), &db_k = component(db, k);
        const Linear delta{{db_k.c[0] - Interval(s) * da_k.c[0], db_k.c[1] - Interval(s) * da_k.c[1]}};
        // (i, j, k) cyclic: e_i x e_k = -e_j and e_j x e_k = e_i, so da x e_k = da_j e_i - da_i e_j
        // and F = r . (da x e_k) = r_i da_j - r_j da_i.
        const contact::Poly<Interval, 2> F = component(rv, i) * component(da, j) - component(rv, j) * component(da, i);
        if (exactly_zero(delta) || exactly_zero(F)) return {};  // V = 0 for all t: not this case
        RootCells delta_cells, f_cells;
        if (isolate_roots(delta, delta_cells) == Isolation::failed || isolate_roots(F, f_cells) == Isolation::failed)
          return {};
        struct Candidate {
          RootCell cell;
          bool of_delta;
        };
        boost::container::small_vector<Candidate, 3> candidates;
        for (const RootCell& c : delta_cells) candidates.push_back({c, true});
        for (const RootCell& c : f_cells) candidates.push_back({c, false});
        // Order the candidates: isolating cells of the two factors may overlap (a linear Delta's
        // cell is [0, 1]); narrow both by certified bisection of their own factor until they
        // are disjoint. The same exact point for both (a common root) is one candidate, Delta's
        // (its oracle knows more). Still overlapping after the budget: leave it to later stages.
        const auto defining_narrow = [&](Candidate& c) {
          const RootCell before = c.cell;
          if (c.of_delta)
            narrow(delta, c.cell, 1);
          else
            narrow(F, c.cell, 1);
          return c.cell.lo != before.lo || c.cell.hi != before.hi;
        };
        for (int round = 0;; ++round) {
          std::sort(candidates.begin(), candidates.end(),
                    [](const Candidate& a, const Candidate& b) { return a.cell.lo < b.cell.lo; });
          std::size_t clash = 0;
          for (std::size_t n = 1; n < candidates.size() && clash == 0; ++n) {
            const RootCell &a = candidates[n - 1].cell, &b = candidates[n].cell;
            if (a.is_point() && b.is_point() && a.lo == b.lo) {
              candidates.erase(candidates.begin() + static_cast<std::ptrdiff_t>(candidates[n - 1].of_delta ? n : n - 1));
              clash = candidates.size() + 1;  // changed: sort and scan again
            } else if (!(a.hi < b.lo || (a.hi == b.lo && !(a.is_point() && b.is_point())))) {
              clash = n;
            }
          }
          if (clash == 0) break;
          if (clash > candidates.size()) continue;
          if (round == 64) return {};  // unordered
          const bool left = defining_narrow(candidates[clash - 1]), right = defining_narrow(candidates[clash]);
          if (!left && !right) return {};
        }
        const auto& w = P.direction_cross();
        for (Candidate& c : candidates) {
          CellVerdict v = CellVerdict::uncertain;
          if (c.of_delta) {
            // At Delta's root w = 0 exactly; retry on a narrower cell while uncertain.
            for (int attempt = 0; attempt < 3; ++attempt) {
              const contact::Truth t =
                  contact::in_plane_contact(P, FactorRootOracle{Interval(c.cell.lo, c.cell.hi), {&w.x, &w.y, &w.z}});
              if (t != contact::Truth::unknown) {
                v = t == contact::Truth::yes ? CellVerdict::contact : CellVerdict::no_contact;
                break;
              }
              if (c.cell.is_point()) break;
              const RootCell before = c.cell;
              narrow(delta, c.cell, attempt == 0 ? 16 : 1100);
              if (c.cell.lo == before.lo && c.cell.hi == before.hi) break;
            }
          } else {
            v = in_plane_verdict(P, F, false, c.cell);
          }
          if (v == CellVerdict::uncertain) return {};  // the earliest undecided candidate blocks the rest
          if (v == CellVerdict::no_contact) continue;
          StageResult result{Verdict::collision, std::nullopt};
          if (want_toi) {
            const Narrowing n = c.of_delta ? narrow(delta, c.cell, 1100) : narrow(F, c.cell, 1100);
            if (n == Narrowing::done) result.toi = TimeInterval{c.cell.lo, c.cell.hi};
          }
          return result;
        }
        return {Verdict::no_collision, std::nullopt};
      }
    }
    return {};
  }
}

/// The in-plane rule with every sign certified over all of [0, 1]: a certain answer holds at
/// every t there (an exact [0, 0] value means the polynomial vanishes on [0, 1]).
template <class Polys>
contact::Truth rule_over_unit_interval(const Polys& P) {
  return contact::in_plane_contact(P, IntervalSignOracle{Interval(0.0, 1.0)});
}

/// The stage when V vanishes identically (coplanar for all t): see the file comment, item 4.
template <class Polys>
StageResult coplanar_strategy(const Polys& P, bool want_toi) {
  // First the rule over all of [0, 1] at once: a sign certified over the whole interval holds
  // at every t in it, so a certain answer is the answer at every t (a certain contact holds at
  // t = 0: the TOI is exactly 0). This decides static and slowly moving coplanar pairs whose
  // rule hinges on one certain sign, even when another polynomial of the rule (never consulted
  // for the answer) is too close to zero for its roots to be isolated below.
  switch (rule_over_unit_interval(P)) {
    case contact::Truth::no:
      return {Verdict::no_collision, std::nullopt};
    case contact::Truth::yes:
      return {Verdict::collision, want_toi ? std::optional<TimeInterval>(TimeInterval{0.0, 0.0}) : std::nullopt};
    case contact::Truth::unknown:
      break;
  }
  bool failed = false, uncertain = false;
  std::optional<TimeInterval> earliest_contact;  // among decided candidates
  double earliest_undecided = kInf;              // the smallest lo of an undecided cell
  const auto examine = [&](const auto& defining, bool is_rule_poly, RootCell cell) {
    const CellVerdict v = in_plane_verdict(P, defining, is_rule_poly, cell);
    if (v == CellVerdict::uncertain) {
      uncertain = true;
      earliest_undecided = std::min(earliest_undecided, cell.lo);
    } else if (v == CellVerdict::contact) {
      const TimeInterval t{cell.lo, cell.hi};
      if (!earliest_contact || t.lo < earliest_contact->lo ||
          (t.lo == earliest_contact->lo && t.hi < earliest_contact->hi))
        earliest_contact = t;
    }
  };
  const auto candidates_of = [&](const auto& p) {  // returns the number of roots
    if (failed || exactly_zero(p)) return std::size_t{0};
    RootCells cells;
    if (isolate_roots(p, cells, false) == Isolation::failed) {
      failed = true;
      return std::size_t{0};
    }
    for (const RootCell& c : cells) examine(p, true, c);
    return cells.size();
  };
  const contact::Poly<Interval, 0> constant{{Interval(1)}};  // defines no root: ends of [0, 1]
  examine(constant, false, RootCell{0.0, 0.0, 0});
  examine(constant, false, RootCell{1.0, 1.0, 0});
  bool nowhere_zero = false, identically_zero = true;
  const auto& v = contact::branch_vector(P);
  for (const auto* component : {&v.x, &v.y, &v.z}) {
    if (exactly_zero(*component)) continue;
    identically_zero = false;
    if (candidates_of(*component) == 0 && !failed && certain_sign((*component)(Interval(0.0, 1.0))) != 0)
      nowhere_zero = true;  // no root and certainly nonzero on [0, 1]
  }
  if (!identically_zero) contact::for_each_proper_poly(P, candidates_of);
  if (!nowhere_zero) contact::for_each_degenerate_poly(P, candidates_of);
  if (failed) return {};
  if (!earliest_contact) return uncertain ? StageResult{} : StageResult{Verdict::no_collision, std::nullopt};
  StageResult r{Verdict::collision, std::nullopt};
  // The TOI is certain when the earliest contact is an exact point that no undecided cell
  // precedes (a contact cell (lo, hi) is not narrowed to a tight enclosure here).
  if (want_toi && earliest_contact->lo == earliest_contact->hi && earliest_undecided > earliest_contact->lo)
    r.toi = earliest_contact;
  return r;
}


}  // namespace exactccd::filter::interval
