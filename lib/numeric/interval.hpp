// Interval arithmetic in doubles (CGAL::Interval_nt<false>) and what the interval stages (the
// contact stage, filter/interval_stage.cpp; the separation walk, separation/separation_walk.cpp;
// the rigid walks, rigid/) ask of an interval: its certain sign, its sign class, the sign it
// certifies for the contact rule's oracles, the next double of a cell.
//
// Soundness rests on the inclusion property: every interval computed contains the exact real
// value of the quantity it stands for. Interval_nt<false> needs the rounding towards
// +infinity, which the stages install (CGAL::Protect_FPU_rounding) for their duration.
#pragma once

#include <CGAL/Interval_nt.h>

#include <cstdint>
#include <cstring>
#include <limits>

namespace exactccd::numeric {

/// Intervals of doubles; only under the upward rounding of CGAL::Protect_FPU_rounding<true>.
using Interval = CGAL::Interval_nt<false>;

/// 1 / -1 when the interval is certainly positive / negative, 0 otherwise (it contains 0, or
/// has NaN bounds).
inline int certain_sign(const Interval& x) {
  if (x.inf() > 0) return 1;
  if (x.sup() < 0) return -1;
  return 0;
}

/// Sign class of an interval: exactly [0, 0] is a certain zero (it encloses only 0).
enum class SignClass { negative, zero, positive, unknown };

/// The sign class of x.
inline SignClass classify(const Interval& x) {
  if (x.inf() > 0) return SignClass::positive;
  if (x.sup() < 0) return SignClass::negative;
  if (x.inf() == 0 && x.sup() == 0) return SignClass::zero;
  return SignClass::unknown;
}

/// The sign an oracle of the contact rule (contact/contact_rule.hpp) gives when it cannot
/// certify one: neither -1, 0 nor 1.
inline constexpr int kUnknownSign = 2;

/// The sign of the value that x encloses, where x certifies it: 1 or -1 when x excludes 0, 0
/// when x is exactly [0, 0] (it encloses only 0), otherwise kUnknownSign. The one interval sign
/// test of the filters' sign oracles, linear and rigid.
inline int interval_sign(const Interval& x) {
  switch (classify(x)) {
    case SignClass::positive:
      return 1;
    case SignClass::negative:
      return -1;
    case SignClass::zero:
      return 0;
    case SignClass::unknown:
      break;
  }
  return kUnknownSign;
}

/// The sign class of an exact sign (-1, 0, 1).
inline SignClass sign_class(int sign) {
  return sign > 0 ? SignClass::positive : sign < 0 ? SignClass::negative : SignClass::zero;
}

/// The next double above x, for finite x >= 0 (every cell of the stages lies in [0, 1]): the
/// bit patterns of the non-negative doubles are ordered as their values, so it is the pattern
/// plus one (std::nextafter, a library call, showed in profiles of the narrowing loops).
inline double next_up_nonnegative(double x) {
  // The smallest subnormal, 2^-1074, as a double literal (also for -0.0). Not
  // numeric_limits<double>::denorm_min(): libstdc++ spells it as a long double literal cast to
  // double, which -frounding-math (CGAL's intervals need it) leaves to run time, as an x87 load
  // and store whose subnormal result takes a microcode assist: about a third of the narrowing
  // loops' time on the cloth-ball step (perf annotate), wherever a cell starts at t = 0.
  if (x == 0) return 0x1p-1074;
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  ++bits;
  std::memcpy(&x, &bits, sizeof bits);
  return x;
}

}  // namespace exactccd::numeric
