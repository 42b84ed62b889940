// Exact minimum separation (docs/design.md, "Minimum separation"). The set
// S = {t in [0, tmax] : some term holds at t} is closed. Its least element t* is 0, or a root
// of a term's distance polynomial f that is not identically zero: at t* > 0 a term holds, its
// strict conditions g > 0 hold on a neighbourhood of t*, so it fails just before t* only
// through f > 0 there, while f(t*) <= 0; by continuity f(t*) = 0, and f is not identically
// zero. So t* is the first candidate (0 and those roots in [0, tmax], increasing) at which a
// term holds, decided with exact signs at algebraic numbers.
#include "separation/exact_separation.hpp"

#include <algorithm>
#include <vector>

#include "exact/algebraic_kernel.hpp"
#include "exact/stack_budget.hpp"
#include "contact/separation_terms.hpp"

namespace exactccd::separation {
namespace {

using namespace exact::algebraic;

/// A term with integer polynomials (each a positive multiple of the rational one).
struct IntegerTerm {
  IntegerPoly distance;
  std::vector<IntegerPoly> positive;
};

/// The terms of the query's feature pairs with use[f], as integer polynomials; `bits` receives
/// the most bits of a coefficient (which bounds CGAL's recursion depth).
template <class Query>
std::vector<IntegerTerm> integer_terms(const Query& q, const RationalCcdParams& params, const kinds::FeatureMask& use,
                                       std::size_t& bits) {
  using Kind = kinds::kind_of<Query>;
  static_assert(Kind::features.size() <= std::tuple_size_v<kinds::FeatureMask>);
  const mpq_class d2 = params.min_distance * params.min_distance;
  std::vector<IntegerTerm> terms;
  bits = 0;
  for (const contact::Term<mpq_class>& t : contact::terms<Kind>(contact::points3<mpq_class>(q), d2, use.data())) {
    IntegerTerm it{integer_poly(t.distance), {}};
    bits = std::max(bits, coefficient_bits(it.distance));
    for (int i = 0; i < t.positives; ++i) {
      it.positive.push_back(integer_poly(t.positive[i]));
      bits = std::max(bits, coefficient_bits(it.positive.back()));
    }
    terms.push_back(std::move(it));
  }
  return terms;
}

/// Some term holds at the algebraic time t (every sign exact).
bool some_term_holds(const Kernel& kernel, const std::vector<IntegerTerm>& terms, const Root& t) {
  const auto sign_at = kernel.sign_at_1_object();
  const auto sign = [&](const IntegerPoly& p) { return CGAL::is_zero(p) ? 0 : static_cast<int>(sign_at(p, t)); };
  return std::any_of(terms.begin(), terms.end(), [&](const IntegerTerm& term) {
    return std::all_of(term.positive.begin(), term.positive.end(), [&](const IntegerPoly& g) { return sign(g) > 0; }) &&
           sign(term.distance) <= 0;
  });
}

/// The first candidate time (0 and the roots in [0, tmax] of every nonzero f, increasing) at
/// which a term holds, in its tightest double interval.
std::optional<TimeInterval> earliest(const std::vector<IntegerTerm>& terms, const mpq_class& tmax) {
  const Kernel kernel;
  std::vector<Root> times{rational_root(0)};
  for (const IntegerTerm& t : terms)
    if (!CGAL::is_zero(t.distance)) append_roots(kernel, t.distance, 0, tmax, times);
  sort_unique(kernel, times);
  for (const Root& t : times)
    if (some_term_holds(kernel, terms, t)) return enclose(kernel, t);
  return std::nullopt;
}

}  // namespace

template <class RationalQuery>
std::optional<TimeInterval> exact_toi(const RationalQuery& q, const RationalCcdParams& params,
                                      const kinds::FeatureMask& use) {
  std::size_t bits = 0;
  const std::vector<IntegerTerm> terms = integer_terms(q, params, use, bits);
  std::optional<TimeInterval> result;
  exact::run_with_stack_for_depth(exact::descartes_depth_bound(bits), [&] { result = earliest(terms, params.tmax); });
  return result;
}

// The exact path for every kind of the minimum-separation question (kinds::for_each_kind).
template std::optional<TimeInterval> exact_toi(const RationalVertexFaceQuery&, const RationalCcdParams&, const kinds::FeatureMask&);
template std::optional<TimeInterval> exact_toi(const RationalEdgeEdgeQuery&, const RationalCcdParams&, const kinds::FeatureMask&);
template std::optional<TimeInterval> exact_toi(const RationalPointEdgeQuery&, const RationalCcdParams&, const kinds::FeatureMask&);
template std::optional<TimeInterval> exact_toi(const RationalPointPointQuery&, const RationalCcdParams&, const kinds::FeatureMask&);
template std::optional<TimeInterval> exact_toi(const RationalEdgeEdge2dQuery&, const RationalCcdParams&, const kinds::FeatureMask&);
template std::optional<TimeInterval> exact_toi(const RationalPointEdge2dQuery&, const RationalCcdParams&, const kinds::FeatureMask&);
template std::optional<TimeInterval> exact_toi(const RationalPointPoint2dQuery&, const RationalCcdParams&, const kinds::FeatureMask&);

}  // namespace exactccd::separation
