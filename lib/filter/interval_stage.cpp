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
// 2. Cells come out in increasing t. Over a root cell T every other polynomial of the rule is
//    evaluated with interval Horner on T: an interval that excludes 0 gives the polynomial's
//    sign at the root, an exact [0, 0] means the polynomial vanishes identically, anything else
//    is uncertain. Uncertain: shrink T by certified bisection of V and retry once.
// 3. The earliest root where the rule holds is the TOI (the candidate argument of
//    exact_ccd.cpp). It is narrowed by certified bisection to two consecutive doubles.
// 4. Coplanar for all t (V's coefficients exactly [0, 0]): the candidates are 0, 1 and the
//    roots of the in-plane polynomials the rule can consult (pruned as in the integer stage),
//    isolated the same way (Bernstein of degree 2 or 4). At a candidate root of q, q's sign is
//    0 and every other sign comes from the cell as above (narrowed by bisection of q). The
//    answer is certain when every candidate is decided; the TOI only when the earliest
//    contact is an exact point and no undecided or contacting cell starts before it.
// 5. V not identically zero but uncertain in item 2: if the in-plane rule is certainly false over
//    all of [0, 1], no collision (whatever V's roots). Else, with a visible factorisation: when three
//    of the four points share one coordinate for all t (two components of a point-on-segment
//    cross product are exactly zero), V is a linear factor times the third component C_k, and
//    the candidates are the roots of the two factors (factored_stage). At a root of C_k the
//    rule's segment test has a sign known to be zero, which decides contacts exactly on an
//    edge's line; a contact found there has a certified TOI (narrowed on C_k).
#include "filter/interval_stage.hpp"

#include <CGAL/Interval_nt.h>
#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "contact/contact_rule.hpp"
#include "filter/static_stage.hpp"

namespace exactccd::filter {
namespace {

using Interval = CGAL::Interval_nt<false>;  // requires the rounding mode set by the caller
template <int D>
using Bernstein = std::array<Interval, D + 1>;

constexpr int kMaxSubdivisionDepth = 30;  // cells of width 2^-30; closer roots go to exact
// Halvings spent narrowing a TOI cell in intervals before handing it to the double-double /
// exact narrowing (toi_in_cell): interval signs of V fail a few bits short of adjacent doubles
// for most roots (design.md, 5.2), so a long interval bisection mostly wastes time; 16 still
// finds exact dyadic roots of small-integer input (t = 1/2, 3/8, ...) here.
constexpr int kToiHalvings = 16;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kBinomial[5][5] = {
    {1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 2, 1, 0, 0}, {1, 3, 3, 1, 0}, {1, 4, 6, 4, 1}};

int certain_sign(const Interval& x) {
  if (x.inf() > 0) return 1;
  if (x.sup() < 0) return -1;
  return 0;  // contains zero (or NaN bounds)
}

/// lcm of C(D, 0..D): 1, 1, 2, 3, 12.
constexpr int kBinomialLcm[5] = {1, 1, 2, 3, 12};

/// Bernstein coefficients on [0, 1] times L = kBinomialLcm[D] (a positive factor: same signs):
/// L b_j = sum_{i <= j} C(j, i) (L / C(D, i)) c_i. Every multiplier is a small integer, so with
/// exactly known coefficients (dyadic input) the result is exact; dividing by C(D, i) instead
/// would round 1/3, 1/4, 1/6 and hide exact zeros (a double root at t = 1/2).
template <int D>
Bernstein<D> to_bernstein(const contact::Poly<Interval, D>& p) {
  Bernstein<D> b;
  for (int j = 0; j <= D; ++j) {
    Interval sum(0);
    for (int i = 0; i <= j; ++i) sum = sum + p.c[i] * (kBinomial[j][i] * (kBinomialLcm[D] / kBinomial[D][i]));
    b[j] = sum;
  }
  return b;
}

/// de Casteljau at 1/2 (divisions by 2 are exact): the coefficients on the two halves.
template <int D>
void halve(const Bernstein<D>& b, Bernstein<D>& left, Bernstein<D>& right) {
  Bernstein<D> work = b;
  left[0] = work[0];
  right[D] = work[D];
  for (int level = 1; level <= D; ++level) {
    for (int i = 0; i <= D - level; ++i) work[i] = (work[i] + work[i + 1]) / 2;
    left[level] = work[0];
    right[D - level] = work[D - level];
  }
}

/// Where a polynomial vanishes: exactly at the double lo == hi (an exact zero at a dyadic
/// point), or at exactly one simple root in the open interval (lo, hi), with its sign at lo.
struct RootCell {
  double lo, hi;
  int sign_at_lo;
  bool is_point() const { return lo == hi; }
};

enum class Isolation { complete, failed };

/// Root cells of one polynomial: at most its degree (4), so no allocation on this path.
using RootCells = boost::container::small_vector<RootCell, 4>;

/// Sign class of an interval: exactly [0, 0] is a certain zero (it encloses only 0).
enum class SignClass { negative, zero, positive, unknown };

SignClass classify(const Interval& x) {
  if (x.inf() > 0) return SignClass::positive;
  if (x.sup() < 0) return SignClass::negative;
  if (x.inf() == 0 && x.sup() == 0) return SignClass::zero;
  return SignClass::unknown;
}

/// Appends the roots in the cell [lo, hi] (Bernstein coefficients b) in increasing order; the
/// roots at the cell's ends are the caller's. Descartes' rule in the Bernstein basis counts
/// sign changes among the nonzero coefficients. `first` / `last`, when not unknown, are the
/// exact signs of b[0] / b[D] (the polynomial's values at lo / hi), known from elsewhere.
template <int D>
Isolation isolate(const Bernstein<D>& b, double lo, double hi, int depth, RootCells& out,
                  SignClass first = SignClass::unknown, SignClass last = SignClass::unknown) {
  std::array<SignClass, D + 1> s{};
  bool certain = true, all_zero = true;
  for (int i = 0; i <= D; ++i) {
    s[i] = classify(b[i]);
    if (i == 0 && s[i] == SignClass::unknown) s[i] = first;
    if (i == D && s[i] == SignClass::unknown) s[i] = last;
    certain = certain && s[i] != SignClass::unknown;
    all_zero = all_zero && s[i] == SignClass::zero;
  }
  if (certain) {
    if (all_zero) return Isolation::failed;  // vanishes identically on the cell
    int changes = 0;
    SignClass last = SignClass::zero;
    for (SignClass c : s) {
      if (c == SignClass::zero) continue;
      changes += last != SignClass::zero && c != last;
      last = c;
    }
    if (changes == 0) return Isolation::complete;
    if (changes == 1 && s[0] != SignClass::zero && s[D] != SignClass::zero) {
      out.push_back(RootCell{lo, hi, s[0] == SignClass::positive ? 1 : -1});
      return Isolation::complete;
    }
  }
  if (depth == kMaxSubdivisionDepth) return Isolation::failed;
  Bernstein<D> left, right;
  halve<D>(b, left, right);
  const double mid = lo + (hi - lo) / 2;  // exact: dyadic cells of [0, 1]
  if (isolate<D>(left, lo, mid, depth + 1, out, s[0], SignClass::unknown) == Isolation::failed)
    return Isolation::failed;
  if (classify(left[D]) == SignClass::zero) out.push_back(RootCell{mid, mid, 0});
  return isolate<D>(right, mid, hi, depth + 1, out, SignClass::unknown, s[D]);
}

SignClass sign_class(int sign) {
  return sign > 0 ? SignClass::positive : sign < 0 ? SignClass::negative : SignClass::zero;
}

/// The roots in [0, 1] of a polynomial not identically zero, in increasing order, exact zeros
/// at 0 and 1 included when include_ends. `exact_sign_at_end(e)` (e = 0, 1), called only when
/// the interval value at that end is uncertain, returns the exact sign there or kUnknownSign.
template <int D, class EndSign>
Isolation isolate_roots(const contact::Poly<Interval, D>& p, RootCells& out, bool include_ends,
                        EndSign&& exact_sign_at_end) {
  const Bernstein<D> b = to_bernstein(p);
  SignClass first = classify(b[0]), last = classify(b[D]);
  for (auto [end, s] : {std::pair<int, SignClass*>{0, &first}, {1, &last}})
    if (*s == SignClass::unknown)
      if (const int exact = exact_sign_at_end(end); exact != contact::kUnknownSign) *s = sign_class(exact);
  if (include_ends && first == SignClass::zero) out.push_back(RootCell{0.0, 0.0, 0});
  if (isolate<D>(b, 0.0, 1.0, 0, out, first, last) == Isolation::failed) return Isolation::failed;
  if (include_ends && last == SignClass::zero) out.push_back(RootCell{1.0, 1.0, 0});
  return Isolation::complete;
}

template <int D>
Isolation isolate_roots(const contact::Poly<Interval, D>& p, RootCells& out, bool include_ends = true) {
  return isolate_roots(p, out, include_ends, [](int) { return contact::kUnknownSign; });
}

/// How far narrow() got.
enum class Narrowing {
  done,     ///< lo and hi are consecutive doubles, or the cell became an exact point
  partial,  ///< max_steps halvings done
  stuck,    ///< a midpoint's sign is uncertain; the cell is still valid, just not narrower
};

/// Halves the root cell of p while p's sign at the midpoint is certain, at most max_steps
/// times, until lo and hi are consecutive doubles or the midpoint is an exact zero (the cell
/// becomes that point).
template <int D>
Narrowing narrow(const contact::Poly<Interval, D>& p, RootCell& cell, int max_steps) {
  for (int step = 0; step < max_steps; ++step) {
    if (cell.is_point() || !(std::nextafter(cell.lo, kInf) < cell.hi)) return Narrowing::done;
    double mid = cell.lo + (cell.hi - cell.lo) / 2;
    if (!(cell.lo < mid && mid < cell.hi)) mid = std::nextafter(cell.lo, kInf);
    const SignClass c = classify(p(Interval(mid)));
    if (c == SignClass::unknown) return Narrowing::stuck;
    if (c == SignClass::zero) {
      cell = RootCell{mid, mid, 0};
      return Narrowing::done;
    }
    const int s = c == SignClass::positive ? 1 : -1;
    (s == cell.sign_at_lo ? cell.lo : cell.hi) = mid;
  }
  return cell.is_point() || !(std::nextafter(cell.lo, kInf) < cell.hi) ? Narrowing::done
                                                                         : Narrowing::partial;
}

/// Sign oracle over a time interval: certain signs, or kUnknownSign. The polynomial whose root
/// defines the candidate (if any) is zero there by construction.
struct IntervalSignOracle {
  Interval t;
  const void* zero_at_candidate = nullptr;
  template <int D>
  int operator()(const contact::Poly<Interval, D>& p) const {
    if (static_cast<const void*>(&p) == zero_at_candidate) return 0;
    const Interval value = p(t);
    const int s = certain_sign(value);
    if (s != 0) return s;
    if (value.inf() == 0 && value.sup() == 0) return 0;  // p vanishes identically on t
    return contact::kUnknownSign;
  }
};

enum class CellVerdict { contact, no_contact, uncertain };

/// The in-plane rule over a root cell of `defining`; on an uncertain sign the cell is narrowed
/// (16 halvings, then to consecutive doubles) and the rule retried, while that makes progress.
template <class Polys, int D>
CellVerdict in_plane_verdict(const Polys& P, const contact::Poly<Interval, D>& defining, bool defining_is_rule_poly,
                             RootCell& cell) {
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

template <class IntervalQuery, class Query>
IntervalQuery to_interval_query(const Query& q) {
  std::array<Vec3T<Interval>, 8> r;
  const auto d = rows(q);
  for (std::size_t i = 0; i < d.size(); ++i)
    r[i] = {Interval(d[i].x), Interval(d[i].y), Interval(d[i].z)};
  return from_rows<IntervalQuery>(r);
}

template <int D>
bool exactly_zero(const contact::Poly<Interval, D>& p) {
  for (const Interval& c : p.c)
    if (classify(c) != SignClass::zero) return false;
  return true;
}

/// The stage when V is not identically zero: the roots of V in increasing order. At t = 0 and
/// t = 1 the configuration is static: where intervals are uncertain there, `ends` gives V's
/// exact sign and the exact contact (CGAL's static predicates, static_stage.hpp).
template <class Polys, class Ends>
StageResult moving_stage(const Polys& P, const Ends& ends, bool want_toi) {
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
constexpr std::array<SegmentTest, 3> kVertexFaceTests{{{0, 0, 3}, {1, 0, 1}, {2, 0, 2}}};
// Edge-edge rows a0, a1, b0, b1: a0 and a1 on edge b, b0 and b1 on edge a; W the other
// endpoint of X's own edge.
constexpr std::array<SegmentTest, 4> kEdgeEdgeTests{{{0, 0, 1}, {1, 1, 0}, {2, 2, 3}, {3, 3, 2}}};

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
StageResult factored_stage(const Polys& P, const IntervalQuery& q, bool want_toi) {
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

/// The in-plane rule with every sign certified over all of [0, 1]: a certain answer holds at
/// every t there (an exact [0, 0] value means the polynomial vanishes on [0, 1]).
template <class Polys>
contact::Truth rule_over_unit_interval(const Polys& P) {
  return contact::in_plane_contact(P, IntervalSignOracle{Interval(0.0, 1.0)});
}

/// The stage when V vanishes identically (coplanar for all t): see the file comment, item 4.
template <class Polys>
StageResult coplanar_stage(const Polys& P, bool want_toi) {
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

/// Exact facts at t = 0 and t = 1 of a double query, for moving_stage. CGAL's static filters
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

/// The stage on one query.
template <class IntervalQuery, class Query>
StageResult interval_stage(const IntervalQuery& q, const Query& double_query, bool want_toi) {
  const auto P = contact::polynomials(q);
  if (exactly_zero(P.volume())) return coplanar_stage(P, want_toi);
  const StageResult moving = moving_stage(P, ExactEnds<Query>{double_query}, want_toi);
  // A collision whose TOI cell was handed over (toi_cell) needs nothing more here.
  const bool toi_missing = want_toi && moving.verdict == Verdict::collision && !moving.toi && !moving.toi_cell;
  if (moving.verdict != Verdict::uncertain && !toi_missing) return moving;
  // Contact needs V(t) = 0 and the in-plane rule at the same t: a rule certainly false at every
  // t of [0, 1] (its deciding sign certified over the whole interval) excludes contact wherever
  // V's roots are. Decides nearly coplanar motion (resting contact, V within rounding of 0 for
  // all t, roots not isolable) when the point stays clearly outside the triangle's edge.
  if (moving.verdict == Verdict::uncertain && rule_over_unit_interval(P) == contact::Truth::no)
    return {Verdict::no_collision, std::nullopt};
  // Uncertain, or a collision whose TOI could not be narrowed on V (V's sign is uncertain near
  // a root it shares with a factor's): the factored view may decide or narrow on the factor.
  const StageResult factored = factored_stage(P, q, want_toi);
  if (factored.verdict == Verdict::uncertain || (toi_missing && !factored.toi)) return moving;
  return factored;
}

}  // namespace

StageResult vertex_face_interval_stage(const VertexFaceQuery& q, bool want_toi) {
  CGAL::Protect_FPU_rounding<true> rounding_towards_infinity;
  return interval_stage(to_interval_query<VertexFaceQueryT<Interval>>(q), q, want_toi);
}

StageResult edge_edge_interval_stage(const EdgeEdgeQuery& q, bool want_toi) {
  CGAL::Protect_FPU_rounding<true> rounding_towards_infinity;
  return interval_stage(to_interval_query<EdgeEdgeQueryT<Interval>>(q), q, want_toi);
}

}  // namespace exactccd::filter
