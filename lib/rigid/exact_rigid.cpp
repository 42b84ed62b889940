// The exact path of the rigid motion model (docs/design.md, 9.3).
//
// 1. Integers: every length (translations, body points, d) is multiplied by the lcm of their
//    denominators, and each body's two quaternions by the lcm of theirs. The first multiplies
//    every polynomial of the rule by a positive power of that factor (they are homogeneous in
//    lengths), the second changes no rotation (R(s q) = R(q) for s != 0, and both ends of the
//    body's path are scaled alike, so q(t) becomes s q(t)). Signs and roots are unchanged.
// 2. The rule's polynomials on the scaled frame (rigid_frame.hpp): the true values times
//    D(t)^k, with D = |qA|^2 |qB|^2 > 0 on [0, 1].
// 3. Each is divided by the primitive parts of |qA|^2 and |qB|^2 (positive on [0, 1]) while
//    they divide it exactly; then by its content. A positive factor changes no sign, so the
//    result has the roots and signs of the true rational function on [0, 1].
// 4. The one exact "earliest root where the rule holds" of the linear paths (exact/
//    earliest_root.hpp: candidates the roots of V in [0, tmax], or, when V vanishes identically,
//    0 and the roots of every in-plane polynomial; at d > 0, 0 and the roots of the terms' f),
//    whose proofs (docs/design.md, 3 and 4b.2) use only that the rule is a Boolean formula over
//    the signs of finitely many continuous functions whose zero sets are finite or everything,
//    and that the contact set is closed: both hold for rational functions with a positive
//    denominator.
#include "rigid/exact_rigid.hpp"

#include <algorithm>
#include <map>
#include <vector>

#include "contact/contact_rule.hpp"
#include "exact/algebraic_kernel.hpp"
#include "exact/earliest_root.hpp"
#include "exact/stack_budget.hpp"
#include "rigid/rigid_frame.hpp"
#include "contact/separation_terms.hpp"

namespace exactccd::rigid {
namespace {

using namespace exact::algebraic;
using Z = mpz_class;
using Coefficients = std::vector<Z>;

// --- 1. integers ------------------------------------------------------------------------------

/// The lcm of the denominators of `values` times 1.
mpz_class common_denominator(const std::vector<const mpq_class*>& values) {
  mpz_class l = 1;
  for (const mpq_class* v : values) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), v->get_den_mpz_t());
  return l;
}

Z times(const mpq_class& x, const mpz_class& l) { return x.get_num() * (l / x.get_den()); }

/// The query type of the kind of Query in integers.
template <class Query>
using IntegerQuery = typename kinds::kind_of<Query>::template RigidQuery<Z>;

/// The query and d in integers (step 1).
template <class Query>
std::pair<IntegerQuery<Query>, Z> to_integers(const Query& q, const mpq_class& d) {
  std::vector<const mpq_class*> lengths{&d}, qa, qb;
  const auto add3 = [](std::vector<const mpq_class*>& v, const Vec3T<mpq_class>& p) {
    v.insert(v.end(), {&p.x, &p.y, &p.z});
  };
  const auto add4 = [](std::vector<const mpq_class*>& v, const QuaternionT<mpq_class>& r) {
    v.insert(v.end(), {&r.w, &r.x, &r.y, &r.z});
  };
  for (const auto* pose : {&q.a_t0, &q.a_t1, &q.b_t0, &q.b_t1}) add3(lengths, pose->c);
  const auto points = body_points(q);
  for (const auto& p : points) add3(lengths, p);
  add4(qa, q.a_t0.q), add4(qa, q.a_t1.q), add4(qb, q.b_t0.q), add4(qb, q.b_t1.q);
  const mpz_class L = common_denominator(lengths), LA = common_denominator(qa), LB = common_denominator(qb);
  const auto vec = [&](const Vec3T<mpq_class>& p) { return Vec3T<Z>{times(p.x, L), times(p.y, L), times(p.z, L)}; };
  const auto quat = [](const QuaternionT<mpq_class>& r, const mpz_class& l) {
    return QuaternionT<Z>{times(r.w, l), times(r.x, l), times(r.y, l), times(r.z, l)};
  };
  IntegerQuery<Query> out;
  out.a_t0 = {vec(q.a_t0.c), quat(q.a_t0.q, LA)};
  out.a_t1 = {vec(q.a_t1.c), quat(q.a_t1.q, LA)};
  out.b_t0 = {vec(q.b_t0.c), quat(q.b_t0.q, LB)};
  out.b_t1 = {vec(q.b_t1.c), quat(q.b_t1.q, LB)};
  if constexpr (std::is_same_v<kinds::kind_of<Query>, kinds::VertexFace>)
    out.p = vec(q.p), out.a = vec(q.a), out.b = vec(q.b), out.c = vec(q.c);
  else
    out.a0 = vec(q.a0), out.a1 = vec(q.a1), out.b0 = vec(q.b0), out.b1 = vec(q.b1);
  return {out, times(d, L)};
}

// --- 3. division by the positive factors --------------------------------------------------------

void trim(Coefficients& c) {
  while (!c.empty() && c.back() == 0) c.pop_back();
}

/// Replaces c by c / f when the primitive f (degree >= 1) divides it in Z[t] (by Gauss's lemma,
/// iff it divides it in Q[t]); false, c unchanged, otherwise.
bool divide_exactly(Coefficients& c, const Coefficients& f) {
  const std::size_t m = f.size() - 1;
  if (c.size() < f.size()) return false;  // also the zero polynomial: left as it is
  const std::size_t n = c.size() - 1;
  Coefficients r = c, quotient(n - m + 1);
  for (std::size_t k = n + 1; k-- > m;) {
    if (!mpz_divisible_p(r[k].get_mpz_t(), f[m].get_mpz_t())) return false;
    const Z qk = r[k] / f[m];
    for (std::size_t j = 0; j <= m; ++j) r[k - m + j] -= qk * f[j];
    quotient[k - m] = qk;
  }
  for (std::size_t j = 0; j < m; ++j)
    if (r[j] != 0) return false;
  c = std::move(quotient);
  return true;
}

/// The positive factors |qA|^2 and |qB|^2 that are not constant, as primitive polynomials.
struct Factors {
  std::vector<Coefficients> primitive;

  explicit Factors(const ScaledFrame<Z>& frame) {
    for (const auto* f : {&frame.norm_a, &frame.norm_b}) {
      Coefficients c(f->c.begin(), f->c.end());
      trim(c);
      if (c.size() < 2) continue;  // constant: a positive number, changes nothing
      Z g = 0;
      for (const Z& x : c) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), x.get_mpz_t());
      for (Z& x : c) x /= g;  // g > 0 (|q(t)|^2 is a sum of squares): the same signs
      primitive.push_back(std::move(c));
    }
  }
};

/// The polynomial divided by the positive factors while they divide it, then by its content:
/// the same signs as p on [0, 1] (step 3).
template <int D>
IntegerPoly reduce(const contact::Poly<Z, D>& p, const Factors& factors) {
  Coefficients c(p.c.begin(), p.c.end());
  trim(c);
  for (const Coefficients& f : factors.primitive)
    while (divide_exactly(c, f)) {
    }
  Z g = 0;
  for (const Z& x : c) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), x.get_mpz_t());
  std::vector<CGAL::Gmpz> out;
  out.reserve(c.size());
  for (Z& x : c) out.emplace_back(Z(x / g).get_mpz_t());
  if (out.empty()) out.emplace_back(0);
  return IntegerPoly(out.begin(), out.end());
}

/// The reduced polynomials of one query's terms, each built once (the term classes keep their
/// polynomials, so their addresses identify them), with the largest degree and coefficient size
/// seen (for the stack budget).
class Reduced {
 public:
  explicit Reduced(const Factors& factors) : factors_(factors) {}
  template <int D>
  const IntegerPoly& operator()(const contact::Poly<Z, D>& p) {
    const auto it = cache_.find(&p);
    if (it != cache_.end()) return it->second;
    return note(cache_.emplace(&p, reduce(p, factors_)).first->second);
  }
  /// Notes a polynomial reduced elsewhere.
  const IntegerPoly& note(const IntegerPoly& p) {
    degree_ = std::max(degree_, CGAL::degree(p));
    bits_ = std::max(bits_, coefficient_bits(p));
    return p;
  }
  /// The stack CGAL's isolation needs for every polynomial reduced so far.
  std::size_t depth_bound() const { return exact::descartes_depth_bound(bits_, std::max(degree_, 1)); }

 private:
  const Factors& factors_;
  std::map<const void*, IntegerPoly> cache_;
  int degree_ = 0;
  std::size_t bits_ = 0;
};

// --- 4. the contact rule (d = 0) ----------------------------------------------------------------

template <class Query>
std::optional<TimeInterval> contact_toi(const Query& q, const mpq_class& tmax) {
  const auto [integer, d] = to_integers(q, mpq_class(0));
  const ScaledFrame<Z> frame = scaled_frame(integer);
  const Factors factors(frame);
  const auto P = contact_terms<decltype(integer)>(frame);
  Reduced reduced(factors);
  reduced(P.volume());  // every polynomial CGAL may see, for the stack bound
  contact::for_each_in_plane_poly(P, [&](const auto& p) { reduced(p); });
  std::optional<TimeInterval> result;
  exact::run_with_stack_for_depth(reduced.depth_bound(), [&] {
    const Kernel kernel;
    if (const std::optional<Root> t = earliest_contact(kernel, P, reduced, tmax)) result = enclose(kernel, *t);
  });
  return result;
}

// --- 4. the feature-pair terms (any d) ----------------------------------------------------------

/// Every feature pair's term on the scaled frame, reduced: f(t) D^k and g(t) D^k (with d D(t) in
/// place of d: f is homogeneous in the lengths and d together).
template <class Kind>
std::vector<IntegerTerm> integer_terms(const ScaledFrame<Z>& frame, const Z& d, Reduced& reduced, const Factors& factors) {
  const ScaledFrameMotion<Z> motion(frame);
  const auto rel = [&](int i, int j) { return motion.rel(i, j); };
  const contact::Poly<Z, 0> d2{{Z(d * d)}};
  const auto dd = d2 * frame.D * frame.D;  // (d D)^2
  std::vector<IntegerTerm> terms;
  for (const kinds::Feature& f : Kind::features)
    contact::feature_condition(f, rel, dd, [&](const auto& distance, const auto&... positive) {
      IntegerTerm t{reduced.note(reduce(distance, factors)), {}};
      (t.positive.push_back(reduced.note(reduce(positive, factors))), ...);
      terms.push_back(std::move(t));
    });
  return terms;
}

template <class Query>
std::optional<TimeInterval> separation_toi(const Query& q, const RationalCcdParams& params) {
  const auto [integer, d] = to_integers(q, params.min_distance);
  const ScaledFrame<Z> frame = scaled_frame(integer);
  const Factors factors(frame);
  Reduced reduced(factors);
  const std::vector<IntegerTerm> terms = integer_terms<kinds::kind_of<Query>>(frame, d, reduced, factors);
  std::optional<TimeInterval> result;
  exact::run_with_stack_for_depth(reduced.depth_bound(), [&] {
    const Kernel kernel;
    if (const std::optional<Root> t = earliest_term_time(kernel, terms, params.tmax)) result = enclose(kernel, *t);
  });
  return result;
}

template <class Query>
ReducedDegrees degrees_of(const Query& q, const mpq_class& d_rational) {
  const auto [integer, d] = to_integers(q, d_rational);
  const ScaledFrame<Z> frame = scaled_frame(integer);
  const Factors factors(frame);
  const auto P = contact_terms<decltype(integer)>(frame);
  Reduced reduced(factors);
  ReducedDegrees out;
  const auto degree = [](const IntegerPoly& p) { return CGAL::is_zero(p) ? -1 : CGAL::degree(p); };
  out.volume = degree(reduced(P.volume()));
  contact::for_each_in_plane_poly(P, [&](const auto& p) { out.in_plane = std::max(out.in_plane, degree(reduced(p))); });
  for (const IntegerTerm& t : integer_terms<kinds::kind_of<Query>>(frame, d, reduced, factors)) {
    out.term = std::max(out.term, degree(t.distance));
    for (const IntegerPoly& g : t.positive) out.term = std::max(out.term, degree(g));
  }
  return out;
}

template <class Query>
std::optional<TimeInterval> toi_of(const Query& q, const RationalCcdParams& params) {
  if (params.contact_only()) return contact_toi(q, params.tmax);
  return separation_toi(q, params);
}

}  // namespace

std::optional<TimeInterval> exact_toi(const RationalRigidVertexFaceQuery& q, const RationalCcdParams& p) { return toi_of(q, p); }
std::optional<TimeInterval> exact_toi(const RationalRigidEdgeEdgeQuery& q, const RationalCcdParams& p) { return toi_of(q, p); }
std::optional<TimeInterval> exact_separation_toi(const RationalRigidVertexFaceQuery& q, const RationalCcdParams& p) {
  return separation_toi(q, p);
}
std::optional<TimeInterval> exact_separation_toi(const RationalRigidEdgeEdgeQuery& q, const RationalCcdParams& p) {
  return separation_toi(q, p);
}
ReducedDegrees reduced_degrees(const RationalRigidVertexFaceQuery& q, const mpq_class& d) { return degrees_of(q, d); }
ReducedDegrees reduced_degrees(const RationalRigidEdgeEdgeQuery& q, const mpq_class& d) { return degrees_of(q, d); }

}  // namespace exactccd::rigid
