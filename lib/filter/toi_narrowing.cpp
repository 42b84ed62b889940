#include "filter/toi_narrowing.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "contact/contact_polynomials.hpp"
#include "exact/integer_poly.hpp"
#include "filter/integer_query.hpp"
#include "filter/volume_sign.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd::filter {
namespace {

/// The tightest double interval around the only root of V in the open cell (lo, hi) (lo, hi
/// doubles, V's sign at lo nonzero and known, the opposite at hi). `sign(t)` is V's exact sign
/// at a double t. A long-double guess picks a double d; the signs at d and at its neighbour
/// on the root's side usually settle it in two evaluations; otherwise bisection over the
/// doubles of the cell, one sign per step.
template <class Sign>
TimeInterval tightest_enclosure(double guess, double lo, double hi, int sign_at_lo, Sign&& sign) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (lo < guess && guess < hi) {
    const int s = sign(guess);
    if (s == 0) return {guess, guess};
    if (s == sign_at_lo) {
      lo = guess;
      const double next = std::nextafter(guess, kInf);
      if (next >= hi) return {lo, hi};
      const int s_next = sign(next);
      if (s_next == 0) return {next, next};
      if (s_next != sign_at_lo) return {guess, next};
      lo = next;
    } else {
      hi = guess;
      const double previous = std::nextafter(guess, -kInf);
      if (previous <= lo) return {lo, hi};
      const int s_previous = sign(previous);
      if (s_previous == 0) return {previous, previous};
      if (s_previous == sign_at_lo) return {previous, guess};
      hi = previous;
    }
  }
  while (std::nextafter(lo, kInf) < hi) {
    double mid = lo + (hi - lo) / 2;
    if (!(lo < mid && mid < hi)) mid = std::nextafter(lo, kInf);
    const int s = sign(mid);
    if (s == 0) return {mid, mid};
    (s == sign_at_lo ? lo : hi) = mid;
  }
  return {lo, hi};
}

template <class IntegerQuery, class Query>
std::optional<TimeInterval> narrow_toi_in_cell(const Query& q, const VolumeRootCell& cell) {
  if (!(0 <= cell.lo && cell.lo < cell.hi && cell.hi <= 1) || cell.sign_at_lo == 0) return std::nullopt;
  // The guess from V in long double (built from the doubles; only a guess).
  using LongQuery = typename kinds::kind_of<Query>::template Query<long double>;
  std::array<Vec3T<long double>, 8> long_rows;
  {
    const auto r = rows(q);
    for (std::size_t i = 0; i < r.size(); ++i) long_rows[i] = {r[i].x, r[i].y, r[i].z};
  }
  const auto approximate = contact::polynomials(from_rows<LongQuery>(long_rows)).volume();
  std::array<long double, 5> c{};
  for (int i = 0; i <= 3; ++i) c[static_cast<std::size_t>(i)] = approximate.c[static_cast<std::size_t>(i)];
  const double guess = exact::approximate_root(c, 3, cell.lo, cell.hi, cell.sign_at_lo);
  // Signs: double-double first (certified, usually decisive), exact V in GMP on demand.
  std::optional<exact::IntegerPoly> v;
  const auto sign = [&](double t) {
    if (const int s = certified_volume_sign(q, t); s != contact::kUnknownSign) return s;
    if (!v) v = integer_poly(contact::polynomials(to_integer_query<IntegerQuery>(q)).volume());
    return exact::sign_at(*v, t);
  };
  return tightest_enclosure(guess, cell.lo, cell.hi, cell.sign_at_lo, sign);
}

}  // namespace

std::optional<TimeInterval> toi_in_cell(const VertexFaceQuery& q, const VolumeRootCell& cell) {
  return narrow_toi_in_cell<VertexFaceQueryT<Integer>>(q, cell);
}

std::optional<TimeInterval> toi_in_cell(const EdgeEdgeQuery& q, const VolumeRootCell& cell) {
  return narrow_toi_in_cell<EdgeEdgeQueryT<Integer>>(q, cell);
}

}  // namespace exactccd::filter
