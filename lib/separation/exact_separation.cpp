// Exact minimum separation (docs/design.md, "Minimum separation"): the feature-pair terms
// (contact/separation_terms.hpp) in GMP rationals, made integers, and the one exact "earliest
// root where the rule holds" (exact/earliest_root.hpp, the proof there: the candidates are 0 and
// the roots in [0, tmax] of every term's f).
#include "separation/exact_separation.hpp"

#include <algorithm>
#include <vector>

#include "contact/separation_terms.hpp"
#include "exact/algebraic_kernel.hpp"
#include "exact/earliest_root.hpp"
#include "exact/stack_budget.hpp"

namespace exactccd::separation {
namespace {

using namespace exact::algebraic;

/// The terms of the query's feature pairs with use[f], as integer polynomials (each a positive
/// multiple of the rational one); `bits` receives the most bits of a coefficient (which bounds
/// CGAL's recursion depth).
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

/// The earliest time in [0, tmax] at which a term holds, in its tightest double interval.
std::optional<TimeInterval> earliest(const std::vector<IntegerTerm>& terms, const mpq_class& tmax) {
  const Kernel kernel;
  const std::optional<Root> t = earliest_term_time(kernel, terms, tmax);
  if (!t) return std::nullopt;
  return enclose(kernel, *t);
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
