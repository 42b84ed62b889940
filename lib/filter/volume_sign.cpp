#include "filter/volume_sign.hpp"

#include <cstddef>

#include "kinds/primitive_kinds.hpp"

namespace exactccd::filter {

template <class Query>
void VolumeSigns::hoist(const Query& q) {
  const numeric::ScaledRows<8> scaled(rows(q));
  if (!scaled.usable()) return;
  constexpr auto v = kinds::kind_of<Query>::volume_rows;  // {base, u, v, w}
  constexpr std::size_t P = 4;                              // the row at t1 is P rows after t0's
  const auto& y = scaled.rows();
  const auto part = [](double u0, double v0, double u1, double v1, Approx& start, Approx& change) {
    const Approx d0{numeric::double_word::two_sum(v0, -u0), 0.0};
    const Approx d1{numeric::double_word::two_sum(v1, -u1), 0.0};
    start = d0;
    change = d1 - d0;
  };
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec3 &u0 = y[static_cast<std::size_t>(v[0])], &u1 = y[static_cast<std::size_t>(v[0]) + P];
    const Vec3 &v0 = y[static_cast<std::size_t>(v[k + 1])], &v1 = y[static_cast<std::size_t>(v[k + 1]) + P];
    part(u0.x, v0.x, u1.x, v1.x, start_[k].x, change_[k].x);
    part(u0.y, v0.y, u1.y, v1.y, start_[k].y, change_[k].y);
    part(u0.z, v0.z, u1.z, v1.z, start_[k].z, change_[k].z);
  }
  usable_ = true;
}

VolumeSigns::VolumeSigns(const VertexFaceQuery& q) { hoist(q); }
VolumeSigns::VolumeSigns(const EdgeEdgeQuery& q) { hoist(q); }

// V = det[A, B, C] (the vectors of the kind's volume rows), from the geometry at t
// (numeric/certified_sign.hpp: V is homogeneous of degree 3 in lengths); each vector as
// GeometryAt::vector computes it (difference_at: start + t change).
int VolumeSigns::sign_at(double t, double* approximation) const {
  if (!(t >= 0 && t <= 1 && usable_)) return 0;  // GeometryAt::usable
  std::array<Vec3T<Approx>, 3> at;
  for (std::size_t k = 0; k < 3; ++k) {
    using numeric::double_word::scaled;
    at[k] = {start_[k].x + scaled(change_[k].x, t), start_[k].y + scaled(change_[k].y, t),
             start_[k].z + scaled(change_[k].z, t)};
  }
  const auto &A = at[0], &B = at[1], &C = at[2];
  const Approx value =
      A.x * (B.y * C.z - B.z * C.y) + A.y * (B.z * C.x - B.x * C.z) + A.z * (B.x * C.y - B.y * C.x);
  if (approximation) *approximation = value.value.hi + value.value.lo;
  return numeric::double_word::certain_sign(value);
}

int certified_volume_sign(const VertexFaceQuery& q, double t) { return VolumeSigns(q).sign_at(t); }
int certified_volume_sign(const EdgeEdgeQuery& q, double t) { return VolumeSigns(q).sign_at(t); }

}  // namespace exactccd::filter
