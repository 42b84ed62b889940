// The 40 numbers of a rigid query, in the order of the CLI's lines, the C API and the Python
// arrays: cA0 (3), qA0 (4: w x y z), cA1 (3), qA1 (4), cB0 (3), qB0 (4), cB1 (3), qB1 (4), then
// the body points (vertex-face: p of A, then a, b, c of B; edge-edge: a0, a1 of A, then b0, b1 of
// B; 12 numbers).
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

#include "exactccd/rigid.hpp"

namespace exactccd::rigid {

/// How many numbers a rigid query has.
constexpr std::size_t kQueryNumbers = 40;

/// Calls f on each body point of the query (by reference, in the kind's order).
template <class T, class F>
void set_points(RigidVertexFaceQueryT<T>& q, F&& f) {
  f(q.p), f(q.a), f(q.b), f(q.c);
}
/// See set_points(RigidVertexFaceQueryT<T>&, F&&).
template <class T, class F>
void set_points(RigidEdgeEdgeQueryT<T>& q, F&& f) {
  f(q.a0), f(q.a1), f(q.b0), f(q.b1);
}

/// The query whose numbers, in the order of the file comment, are x[0..40).
template <class Query, class T>
Query from_numbers(const T* x) {
  Query q;
  std::size_t k = 0;
  const auto vec = [&](auto& v) { v.x = x[k], v.y = x[k + 1], v.z = x[k + 2], k += 3; };
  const auto quat = [&](auto& r) { r.w = x[k], r.x = x[k + 1], r.y = x[k + 2], r.z = x[k + 3], k += 4; };
  for (auto* pose : {&q.a_t0, &q.a_t1, &q.b_t0, &q.b_t1}) vec(pose->c), quat(pose->q);
  set_points(q, [&](auto& v) { vec(v); });
  return q;
}

/// The query's numbers in the order of the file comment.
template <class Query>
auto to_numbers(const Query& q) {
  using T = std::decay_t<decltype(q.a_t0.c.x)>;
  std::array<T, kQueryNumbers> x;
  std::size_t k = 0;
  const auto vec = [&](const Vec3T<T>& v) { x[k] = v.x, x[k + 1] = v.y, x[k + 2] = v.z, k += 3; };
  const auto quat = [&](const QuaternionT<T>& r) { x[k] = r.w, x[k + 1] = r.x, x[k + 2] = r.y, x[k + 3] = r.z, k += 4; };
  for (const auto* pose : {&q.a_t0, &q.a_t1, &q.b_t0, &q.b_t1}) vec(pose->c), quat(pose->q);
  for (const Vec3T<T>& p : body_points(q)) vec(p);
  return x;
}

}  // namespace exactccd::rigid
