// Stage 3: exact integer arithmetic (docs/design.md, "Integer stage").
//
// Every double is m 2^e with an integer m, |m| < 2^53. Multiplying all 24 coordinates of a
// query by 2^-emin (emin the smallest such e) makes them integers; the contact polynomials of
// the scaled query are the true ones times positive powers of two, so every sign, root and
// decision is unchanged. The polynomials then have integer coefficients and degree <= 4.
//
// Candidate times are those of exact_ccd.cpp: the roots in [0, 1] of V when V is not
// identically zero, else 0, 1 and the roots of the in-plane polynomials the rule can consult.
// Each root is a simple root of an integer polynomial R (the polynomial itself, or its
// square-free part), known exactly (a dyadic) or as R's only root in an open dyadic cell where
// R changes sign. The sign of another polynomial q at a root r in a cell:
// - q(r) = 0 iff r is a root of G = gcd(R, q); G divides R and r is a simple root of R, so a
//   root of G at r is simple and G has no other root in the cell: G(r) = 0 iff G changes sign
//   on the cell;
// - otherwise the cell is halved (exact signs of R at dyadic midpoints) until q's Bernstein
//   coefficients on the cell share one strict sign, which then is q's sign at r. This ends
//   because q(r) != 0 and q is continuous.
#include "filter/integer_stage.hpp"

#include <climits>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <stdexcept>
#include <vector>

#include "contact/contact_rule.hpp"
#include "exact/integer_poly.hpp"
#include "filter/integer_query.hpp"
#include "kinds/primitive_kinds.hpp"
#include "numeric/interval.hpp"

namespace exactccd::filter {
namespace {

using exact::DyadicT;
using exact::IntegerPolyT;
using exact::IsolatedRootT;

/// Cells narrower than 2^-kMaxRefinementBits are left to the CGAL path (measured: a sign that
/// needed ~1000 bisections took 140 ms here, 11 ms in CGAL's kernel).
constexpr unsigned kMaxRefinementBits = 192;

/// A candidate time: a simple root of the polynomial *defining.
template <class Z>
struct Candidate {
  IsolatedRootT<Z> root;
  const IntegerPolyT<Z>* defining = nullptr;  // unused when root.exact
};

using numeric::Interval;  // only under Protect_FPU_rounding

/// A polynomial of the rule seen twice: its interval version (from the double query, built
/// up front) and a thunk building its exact integer version on first need. Most signs are
/// certain in intervals over the candidate's (narrow) cell; only the others cost GMP work.
template <class Z, int D>
struct DualPoly {
  const contact::Poly<Interval, D>* approx;
  std::function<const contact::Poly<Z, D>&()> exact;
};

template <class Z, int D, class Exact>
DualPoly<Z, D> dual(const contact::Poly<Interval, D>& approx, Exact&& exact) {
  return {&approx, std::forward<Exact>(exact)};
}

/// "Point on segment" polynomials as duals (see contact::PointOnSegmentPolys).
template <class Z>
struct DualSegment {
  Vec3T<DualPoly<Z, 2>> cross;
  DualPoly<Z, 2> dot;
};

/// The accessors of VertexFacePolys / EdgeEdgePolys over pairs (interval, exact): the contact
/// rule runs on this unchanged (it is generic over the polynomial set).
template <class Z>
struct DualVertexFace {
  const contact::VertexFacePolys<Interval>& I;
  const contact::VertexFacePolys<Z>& E;
  Vec3T<DualPoly<Z, 2>> normal() const {
    const auto& n = I.normal();
    const auto* z = &E;
    return {dual<Z>(n.x, [z]() -> const auto& { return z->normal().x; }),
            dual<Z>(n.y, [z]() -> const auto& { return z->normal().y; }),
            dual<Z>(n.z, [z]() -> const auto& { return z->normal().z; })};
  }
  DualPoly<Z, 4> barycentric(int i) const {
    const auto* z = &E;
    return dual<Z>(I.barycentric(i), [z, i]() -> const auto& { return z->barycentric(i); });
  }
  DualSegment<Z> on_edge(int i) const {
    const auto& s = I.on_edge(i);
    const auto* z = &E;
    return {{dual<Z>(s.cross.x, [z, i]() -> const auto& { return z->on_edge(i).cross.x; }),
             dual<Z>(s.cross.y, [z, i]() -> const auto& { return z->on_edge(i).cross.y; }),
             dual<Z>(s.cross.z, [z, i]() -> const auto& { return z->on_edge(i).cross.z; })},
            dual<Z>(s.dot, [z, i]() -> const auto& { return z->on_edge(i).dot; })};
  }
};

template <class Z>
struct DualEdgeEdge {
  const contact::EdgeEdgePolys<Interval>& I;
  const contact::EdgeEdgePolys<Z>& E;
  Vec3T<DualPoly<Z, 2>> direction_cross() const {
    const auto& w = I.direction_cross();
    const auto* z = &E;
    return {dual<Z>(w.x, [z]() -> const auto& { return z->direction_cross().x; }),
            dual<Z>(w.y, [z]() -> const auto& { return z->direction_cross().y; }),
            dual<Z>(w.z, [z]() -> const auto& { return z->direction_cross().z; })};
  }
  DualPoly<Z, 4> parameter(int i) const {
    const auto* z = &E;
    return dual<Z>(I.parameter(i), [z, i]() -> const auto& { return z->parameter(i); });
  }
  DualSegment<Z> endpoint_on_edge(int i) const {
    const auto& s = I.endpoint_on_edge(i);
    const auto* z = &E;
    return {{dual<Z>(s.cross.x, [z, i]() -> const auto& { return z->endpoint_on_edge(i).cross.x; }),
             dual<Z>(s.cross.y, [z, i]() -> const auto& { return z->endpoint_on_edge(i).cross.y; }),
             dual<Z>(s.cross.z, [z, i]() -> const auto& { return z->endpoint_on_edge(i).cross.z; })},
            dual<Z>(s.dot, [z, i]() -> const auto& { return z->endpoint_on_edge(i).dot; })};
  }
};

template <class Z>
DualVertexFace<Z> dual_polys(const contact::VertexFacePolys<Interval>& I, const contact::VertexFacePolys<Z>& E) {
  return {I, E};
}
template <class Z>
DualEdgeEdge<Z> dual_polys(const contact::EdgeEdgePolys<Interval>& I, const contact::EdgeEdgePolys<Z>& E) {
  return {I, E};
}

/// A double interval holding the dyadic cell [lo, hi] (0 <= lo <= hi <= 1), computed with
/// integer arithmetic and exact scalings only: no dependence on the rounding mode. With
/// the truncated mantissa m (in [0.5, 1), at most 53 bits; exact::truncated_mantissa, as
/// mpz_get_d_2exp) and exponent x, d >= m 2^x and d < 2^x. While m 2^x is a normal double
/// (x >= -1021) ldexp is exact; below that it could round (in either direction), so the bounds
/// are 0 and 2^-1021 instead, which hold d as well (a cell that close to t = 0 only costs
/// interval precision).
template <class Z>
std::pair<double, double> enclosing_doubles(const DyadicT<Z>& lo, const DyadicT<Z>& hi) {
  const auto split = [](const DyadicT<Z>& d, long& x) {
    long e = 0;
    const double m = exact::truncated_mantissa(d.a, e);  // truncated mantissa in [0.5, 1), or 0
    x = e - static_cast<long>(d.k);
    return m;
  };
  long x_lo = 0, x_hi = 0;
  const double m_lo = split(lo, x_lo), m_hi = split(hi, x_hi);
  const double below = m_lo == 0 || x_lo < -1021 ? 0.0 : std::ldexp(m_lo, static_cast<int>(x_lo));
  const double above = m_hi == 0 ? 0.0 : x_hi < -1021 ? 0x1p-1021 : std::nextafter(std::ldexp(m_hi, static_cast<int>(x_hi)), 2.0);
  return {below, above};
}

/// Exact sign oracle at a candidate; tries the interval polynomial over the candidate's cell
/// first, then the exact integer one (refining the cell as it goes).
template <class Z>
struct RootSignOracle {
  Candidate<Z>& candidate;

  template <int D>
  int operator()(const DualPoly<Z, D>& p) const {
    IsolatedRootT<Z>& r = candidate.root;
    {
      const auto [lo, hi] = r.exact ? enclosing_doubles(r.at, r.at) : enclosing_doubles(r.lo, r.hi);
      CGAL::Protect_FPU_rounding<true> rounding_towards_infinity;
      const Interval value = (*p.approx)(Interval(lo, hi));
      if (value.inf() > 0) return 1;
      if (value.sup() < 0) return -1;
      if (value.inf() == 0 && value.sup() == 0) return 0;  // exactly zero on the whole cell
    }
    const IntegerPolyT<Z> q = integer_poly(p.exact());
    if (q.is_zero()) return 0;
    if (r.exact) return exact::sign_at(q, r.at);
    if (const int s = exact::sign_on_cell(q, r.lo); s != 0) return s;
    const IntegerPolyT<Z> g = exact::gcd(*candidate.defining, q);
    if (g.deg >= 1 && exact::sign_at(g, r.lo) * exact::sign_at(g, r.hi) < 0) return 0;
    for (;;) {
      const int s = exact::sign_on_cell(q, r.lo);
      if (s != 0) return s;
      // q(r) != 0 but tiny: a root of q lies very close to r. Separating them costs one
      // bisection per bit; past kMaxRefinementBits CGAL's kernel is the faster exact judge.
      if (r.lo.k > kMaxRefinementBits) throw std::runtime_error("integer stage: refinement limit");
      exact::bisect(*candidate.defining, r);
      if (r.exact) return exact::sign_at(q, r.at);
    }
  }
};

/// The tightest double interval around a dyadic in [0, 1].
template <class Z>
TimeInterval enclose(const DyadicT<Z>& d) {
  bool exact = false;
  const double lo = exact::floor_to_double(d.a, d.k, exact);
  if (exact) return {lo, lo};
  return {lo, std::nextafter(lo, std::numeric_limits<double>::infinity())};
}

/// The tightest double interval around a candidate.
template <class Z>
TimeInterval enclose(Candidate<Z> c) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  IsolatedRootT<Z>& r = c.root;
  for (;;) {
    if (r.exact) return enclose(r.at);
    bool exact = false;
    const double below = exact::floor_to_double(r.lo.a, r.lo.k, exact);  // <= lo
    const TimeInterval above = enclose(r.hi);             // hi <= above.hi
    if (std::nextafter(below, kInf) >= above.hi) return {below, above.hi};  // lo < t < hi
    exact::bisect(*c.defining, r);
  }
}

/// The earlier of two certified TOI enclosures (a point [d, d] precedes (d, next(d))).
bool earlier(const TimeInterval& a, const TimeInterval& b) {
  return a.lo < b.lo || (a.lo == b.lo && a.hi < b.hi);
}

/// The candidate times of a query, each with the polynomial whose simple root it is (kept at
/// stable addresses).
template <class Z>
struct CandidateTimes {
  std::deque<IntegerPolyT<Z>> defining;
  std::vector<Candidate<Z>> list;

  /// Adds the roots of p in [0, 1] (increasing); returns how many it added.
  std::size_t add_roots_of(const IntegerPolyT<Z>& p) {
    exact::RootsOfT<Z> found = exact::isolate_roots(p);
    defining.push_back(std::move(found.defining));
    for (IsolatedRootT<Z>& r : found.roots) {
      exact::refine_with_approximation(defining.back(), r);
      list.push_back({std::move(r), &defining.back()});
    }
    return found.roots.size();
  }
  /// Adds an exact dyadic time.
  void add_exact(const DyadicT<Z>& at) {
    Candidate<Z> c;
    c.root.exact = true;
    c.root.at = at;
    list.push_back(std::move(c));
  }
};

/// The candidates of a query coplanar for all t (V = 0): 0, 1 and the roots of the polynomials
/// the rule can consult somewhere in [0, 1] (docs/design.md): a branch-vector component that is
/// nonzero without a root in [0, 1] keeps the rule in its proper branch throughout; a branch
/// vector that vanishes identically, in the other.
template <class Z, class Polys>
void add_coplanar_candidates(const Polys& P, CandidateTimes<Z>& times) {
  times.add_exact(DyadicT<Z>{Z(0), 0});
  times.add_exact(DyadicT<Z>{Z(1), 0});
  bool vector_nowhere_zero = false, vector_identically_zero = true;
  const auto& v = contact::branch_vector(P);
  for (const auto* component : {&v.x, &v.y, &v.z}) {
    const IntegerPolyT<Z> ip = integer_poly(*component);
    if (ip.is_zero()) continue;
    vector_identically_zero = false;
    if (times.add_roots_of(ip) == 0) vector_nowhere_zero = true;
  }
  const auto add = [&](const auto& p) {
    const IntegerPolyT<Z> ip = integer_poly(p);
    if (!ip.is_zero()) times.add_roots_of(ip);
  };
  if (!vector_identically_zero) contact::for_each_proper_poly(P, add);
  if (!vector_nowhere_zero) contact::for_each_degenerate_poly(P, add);
}

/// The interval versions of the rule's polynomials of the double query, built up front under
/// the rounding mode interval arithmetic needs (every interval operation, the motions computed
/// by the constructor included, must run under it; the dual oracle evaluates them).
template <class Query>
auto interval_polynomials(const Query& double_query) {
  using IntervalQuery = typename kinds::kind_of<Query>::template Query<Interval>;
  std::array<Vec3T<Interval>, 8> interval_rows;
  const auto d = rows(double_query);
  for (std::size_t i = 0; i < d.size(); ++i) interval_rows[i] = {Interval(d[i].x), Interval(d[i].y), Interval(d[i].z)};
  std::optional<decltype(contact::polynomials(from_rows<IntervalQuery>(interval_rows)))> P;
  CGAL::Protect_FPU_rounding<true> rounding_towards_infinity;
  P.emplace(contact::polynomials(from_rows<IntervalQuery>(interval_rows)));
  contact::for_each_in_plane_poly(*P, [](const auto&) {});
  return P;
}

/// The first candidate where the rule holds (exactly): a collision with its tightest TOI when
/// asked; the roots of V come in increasing order, a coplanar query's are compared.
template <class Z, class DualSet>
pipeline::Outcome earliest_contact(CandidateTimes<Z>& times, const DualSet& dual_set, bool coplanar, bool want_toi) {
  std::optional<TimeInterval> best;
  for (Candidate<Z>& c : times.list) {
    if (contact::in_plane_contact(dual_set, RootSignOracle<Z>{c}) != contact::Truth::yes) continue;  // exact
    if (!want_toi) return pipeline::Outcome::collides();
    const TimeInterval t = enclose(c);
    if (!best || earlier(t, *best)) best = t;
    if (!coplanar) break;
  }
  return best ? pipeline::Outcome::collides(best) : pipeline::Outcome::separate();
}

template <class Z, class IntegerQuery, class Query>
pipeline::Outcome run_integer_stage(const IntegerQuery& q, const Query& double_query, bool want_toi) {
  CandidateTimes<Z> times;
  const auto P = contact::polynomials(q);
  const IntegerPolyT<Z> v = integer_poly(P.volume());
  const bool coplanar = v.is_zero();
  if (coplanar)
    add_coplanar_candidates(P, times);
  else if (times.add_roots_of(v) == 0)
    return pipeline::Outcome::separate();
  const auto PI = interval_polynomials(double_query);
  return earliest_contact(times, dual_polys(*PI, P), coplanar, want_toi);
}

template <class Z, class Query>
pipeline::Outcome integer_stage_of(const Query& q, bool want_toi) {
  try {
    using IntegerQuery = typename kinds::kind_of<Query>::template Query<Z>;
    return run_integer_stage<Z>(to_integer_query<IntegerQuery>(q), q, want_toi);
  } catch (const std::runtime_error&) {
    // GMP: an internal limit, the CGAL path decides. FixedInteger: also an overflow
    // (std::overflow_error) or a subnormal time (integer_ops.hpp): the GMP stage decides.
    return pipeline::Outcome::undecided();
  }
}

template <class Query>
pipeline::Outcome fixed_integer_stage_of(const Query& q, bool want_toi) {
  if (exponent_spread(q) > kFixedIntegerSpreadLimit) return pipeline::Outcome::undecided();
  return integer_stage_of<exact::FixedInteger>(q, want_toi);
}

}  // namespace

pipeline::Outcome integer_stage(const VertexFaceQuery& q, bool want_toi) { return integer_stage_of<Integer>(q, want_toi); }
pipeline::Outcome integer_stage(const EdgeEdgeQuery& q, bool want_toi) { return integer_stage_of<Integer>(q, want_toi); }

pipeline::Outcome fixed_integer_stage(const VertexFaceQuery& q, bool want_toi) { return fixed_integer_stage_of(q, want_toi); }
pipeline::Outcome fixed_integer_stage(const EdgeEdgeQuery& q, bool want_toi) { return fixed_integer_stage_of(q, want_toi); }

}  // namespace exactccd::filter
