#include "filter/volume_sign.hpp"

#include <cstddef>

#include "kinds/primitive_kinds.hpp"

namespace exactccd::filter {

template <class Query>
void VolumeSigns::hoist(const Query& q) {
  const numeric::ScaledRows<8> scaled(rows(q));
  if (!scaled.usable()) return;
  constexpr auto v = kinds::kind_of<Query>::volume_rows;  // {base, u, v, w}
  for (std::size_t k = 0; k < 3; ++k) vectors_[k] = numeric::moving_vector(scaled, v[0], v[k + 1]);
  usable_ = true;
}

VolumeSigns::VolumeSigns(const VertexFaceQuery& q) { hoist(q); }
VolumeSigns::VolumeSigns(const EdgeEdgeQuery& q) { hoist(q); }

// V = det[A, B, C] (the vectors of the kind's volume rows), from the geometry at t
// (numeric/certified_sign.hpp: V is homogeneous of degree 3 in lengths): the same values as
// GeometryAt::vector's at t.
int VolumeSigns::sign_at(double t, double* approximation) const {
  if (!(t >= 0 && t <= 1 && usable_)) return 0;  // GeometryAt::usable
  const std::array<Vec3T<Approx>, 3> at{numeric::vector_at(vectors_[0], t), numeric::vector_at(vectors_[1], t),
                                        numeric::vector_at(vectors_[2], t)};
  const auto &A = at[0], &B = at[1], &C = at[2];
  const Approx value =
      A.x * (B.y * C.z - B.z * C.y) + A.y * (B.z * C.x - B.x * C.z) + A.z * (B.x * C.y - B.y * C.x);
  if (approximation) *approximation = value.value.hi + value.value.lo;
  return numeric::double_word::certain_sign(value);
}

int certified_volume_sign(const VertexFaceQuery& q, double t) { return VolumeSigns(q).sign_at(t); }
int certified_volume_sign(const EdgeEdgeQuery& q, double t) { return VolumeSigns(q).sign_at(t); }

}  // namespace exactccd::filter
