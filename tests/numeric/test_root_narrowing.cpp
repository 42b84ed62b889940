// numeric::tightest_enclosure (root_narrowing.hpp) with each chooser: the result is the
// tightest double interval around the root whatever the guess and the approximations (good,
// missing, or wrong), checked against exact rational signs; and the Secant chooser, given
// approximations accurate to many bits (as the contact TOI's double-double values are), needs
// only a few signs from a guess far off, where halving needs about one per bit of the cell.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "numeric/root_narrowing.hpp"

namespace exactccd {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// f(t) = (t - r)(t + 1)(2 - t) with r rational in (0, 1): one root in [0, 1], f < 0 left of it.
struct Cubic {
  mpq_class r;
  mpq_class at(double t) const {
    const mpq_class T(t);
    return (T - r) * (T + 1) * (2 - T);
  }
};

/// The tightest double interval around r: [r, r] when r is a double, else the doubles below
/// and above it.
TimeInterval tightest(const mpq_class& r) {
  const double d = r.get_d();  // truncates towards zero: r >= 0, so d <= r
  if (mpq_class(d) == r) return {d, d};
  return {d, std::nextafter(d, kInf)};
}

enum class Approximations { exact, none, wrong };

/// Runs tightest_enclosure on (lo, hi) with `chooser`; the signs are exact, the approximations
/// as asked; `evaluations` counts the signs taken.
template <class Chooser>
TimeInterval narrow(const Cubic& f, double lo, double hi, double guess, Approximations a, Chooser& chooser,
                    int& evaluations, std::mt19937_64& rng) {
  evaluations = 0;
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  const auto sign = [&](double t) {
    ++evaluations;
    const mpq_class v = f.at(t);
    const int s = sgn(v);
    double approximation = 0;
    if (a == Approximations::exact) approximation = v.get_d();
    if (a == Approximations::wrong) approximation = noise(rng);  // any value, even of the wrong sign
    return numeric::SignAt{s, approximation};
  };
  return numeric::tightest_enclosure(lo, hi, -1, guess, sign, chooser);
}

TEST(RootNarrowing, EveryChooserGivesTheTightestEnclosure) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<long> numerator(1, (1L << 40) - 1);
  std::uniform_int_distribution<int> exponent(0, 60), shift(0, 1 << 20);
  for (int n = 0; n < 600; ++n) {
    Cubic f;
    // Dyadic roots (doubles, some at a cell's midpoint) and roots that are not doubles.
    f.r = n % 4 == 0 ? mpq_class(numerator(rng), 1L << 40) : mpq_class(numerator(rng), (1L << 40) - 1);
    f.r.canonicalize();
    const TimeInterval expected = tightest(f.r);
    // The cell: [0, 1], or a dyadic cell of width 2^-k around the root.
    const int k = n % 3 == 0 ? 0 : exponent(rng) % 40;
    const double width = std::ldexp(1.0, -k);
    double lo = std::floor(expected.lo / width) * width, hi = lo + width;
    if (!(lo < expected.lo || mpq_class(lo) < f.r)) lo = std::max(0.0, lo - width);
    if (!(mpq_class(hi) > f.r)) hi = std::min(1.0, hi + width);
    if (!(mpq_class(lo) < f.r && f.r < mpq_class(hi))) continue;  // the root on a cell end: not this case
    // Guesses: the root, a few ulps off, far off, outside the cell.
    double guess = expected.lo;
    for (int s = shift(rng) % (n % 5 == 0 ? 3 : 1 << (n % 20)); s > 0; --s) guess = std::nextafter(guess, n % 2 ? kInf : -kInf);
    if (n % 7 == 0) guess = -1;
    for (const Approximations a : {Approximations::exact, Approximations::none, Approximations::wrong}) {
      int evaluations = 0;
      numeric::Bisection bisection;
      numeric::Secant secant;
      const TimeInterval by_halving = narrow(f, lo, hi, guess, a, bisection, evaluations, rng);
      const TimeInterval by_secant = narrow(f, lo, hi, guess, a, secant, evaluations, rng);
      EXPECT_EQ(by_halving.lo, expected.lo) << "root " << f.r << ", query " << n;
      EXPECT_EQ(by_halving.hi, expected.hi) << "root " << f.r << ", query " << n;
      EXPECT_EQ(by_secant.lo, expected.lo) << "root " << f.r << ", query " << n << ", approximations " << int(a);
      EXPECT_EQ(by_secant.hi, expected.hi) << "root " << f.r << ", query " << n << ", approximations " << int(a);
    }
  }
}

// From a guess 2^10 to 2^30 ulps off, in a cell of width 2^-20 around a root near 0.37:
// halving takes about 30 signs (the cell's width in ulps is 2^33), the secant steps on exact
// approximations at most 6 (the guess, its neighbour, a step to within an ulp, its neighbour,
// and two to spare).
TEST(RootNarrowing, SecantNeedsFewSignsWithAccurateApproximations) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<long> numerator(1, (1L << 40) - 1);
  std::uniform_int_distribution<int> ulps(10, 30);
  int most_secant = 0, least_halving = 1000;
  for (int n = 0; n < 300; ++n) {
    Cubic f;
    f.r = mpq_class(3L << 39, 1L << 42) + mpq_class(numerator(rng), (1L << 62) - 1);  // about 0.375 + 2^-22
    f.r.canonicalize();
    const TimeInterval expected = tightest(f.r);
    const double lo = 0.375, hi = 0.375 + 0x1p-20;
    ASSERT_TRUE(mpq_class(lo) < f.r && f.r < mpq_class(hi));
    const double off = std::ldexp(std::nextafter(expected.lo, kInf) - expected.lo, ulps(rng));
    const double guess = std::clamp(n % 2 ? expected.lo + off : expected.lo - off, lo, hi);
    int evaluations = 0;
    numeric::Secant secant;
    const TimeInterval got = narrow(f, lo, hi, guess, Approximations::exact, secant, evaluations, rng);
    EXPECT_EQ(got.lo, expected.lo);
    EXPECT_EQ(got.hi, expected.hi);
    most_secant = std::max(most_secant, evaluations);
    numeric::Bisection bisection;
    narrow(f, lo, hi, guess, Approximations::exact, bisection, evaluations, rng);
    least_halving = std::min(least_halving, evaluations);
  }
  EXPECT_LE(most_secant, 6);
  EXPECT_GE(least_halving, 20);  // what the secant steps save
}

}  // namespace
}  // namespace exactccd
