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
#include "separation/separation_terms.hpp"

namespace exactccd::separation {
namespace {

using namespace exact::algebraic;

/// A term with integer polynomials (each a positive multiple of the rational one).
struct IntegerTerm {
  IntegerPoly distance;
  std::vector<IntegerPoly> positive;
};

template <class Query>
std::optional<TimeInterval> earliest(const Query& q, const RationalCcdParams& params, const FeatureMask* use = nullptr) {
  using Kind = kinds::kind_of<Query>;
  const mpq_class d2 = params.min_distance * params.min_distance;
  std::vector<IntegerTerm> terms;
  std::size_t bits = 0;
  static_assert(Kind::features.size() <= std::tuple_size_v<FeatureMask>);
  std::array<bool, Kind::features.size()> used;
  for (std::size_t f = 0; f < used.size(); ++f) used[f] = !use || (*use)[f];
  for (const Term<mpq_class>& t : separation::terms<Kind>(points3<mpq_class>(q), d2, used.data())) {
    IntegerTerm it{integer_poly(t.distance), {}};
    bits = std::max(bits, coefficient_bits(it.distance));
    for (int i = 0; i < t.positives; ++i) {
      it.positive.push_back(integer_poly(t.positive[i]));
      bits = std::max(bits, coefficient_bits(it.positive.back()));
    }
    terms.push_back(std::move(it));
  }
  std::optional<TimeInterval> result;
  exact::run_with_stack_for_depth(exact::descartes_depth_bound(bits), [&] {
    const Kernel kernel;
    std::vector<Root> times{rational_root(0)};
    for (const IntegerTerm& t : terms)
      if (!CGAL::is_zero(t.distance)) append_roots(kernel, t.distance, 0, params.tmax, times);
    sort_unique(kernel, times);
    const auto sign_at = kernel.sign_at_1_object();
    const auto sign = [&](const IntegerPoly& p, const Root& t) {
      return CGAL::is_zero(p) ? 0 : static_cast<int>(sign_at(p, t));
    };
    for (const Root& t : times) {
      const bool holds = std::any_of(terms.begin(), terms.end(), [&](const IntegerTerm& term) {
        return std::all_of(term.positive.begin(), term.positive.end(),
                           [&](const IntegerPoly& g) { return sign(g, t) > 0; }) &&
               sign(term.distance, t) <= 0;
      });
      if (holds) {
        result = enclose(kernel, t);
        return;
      }
    }
  });
  return result;
}

}  // namespace

std::optional<TimeInterval> exact_toi(const RationalVertexFaceQuery& q, const RationalCcdParams& p) { return earliest(q, p); }
std::optional<TimeInterval> exact_toi(const RationalEdgeEdgeQuery& q, const RationalCcdParams& p) { return earliest(q, p); }
std::optional<TimeInterval> exact_toi(const RationalPointEdgeQuery& q, const RationalCcdParams& p) { return earliest(q, p); }
std::optional<TimeInterval> exact_toi(const RationalPointPointQuery& q, const RationalCcdParams& p) { return earliest(q, p); }
std::optional<TimeInterval> exact_toi(const RationalEdgeEdge2dQuery& q, const RationalCcdParams& p) { return earliest(q, p); }
std::optional<TimeInterval> exact_toi(const RationalPointEdge2dQuery& q, const RationalCcdParams& p) { return earliest(q, p); }
std::optional<TimeInterval> exact_toi(const RationalPointPoint2dQuery& q, const RationalCcdParams& p) { return earliest(q, p); }

#define EXACTCCD_EXACT_TOI_MASKED(Query)                                                                   \
  std::optional<TimeInterval> exact_toi(const Query& q, const RationalCcdParams& p, const FeatureMask& use) { \
    return earliest(q, p, &use);                                                                             \
  }
EXACTCCD_EXACT_TOI_MASKED(RationalVertexFaceQuery)
EXACTCCD_EXACT_TOI_MASKED(RationalEdgeEdgeQuery)
EXACTCCD_EXACT_TOI_MASKED(RationalPointEdgeQuery)
EXACTCCD_EXACT_TOI_MASKED(RationalPointPointQuery)
EXACTCCD_EXACT_TOI_MASKED(RationalEdgeEdge2dQuery)
EXACTCCD_EXACT_TOI_MASKED(RationalPointEdge2dQuery)
EXACTCCD_EXACT_TOI_MASKED(RationalPointPoint2dQuery)
#undef EXACTCCD_EXACT_TOI_MASKED

}  // namespace exactccd::separation
