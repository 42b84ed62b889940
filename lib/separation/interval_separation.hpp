// The filtered method's interval stage for minimum separation (docs/design.md, 4b.3). The
// terms of separation_terms.hpp are built in interval arithmetic (CGAL::Interval_nt under
// upward rounding) from the double coordinates, so every coefficient encloses the exact one and
// every evaluation below encloses the exact value (inclusion property; overflow gives infinite
// bounds, which never certify; the caller's DefaultFpEnvironment has cleared flush-to-zero).
//
// A term is *excluded* on a time cell when its f is certainly > 0 or one of its g certainly
// <= 0 on the whole cell: it holds nowhere there. A cell is also free of contact when a
// direction separates the primitives over it (separating_direction.hpp: the rows at the cell's
// ends, ProjectionFrame::over). The stage
//  0. walks the cells in time order first with directions alone (every direction, halving down
//     to depth 3, i.e. eighths of [0, tmax]); the terms are built only at the first cell no
//     direction separates (most near misses never need them), and step 1 runs only if that
//     cell starts at 0 (otherwise [0, a] is free);
//  1. decides t = 0: a term certainly holding (f <= 0, every g > 0) gives TOI [0, 0];
//  2. walks the cells of [0, tmax] in time order, splitting a cell while a term is not excluded
//     (and the primitives' own pair's direction does not separate it);
//     cells where every term is excluded are free of contact;
//  3. in the first cell where one term i is left, if its g are certainly > 0 on the cell, its f
//     certainly > 0 at the cell's start a and < 0 at its end b, and f' certainly != 0 on the
//     cell, then f_i has exactly one root t* in (a, b), every other term is excluded, [0, a] is
//     free: t* is the earliest contact (by 4b.2 it is a root of f_i where term i holds: f_i < 0
//     just after t*, g_i > 0). Halving at doubles m with certain signs of f_i(m) narrows (a, b)
//     to two consecutive doubles, the tight TOI (t* is not a double: f_i has a nonzero sign at
//     every double examined);
//  4. if all of [0, tmax] is free: no collision;
//  For the answer alone (no TOI asked), a term certainly holding at a cell's midpoint, or the
//  single sign change of step 3, ends the walk with "collides" (and an enclosure of the TOI,
//  not the tightest: no narrowing);
//  5. if the walk is undecided and every point lies in one plane, walks again without the
//     point-triangle and edge-edge terms (the argument at step 5 below).
// The signs of f at the doubles examined in step 3 are certified in double-double arithmetic
// (distance_sign.hpp), exactly in integers only where that is not decisive.
// Anything else (a sign that intervals cannot certify: tangent passes, a root that is a double,
// two terms meeting at t*) returns "undecided" and the exact path answers.
#pragma once

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "exactccd/rational.hpp"
#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"
#include "separation/distance_sign.hpp"
#include "separation/separating_direction.hpp"
#include "separation/separation_terms.hpp"

namespace exactccd::separation {

/// The interval stage's verdict: decided (the TOI, or nullopt for no collision) or not.
struct IntervalVerdict {
  bool decided = false;
  std::optional<TimeInterval> toi;
  bool used_integers = false;  ///< GMP was used: an exact sign at a double, or the plane test (step 5)
  /// When undecided: the feature pairs not proven apart (use[f] false: feature f's term holds
  /// nowhere in [0, 1], feature_separated), for the exact path.
  std::array<bool, 9> use{true, true, true, true, true, true, true, true, true};
};

namespace interval_detail {

using I = CGAL::Interval_nt<false>;

/// p(t) by Horner's scheme, from p's highest coefficient that is not exactly [0, 0] (terms are
/// stored with degree 6, most of them have a lower degree: for a finite t the skipped steps
/// would compute [0, 0] t + [0, 0] = [0, 0], so the result is the same interval).
template <int D>
I evaluate(const contact::Poly<I, D>& p, const I& t) {
  int k = D;
  while (k > 0 && p.c[k].inf() == 0 && p.c[k].sup() == 0) --k;
  I r = p.c[k];
  for (--k; k >= 0; --k) r = r * t + p.c[k];
  return r;
}

/// 1 / -1 when the interval is certainly positive / negative, 0 otherwise.
inline int certain_sign(const I& x) { return x.inf() > 0 ? 1 : x.sup() < 0 ? -1 : 0; }

/// p' (coefficients above p's degree left exactly [0, 0], as evaluate expects).
inline contact::Poly<I, 5> derivative(const Poly6<I>& p) {
  contact::Poly<I, 5> r;
  int degree = 6;
  while (degree > 0 && p.c[degree].inf() == 0 && p.c[degree].sup() == 0) --degree;
  for (int k = 1; k <= 6; ++k) r.c[k - 1] = k <= degree ? p.c[k] * I(k) : I(0);
  return r;
}

/// A term (separation_terms.hpp) with the derivatives of its polynomials (formed once per
/// query, used on every cell): slope[0] of the distance, slope[1 + k] of positive[k].
struct SlopedTerm {
  Term<I> term;
  std::array<contact::Poly<I, 5>, 5> slope;

  explicit SlopedTerm(Term<I>&& t) : term(std::move(t)) {
    slope[0] = derivative(term.distance);
    for (int k = 0; k < term.positives; ++k) slope[1 + k] = derivative(term.positive[k]);
  }
};

/// An enclosure of p over the cell [a, b] (t = [a, b], m its midpoint; dp = p'): where p' has
/// a certain sign on the cell, p is monotone there and its range is the hull of p(a) and p(b);
/// otherwise the mean-value form p(m) + p'(t) (t - m) intersected with Horner's scheme over t
/// (both enclose the range; the first shrinks with the cell's width squared near a root, where
/// Horner's scheme over power-basis coefficients suffers from cancellation).
inline I range(const Poly6<I>& p, const contact::Poly<I, 5>& dp, double a, double b) {
  const I t(a, b);
  const I slope = evaluate(dp, t);
  if (certain_sign(slope) != 0) {
    const I pa = evaluate(p, I(a)), pb = evaluate(p, I(b));
    return I(std::min(pa.inf(), pb.inf()), std::max(pa.sup(), pb.sup()));
  }
  const double m = a + (b - a) / 2;  // any point of the cell will do
  const I mean_value = evaluate(p, I(m)) + slope * (t - I(m));
  const I horner = evaluate(p, t);
  return I(std::max(mean_value.inf(), horner.inf()), std::min(mean_value.sup(), horner.sup()));
}

/// The term holds nowhere in the cell [a, b] (certainly).
inline bool excluded(const SlopedTerm& sloped, double a, double b) {
  const Term<I>& term = sloped.term;
  if (range(term.distance, sloped.slope[0], a, b).inf() > 0) return true;
  for (int k = 0; k < term.positives; ++k)
    if (range(term.positive[k], sloped.slope[1 + k], a, b).sup() <= 0) return true;
  return false;
}

/// The term holds at t (certainly): f <= 0 and every g > 0.
inline bool holds(const Term<I>& term, const I& t) {
  if (evaluate(term.distance, t).sup() > 0) return false;
  for (int k = 0; k < term.positives; ++k)
    if (evaluate(term.positive[k], t).inf() <= 0) return false;
  return true;
}

/// The exact sign of feature f's distance polynomial at the double m in [0, 1], from the
/// positions at m (x: the query's points3 rows in doubles): certified in double-double
/// arithmetic when that is decisive (distance_sign.hpp), else exactly in integers (a root at a
/// double gives 0). Needs round-to-nearest. `approximation`: as in certified_distance_sign
/// (the same positive factor for every m of one query), when the double-double sign decides.
template <std::size_t N>
int distance_sign_at(const kinds::Feature& f, const std::array<Vec3, N>& x, double d, double m,
                     double* approximation, bool& used_integers) {
  constexpr std::size_t P = N / 2;
  if (const int s = certified_distance_sign(f, x, d, m, approximation); s != 0) return s;
  used_integers = true;
  // Exactly, in integers: every double is an integer times 2^e; scaling every length (the
  // coordinates and d) by one power of two 2^S multiplies f, homogeneous of degree 2, 4 or 6 in
  // lengths, by a positive factor, so its sign is unchanged. With E the least ulp exponent of
  // the coordinates and d, and m = M 2^-K, the positions at m scaled by 2^(K - E) are the
  // integers X0 2^K + M (X1 - X0). Constant polynomials carry the values (their operators
  // evaluate at once; mpz_class's expression templates would dangle in feature_condition's
  // `auto` temporaries).
  using Z = contact::Poly<mpz_class, 0>;
  const auto ulp_exponent = [](double v) {
    int e = 0;
    std::frexp(v, &e);
    return v == 0 ? std::numeric_limits<int>::max() : e - 53;
  };
  int E = ulp_exponent(d);
  for (std::size_t i = 0; i < N; ++i)
    for (const double c : {x[i].x, x[i].y, x[i].z}) E = std::min(E, ulp_exponent(c));
  if (E == std::numeric_limits<int>::max()) E = 0;  // everything is zero
  const auto scaled = [&](double v) {  // v 2^-E, an integer
    if (v == 0) return mpz_class(0);
    int e = 0;
    const double f = std::frexp(v, &e);
    mpz_class z(std::ldexp(f, 53));  // |f| 2^53 < 2^53: exact
    return mpz_class(z << static_cast<mp_bitcnt_t>(e - 53 - E));
  };
  int em = 0;
  const double fm = std::frexp(m, &em);  // m = M 2^-K, K = 53 - em >= 0 for m in (0, 1)
  const mpz_class M(std::ldexp(fm, 53));
  const mp_bitcnt_t K = static_cast<mp_bitcnt_t>(53 - em);
  std::array<Vec3T<Z>, P> exact;
  const auto move_exactly = [&](double x0, double x1) {
    const mpz_class X0 = scaled(x0);
    return Z{{mpz_class((X0 << K) + M * (scaled(x1) - X0))}};
  };
  for (std::size_t p = 0; p < P; ++p)
    exact[p] = {move_exactly(x[p].x, x[p + P].x), move_exactly(x[p].y, x[p + P].y),
                move_exactly(x[p].z, x[p + P].z)};
  const mpz_class D = scaled(d) << K;
  return sgn(distance_at(f, exact, Z{{mpz_class(D * D)}}).c[0]);
}

/// True when every point of x lies in one plane (exactly, in GMP rationals): the points minus
/// the first span at most a plane.
template <std::size_t N>
bool coplanar(const std::array<Vec3, N>& x) {
  std::array<std::array<mpq_class, 3>, N> v;
  for (std::size_t i = 0; i < N; ++i)
    v[i] = {mpq_class(x[i].x) - mpq_class(x[0].x), mpq_class(x[i].y) - mpq_class(x[0].y),
            mpq_class(x[i].z) - mpq_class(x[0].z)};
  for (std::size_t i = 1; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j) {
      const std::array<mpq_class, 3> n{mpq_class(v[i][1] * v[j][2] - v[i][2] * v[j][1]),
                                       mpq_class(v[i][2] * v[j][0] - v[i][0] * v[j][2]),
                                       mpq_class(v[i][0] * v[j][1] - v[i][1] * v[j][0])};
      if (sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0) continue;
      for (std::size_t k = 1; k < N; ++k)
        if (sgn(mpq_class(n[0] * v[k][0] + n[1] * v[k][1] + n[2] * v[k][2])) != 0) return false;
      return true;  // n spans the normal of the plane through x[0], x[i], x[j]: all lie in it
    }
  return true;  // all on one line: in a plane
}

/// A guess of the root of feature f's distance in (a, b) (f(a) > 0 > f(b)): the Illinois
/// variant of regula falsi on the distance evaluated from the geometry in long double. Only a
/// guess: the caller certifies signs at whatever it returns.
template <std::size_t N>
double root_guess(const kinds::Feature& f, const std::array<Vec3, N>& x, double d, double a, double b) {
  constexpr std::size_t P = N / 2;
  using L = long double;
  const auto value = [&](L t) {
    std::array<Vec3T<L>, P> at;
    const auto move = [&](double x0, double x1) { return L(x0) + t * (L(x1) - L(x0)); };
    for (std::size_t p = 0; p < P; ++p)
      at[p] = {move(x[p].x, x[p + P].x), move(x[p].y, x[p + P].y), move(x[p].z, x[p + P].z)};
    return distance_at(f, at, L(d) * L(d));
  };
  L lo = a, hi = b, f_lo = value(lo), f_hi = value(hi);
  if (!(f_lo > 0 && f_hi < 0)) return a + (b - a) / 2;
  int side = 0;
  for (int i = 0; i < 60 && hi - lo > 0; ++i) {
    const L m = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(m > lo && m < hi)) break;
    const L fm = value(m);
    if (fm == 0) return static_cast<double>(m);
    if (fm > 0) {
      lo = m;
      f_lo = fm;
      if (side == 1) f_hi /= 2;  // Illinois: halve the stale end
      side = 1;
    } else {
      hi = m;
      f_hi = fm;
      if (side == -1) f_lo /= 2;
      side = -1;
    }
  }
  return static_cast<double>((lo + hi) / 2);
}

}  // namespace interval_detail

/// The interval stage for a query of any kind with min_distance d and time limit tmax (valid,
/// checked by the caller). Needs round-to-nearest on entry (it installs upward rounding itself).
/// Without `want_toi` only whether the query collides is decided: a collision's TOI is then an
/// enclosure [lo, hi] of the earliest time, not the tightest one (a term that certainly holds
/// at a double m of [0, tmax] gives [0, m]; a single root in a cell (a, b) with [0, a] free
/// gives [a, b]).
template <class Query>
IntervalVerdict interval_separation(const Query& q, double d, double tmax, bool want_toi = true) {
  using namespace interval_detail;
  using Kind = kinds::kind_of<Query>;
  // Upward rounding (for Interval_nt) is installed when the terms are built: the directions
  // before that are certified in any rounding mode (separating_direction.hpp).
  std::optional<CGAL::Protect_FPU_rounding<true>> upward;
  const auto xd = points3<double>(q);
  const ProjectionFrame frame(xd, d);
  // The terms are built when the walk first meets a cell that no direction separates (0.
  // below); a query whose cells down to kSeparationDepth are all separated needs none.
  std::array<bool, Kind::features.size()> use{};
  std::array<int, Kind::features.size()> feature_of_term{};
  std::vector<SlopedTerm> terms;
  bool built = false;
  bool zero_undecided = false;  // step 1 could not decide t = 0
  IntervalVerdict undecided{};
  // Builds the terms; with `at_zero`, decides t = 0 (step 1): a verdict when that decides the
  // query (or leaves it undecided), nothing when every term certainly fails at 0.
  const auto build = [&](bool at_zero) -> std::optional<IntervalVerdict> {
    built = true;
    upward.emplace();
    // Feature pairs whose parts a direction keeps farther than d apart never hold: no term.
    std::size_t used = 0;
    for (std::size_t f = 0; f < Kind::features.size(); ++f)
      if ((use[f] = !feature_separated<Kind>(frame, Kind::features[f]))) feature_of_term[used++] = static_cast<int>(f);
    for (std::size_t f = 0; f < use.size(); ++f) undecided.use[f] = use[f];
    if (used == 0) return IntervalVerdict{true, std::nullopt};
    terms.reserve(used);
    for_each_term<Kind>(points3<I>(q), I(d) * I(d), use.data(), [&](Term<I>&& t) { terms.emplace_back(std::move(t)); });
    if (!at_zero) return std::nullopt;
    // 1. t = 0.
    bool all_fail_at_zero = true;
    for (const SlopedTerm& term : terms) {
      if (holds(term.term, I(0))) return IntervalVerdict{true, TimeInterval{0.0, 0.0}};
      all_fail_at_zero = all_fail_at_zero && excluded(term, 0.0, 0.0);
    }
    if (!all_fail_at_zero) {
      zero_undecided = true;  // step 5 needs t = 0 ruled out: the exact path answers
      return undecided;
    }
    return std::nullopt;
  };
  // 2.-4. The walk over the cells, with the terms whose bits are set in `initial`.
  const auto walk = [&](std::uint32_t initial) -> IntervalVerdict {
    // 2. Cells in time order (a stack of right halves).
    constexpr int kMaxDepth = 48;
    constexpr int kSeparationDepth = 3;
    // Each cell carries the terms not excluded on its parent (a bit per term): a term excluded
    // on a cell holds nowhere in it, so nowhere in its halves, and is not examined again there.
    struct Cell {
      double a, b;
      int depth;
      std::uint32_t open;  // bit i: term i not excluded on the parent cell
    };
    static_assert(Kind::features.size() <= 9);  // IntervalVerdict::use
    std::array<Cell, kMaxDepth + 2> stack;
    int top = 0;
    stack[top++] = {0.0, tmax, 0, initial};
    while (top > 0) {
      const Cell cell = stack[--top];
      // 0. A direction keeping the primitives apart over the cell excludes every term at once:
      // before the terms exist every direction is tried, down to kSeparationDepth; then only
      // the primitives' own pair's (cheap, and the one that separates most cells).
      if (cell.depth > 0 && (built ? primitives_separated<Kind>(frame.over(cell.a, cell.b), true, 1)
                                   : primitives_separated<Kind>(frame.over(cell.a, cell.b), false)))
        continue;
      if (!built) {
        if (cell.depth < kSeparationDepth) {
          const double m = cell.a + (cell.b - cell.a) / 2;
          if (cell.a < m && m < cell.b) {
            stack[top++] = {m, cell.b, cell.depth + 1, cell.open};
            stack[top++] = {cell.a, m, cell.depth + 1, cell.open};
            continue;
          }
        }
        // [0, cell.a] is free (its cells were separated), so t = 0 needs deciding only when
        // this cell starts at 0.
        if (const auto verdict = build(cell.a == 0)) return *verdict;
      }
      if (!want_toi) {  // a term certainly holding at the cell's midpoint: a collision there or earlier
        const double m = cell.a + (cell.b - cell.a) / 2;
        for (std::size_t i = 0; i < terms.size(); ++i)
          if ((cell.open >> i & 1) && holds(terms[i].term, I(m))) return {true, TimeInterval{0.0, m}};
      }
      int alive = -1, alive_count = 0;
      std::uint32_t open = 0;
      for (std::size_t i = 0; i < terms.size(); ++i)
        if ((cell.open >> i & 1) && !excluded(terms[i], cell.a, cell.b)) {
          alive = static_cast<int>(i);
          ++alive_count;
          open |= std::uint32_t{1} << i;
        }
      if (alive_count == 0) continue;  // free of contact
      if (alive_count == 1) {
        // 3. One term left: a simple sign change of f with every g positive?
        const Term<I>& term = terms[alive].term;
        const auto& slope = terms[alive].slope;
        bool g_positive = true;
        for (int k = 0; k < term.positives && g_positive; ++k)
          g_positive = range(term.positive[k], slope[1 + k], cell.a, cell.b).inf() > 0;
        if (g_positive && certain_sign(evaluate(term.distance, I(cell.a))) > 0 &&
            certain_sign(evaluate(term.distance, I(cell.b))) < 0 &&
            certain_sign(evaluate(slope[0], I(cell.a, cell.b))) != 0) {
          if (!want_toi) return {true, TimeInterval{cell.a, cell.b}};
          const kinds::Feature& feature = Kind::features[feature_of_term[alive]];
          // Signs at doubles in double-double arithmetic, which needs round-to-nearest (restored
          // to upward rounding when this scope ends; the stage returns from it).
          const CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
          // Narrowing: f(a) > 0 > f(b) around the single root. Each step examines one double m
          // strictly inside (a, b) and keeps the half with the sign change; any choice of m is
          // valid (only the certain sign at m is used), so m is chosen for speed.
          double a = cell.a, b = cell.b;
          bool used_integers = false;
          // First a guess of the root from the geometry in long double (only a guess: any double
          // of the cell may be examined), then the certain signs at the guess and at its
          // neighbour on the root's side: where the guess is right to an ulp, two signs give the
          // tight TOI (as the contact path's TOI narrowing does).
          constexpr double kInf = std::numeric_limits<double>::infinity();
          // Approximations of f (one positive factor for the whole query: distance_sign.hpp) at
          // a and at b, for the estimates below; 0 when not computed yet.
          double fa = 0, fb = 0;
          const auto step = [&](double m) {  // the certain sign at m moves a or b; 0: f(m) = 0
            double approximation = 0;
            const int sign = distance_sign_at(feature, xd, d, m, &approximation, used_integers);
            const double fm = sign * std::max(std::abs(approximation), 0x1p-1000);
            if (sign > 0) a = m, fa = fm;
            if (sign < 0) b = m, fb = fm;
            return sign;
          };
          const double guess = root_guess(feature, xd, d, a, b);
          if (a < guess && guess < b) {
            const int s = step(guess);
            if (s == 0) return {true, TimeInterval{guess, guess}, true};
            const double neighbour = s > 0 ? std::nextafter(guess, kInf) : std::nextafter(guess, -kInf);
            if (a < neighbour && neighbour < b && step(neighbour) == 0)
              return {true, TimeInterval{neighbour, neighbour}, true};
          }
          // Then regula falsi on the double-double approximations (Illinois: the end that stays
          // twice has its value halved), the estimate moved to the nearest double inside (a, b)
          // when it rounds onto an end (the root is then within an ulp or so of that end), and a
          // bisection after three steps in a row that did not halve the cell, so that the cell
          // shrinks at least geometrically.
          if (std::nextafter(a, kInf) < b) {
            if (fa == 0) certified_distance_sign(feature, xd, d, a, &fa);
            if (fb == 0) certified_distance_sign(feature, xd, d, b, &fb);
          }
          int side = 0, slow = 0;
          while (std::nextafter(a, kInf) < b) {
            double m = a + (b - a) / 2;
            if (slow < 3 && fa > 0 && fb < 0) {
              m = a + (b - a) * (fa / (fa - fb));
              if (!(m > a)) m = std::nextafter(a, kInf);
              if (!(m < b)) m = std::nextafter(b, -kInf);
            } else {
              slow = 0;
            }
            if (!(a < m && m < b)) m = std::nextafter(a, kInf);
            const double width = b - a;
            const int s = step(m);
            if (s == 0) return {true, TimeInterval{m, m}, true};  // f(m) = 0 exactly: t* = m
            if (s == side) (s > 0 ? fb : fa) /= 2;
            side = s;
            slow = (b - a) > width / 2 ? slow + 1 : 0;
          }
          if (std::nextafter(a, std::numeric_limits<double>::infinity()) != b) return undecided;
          return {true, TimeInterval{a, b}, used_integers};
        }
      }
      if (cell.depth >= kMaxDepth) return undecided;
      const double m = cell.a + (cell.b - cell.a) / 2;
      if (!(cell.a < m && m < cell.b)) return undecided;
      stack[top++] = {m, cell.b, cell.depth + 1, open};  // right half, examined after the left one
      stack[top++] = {cell.a, m, cell.depth + 1, open};
    }
    return {true, std::nullopt};  // 4. every cell of [0, tmax] is free
  };
  const IntervalVerdict verdict = walk(~std::uint32_t{0});  // every term (bits beyond them unused)
  if (verdict.decided || zero_undecided) return verdict;
  const std::uint32_t all = (std::uint32_t{1} << terms.size()) - 1;
  // 5. Coplanar queries: when every point lies in one fixed plane at t0 and at t1 (so at every
  // t), the point-triangle and edge-edge terms never hold first at a t > 0, and the walk runs
  // again without them. Their normal (n, or w) is normal to the plane or zero, and the vector
  // to the other point (p - a, or r) lies in it, so h = 0 and f = -d^2 |n|^2 (d > 0 here):
  // f(t) = 0 only where n(t) = 0, where every g (a multiple of n) is 0 and the term fails.
  // By 4b.2 (docs/design.md) the earliest t* > 0 of S is a root of the f of a term holding
  // there, so not of these terms: at t* another term holds, and the walk without them finds
  // the same t* (t* = 0 was ruled out in step 1, with every term), or no t* when S is empty
  // (the walk's terms are a subset). Such queries (a 2D query, z = 0; a simulation in a
  // plane) reach here when their edges or triangle become
  // degenerate (n = 0) inside [0, tmax]: every g of the term vanishes there and intervals
  // cannot exclude it. The plane test is exact (GMP rationals: counted as integer signs).
  std::uint32_t planar = 0;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    const kinds::FeaturePair pair = Kind::features[feature_of_term[i]].pair;
    if (pair == kinds::FeaturePair::point_triangle || pair == kinds::FeaturePair::edge_edge) planar |= std::uint32_t{1} << i;
  }
  if (planar == 0 || !(Kind::dimension == 2 || coplanar(xd))) return verdict;
  IntervalVerdict again = walk(all & ~planar);
  if (!again.decided) return verdict;
  again.used_integers = again.used_integers || Kind::dimension == 3;
  return again;
}

}  // namespace exactccd::separation
