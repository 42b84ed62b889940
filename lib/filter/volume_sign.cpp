#include "filter/volume_sign.hpp"

#include "kinds/primitive_kinds.hpp"
#include "numeric/certified_sign.hpp"

namespace exactccd::filter {
namespace {

/// V = det[u - base, v - base, w - base] for the kind's volume rows {base, u, v, w}, from the
/// geometry at t (numeric/certified_sign.hpp: V is homogeneous of degree 3 in lengths).
template <class Query>
int volume_sign_at(const Query& q, double t) {
  constexpr auto v = kinds::kind_of<Query>::volume_rows;
  const numeric::GeometryAt<8> at(rows(q), t);
  if (!at.usable()) return 0;
  const auto A = at.vector(v[0], v[1]), B = at.vector(v[0], v[2]), C = at.vector(v[0], v[3]);
  return numeric::double_word::certain_sign(A.x * (B.y * C.z - B.z * C.y) + A.y * (B.z * C.x - B.x * C.z) +
                                            A.z * (B.x * C.y - B.y * C.x));
}

}  // namespace

int certified_volume_sign(const VertexFaceQuery& q, double t) { return volume_sign_at(q, t); }
int certified_volume_sign(const EdgeEdgeQuery& q, double t) { return volume_sign_at(q, t); }

}  // namespace exactccd::filter
