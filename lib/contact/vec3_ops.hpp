// Vector operations on Vec3T<T> for any ring T (numbers, intervals, polynomials in t).
#pragma once

#include "exactccd/types.hpp"

namespace exactccd::contact {

template <class T>
Vec3T<T> operator-(const Vec3T<T>& u, const Vec3T<T>& v) {
  return {u.x - v.x, u.y - v.y, u.z - v.z};
}

/// u x v. For polynomial T the degree of the result is the sum of the operands' degrees.
template <class T, class U>
auto cross(const Vec3T<T>& u, const Vec3T<U>& v) -> Vec3T<decltype(u.y * v.z - u.z * v.y)> {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}

/// u . v
template <class T, class U>
auto dot(const Vec3T<T>& u, const Vec3T<U>& v) -> decltype(u.x * v.x + u.y * v.y + u.z * v.z) {
  return u.x * v.x + u.y * v.y + u.z * v.z;
}

}  // namespace exactccd::contact
