// Boxes of floats rounded outwards, for the trees of the broad phase (box_tree.hpp): half the
// memory of the double boxes and twice the boxes per cache line. Every float box holds the
// double box it was made from, so float boxes that do not overlap prove that the double boxes
// do not; pairs whose float boxes overlap are then tested on the exact double boxes. (Rounding
// every bound to nearest would keep overlaps too, rounding being monotone, as long as every
// conversion used the same rounding mode; the outward rounding needs no such assumption.)
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "scene/broad_phase.hpp"

namespace exactccd::scene {

/// A closed axis-aligned box of floats.
struct FloatBox {
  std::array<float, 3> lo, hi;
};

/// The float next to f towards -infinity, for f not NaN and not -infinity: std::nextafter(f,
/// -inf) without the library call. IEEE 754 floats of one sign are ordered as their bit
/// patterns: a positive f (+infinity included: its predecessor is the largest finite float)
/// steps down by one in its bits, a negative one up by one; either zero goes to the negative
/// float of least magnitude, -2^-149.
inline float float_down(float f) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof bits);
  if (f > 0)
    --bits;
  else if (f < 0)
    ++bits;
  else
    bits = 0x80000001u;
  float r = 0;
  std::memcpy(&r, &bits, sizeof r);
  return r;
}

/// The float next to f towards +infinity (float_down mirrored: -float_down(-f)), for f not NaN
/// and not +infinity.
inline float float_up(float f) { return -float_down(-f); }

/// The largest float <= x. static_cast<float>(x) is, in any rounding direction, x itself or
/// one of the two floats around it (or an infinity / the largest finite float on overflow); if
/// it is above x, the float below it is not (it is the float below x's upper neighbour), and
/// comparing a float with a double is exact. x = -inf gives -inf (never stepped down).
inline float float_below(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? float_down(f) : f;
}

/// The smallest float >= x (as float_below, mirrored).
inline float float_above(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? float_up(f) : f;
}

/// The float box holding a double box (each bound rounded outwards).
inline FloatBox float_box(const Box& b) {
  return {{{float_below(b.lo[0]), float_below(b.lo[1]), float_below(b.lo[2])}},
          {{float_above(b.hi[0]), float_above(b.hi[1]), float_above(b.hi[2])}}};
}

/// A box as a float box holding it: float_box() of a double box, a float box itself.
inline FloatBox as_float_box(const Box& b) { return float_box(b); }
inline const FloatBox& as_float_box(const FloatBox& b) { return b; }

/// An empty float box (lo = +inf, hi = -inf): the hull's neutral element, overlapping nothing.
inline FloatBox empty_float_box() {
  constexpr float inf = std::numeric_limits<float>::infinity();
  return {{{inf, inf, inf}}, {{-inf, -inf, -inf}}};
}

/// The smallest float box holding both (exact: min and max).
inline FloatBox hull(const FloatBox& a, const FloatBox& b) {
  FloatBox h;
  for (int k = 0; k < 3; ++k) {
    h.lo[k] = a.lo[k] < b.lo[k] ? a.lo[k] : b.lo[k];
    h.hi[k] = a.hi[k] > b.hi[k] ? a.hi[k] : b.hi[k];
  }
  return h;
}

/// Whether two closed float boxes overlap (exact; combined without short circuit as
/// overlap(Box, Box)). Two overlapping double boxes have overlapping float boxes.
inline bool overlap(const FloatBox& a, const FloatBox& b) {
  const auto apart = [](float hi, float lo) { return static_cast<int>(hi < lo); };
  return (apart(a.hi[0], b.lo[0]) | apart(b.hi[0], a.lo[0]) | apart(a.hi[1], b.lo[1]) | apart(b.hi[1], a.lo[1]) |
          apart(a.hi[2], b.lo[2]) | apart(b.hi[2], a.lo[2])) == 0;
}

}  // namespace exactccd::scene
