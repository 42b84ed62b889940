#include "exact/integer_poly.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

namespace exactccd::exact {
namespace {

int sgn(const mpz_class& x) { return mpz_sgn(x.get_mpz_t()); }

/// x * 2^e for e >= 0.
mpz_class shifted(const mpz_class& x, unsigned long e) {
  mpz_class r;
  mpz_mul_2exp(r.get_mpz_t(), x.get_mpz_t(), e);
  return r;
}

constexpr int kBinomial[5][5] = {
    {1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 2, 1, 0, 0}, {1, 3, 3, 1, 0}, {1, 4, 6, 4, 1}};

/// Pseudo-remainder of a by b, up to a nonzero constant factor.
IntegerPoly pseudo_remainder(IntegerPoly a, const IntegerPoly& b) {
  while (!a.is_zero() && a.deg >= b.deg) {
    const int shift = a.deg - b.deg;
    const mpz_class lead_a = a.leading();
    for (int i = 0; i <= a.deg; ++i) a.c[i] *= b.leading();
    for (int i = 0; i <= b.deg; ++i) a.c[i + shift] -= lead_a * b.c[i];
    a.normalize();
  }
  return a;
}

/// Exact quotient p / g over the integers (g divides p, g primitive, p primitive).
IntegerPoly exact_quotient(IntegerPoly p, const IntegerPoly& g) {
  IntegerPoly q;
  q.deg = p.deg - g.deg;
  for (int j = q.deg; j >= 0; --j) {
    q.c[j] = p.c[j + g.deg];
    mpz_divexact(q.c[j].get_mpz_t(), q.c[j].get_mpz_t(), g.leading().get_mpz_t());
    for (int i = 0; i <= g.deg; ++i) p.c[i + j] -= q.c[j] * g.c[i];
  }
  q.normalize();
  return q;
}

using Coefficients = std::array<mpz_class, 5>;

int sign_variations(const Coefficients& b, int d) {
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
Coefficients bernstein_coefficients(const Coefficients& c, int d) {
  Coefficients b;
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
bool isolate(const IntegerPoly& p, const Coefficients& b, unsigned max_depth, std::vector<IsolatedRoot>& out) {
  const int d = p.deg;
  struct Cell {
    Coefficients b;             // scaled Bernstein coefficients on [a / 2^k, (a + 1) / 2^k]
    mpz_class a;
    unsigned k = 0;
    bool midpoint_root = false;  // not a cell: the exact root a / 2^k, emitted in order
  };
  std::vector<Cell> pending;
  pending.push_back(Cell{b, 0, 0, false});
  while (!pending.empty()) {
    Cell cell = std::move(pending.back());
    pending.pop_back();
    if (cell.midpoint_root) {
      IsolatedRoot r;
      r.exact = true;
      r.at = {std::move(cell.a), cell.k};
      out.push_back(std::move(r));
      continue;
    }
    const int changes = sign_variations(cell.b, d);
    if (changes == 0) continue;
    if (changes == 1 && sgn(cell.b[0]) != 0 && sgn(cell.b[d]) != 0) {
      IsolatedRoot r;
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
      mpz_class l = 0, r = 0;
      for (int i = 0; i <= j; ++i) l += kBinomial[j][i] * cell.b[i];
      for (int i = j; i <= d; ++i) r += kBinomial[d - j][i - j] * cell.b[i];
      left.b[j] = shifted(l, static_cast<unsigned long>(d - j));
      right.b[j] = shifted(r, static_cast<unsigned long>(j));
    }
    const mpz_class a2 = 2 * cell.a;
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

void IntegerPoly::normalize() {
  deg = 4;
  while (deg >= 0 && sgn(c[deg]) == 0) --deg;
}

int sign_at(const IntegerPoly& p, const Dyadic& x) {
  if (p.is_zero()) return 0;
  // 2^(k deg) p(a / 2^k) = sum_i c_i a^i 2^(k (deg - i)), by Horner's scheme.
  mpz_class acc = p.c[p.deg];
  for (int i = p.deg - 1; i >= 0; --i)
    acc = acc * x.a + shifted(p.c[i], static_cast<unsigned long>(x.k) * (p.deg - i));
  return sgn(acc);
}

Dyadic to_dyadic(double t) {
  Dyadic d;
  if (t == 0) return d;  // a = 0, k = 0
  int e = 0;
  const double f = std::frexp(t, &e);     // t = f 2^e, f in [0.5, 1)
  d.a = mpz_class(std::ldexp(f, 53));     // exact: a 53-bit integer
  const int exponent = e - 53;            // t = a 2^exponent
  if (exponent >= 0) {
    d.a = shifted(d.a, static_cast<unsigned long>(exponent));
  } else {
    d.k = static_cast<unsigned>(-exponent);
  }
  return d;
}

int sign_at(const IntegerPoly& p, double t) { return sign_at(p, to_dyadic(t)); }

IntegerPoly primitive_part(const IntegerPoly& p) {
  IntegerPoly r = p;
  if (r.is_zero()) return r;
  mpz_class g = 0;
  for (int i = 0; i <= r.deg; ++i) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), r.c[i].get_mpz_t());
  if (sgn(r.leading()) < 0) g = -g;
  for (int i = 0; i <= r.deg; ++i) mpz_divexact(r.c[i].get_mpz_t(), r.c[i].get_mpz_t(), g.get_mpz_t());
  return r;
}

IntegerPoly derivative(const IntegerPoly& p) {
  IntegerPoly r;
  for (int i = 1; i <= p.deg; ++i) r.c[i - 1] = i * p.c[i];
  r.normalize();
  return r;
}

IntegerPoly gcd(const IntegerPoly& p, const IntegerPoly& q) {
  IntegerPoly a = primitive_part(p), b = primitive_part(q);
  if (a.deg < b.deg) std::swap(a, b);
  while (!b.is_zero()) {
    IntegerPoly r = pseudo_remainder(a, b);
    a = std::move(b);
    b = primitive_part(r);
  }
  return a;
}

namespace {

/// True when p (degree <= 3) certainly has no multiple root: its discriminant is nonzero.
/// Cheaper than a gcd with p' (no coefficient gcds), and the common case.
bool has_nonzero_discriminant(const IntegerPoly& p) {
  if (p.deg <= 1) return true;
  if (p.deg == 2) return sgn(p.c[1] * p.c[1] - 4 * p.c[2] * p.c[0]) != 0;
  if (p.deg == 3) {
    const mpz_class &a = p.c[3], &b = p.c[2], &c = p.c[1], &d = p.c[0];
    const mpz_class disc = 18 * a * b * c * d - 4 * b * b * b * d + b * b * c * c -
                           4 * a * c * c * c - 27 * a * a * d * d;
    return sgn(disc) != 0;
  }
  return false;  // degree 4: decide with the gcd
}

}  // namespace

IntegerPoly square_free_part(const IntegerPoly& p) {
  if (has_nonzero_discriminant(p)) return p;
  const IntegerPoly pp = primitive_part(p);
  if (pp.deg <= 1) return pp;
  const IntegerPoly g = gcd(pp, derivative(pp));
  if (g.deg <= 0) return pp;
  return exact_quotient(pp, g);
}

std::optional<std::vector<IsolatedRoot>> roots_in_unit_interval(const IntegerPoly& p,
                                                                 unsigned max_depth) {
  std::vector<IsolatedRoot> roots;
  if (p.deg <= 0) return roots;
  const int d = p.deg;
  const bool root_at_0 = sgn(p.c[0]) == 0;
  mpz_class at_1 = 0;
  for (int i = 0; i <= d; ++i) at_1 += p.c[i];
  if (root_at_0) {
    IsolatedRoot r;
    r.exact = true;
    r.at = {0, 0};
    roots.push_back(std::move(r));
  }
  if (!isolate(p, bernstein_coefficients(p.c, d), max_depth, roots)) return std::nullopt;
  if (sgn(at_1) == 0) {
    IsolatedRoot r;
    r.exact = true;
    r.at = {1, 0};
    roots.push_back(std::move(r));
  }
  return roots;
}

RootsOf isolate_roots(const IntegerPoly& p) {
  // Most polynomials have simple roots in [0, 1]: isolate them directly (a shallow failure
  // costs little), and pay for the square-free part only when that does not settle.
  constexpr unsigned kShallowDepth = 64;
  if (auto roots = roots_in_unit_interval(p, kShallowDepth)) return {p, std::move(*roots)};
  IntegerPoly sf = square_free_part(p);
  // A square-free polynomial of degree <= 4 has simple, separated roots: the subdivision ends.
  // The cap only guards against a logic error.
  auto roots = roots_in_unit_interval(sf, 1u << 16);
  if (!roots) throw std::runtime_error("exactccd: root isolation did not terminate");
  return {std::move(sf), std::move(*roots)};
}

int sign_on_cell(const IntegerPoly& q, const Dyadic& lo) {
  if (q.is_zero()) return 0;
  const int d = q.deg;
  // Q(x) = 2^(k d) q((a + x) / 2^k) = sum_j e_j x^j for x in [0, 1], with
  // e_j = sum_{i >= j} C(i, j) a^(i-j) 2^(k (d-i)) c_i; then Q's Bernstein coefficients.
  std::array<mpz_class, 5> power_of_a;
  power_of_a[0] = 1;
  for (int i = 1; i <= d; ++i) power_of_a[i] = power_of_a[i - 1] * lo.a;
  Coefficients e;
  for (int j = 0; j <= d; ++j) {
    e[j] = 0;
    for (int i = j; i <= d; ++i)
      e[j] += kBinomial[i][j] * power_of_a[i - j] *
              shifted(q.c[i], static_cast<unsigned long>(lo.k) * (d - i));
  }
  const Coefficients b = bernstein_coefficients(e, d);
  const int s = sgn(b[0]);
  for (int j = 1; j <= d; ++j)
    if (sgn(b[j]) != s) return 0;
  return s;
}

namespace {

/// p's coefficients as long doubles (64-bit significands, so the guess below is accurate to
/// about 2^-64 relative), all scaled by one power of two (same signs and roots).
std::array<long double, 5> scaled_coefficients(const IntegerPoly& p) {
  std::array<long, 5> shift{};
  std::array<long double, 5> top{};
  long max_bits = 0;
  for (int i = 0; i <= p.deg; ++i) {
    const long bits = static_cast<long>(mpz_sizeinbase(p.c[i].get_mpz_t(), 2));
    shift[i] = std::max(bits - 64, 0L);  // keep the leading 64 bits
    mpz_class t;
    mpz_tdiv_q_2exp(t.get_mpz_t(), p.c[i].get_mpz_t(), static_cast<unsigned long>(shift[i]));
    mpz_class magnitude = abs(t);
    top[i] = static_cast<long double>(mpz_get_ui(magnitude.get_mpz_t())) * sgn(t);
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

double to_double_down(const Dyadic& d) {
  mpq_class x(d.a);
  mpq_div_2exp(x.get_mpq_t(), x.get_mpq_t(), d.k);
  return x.get_d();  // truncation: rounds down for x >= 0
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
int compare(const Dyadic& x, const Dyadic& y) {
  const unsigned k = std::max(x.k, y.k);
  return cmp(shifted(x.a, k - x.k), shifted(y.a, k - y.k));
}

}  // namespace

void refine_with_approximation(const IntegerPoly& p, IsolatedRoot& r) {
  if (r.exact) return;
  const std::array<long double, 5> c = scaled_coefficients(p);
  // A guess, checked exactly below.
  const long double approx =
      newton_guess(c, p.deg, to_double_down(r.lo), std::nextafter(to_double_down(r.hi), 2.0), r.sign_at_lo);
  const auto inside = [&](const Dyadic& x) { return compare(r.lo, x) < 0 && compare(x, r.hi) < 0; };
  const double guess = static_cast<double>(approx);
  for (double d : {guess, std::nextafter(guess, 0.0), std::nextafter(guess, 2.0)}) {
    const Dyadic x = to_dyadic(d);
    if (inside(x) && sign_at(p, x) == 0) {  // p's only root in the cell
      r.exact = true;
      r.at = x;
      return;
    }
  }
  const unsigned k = kRefinedCellBits;
  if (k <= r.lo.k) return;
  // approx in [0, 1], so floor(approx 2^k) < 2^56 fits an unsigned long exactly.
  const mpz_class a(static_cast<unsigned long>(std::floor(std::ldexp(approx, static_cast<int>(k)))));
  for (const mpz_class& start : {a, mpz_class(a - 1), mpz_class(a + 1)}) {
    const Dyadic lo_x{start, k}, hi_x{start + 1, k};
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

void bisect(const IntegerPoly& p, IsolatedRoot& r) {
  const Dyadic mid{2 * r.lo.a + 1, r.lo.k + 1};
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

}  // namespace exactccd::exact
