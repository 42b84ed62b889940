#include "exact/earliest_root.hpp"

#include <algorithm>

namespace exactccd::exact::algebraic {

int sign_at(const Kernel& kernel, const IntegerPoly& p, const Root& t) {
  return CGAL::is_zero(p) ? 0 : static_cast<int>(kernel.sign_at_1_object()(p, t));
}

bool some_term_holds(const Kernel& kernel, const std::vector<IntegerTerm>& terms, const Root& t) {
  return std::any_of(terms.begin(), terms.end(), [&](const IntegerTerm& term) {
    return std::all_of(term.positive.begin(), term.positive.end(),
                       [&](const IntegerPoly& g) { return sign_at(kernel, g, t) > 0; }) &&
           sign_at(kernel, term.distance, t) <= 0;
  });
}

std::optional<Root> earliest_term_time(const Kernel& kernel, const std::vector<IntegerTerm>& terms, const mpq_class& hi) {
  std::vector<Root> times{rational_root(0)};
  for (const IntegerTerm& t : terms)
    if (!CGAL::is_zero(t.distance)) append_roots(kernel, t.distance, 0, hi, times);
  sort_unique(kernel, times);
  for (const Root& t : times)
    if (some_term_holds(kernel, terms, t)) return t;
  return std::nullopt;
}

}  // namespace exactccd::exact::algebraic
