// Quaternion arithmetic for the rigid motion model (docs/design.md, 9.1), on any ring: numbers,
// intervals, polynomials in t (the degrees then add up in the types).
//
// M(q) v = |q|^2 R(q) v is written as (w^2 - |u|^2) v + 2 (u . v) u + 2 w (u x v) (u = (x, y, z)):
// for a unit q this is Rodrigues' v + 2 w (u x v) + 2 u x (u x v), and both sides are
// homogeneous of degree 2 in q, so it holds for every q; its matrix is the M(q). R is a
// homomorphism, R(p q) = R(p) R(q), and R(conj(q)) = R(q)^T with |conj(q)| = |q|, so
// M(conj(q)) = M(q)^T and M(conj(qB) qA) = |qA|^2 |qB|^2 R(qB)^T R(qA).
#pragma once

#include "contact/vec3_ops.hpp"
#include "exactccd/rigid.hpp"

namespace exactccd::rigid {

/// x + x (doubling: exact in every arithmetic that does not overflow).
template <class T>
T twice(const T& x) {
  return x + x;
}

/// The Hamilton product p q.
template <class A, class B>
auto product(const QuaternionT<A>& p, const QuaternionT<B>& q) -> QuaternionT<decltype(p.w * q.w)> {
  return {p.w * q.w - p.x * q.x - p.y * q.y - p.z * q.z, p.w * q.x + p.x * q.w + p.y * q.z - p.z * q.y,
          p.w * q.y - p.x * q.z + p.y * q.w + p.z * q.x, p.w * q.z + p.x * q.y - p.y * q.x + p.z * q.w};
}

/// The conjugate (w, -x, -y, -z), with `negate` giving -a for the ring's elements.
template <class T, class Negate>
QuaternionT<T> conjugate(const QuaternionT<T>& q, Negate&& negate) {
  return {q.w, negate(q.x), negate(q.y), negate(q.z)};
}

/// |q|^2.
template <class T>
auto squared_norm(const QuaternionT<T>& q) {
  return q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
}

/// The vector part (x, y, z).
template <class T>
Vec3T<T> vector_part(const QuaternionT<T>& q) {
  return {q.x, q.y, q.z};
}

/// M(q) v = |q|^2 R(q) v (file comment).
template <class T, class V>
auto rotate_scaled(const QuaternionT<T>& q, const Vec3T<V>& v) {
  using contact::cross;
  using contact::dot;
  const Vec3T<T> u = vector_part(q);
  const auto s = q.w * q.w - dot(u, u);
  const auto uv = dot(u, v);
  const auto two_uv = twice(uv);
  const auto two_w = twice(q.w);
  const auto c = cross(u, v);
  using R = decltype(s * v.x + two_uv * u.x + two_w * c.x);
  return Vec3T<R>{R(s * v.x + two_uv * u.x + two_w * c.x), R(s * v.y + two_uv * u.y + two_w * c.y),
                  R(s * v.z + two_uv * u.z + two_w * c.z)};
}

}  // namespace exactccd::rigid
