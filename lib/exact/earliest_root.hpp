// The one exact "earliest root where the rule holds" (docs/design.md 3, 4b.2 and 9.3), for the
// exact paths of both questions and both motion models: exact_ccd.cpp (linear contact),
// separation/exact_separation.cpp (linear minimum separation), rigid/exact_rigid.cpp (both,
// rigid). The set S of times in [0, hi] where the rule holds is closed, and the rule is a
// Boolean formula over the signs of finitely many continuous functions whose zero sets in
// [0, hi] are finite or everything; so S is empty iff the rule fails at every candidate, and
// min S is the first candidate, in increasing order, where it holds:
//  - contact (d = 0): the roots in [0, hi] of the volume V when V is not identically zero
//    (contact needs V(t) = 0); otherwise 0 and the roots in [0, hi] of every in-plane polynomial
//    not identically zero (a cell where the rule holds has its left end in S, which is then 0 or
//    a root);
//  - minimum separation: 0 and the roots in [0, hi] of every term's f not identically zero (at
//    min S > 0 a term holds whose strict conditions hold nearby, so it fails just before only
//    through f > 0: f(min S) = 0).
// Signs are exact at algebraic numbers (CGAL's Sign_at_1, multiple roots included). Every
// polynomial is given in integers with the signs and roots on [0, hi] of the rule's own (a
// positive multiple of a rational one; the rigid path's reductions).
#pragma once

#include <optional>
#include <vector>

#include "contact/contact_rule.hpp"
#include "exact/algebraic_kernel.hpp"

namespace exactccd::exact::algebraic {

/// The exact sign of p at t (0 for the zero polynomial).
int sign_at(const Kernel& kernel, const IntegerPoly& p, const Root& t);

/// The earliest t in [0, hi] where the contact rule (contact/contact_rule.hpp) holds for the
/// rule's terms P, exactly, or nothing. `integer(p)` gives each polynomial p of P as an
/// IntegerPoly with p's signs and roots on [0, hi] (by value or by reference).
template <class Terms, class Integer>
std::optional<Root> earliest_contact(const Kernel& kernel, const Terms& P, Integer&& integer, const mpq_class& hi) {
  std::vector<Root> times;
  const IntegerPoly& volume = integer(P.volume());
  if (!CGAL::is_zero(volume)) {
    append_roots(kernel, volume, 0, hi, times);  // sorted and distinct
  } else {
    times.push_back(rational_root(0));
    contact::for_each_in_plane_poly(P, [&](const auto& p) {
      const IntegerPoly& r = integer(p);
      if (!CGAL::is_zero(r)) append_roots(kernel, r, 0, hi, times);
    });
    sort_unique(kernel, times);
  }
  for (const Root& t : times) {
    const auto sign = [&](const auto& p) { return sign_at(kernel, integer(p), t); };
    if (contact::in_contact(P, sign) == contact::Truth::yes) return t;  // exact: never unknown
  }
  return std::nullopt;
}

/// A minimum-separation term (contact/separation_terms.hpp) in integer polynomials: it holds
/// where distance <= 0 and every positive > 0.
struct IntegerTerm {
  IntegerPoly distance;               ///< f
  std::vector<IntegerPoly> positive;  ///< its strict conditions g
};

/// True when some term holds at the algebraic time t (every sign exact).
bool some_term_holds(const Kernel& kernel, const std::vector<IntegerTerm>& terms, const Root& t);

/// The earliest t in [0, hi] where some term holds, exactly (the candidates: 0 and the roots of
/// every f not identically zero), or nothing.
std::optional<Root> earliest_term_time(const Kernel& kernel, const std::vector<IntegerTerm>& terms, const mpq_class& hi);

}  // namespace exactccd::exact::algebraic
