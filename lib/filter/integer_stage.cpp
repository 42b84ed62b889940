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

/// Cells narrower than 2^-kMaxRefinementBits are left to the CGAL path (measured: a sign that
/// needed ~1000 bisections took 140 ms here, 11 ms in CGAL's kernel).
constexpr unsigned kMaxRefinementBits = 192;

/// A candidate time: a simple root of the polynomial *defining.
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
      // q(r) != 0 but tiny: a root of q lies very close to r. Separating them costs one
      // bisection per bit; past kMaxRefinementBits CGAL's kernel is the faster exact judge.
      if (r.lo.k > kMaxRefinementBits) throw std::runtime_error("integer stage: refinement limit");
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
  const auto add_roots_of = [&](const IntegerPoly& p) {  // returns how many roots it added
    exact::RootsOf found = exact::isolate_roots(p);
    defining.push_back(std::move(found.defining));
    for (IsolatedRoot& r : found.roots) {
      exact::refine_with_approximation(defining.back(), r);
      candidates.push_back({std::move(r), &defining.back()});
    }
    return found.roots.size();
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
    // Only the polynomials the rule can consult somewhere in [0, 1] matter (docs/design.md):
    // a branch-vector component that is nonzero without a root in [0, 1] keeps the rule in
    // its proper branch throughout; a branch vector that vanishes identically, in the other.
    bool vector_nowhere_zero = false, vector_identically_zero = true;
    const auto& v = contact::branch_vector(P);
    for (const auto* component : {&v.x, &v.y, &v.z}) {
      const IntegerPoly ip = integer_poly(*component);
      if (ip.is_zero()) continue;
      vector_identically_zero = false;
      if (add_roots_of(ip) == 0) vector_nowhere_zero = true;
    }
    const auto add = [&](const auto& p) {
      const IntegerPoly ip = integer_poly(p);
      if (!ip.is_zero()) add_roots_of(ip);
    };
    if (!vector_identically_zero) contact::for_each_proper_poly(P, add);
    if (!vector_nowhere_zero) contact::for_each_degenerate_poly(P, add);
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
