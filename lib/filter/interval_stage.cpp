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
#include "filter/interval_stage.hpp"

#include <CGAL/Interval_nt.h>

#include <array>
#include <cmath>
#include <limits>

#include "contact/contact_rule.hpp"

namespace exactccd::filter {
namespace {

using Interval = CGAL::Interval_nt<false>;  // requires the rounding mode set by the caller
using Bernstein = std::array<Interval, 4>;

constexpr int kMaxSubdivisionDepth = 30;  // cells of width 2^-30; closer roots go to exact
constexpr double kInf = std::numeric_limits<double>::infinity();

int certain_sign(const Interval& x) {
  if (x.inf() > 0) return 1;
  if (x.sup() < 0) return -1;
  return 0;  // contains zero (or NaN bounds)
}

Bernstein to_bernstein(const contact::Poly<Interval, 3>& v) {
  const Interval& c0 = v.c[0];
  const Interval& c1 = v.c[1];
  const Interval& c2 = v.c[2];
  const Interval& c3 = v.c[3];
  return {c0, c0 + c1 / 3, c0 + (2 * c1 + c2) / 3, c0 + c1 + c2 + c3};
}

/// de Casteljau at 1/2: the coefficients on the left and right halves.
void halve(const Bernstein& b, Bernstein& left, Bernstein& right) {
  const Interval b01 = (b[0] + b[1]) / 2, b12 = (b[1] + b[2]) / 2, b23 = (b[2] + b[3]) / 2;
  const Interval b012 = (b01 + b12) / 2, b123 = (b12 + b23) / 2;
  const Interval mid = (b012 + b123) / 2;
  left = {b[0], b01, b012, mid};
  right = {mid, b123, b23, b[3]};
}

/// Where V vanishes: either exactly at the double lo == hi (an exact zero found at a dyadic
/// point), or at exactly one simple root in the open interval (lo, hi), with V's sign at lo.
struct RootCell {
  double lo, hi;
  int sign_at_lo;
  bool is_point() const { return lo == hi; }
};

/// Small fixed-capacity list: a cubic that is not identically zero has at most three roots.
struct RootCells {
  std::array<RootCell, 3> cells;
  int size = 0;
  bool overflow = false;
  void push_back(const RootCell& c) {
    if (size < 3)
      cells[size++] = c;
    else
      overflow = true;
  }
};

enum class Isolation { complete, failed };

/// Sign class of a Bernstein coefficient: an interval that is exactly [0, 0] is a certain zero
/// (interval arithmetic encloses the true value, so the true value is 0).
enum class SignClass { negative, zero, positive, unknown };

SignClass classify(const Interval& x) {
  if (x.inf() > 0) return SignClass::positive;
  if (x.sup() < 0) return SignClass::negative;
  if (x.inf() == 0 && x.sup() == 0) return SignClass::zero;
  return SignClass::unknown;
}

/// Appends the roots of V in the cell [lo, hi] with coefficients b, in increasing order; the
/// roots at the cell's ends are the caller's. Descartes' rule in the Bernstein basis counts
/// sign changes among the nonzero coefficients.
Isolation isolate(const Bernstein& b, double lo, double hi, int depth, RootCells& out) {
  std::array<SignClass, 4> s{};
  bool certain = true, all_zero = true;
  for (int i = 0; i < 4; ++i) {
    s[i] = classify(b[i]);
    certain = certain && s[i] != SignClass::unknown;
    all_zero = all_zero && s[i] == SignClass::zero;
  }
  if (certain) {
    if (all_zero) return Isolation::failed;  // V vanishes identically: a later stage decides
    int changes = 0;
    SignClass last = SignClass::zero;
    for (SignClass c : s) {
      if (c == SignClass::zero) continue;
      changes += last != SignClass::zero && c != last;
      last = c;
    }
    if (changes == 0) return Isolation::complete;
    if (changes == 1 && s[0] != SignClass::zero && s[3] != SignClass::zero) {
      out.push_back(RootCell{lo, hi, s[0] == SignClass::positive ? 1 : -1});
      return Isolation::complete;
    }
  }
  if (depth == kMaxSubdivisionDepth) return Isolation::failed;
  Bernstein left, right;
  halve(b, left, right);
  const double mid = lo + (hi - lo) / 2;  // exact: dyadic cells of [0, 1]
  if (isolate(left, lo, mid, depth + 1, out) == Isolation::failed) return Isolation::failed;
  if (classify(left[3]) == SignClass::zero) out.push_back(RootCell{mid, mid, 0});
  return isolate(right, mid, hi, depth + 1, out);
}

/// The roots of V in [0, 1] in increasing order, exact zeros at 0 and 1 included.
Isolation isolate_roots(const contact::Poly<Interval, 3>& v, RootCells& out) {
  const Bernstein b = to_bernstein(v);
  if (classify(b[0]) == SignClass::zero) out.push_back(RootCell{0.0, 0.0, 0});
  if (isolate(b, 0.0, 1.0, 0, out) == Isolation::failed) return Isolation::failed;
  if (classify(b[3]) == SignClass::zero) out.push_back(RootCell{1.0, 1.0, 0});
  return out.overflow ? Isolation::failed : Isolation::complete;
}

/// How far narrow() got.
enum class Narrowing {
  done,     ///< lo and hi are consecutive doubles, or the cell became an exact point
  partial,  ///< max_steps halvings done
  stuck,    ///< a midpoint's sign is uncertain; the cell is still valid, just not narrower
};

/// Halves the root cell while V's sign at the midpoint is certain, at most max_steps times,
/// until lo and hi are consecutive doubles or the midpoint is an exact zero (the cell becomes
/// that point).
Narrowing narrow(const contact::Poly<Interval, 3>& v, RootCell& cell, int max_steps) {
  for (int step = 0; step < max_steps; ++step) {
    if (cell.is_point() || !(std::nextafter(cell.lo, kInf) < cell.hi)) return Narrowing::done;
    double mid = cell.lo + (cell.hi - cell.lo) / 2;
    if (!(cell.lo < mid && mid < cell.hi)) mid = std::nextafter(cell.lo, kInf);
    const SignClass c = classify(v(Interval(mid)));
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

/// Sign oracle over a time interval: certain signs, or kUnknownSign.
struct IntervalSignOracle {
  Interval t;
  template <int D>
  int operator()(const contact::Poly<Interval, D>& p) const {
    const Interval value = p(t);
    const int s = certain_sign(value);
    if (s != 0) return s;
    if (value.inf() == 0 && value.sup() == 0) return 0;  // p vanishes identically on t
    return contact::kUnknownSign;
  }
};

enum class CellVerdict { contact, no_contact, uncertain };

/// The in-plane rule over a root cell; on an uncertain sign the cell is narrowed (16 halvings,
/// then to consecutive doubles) and the rule retried, while narrowing makes progress.
template <class Polys>
CellVerdict in_plane_verdict(const Polys& P, RootCell& cell) {
  for (int attempt = 0; attempt < 3; ++attempt) {
    const contact::Truth t = contact::in_plane_contact(P, IntervalSignOracle{Interval(cell.lo, cell.hi)});
    if (t == contact::Truth::yes) return CellVerdict::contact;
    if (t == contact::Truth::no) return CellVerdict::no_contact;
    if (cell.is_point()) return CellVerdict::uncertain;
    const RootCell before = cell;
    narrow(P.volume(), cell, attempt == 0 ? 16 : 1100);
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

/// The stage on one query.
template <class IntervalQuery>
StageResult interval_stage(const IntervalQuery& q, bool want_toi) {
  const auto P = contact::polynomials(q);
  RootCells cells;
  if (isolate_roots(P.volume(), cells) == Isolation::failed) return {};
  if (cells.size == 0) return {Verdict::no_collision, std::nullopt};
  bool earlier_uncertain = false;
  for (int i = 0; i < cells.size; ++i) {
    RootCell cell = cells.cells[i];
    const CellVerdict v = in_plane_verdict(P, cell);
    if (v == CellVerdict::uncertain) {
      earlier_uncertain = true;
      continue;
    }
    if (v == CellVerdict::no_contact) continue;
    StageResult r{Verdict::collision, std::nullopt};
    // The TOI is this root only if no earlier root is uncertain; narrowing may still fail
    // (e.g. the root is itself a double), then the exact path encloses it.
    if (want_toi && !earlier_uncertain && narrow(P.volume(), cell, 1100) == Narrowing::done)
      r.toi = TimeInterval{cell.lo, cell.hi};
    return r;
  }
  if (earlier_uncertain) return {};
  return {Verdict::no_collision, std::nullopt};
}

}  // namespace

StageResult vertex_face_interval_stage(const VertexFaceQuery& q, bool want_toi) {
  CGAL::Protect_FPU_rounding<true> rounding_towards_infinity;
  return interval_stage(to_interval_query<VertexFaceQueryT<Interval>>(q), want_toi);
}

StageResult edge_edge_interval_stage(const EdgeEdgeQuery& q, bool want_toi) {
  CGAL::Protect_FPU_rounding<true> rounding_towards_infinity;
  return interval_stage(to_interval_query<EdgeEdgeQueryT<Interval>>(q), want_toi);
}

}  // namespace exactccd::filter
