// Stage 3: exact integer arithmetic (docs/design.md, "Integer stage").
//
// Every double is m 2^e with an integer m, |m| < 2^53. Multiplying all 24 coordinates of a
// query by 2^-emin (emin the smallest such e) makes them integers; the contact polynomials of
// the scaled query are the true ones times positive powers of two, so every sign, root and
// decision is unchanged. The polynomials then have integer coefficients and degree <= 4.
//
// Candidate times are those of exact_ccd.cpp: the roots in [0, 1] of V when V is not
// identically zero, else 0, 1 and the roots of every in-plane polynomial. Each root is that
// of a square-free integer polynomial R, known exactly (a dyadic) or isolated in an open
// dyadic cell where R changes sign. The sign of another polynomial q at a root r in a cell:
// - q(r) = 0 iff r is a root of G = gcd(R, q); G divides the square-free R, so its roots are
//   simple and r is the only root of R in the cell: G(r) = 0 iff G changes sign on the cell;
// - otherwise the cell is halved (exact signs of R at dyadic midpoints) until q's Bernstein
//   coefficients on the cell share one strict sign, which then is q's sign at r. This ends
//   because q(r) != 0 and q is continuous.
#include "filter/integer_stage.hpp"

#include <climits>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>
#include <vector>

#include "contact/contact_rule.hpp"
#include "exact/integer_poly.hpp"

namespace exactccd::filter {
namespace {

using exact::Dyadic;
using exact::IntegerPoly;
using exact::IsolatedRoot;
using Integer = mpz_class;

template <int D>
IntegerPoly integer_poly(const contact::Poly<Integer, D>& p) {
  IntegerPoly r;
  for (int i = 0; i <= D; ++i) r.c[i] = p.c[i];
  r.normalize();
  return r;
}

/// The query's coordinates times 2^-emin, all integers (see the file comment).
template <class IntegerQuery, class Query>
IntegerQuery to_integer_query(const Query& q) {
  const auto r = rows(q);
  int emin = INT_MAX;
  for (const Vec3& v : r)
    for (double x : {v.x, v.y, v.z})
      if (x != 0) {
        int e = 0;
        std::frexp(x, &e);
        emin = std::min(emin, e - 53);
      }
  const auto scaled = [emin](double x) {
    Integer z;
    if (x == 0) return z;
    int e = 0;
    const double f = std::frexp(x, &e);
    z = Integer(std::ldexp(f, 53));  // exact: an integer below 2^53 in magnitude
    mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), static_cast<unsigned long>(e - 53 - emin));
    return z;
  };
  std::array<Vec3T<Integer>, 8> out;
  for (std::size_t i = 0; i < r.size(); ++i) out[i] = {scaled(r[i].x), scaled(r[i].y), scaled(r[i].z)};
  return from_rows<IntegerQuery>(out);
}

/// A candidate time: a root of the square-free polynomial *defining.
struct Candidate {
  IsolatedRoot root;
  const IntegerPoly* defining = nullptr;  // unused when root.exact
};

/// Exact sign oracle at a candidate; refines the candidate's cell as it goes.
struct RootSignOracle {
  Candidate& candidate;

  template <int D>
  int operator()(const contact::Poly<Integer, D>& p) const {
    const IntegerPoly q = integer_poly(p);
    if (q.is_zero()) return 0;
    IsolatedRoot& r = candidate.root;
    if (r.exact) return exact::sign_at(q, r.at);
    if (const int s = exact::sign_on_cell(q, r.lo); s != 0) return s;
    const IntegerPoly g = exact::gcd(*candidate.defining, q);
    if (g.deg >= 1 && exact::sign_at(g, r.lo) * exact::sign_at(g, r.hi) < 0) return 0;
    for (;;) {
      const int s = exact::sign_on_cell(q, r.lo);
      if (s != 0) return s;
      exact::bisect(*candidate.defining, r);
      if (r.exact) return exact::sign_at(q, r.at);
    }
  }
};

mpq_class value(const Dyadic& d) {
  mpq_class x(d.a);
  mpq_div_2exp(x.get_mpq_t(), x.get_mpq_t(), d.k);
  return x;
}

/// The tightest double interval around a dyadic in [0, 1].
TimeInterval enclose(const Dyadic& d) {
  const mpq_class x = value(d);
  const double lo = x.get_d();  // truncation: rounds down for x >= 0
  if (mpq_class(lo) == x) return {lo, lo};
  return {lo, std::nextafter(lo, std::numeric_limits<double>::infinity())};
}

/// The tightest double interval around a candidate.
TimeInterval enclose(Candidate c) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  IsolatedRoot& r = c.root;
  for (;;) {
    if (r.exact) return enclose(r.at);
    const double below = value(r.lo).get_d();            // <= lo
    const TimeInterval above = enclose(r.hi);             // hi <= above.hi
    if (std::nextafter(below, kInf) >= above.hi) return {below, above.hi};  // lo < t < hi
    exact::bisect(*c.defining, r);
  }
}

/// The earlier of two certified TOI enclosures (a point [d, d] precedes (d, next(d))).
bool earlier(const TimeInterval& a, const TimeInterval& b) {
  return a.lo < b.lo || (a.lo == b.lo && a.hi < b.hi);
}

template <class IntegerQuery>
StageResult integer_stage(const IntegerQuery& q, bool want_toi) {
  std::deque<IntegerPoly> defining;  // stable addresses for Candidate::defining
  std::vector<Candidate> candidates;
  const auto add_roots_of = [&](const IntegerPoly& p) {
    defining.push_back(exact::square_free_part(p));
    for (IsolatedRoot& r : exact::roots_in_unit_interval(defining.back())) {
      exact::refine_with_approximation(defining.back(), r);
      candidates.push_back({std::move(r), &defining.back()});
    }
  };

  const auto P = contact::polynomials(q);
  const IntegerPoly v = integer_poly(P.volume());
  const bool coplanar = v.is_zero();
  if (!coplanar) add_roots_of(v);  // increasing order
  if (!coplanar && candidates.empty()) return {Verdict::no_collision, std::nullopt};

  if (coplanar) {
    for (const Dyadic& end : {Dyadic{0, 0}, Dyadic{1, 0}}) {
      Candidate c;
      c.root.exact = true;
      c.root.at = end;
      candidates.push_back(std::move(c));
    }
    contact::for_each_in_plane_poly(P, [&](const auto& p) {
      const IntegerPoly ip = integer_poly(p);
      if (!ip.is_zero()) add_roots_of(ip);
    });
  }

  std::optional<TimeInterval> best;
  for (Candidate& c : candidates) {
    if (contact::in_plane_contact(P, RootSignOracle{c}) != contact::Truth::yes) continue;  // exact
    if (!want_toi) return {Verdict::collision, std::nullopt};
    const TimeInterval t = enclose(c);
    if (!best || earlier(t, *best)) best = t;
    if (!coplanar) break;  // the roots of V come in increasing order
  }
  if (!best) return {Verdict::no_collision, std::nullopt};
  return {Verdict::collision, best};
}

}  // namespace

StageResult vertex_face_integer_stage(const VertexFaceQuery& q, bool want_toi) {
  try {
    return integer_stage(to_integer_query<VertexFaceQueryT<Integer>>(q), want_toi);
  } catch (const std::runtime_error&) {  // an internal limit: let the CGAL path decide
    return {};
  }
}

StageResult edge_edge_integer_stage(const EdgeEdgeQuery& q, bool want_toi) {
  try {
    return integer_stage(to_integer_query<EdgeEdgeQueryT<Integer>>(q), want_toi);
  } catch (const std::runtime_error&) {
    return {};
  }
}

}  // namespace exactccd::filter
