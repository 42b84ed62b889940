#include "exact/integer_poly.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

namespace exactccd::exact {
namespace {

constexpr int kBinomial[5][5] = {
    {1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 2, 1, 0, 0}, {1, 3, 3, 1, 0}, {1, 4, 6, 4, 1}};

/// Pseudo-remainder of a by b, up to a nonzero constant factor.
template <class Z>
IntegerPolyT<Z> pseudo_remainder(IntegerPolyT<Z> a, const IntegerPolyT<Z>& b) {
  while (!a.is_zero() && a.deg >= b.deg) {
    const int shift = a.deg - b.deg;
    const Z lead_a = a.leading();
    for (int i = 0; i <= a.deg; ++i) a.c[i] *= b.leading();
    for (int i = 0; i <= b.deg; ++i) a.c[i + shift] -= lead_a * b.c[i];
    a.normalize();
  }
  return a;
}

/// Exact quotient p / g over the integers (g divides p, g primitive, p primitive).
template <class Z>
IntegerPolyT<Z> exact_quotient(IntegerPolyT<Z> p, const IntegerPolyT<Z>& g) {
  IntegerPolyT<Z> q;
  q.deg = p.deg - g.deg;
  for (int j = q.deg; j >= 0; --j) {
    q.c[j] = p.c[j + g.deg];
    divide_exactly(q.c[j], g.leading());
    for (int i = 0; i <= g.deg; ++i) p.c[i + j] -= q.c[j] * g.c[i];
  }
  q.normalize();
  return q;
}

template <class Z>
using Coefficients = std::array<Z, 5>;

template <class Z>
int sign_variations(const Coefficients<Z>& b, int d) {
  int changes = 0, last = 0;
  for (int j = 0; j <= d; ++j) {
    const int s = sgn(b[j]);
    if (s == 0) continue;
    if (last != 0 && s != last) ++changes;
    last = s;
  }
  return changes;
}

/// Bernstein coefficients on [0, 1] of c[0..d] (monomial basis), times 12 (12 / C(d, i) is an
/// integer for d <= 4): b_j = sum_{i <= j} C(j, i) / C(d, i) c_i.
template <class Z>
Coefficients<Z> bernstein_coefficients(const Coefficients<Z>& c, int d) {
  Coefficients<Z> b;
  for (int j = 0; j <= d; ++j) {
    b[j] = 0;
    for (int i = 0; i <= j; ++i) b[j] += (kBinomial[j][i] * (12 / kBinomial[d][i])) * c[i];
  }
  return b;
}

/// Bernstein subdivision of [0, 1] with scaled Bernstein coefficients b (positive multiples of
/// the true ones), appending the roots in the open interval (0, 1) in increasing order. False
/// when a cell deeper than max_depth is still undecided (a multiple root, or roots closer than
/// 2^-max_depth).
///
/// Depth-first with an explicit stack, not recursion: the depth is the number of bits that
/// separate two roots, which for inputs mixing magnitudes 2^-1074 and 2^1000 reaches thousands
/// (a recursive version needed ~2 MB of stack for one such edge-edge query). The stack holds at
/// most one pending right half per level, so its memory is linear in the depth, on the heap.
template <class Z>
bool isolate(const IntegerPolyT<Z>& p, const Coefficients<Z>& b, unsigned max_depth,
             std::vector<IsolatedRootT<Z>>& out) {
  const int d = p.deg;
  struct Cell {
    Coefficients<Z> b;          // scaled Bernstein coefficients on [a / 2^k, (a + 1) / 2^k]
    Z a;
    unsigned k = 0;
    bool midpoint_root = false;  // not a cell: the exact root a / 2^k, emitted in order
  };
  std::vector<Cell> pending;
  pending.push_back(Cell{b, Z(0), 0, false});
  while (!pending.empty()) {
    Cell cell = std::move(pending.back());
    pending.pop_back();
    if (cell.midpoint_root) {
      IsolatedRootT<Z> r;
      r.exact = true;
      r.at = {std::move(cell.a), cell.k};
      out.push_back(std::move(r));
      continue;
    }
    const int changes = sign_variations(cell.b, d);
    if (changes == 0) continue;
    if (changes == 1 && sgn(cell.b[0]) != 0 && sgn(cell.b[d]) != 0) {
      IsolatedRootT<Z> r;
      r.lo = {cell.a, cell.k};
      r.hi = {cell.a + 1, cell.k};
      r.sign_at_lo = sgn(cell.b[0]);
      out.push_back(std::move(r));
      continue;
    }
    if (cell.k >= max_depth) return false;
    // de Casteljau at the midpoint, both halves scaled by 2^d to stay integral:
    //   left_j = 2^(d-j) sum_{i<=j} C(j,i) b_i,  right_j = 2^j sum_{i>=j} C(d-j,i-j) b_i.
    Cell left, right;
    for (int j = 0; j <= d; ++j) {
      Z l = 0, r = 0;
      for (int i = 0; i <= j; ++i) l += kBinomial[j][i] * cell.b[i];
      for (int i = j; i <= d; ++i) r += kBinomial[d - j][i - j] * cell.b[i];
      left.b[j] = shifted(l, static_cast<unsigned long>(d - j));
      right.b[j] = shifted(r, static_cast<unsigned long>(j));
    }
    const Z a2 = 2 * cell.a;
    left.a = a2;
    right.a = a2 + 1;
    left.k = right.k = cell.k + 1;
    // Processed in the order left cell, midpoint (when it is a root), right cell.
    const bool midpoint_is_root = sgn(left.b[d]) == 0;
    pending.push_back(std::move(right));
    if (midpoint_is_root) pending.push_back(Cell{{}, a2 + 1, cell.k + 1, true});
    pending.push_back(std::move(left));
  }
  return true;
}

}  // namespace

template <class Z>
int sign_at(const IntegerPolyT<Z>& p, const DyadicT<Z>& x) {
  if (p.is_zero()) return 0;
  // 2^(k deg) p(a / 2^k) = sum_i c_i a^i 2^(k (deg - i)), by Horner's scheme.
  Z acc = p.c[p.deg];
  for (int i = p.deg - 1; i >= 0; --i)
    acc = acc * x.a + shifted(p.c[i], static_cast<unsigned long>(x.k) * (p.deg - i));
  return sgn(acc);
}

template <class Z>
DyadicT<Z> to_dyadic(double t) {
  DyadicT<Z> d;
  if (t == 0) return d;  // a = 0, k = 0
  int e = 0;
  const double f = std::frexp(t, &e);     // t = f 2^e, f in [0.5, 1)
  d.a = Z(static_cast<long>(std::ldexp(f, 53)));  // exact: a 53-bit integer
  const int exponent = e - 53;            // t = a 2^exponent
  if (exponent >= 0) {
    d.a = shifted(d.a, static_cast<unsigned long>(exponent));
  } else {
    d.k = static_cast<unsigned>(-exponent);
  }
  return d;
}

template <class Z>
int sign_at(const IntegerPolyT<Z>& p, double t) {
  return sign_at(p, to_dyadic<Z>(t));
}

template <class Z>
IntegerPolyT<Z> primitive_part(const IntegerPolyT<Z>& p) {
  IntegerPolyT<Z> r = p;
  if (r.is_zero()) return r;
  Z g = 0;
  for (int i = 0; i <= r.deg; ++i) g = gcd_of(g, r.c[i]);
  if (sgn(r.leading()) < 0) g = -g;
  for (int i = 0; i <= r.deg; ++i) divide_exactly(r.c[i], g);
  return r;
}

template <class Z>
IntegerPolyT<Z> derivative(const IntegerPolyT<Z>& p) {
  IntegerPolyT<Z> r;
  for (int i = 1; i <= p.deg; ++i) r.c[i - 1] = i * p.c[i];
  r.normalize();
  return r;
}

template <class Z>
IntegerPolyT<Z> gcd(const IntegerPolyT<Z>& p, const IntegerPolyT<Z>& q) {
  IntegerPolyT<Z> a = primitive_part(p), b = primitive_part(q);
  if (a.deg < b.deg) std::swap(a, b);
  while (!b.is_zero()) {
    IntegerPolyT<Z> r = pseudo_remainder(a, b);
    a = std::move(b);
    b = primitive_part(r);
  }
  return a;
}

namespace {

/// True when p (degree <= 3) certainly has no multiple root: its discriminant is nonzero.
/// Cheaper than a gcd with p' (no coefficient gcds), and the common case.
template <class Z>
bool has_nonzero_discriminant(const IntegerPolyT<Z>& p) {
  if (p.deg <= 1) return true;
  if (p.deg == 2) return sgn(p.c[1] * p.c[1] - 4 * p.c[2] * p.c[0]) != 0;
  if (p.deg == 3) {
    const Z &a = p.c[3], &b = p.c[2], &c = p.c[1], &d = p.c[0];
    const Z disc = 18 * a * b * c * d - 4 * b * b * b * d + b * b * c * c -
                           4 * a * c * c * c - 27 * a * a * d * d;
    return sgn(disc) != 0;
  }
  return false;  // degree 4: decide with the gcd
}

}  // namespace

template <class Z>
IntegerPolyT<Z> square_free_part(const IntegerPolyT<Z>& p) {
  if (has_nonzero_discriminant(p)) return p;
  const IntegerPolyT<Z> pp = primitive_part(p);
  if (pp.deg <= 1) return pp;
  const IntegerPolyT<Z> g = gcd(pp, derivative(pp));
  if (g.deg <= 0) return pp;
  return exact_quotient(pp, g);
}

template <class Z>
std::optional<std::vector<IsolatedRootT<Z>>> roots_in_unit_interval(const IntegerPolyT<Z>& p, unsigned max_depth) {
  std::vector<IsolatedRootT<Z>> roots;
  if (p.deg <= 0) return roots;
  const int d = p.deg;
  const bool root_at_0 = sgn(p.c[0]) == 0;
  Z at_1 = 0;
  for (int i = 0; i <= d; ++i) at_1 += p.c[i];
  if (root_at_0) {
    IsolatedRootT<Z> r;
    r.exact = true;
    r.at = {Z(0), 0};
    roots.push_back(std::move(r));
  }
  if (!isolate(p, bernstein_coefficients(p.c, d), max_depth, roots)) return std::nullopt;
  if (sgn(at_1) == 0) {
    IsolatedRootT<Z> r;
    r.exact = true;
    r.at = {Z(1), 0};
    roots.push_back(std::move(r));
  }
  return roots;
}

template <class Z>
RootsOfT<Z> isolate_roots(const IntegerPolyT<Z>& p) {
  // Most polynomials have simple roots in [0, 1]: isolate them directly (a shallow failure
  // costs little), and pay for the square-free part only when that does not settle.
  constexpr unsigned kShallowDepth = 64;
  if (auto roots = roots_in_unit_interval(p, kShallowDepth)) return {p, std::move(*roots)};
  IntegerPolyT<Z> sf = square_free_part(p);
  // A square-free polynomial of degree <= 4 has simple, separated roots: the subdivision ends.
  // The cap only guards against a logic error.
  auto roots = roots_in_unit_interval(sf, 1u << 16);
  if (!roots) throw std::runtime_error("exactccd: root isolation did not terminate");
  return {std::move(sf), std::move(*roots)};
}

template <class Z>
int sign_on_cell(const IntegerPolyT<Z>& q, const DyadicT<Z>& lo) {
  if (q.is_zero()) return 0;
  const int d = q.deg;
  // Q(x) = 2^(k d) q((a + x) / 2^k) = sum_j e_j x^j for x in [0, 1], with
  // e_j = sum_{i >= j} C(i, j) a^(i-j) 2^(k (d-i)) c_i; then Q's Bernstein coefficients.
  std::array<Z, 5> power_of_a;
  power_of_a[0] = 1;
  for (int i = 1; i <= d; ++i) power_of_a[i] = power_of_a[i - 1] * lo.a;
  Coefficients<Z> e;
  for (int j = 0; j <= d; ++j) {
    e[j] = 0;
    for (int i = j; i <= d; ++i)
      e[j] += kBinomial[i][j] * power_of_a[i - j] *
              shifted(q.c[i], static_cast<unsigned long>(lo.k) * (d - i));
  }
  const Coefficients<Z> b = bernstein_coefficients(e, d);
  const int s = sgn(b[0]);
  for (int j = 1; j <= d; ++j)
    if (sgn(b[j]) != s) return 0;
  return s;
}

namespace {

/// p's coefficients as long doubles (64-bit significands, so the guess below is accurate to
/// about 2^-64 relative), all scaled by one power of two (same signs and roots).
template <class Z>
std::array<long double, 5> scaled_coefficients(const IntegerPolyT<Z>& p) {
  std::array<long, 5> shift{};
  std::array<long double, 5> top{};
  long max_bits = 0;
  for (int i = 0; i <= p.deg; ++i) {
    const long bits = bit_length(p.c[i]);
    top[i] = leading_bits(p.c[i], shift[i]);  // the leading 64 bits, times 2^shift[i]
    if (sgn(p.c[i]) != 0) max_bits = std::max(max_bits, bits);
  }
  std::array<long double, 5> c{};
  for (int i = 0; i <= p.deg; ++i)
    c[i] = std::ldexp(top[i], static_cast<int>(std::max(shift[i] - max_bits, -20000L)));
  return c;
}

/// p(t) and p'(t) by Horner's scheme, in long double.
std::pair<long double, long double> approximate_value_and_slope(const std::array<long double, 5>& c, int deg,
                                                               long double t) {
  long double v = c[deg], dv = 0;
  for (int i = deg - 1; i >= 0; --i) {
    dv = dv * t + v;
    v = v * t + c[i];
  }
  return {v, dv};
}

template <class Z>
double to_double_down(const DyadicT<Z>& d) {
  bool exact = false;
  return floor_to_double(d.a, d.k, exact);
}

/// Safeguarded Newton iteration in long double on [lo, hi] for the root of the polynomial with
/// coefficients c (sign at lo: sign_at_lo): the bracket shrinks with every step; a step leaving
/// it is replaced by bisection. Converges in a few steps at a simple root, where plain
/// bisection takes ~64.
long double newton_guess(const std::array<long double, 5>& c, int deg, long double lo, long double hi,
                         int sign_at_lo) {
  long double approx = lo + (hi - lo) / 2;
  for (int i = 0; i < 100 && lo < hi; ++i) {
    const auto [v, dv] = approximate_value_and_slope(c, deg, approx);
    if (v == 0) break;
    if ((v > 0) == (sign_at_lo > 0))
      lo = approx;
    else
      hi = approx;
    long double next = approx - v / dv;
    if (!(next > lo && next < hi)) next = lo + (hi - lo) / 2;  // also catches dv == 0 and NaN
    if (next == approx || next <= lo || next >= hi) break;     // no representable progress
    const bool converged = std::fabs(next - approx) <= std::ldexp(std::fabs(next), -62);
    approx = next;
    if (converged) break;
  }
  return approx;
}

}  // namespace

double approximate_root(const std::array<long double, 5>& c, int deg, double lo, double hi, int sign_at_lo) {
  const double guess = static_cast<double>(newton_guess(c, deg, lo, hi, sign_at_lo));
  return std::min(std::max(guess, lo), hi);
}

namespace {

/// -1, 0 or +1 as x compares to y.
template <class Z>
int compare(const DyadicT<Z>& x, const DyadicT<Z>& y) {
  const unsigned k = std::max(x.k, y.k);
  const Z a = shifted(x.a, k - x.k), b = shifted(y.a, k - y.k);
  return a < b ? -1 : a > b ? 1 : 0;
}

}  // namespace

template <class Z>
void refine_with_approximation(const IntegerPolyT<Z>& p, IsolatedRootT<Z>& r) {
  if (r.exact) return;
  const std::array<long double, 5> c = scaled_coefficients(p);
  // A guess, checked exactly below.
  const long double approx =
      newton_guess(c, p.deg, to_double_down(r.lo), std::nextafter(to_double_down(r.hi), 2.0), r.sign_at_lo);
  const auto inside = [&](const DyadicT<Z>& x) { return compare(r.lo, x) < 0 && compare(x, r.hi) < 0; };
  const double guess = static_cast<double>(approx);
  for (double d : {guess, std::nextafter(guess, 0.0), std::nextafter(guess, 2.0)}) {
    const DyadicT<Z> x = to_dyadic<Z>(d);
    if (inside(x) && sign_at(p, x) == 0) {  // p's only root in the cell
      r.exact = true;
      r.at = x;
      return;
    }
  }
  const unsigned k = kRefinedCellBits;
  if (k <= r.lo.k) return;
  // approx in [0, 1], so floor(approx 2^k) < 2^56 fits an unsigned long exactly.
  const Z a(static_cast<unsigned long>(std::floor(std::ldexp(approx, static_cast<int>(k)))));
  for (const Z& start : {a, Z(a - 1), Z(a + 1)}) {
    const DyadicT<Z> lo_x{start, k}, hi_x{start + 1, k};
    if (!inside(lo_x) || !inside(hi_x)) continue;
    const int s_lo = sign_at(p, lo_x), s_hi = sign_at(p, hi_x);
    if (s_lo == 0 || s_hi == 0) {  // an exact dyadic root
      r.exact = true;
      r.at = s_lo == 0 ? lo_x : hi_x;
      return;
    }
    if (s_lo == r.sign_at_lo && s_hi != s_lo) {
      r.lo = lo_x;
      r.hi = hi_x;
      return;
    }
  }
}

template <class Z>
void bisect(const IntegerPolyT<Z>& p, IsolatedRootT<Z>& r) {
  const DyadicT<Z> mid{2 * r.lo.a + 1, r.lo.k + 1};
  const int s = sign_at(p, mid);
  if (s == 0) {
    r.exact = true;
    r.at = mid;
    return;
  }
  if (s == r.sign_at_lo) {
    r.lo = mid;
    r.hi = {2 * r.hi.a, r.hi.k + 1};
  } else {
    r.lo = {2 * r.lo.a, r.lo.k + 1};
    r.hi = mid;
  }
}

#define EXACTCCD_INSTANTIATE(Z)                                                                  \
  template int sign_at(const IntegerPolyT<Z>&, const DyadicT<Z>&);                               \
  template int sign_at(const IntegerPolyT<Z>&, double);                                          \
  template DyadicT<Z> to_dyadic<Z>(double);                                                      \
  template IntegerPolyT<Z> primitive_part(const IntegerPolyT<Z>&);                               \
  template IntegerPolyT<Z> derivative(const IntegerPolyT<Z>&);                                   \
  template IntegerPolyT<Z> gcd(const IntegerPolyT<Z>&, const IntegerPolyT<Z>&);                  \
  template IntegerPolyT<Z> square_free_part(const IntegerPolyT<Z>&);                             \
  template std::optional<std::vector<IsolatedRootT<Z>>> roots_in_unit_interval(const IntegerPolyT<Z>&, unsigned); \
  template RootsOfT<Z> isolate_roots(const IntegerPolyT<Z>&);                                    \
  template int sign_on_cell(const IntegerPolyT<Z>&, const DyadicT<Z>&);                          \
  template void refine_with_approximation(const IntegerPolyT<Z>&, IsolatedRootT<Z>&);            \
  template void bisect(const IntegerPolyT<Z>&, IsolatedRootT<Z>&);

EXACTCCD_INSTANTIATE(mpz_class)
EXACTCCD_INSTANTIATE(FixedInteger)
#undef EXACTCCD_INSTANTIATE

}  // namespace exactccd::exact
