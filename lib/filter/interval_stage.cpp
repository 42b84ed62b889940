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
//    number). Anything else is halved, up to a depth limit; then the stage gives up.
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

/// Thrown by the sign oracle when a sign is not certain; caught within this file.
struct UncertainSign {};

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

/// An interval [lo, hi] of t holding exactly one simple root of V, with the sign of V at lo.
struct RootCell {
  double lo, hi;
  int sign_at_lo;
};

enum class Isolation { complete, failed };

/// Appends the root cells of V in [lo, hi] (coefficients b) in increasing order.
template <class Out>
Isolation isolate(const Bernstein& b, double lo, double hi, int depth, Out& out) {
  std::array<int, 4> s{};
  bool all_certain = true;
  for (int i = 0; i < 4; ++i) {
    s[i] = certain_sign(b[i]);
    all_certain = all_certain && s[i] != 0;
  }
  if (all_certain) {
    const int changes = (s[0] != s[1]) + (s[1] != s[2]) + (s[2] != s[3]);
    if (changes == 0) return Isolation::complete;
    if (changes == 1) {
      out.push_back(RootCell{lo, hi, s[0]});
      return Isolation::complete;
    }
  }
  if (depth == kMaxSubdivisionDepth) return Isolation::failed;
  Bernstein left, right;
  halve(b, left, right);
  const double mid = lo + (hi - lo) / 2;  // exact: dyadic cells of [0, 1]
  if (isolate(left, lo, mid, depth + 1, out) == Isolation::failed) return Isolation::failed;
  return isolate(right, mid, hi, depth + 1, out);
}

/// Small fixed-capacity list: a cubic has at most three root cells.
struct RootCells {
  std::array<RootCell, 3> cells;
  int size = 0;
  void push_back(const RootCell& c) {
    if (size < 3) cells[size++] = c;
  }
};

/// Certified sign of V at the double t, or 0 when uncertain.
int volume_sign_at(const contact::Poly<Interval, 3>& v, double t) {
  return certain_sign(v(Interval(t)));
}

/// Halves the root cell while V's sign at the midpoint is certain, until lo and hi are
/// consecutive doubles. False when a midpoint's sign is uncertain (the cell is kept valid).
bool narrow(const contact::Poly<Interval, 3>& v, RootCell& cell, int max_steps) {
  for (int step = 0; step < max_steps && std::nextafter(cell.lo, kInf) < cell.hi; ++step) {
    double mid = cell.lo + (cell.hi - cell.lo) / 2;
    if (!(cell.lo < mid && mid < cell.hi)) mid = std::nextafter(cell.lo, kInf);
    const int s = volume_sign_at(v, mid);
    if (s == 0) return false;
    (s == cell.sign_at_lo ? cell.lo : cell.hi) = mid;
  }
  return true;
}

/// Sign oracle over a time interval: certain signs or UncertainSign.
struct IntervalSignOracle {
  Interval t;
  template <int D>
  int operator()(const contact::Poly<Interval, D>& p) const {
    const Interval value = p(t);
    const int s = certain_sign(value);
    if (s != 0) return s;
    if (value.inf() == 0 && value.sup() == 0) return 0;  // p vanishes identically on t
    throw UncertainSign{};
  }
};

enum class CellVerdict { contact, no_contact, uncertain };

template <class Polys>
CellVerdict in_plane_verdict(const Polys& P, RootCell& cell) {
  for (int attempt = 0; attempt < 2; ++attempt) {
    try {
      return contact::in_plane_contact(P, IntervalSignOracle{Interval(cell.lo, cell.hi)})
                 ? CellVerdict::contact
                 : CellVerdict::no_contact;
    } catch (const UncertainSign&) {
      if (attempt == 0 && !narrow(P.volume(), cell, 64)) return CellVerdict::uncertain;
    }
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
  if (isolate(to_bernstein(P.volume()), 0.0, 1.0, 0, cells) == Isolation::failed) return {};
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
    if (want_toi && !earlier_uncertain && narrow(P.volume(), cell, 1100))
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
