// The one narrowing of a root to adjacent doubles, for both questions and both motion models:
// the contact TOI (a root of the volume V, filter/toi_narrowing.cpp; rigid/contact_walk.cpp, and
// of an orientation, rigid/coplanar_walk.cpp) and the minimum-separation TOI (a root of a feature
// pair's distance f, separation/separation_walk.cpp, rigid/rigid_separation_walk.cpp).
//
// Given a cell (lo, hi) of doubles holding exactly one root t* of f, with f's sign at lo known
// and nonzero (the opposite at hi), each step examines one double m strictly inside the cell,
// takes f's exact sign there (0: t* = m, a double) and keeps the half with the sign change.
// Any choice of m is valid (only the certain sign at m is used), so the result is the tightest
// double interval around t* whatever the choices: [t*, t*] when t* is a double, else the two
// consecutive doubles around it. The choices only decide the speed: first a guess of the root
// (from a long-double evaluation: right to an ulp or so, two signs usually settle it: the
// guess and its neighbour on the root's side), then the Chooser's doubles: halving
// (Bisection), regula falsi on approximate values of f at the cell's ends (RegulaFalsi), or
// secant steps through the last two doubles examined (Secant).
#pragma once

#include <cmath>
#include <limits>

#include "exactccd/types.hpp"

namespace exactccd::numeric {

/// f's exact sign at a double, and an approximation of f there (times a positive factor fixed
/// for the root: only its ratio to other approximations matters; 0 when not computed).
struct SignAt {
  int sign = 0;
  double approximation = 0;
};

/// Halving the cell: the doubles examined after the guess are midpoints.
struct Bisection {
  /// Before the first midpoint (nothing to prepare).
  void begin(double, double) {}
  /// f was examined at the double t, an end of the cell that moved there (sign and
  /// approximation at it).
  void moved(double, const SignAt&) {}
  /// A step of the loop changed the cell from a width `width` to (lo, hi).
  void stepped(int, double, double, double) {}
  /// The next double to examine.
  double next(double lo, double hi) const { return lo + (hi - lo) / 2; }
};

/// Regula falsi on approximate values of f (Illinois: the end that stays twice has its value
/// halved), the estimate moved to the nearest double inside the cell when it rounds onto an end
/// (the root is then within an ulp or so of that end), and a bisection after three steps in a
/// row that did not halve the cell, so that the cell shrinks at least geometrically.
/// `approximate(t)`: an approximation of f at the double t (any value), for the ends of the
/// cell whose value no examined sign gave.
template <class Approximate>
class RegulaFalsi {
 public:
  /// With the approximation of f for the ends not examined.
  explicit RegulaFalsi(Approximate approximate) : approximate_(std::move(approximate)) {}

  /// Before the loop: the approximations at the ends not examined yet.
  void begin(double lo, double hi) {
    if (f_lo_ == 0) f_lo_ = approximate_(lo);
    if (f_hi_ == 0) f_hi_ = approximate_(hi);
  }
  /// An end moved to a double where f's sign (nonzero) and approximation are known.
  void moved(double, const SignAt& s) {
    const double f = s.sign * std::fmax(std::fabs(s.approximation), 0x1p-1000);
    (s.sign > 0 ? f_lo_ : f_hi_) = f;
  }
  /// A step of the loop moved an end (sign s at the new end) and left the cell (lo, hi) of
  /// former width `width`: halve the stale end's value (Illinois), count slow steps.
  void stepped(int s, double width, double lo, double hi) {
    if (s == side_) (s > 0 ? f_hi_ : f_lo_) /= 2;
    side_ = s;
    slow_ = (hi - lo) > width / 2 ? slow_ + 1 : 0;
  }
  /// The next double to examine (inside the cell, or the caller moves it there).
  double next(double lo, double hi) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    if (!(slow_ < 3 && f_lo_ > 0 && f_hi_ < 0)) {
      slow_ = 0;
      return lo + (hi - lo) / 2;
    }
    double m = lo + (hi - lo) * (f_lo_ / (f_lo_ - f_hi_));
    if (!(m > lo)) m = std::nextafter(lo, kInf);
    if (!(m < hi)) m = std::nextafter(hi, -kInf);
    return m;
  }

 private:
  Approximate approximate_;
  double f_lo_ = 0, f_hi_ = 0;  // f's approximations at the ends (f > 0 at lo: RegulaFalsi's callers)
  int side_ = 0, slow_ = 0;
};

/// Secant steps on approximate values of f through the last two doubles examined (the guess
/// and its neighbour first: from an approximation accurate to many bits, as double-double
/// gives, one step lands within an ulp or so of the root, and the next examines the neighbour
/// on the root's side: the estimate falls on an end of the cell and is moved inside, next to
/// it). Bisection while fewer than two approximations are known (an approximation of 0: not
/// computed), when the last two are equal, and after three steps in a row that did not halve
/// the cell, so that the cell shrinks at least geometrically (by half every four steps at
/// worst, as bisection does every step). Why three: a secant step landing within an ulp or so of
/// the root, then the step to its neighbour, are two steps that do not halve the cell yet are
/// the fast path; any fixed count keeps the bound geometric and changes no result (only the
/// doubles examined: tightest_enclosure).
class Secant {
 public:
  /// Before the loop (nothing to prepare: the examined doubles give the approximations).
  void begin(double, double) {}
  /// f was examined at the double t (an end of the cell now): the last two examined are kept.
  void moved(double t, const SignAt& s) {
    t0_ = t1_;
    f0_ = f1_;
    t1_ = t;
    f1_ = s.approximation;
    known_ = s.approximation == 0 ? 0 : known_ + 1;
  }
  /// A step of the loop left the cell (lo, hi) of former width `width`: count slow steps.
  void stepped(int, double width, double lo, double hi) { slow_ = (hi - lo) > width / 2 ? slow_ + 1 : 0; }
  /// The next double to examine (inside the cell, or the caller moves it there).
  double next(double lo, double hi) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    if (known_ < 2 || slow_ >= 3 || f0_ == f1_) {
      slow_ = 0;
      return lo + (hi - lo) / 2;
    }
    double m = t1_ - f1_ * ((t1_ - t0_) / (f1_ - f0_));
    if (!(m > lo)) m = std::nextafter(lo, kInf);  // also a NaN estimate
    if (!(m < hi)) m = std::nextafter(hi, -kInf);
    return m;
  }

 private:
  double t0_ = 0, f0_ = 0, t1_ = 0, f1_ = 0;  // the last two doubles examined, f's approximations there
  int known_ = 0, slow_ = 0;                  // approximations known in a row; slow steps in a row
};

/// The tightest double interval around the only root t* of f in the open cell (lo, hi) (lo < hi
/// doubles; f's sign at lo is sign_at_lo != 0, the opposite at hi). `sign(m)` returns SignAt:
/// f's exact sign at a double m inside the cell (0: f(m) = 0) and an approximation; `guess` a
/// double near t* (any value); `chooser` a Bisection, RegulaFalsi (f > 0 at lo) or Secant.
/// The chooser only decides which doubles are examined, never the result: every examined m is
/// strictly inside the cell (moved there otherwise), the signs are exact, and the loop ends
/// only at an exact zero (the point) or at consecutive doubles around the sign change, the one
/// tightest double enclosure of t*.
template <class Sign, class Chooser>
TimeInterval tightest_enclosure(double lo, double hi, int sign_at_lo, double guess, Sign&& sign, Chooser& chooser) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // Examines m: moves an end there (true), or finds t* = m (false).
  const auto examine = [&](double m, int& s) {
    const SignAt at = sign(m);
    s = at.sign;
    if (s == 0) return false;
    (s == sign_at_lo ? lo : hi) = m;
    chooser.moved(m, at);
    return true;
  };
  int s = 0;
  if (lo < guess && guess < hi) {
    if (!examine(guess, s)) return {guess, guess};
    const double neighbour = s == sign_at_lo ? std::nextafter(guess, kInf) : std::nextafter(guess, -kInf);
    if (lo < neighbour && neighbour < hi && !examine(neighbour, s)) return {neighbour, neighbour};
  }
  if (std::nextafter(lo, kInf) < hi) chooser.begin(lo, hi);
  while (std::nextafter(lo, kInf) < hi) {
    double m = chooser.next(lo, hi);
    if (!(lo < m && m < hi)) m = std::nextafter(lo, kInf);
    const double width = hi - lo;
    if (!examine(m, s)) return {m, m};
    chooser.stepped(s, width, lo, hi);
  }
  return {lo, hi};
}

}  // namespace exactccd::numeric
