// A minimum-separation term (separation_terms.hpp) over a time cell, in interval arithmetic
// (numeric/interval.hpp: CGAL::Interval_nt under upward rounding): the terms are built from the
// double coordinates, so every coefficient encloses the exact one and every evaluation below
// encloses the exact value (inclusion property; an overflow gives infinite bounds, which never
// certify; the entry point's DefaultFpEnvironment has cleared flush-to-zero).
// A term is *excluded* on a cell when its f is certainly > 0 or one of its g certainly <= 0 on
// the whole cell: it holds nowhere there.
#pragma once

#include <algorithm>
#include <array>
#include <utility>

#include "numeric/interval.hpp"
#include "contact/separation_terms.hpp"

namespace exactccd::separation {

using numeric::Interval;

/// p(t) by Horner's scheme, from p's highest coefficient that is not exactly [0, 0] (terms are
/// stored with degree 6, most of them have a lower degree: for a finite t the skipped steps
/// would compute [0, 0] t + [0, 0] = [0, 0], so the result is the same interval).
template <int D>
Interval evaluate(const contact::Poly<Interval, D>& p, const Interval& t) {
  int k = D;
  while (k > 0 && p.c[k].inf() == 0 && p.c[k].sup() == 0) --k;
  Interval r = p.c[k];
  for (--k; k >= 0; --k) r = r * t + p.c[k];
  return r;
}

/// p' (coefficients above p's degree left exactly [0, 0], as evaluate expects).
inline contact::Poly<Interval, 5> derivative(const contact::Poly6<Interval>& p) {
  contact::Poly<Interval, 5> r;
  int degree = 6;
  while (degree > 0 && p.c[degree].inf() == 0 && p.c[degree].sup() == 0) --degree;
  for (int k = 1; k <= 6; ++k) r.c[k - 1] = k <= degree ? p.c[k] * Interval(k) : Interval(0);
  return r;
}

/// A term with the derivatives of its polynomials (formed once per query, used on every cell):
/// slope[0] of the distance, slope[1 + k] of positive[k].
struct SlopedTerm {
  contact::Term<Interval> term;
  std::array<contact::Poly<Interval, 5>, 5> slope;

  /// The term and its derivatives.
  explicit SlopedTerm(contact::Term<Interval>&& t) : term(std::move(t)) {
    slope[0] = derivative(term.distance);
    for (int k = 0; k < term.positives; ++k) slope[1 + k] = derivative(term.positive[k]);
  }
};

/// An enclosure of p over the cell [a, b] (t = [a, b], m its midpoint; dp = p'): where p' has
/// a certain sign on the cell, p is monotone there and its range is the hull of p(a) and p(b);
/// otherwise the mean-value form p(m) + p'(t) (t - m) intersected with Horner's scheme over t
/// (both enclose the range; the first shrinks with the cell's width squared near a root, where
/// Horner's scheme over power-basis coefficients suffers from cancellation).
inline Interval range(const contact::Poly6<Interval>& p, const contact::Poly<Interval, 5>& dp, double a, double b) {
  const Interval t(a, b);
  const Interval slope = evaluate(dp, t);
  if (numeric::certain_sign(slope) != 0) {
    const Interval pa = evaluate(p, Interval(a)), pb = evaluate(p, Interval(b));
    return Interval(std::min(pa.inf(), pb.inf()), std::max(pa.sup(), pb.sup()));
  }
  const double m = a + (b - a) / 2;  // any point of the cell will do
  const Interval mean_value = evaluate(p, Interval(m)) + slope * (t - Interval(m));
  const Interval horner = evaluate(p, t);
  return Interval(std::max(mean_value.inf(), horner.inf()), std::min(mean_value.sup(), horner.sup()));
}

/// The term holds nowhere in the cell [a, b] (certainly).
inline bool excluded(const SlopedTerm& sloped, double a, double b) {
  const contact::Term<Interval>& term = sloped.term;
  if (range(term.distance, sloped.slope[0], a, b).inf() > 0) return true;
  for (int k = 0; k < term.positives; ++k)
    if (range(term.positive[k], sloped.slope[1 + k], a, b).sup() <= 0) return true;
  return false;
}

/// The term holds at t (certainly): f <= 0 and every g > 0.
inline bool holds(const contact::Term<Interval>& term, const Interval& t) {
  if (evaluate(term.distance, t).sup() > 0) return false;
  for (int k = 0; k < term.positives; ++k)
    if (evaluate(term.positive[k], t).inf() <= 0) return false;
  return true;
}

/// The term has exactly one root of f in the cell (a, b), a simple one, where it starts to
/// hold: its g certainly > 0 on the cell, f certainly > 0 at a and < 0 at b, f' certainly
/// nonzero on the cell.
inline bool single_entry(const SlopedTerm& sloped, double a, double b) {
  const contact::Term<Interval>& term = sloped.term;
  for (int k = 0; k < term.positives; ++k)
    if (!(range(term.positive[k], sloped.slope[1 + k], a, b).inf() > 0)) return false;
  return numeric::certain_sign(evaluate(term.distance, Interval(a))) > 0 &&
         numeric::certain_sign(evaluate(term.distance, Interval(b))) < 0 &&
         numeric::certain_sign(evaluate(sloped.slope[0], Interval(a, b))) != 0;
}

}  // namespace exactccd::separation
