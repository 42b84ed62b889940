#include "filter/volume_sign.hpp"

#include "kinds/primitive_kinds.hpp"

namespace exactccd::filter {

VolumeSigns::VolumeSigns(const VertexFaceQuery& q)
    : rows_(rows(q)), volume_rows_(kinds::kind_of<VertexFaceQuery>::volume_rows) {}
VolumeSigns::VolumeSigns(const EdgeEdgeQuery& q) : rows_(rows(q)), volume_rows_(kinds::kind_of<EdgeEdgeQuery>::volume_rows) {}

// V = det[u - base, v - base, w - base] for the kind's volume rows {base, u, v, w}, from the
// geometry at t (numeric/certified_sign.hpp: V is homogeneous of degree 3 in lengths).
int VolumeSigns::sign_at(double t, double* approximation) const {
  const numeric::GeometryAt<8> at(rows_, t);
  if (!at.usable()) return 0;
  const auto& v = volume_rows_;
  const auto A = at.vector(v[0], v[1]), B = at.vector(v[0], v[2]), C = at.vector(v[0], v[3]);
  const numeric::double_word::Approx value =
      A.x * (B.y * C.z - B.z * C.y) + A.y * (B.z * C.x - B.x * C.z) + A.z * (B.x * C.y - B.y * C.x);
  if (approximation) *approximation = value.value.hi + value.value.lo;
  return numeric::double_word::certain_sign(value);
}

int certified_volume_sign(const VertexFaceQuery& q, double t) { return VolumeSigns(q).sign_at(t); }
int certified_volume_sign(const EdgeEdgeQuery& q, double t) { return VolumeSigns(q).sign_at(t); }

}  // namespace exactccd::filter
