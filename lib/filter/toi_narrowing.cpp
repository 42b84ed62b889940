#include "filter/toi_narrowing.hpp"

#include <array>
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
double root_guess(const Query& q, const pipeline::VolumeRootCell& cell) {
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
std::optional<TimeInterval> narrow_toi_in_cell(const Query& q, const pipeline::VolumeRootCell& cell) {
  if (!(0 <= cell.lo && cell.lo < cell.hi && cell.hi <= 1) || cell.sign_at_lo == 0) return std::nullopt;
  // Signs: double-double first (certified, usually decisive), exact V in GMP on demand.
  std::optional<exact::IntegerPoly> v;
  const auto sign = [&](double t) {
    if (const int s = certified_volume_sign(q, t); s != 0) return numeric::SignAt{s};
    if (!v) v = integer_poly(contact::polynomials(to_integer_query<IntegerQuery>(q)).volume());
    return numeric::SignAt{exact::sign_at(*v, t)};
  };
  numeric::Bisection halving;
  return numeric::tightest_enclosure(cell.lo, cell.hi, cell.sign_at_lo, root_guess(q, cell), sign, halving);
}

}  // namespace

std::optional<TimeInterval> toi_in_cell(const VertexFaceQuery& q, const pipeline::VolumeRootCell& cell) {
  return narrow_toi_in_cell<VertexFaceQueryT<Integer>>(q, cell);
}

std::optional<TimeInterval> toi_in_cell(const EdgeEdgeQuery& q, const pipeline::VolumeRootCell& cell) {
  return narrow_toi_in_cell<EdgeEdgeQueryT<Integer>>(q, cell);
}

}  // namespace exactccd::filter
