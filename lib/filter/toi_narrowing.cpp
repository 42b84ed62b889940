#include "filter/toi_narrowing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "contact/contact_polynomials.hpp"
#include "exact/integer_poly.hpp"
#include "filter/integer_query.hpp"
#include "filter/volume_sign.hpp"
#include "kinds/primitive_kinds.hpp"
#include "numeric/root_narrowing.hpp"

namespace exactccd::filter {
namespace {

/// A guess of V's root in the cell: Newton's method on V built in long double from the doubles
/// (only a guess: the narrowing certifies signs at whatever it returns).
template <class Query>
double root_guess(const Query& q, const VolumeRootCell& cell) {
  using LongQuery = typename kinds::kind_of<Query>::template Query<long double>;
  std::array<Vec3T<long double>, 8> long_rows;
  const auto r = rows(q);
  for (std::size_t i = 0; i < r.size(); ++i) long_rows[i] = {r[i].x, r[i].y, r[i].z};
  const auto approximate = contact::polynomials(from_rows<LongQuery>(long_rows)).volume();
  std::array<long double, 5> c{};
  for (std::size_t i = 0; i <= 3; ++i) c[i] = approximate.c[i];
  return exact::approximate_root(c, 3, cell.lo, cell.hi, cell.sign_at_lo);
}

template <class IntegerQuery, class Query>
std::optional<TimeInterval> narrow_toi_in_cell(const Query& q, const VolumeRootCell& cell) {
  if (!(0 <= cell.lo && cell.lo < cell.hi && cell.hi <= 1) || cell.sign_at_lo == 0) return std::nullopt;
  // Signs: double-double first (certified, usually decisive; the query scaled once for every
  // t), exact V in GMP on demand. The double-double values steer the secant steps (an exact
  // sign from GMP gives none: bisection then).
  const VolumeSigns volume(q);
  std::optional<exact::IntegerPoly> v;
  const auto sign = [&](double t) {
    double approximation = 0;
    if (const int s = volume.sign_at(t, &approximation); s != 0) return numeric::SignAt{s, approximation};
    if (!v) v = integer_poly(contact::polynomials(to_integer_query<IntegerQuery>(q)).volume());
    return numeric::SignAt{exact::sign_at(*v, t)};
  };
  numeric::Secant secant;
  return numeric::tightest_enclosure(cell.lo, cell.hi, cell.sign_at_lo, root_guess(q, cell), sign, secant);
}

/// p's coefficients in long double times one power of two (a positive factor: the same signs
/// and roots), the largest about 1 in magnitude, so that no value on [0, 1] overflows; only
/// approximations are taken from them (a tiny coefficient may become 0).
std::array<long double, 5> scaled_coefficients(const exact::IntegerPoly& p) {
  std::array<double, 5> mantissa{};
  std::array<long, 5> exponent{};
  long largest = std::numeric_limits<long>::min();
  for (int i = 0; i <= p.deg; ++i) {
    mantissa[i] = mpz_get_d_2exp(&exponent[i], p.c[i].get_mpz_t());  // 1/2 <= |mantissa| < 1, or 0
    if (mantissa[i] != 0) largest = std::max(largest, exponent[i]);
  }
  std::array<long double, 5> c{};
  for (int i = 0; i <= p.deg; ++i)
    if (mantissa[i] != 0)  // a relative exponent below -20000 is 0 in long double anyway
      c[i] = std::ldexp(static_cast<long double>(mantissa[i]), static_cast<int>(std::max(exponent[i] - largest, -20000L)));
  return c;
}

/// The rule's polynomial `poly` (RulePoly) of the integer query, exactly: built alone
/// (an in-plane polynomial's terms on use; a relative motion's coordinate). Zero when `poly`
/// names none.
template <class IntegerQuery>
exact::IntegerPoly rule_poly(const IntegerQuery& q, const RulePoly& poly) {
  exact::IntegerPoly p;  // zero until built
  if (poly.in_plane >= 0) {
    const auto P = contact::polynomials(q);
    contact::visit_in_plane_poly(P, poly.in_plane, [&](const auto& r) { p = integer_poly(r); });
  } else if (const bool rows_valid = 0 <= poly.from && poly.from < 4 && 0 <= poly.to && poly.to < 4;
             rows_valid && 0 <= poly.coordinate && poly.coordinate < 3) {
    const auto motion = contact::relative_motion(rows(q), poly.from, poly.to);
    p = integer_poly(poly.coordinate == 0 ? motion.x : poly.coordinate == 1 ? motion.y : motion.z);
  }
  return p;
}

template <class IntegerQuery, class Query>
std::optional<TimeInterval> narrow_toi_in_rule_cell(const Query& q, const RuleRootCell& cell) {
  if (!(0 <= cell.lo && cell.lo < cell.hi && cell.hi <= 1) || cell.sign_at_lo == 0) return std::nullopt;
  const exact::IntegerPoly p = rule_poly(to_integer_query<IntegerQuery>(q), cell.poly);
  // The cell as handed over: exact signs at its ends (a guard: never a TOI from a wrong cell).
  if (p.is_zero() || exact::sign_at(p, cell.lo) != cell.sign_at_lo || exact::sign_at(p, cell.hi) != -cell.sign_at_lo)
    return std::nullopt;
  const std::array<long double, 5> c = scaled_coefficients(p);
  const auto approximate = [&](double t) {
    long double v = 0;
    for (int i = p.deg; i >= 0; --i) v = v * t + c[i];
    return static_cast<double>(v);
  };
  const auto sign = [&](double t) { return numeric::SignAt{exact::sign_at(p, t), approximate(t)}; };
  numeric::Secant secant;
  const double guess = exact::approximate_root(c, p.deg, cell.lo, cell.hi, cell.sign_at_lo);
  const TimeInterval toi = numeric::tightest_enclosure(cell.lo, cell.hi, cell.sign_at_lo, guess, sign, secant);
  if (!(toi.hi <= cell.later_from)) return std::nullopt;  // another candidate may be earlier
  return toi;
}

}  // namespace

std::optional<TimeInterval> toi_in_rule_cell(const VertexFaceQuery& q, const RuleRootCell& cell) {
  return narrow_toi_in_rule_cell<VertexFaceQueryT<Integer>>(q, cell);
}

std::optional<TimeInterval> toi_in_rule_cell(const EdgeEdgeQuery& q, const RuleRootCell& cell) {
  return narrow_toi_in_rule_cell<EdgeEdgeQueryT<Integer>>(q, cell);
}

std::optional<TimeInterval> toi_in_cell(const VertexFaceQuery& q, const VolumeRootCell& cell) {
  return narrow_toi_in_cell<VertexFaceQueryT<Integer>>(q, cell);
}

std::optional<TimeInterval> toi_in_cell(const EdgeEdgeQuery& q, const VolumeRootCell& cell) {
  return narrow_toi_in_cell<EdgeEdgeQueryT<Integer>>(q, cell);
}

}  // namespace exactccd::filter
