// The textbook CCD algorithm, templated on the number type T (double, or Mpfr<Bits> for the
// precision ladder), with an optional Bridson-style tolerance. NOT robust; see naive_ccd.hpp.
//
// Cubic coefficients of V(t) computed in T, its real roots in [0, 1] by the closed-form cubic
// formula, and at each root the least-squares solve z = (M^T M)^-1 M^T r of the inclusion.
// With tolerance eps > 0 (the conservative variant): roots are accepted in [-eps, 1 + eps],
// inclusion is tested with slack eps (barycentrics >= -eps, segment parameters in
// [-eps, 1 + eps]), and a volume cubic whose coefficients are all below eps (relative to the
// scene scale cubed) counts as "coplanar for all t": reported as a collision.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "contact/contact_polynomials.hpp"
#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd::baseline {

inline double to_double(double x) { return x; }
template <class T>
double to_double(const T& x) {
  return x.to_double();
}

template <class T>
Vec3T<T> to_number(const Vec3& v) {
  return {T(v.x), T(v.y), T(v.z)};
}

template <class T>
Vec3T<T> position_at(const Vec3T<T>& x0, const Vec3T<T>& x1, const T& t) {
  return {x0.x + t * (x1.x - x0.x), x0.y + t * (x1.y - x0.y), x0.z + t * (x1.z - x0.z)};
}

/// Least-squares solve of [m0 m1] z = r via the 2x2 normal equations; false if singular.
template <class T>
bool least_squares(const Vec3T<T>& m0, const Vec3T<T>& m1, const Vec3T<T>& r, T& z0, T& z1) {
  using contact::dot;
  const T a = dot(m0, m0), b = dot(m0, m1), c = dot(m1, m1);
  const T r0 = dot(m0, r), r1 = dot(m1, r);
  const T det = a * c - b * b;
  if (det == T(0)) return false;
  z0 = (c * r0 - b * r1) / det;
  z1 = (a * r1 - b * r0) / det;
  return true;
}

/// Real roots of a t^3 + b t^2 + c t + d in [lo, hi], increasing, by the closed-form formulas
/// (quadratic and linear when leading coefficients are exactly zero).
template <class T>
int cubic_roots_in(const T& a, const T& b, const T& c, const T& d, const T& lo, const T& hi,
                   std::array<T, 3>& roots) {
  using std::acos;
  using std::cbrt;
  using std::cos;
  using std::sqrt;
  const T zero(0);
  std::array<T, 3> r;
  int n = 0;
  if (a == zero) {
    if (b == zero) {
      if (c == zero) return 0;  // constant: no isolated root
      r[n++] = -d / c;
    } else {
      const T disc = c * c - T(4) * b * d;
      if (disc >= zero) {
        const T s = sqrt(disc);
        r[n++] = (-c - s) / (T(2) * b);
        r[n++] = (-c + s) / (T(2) * b);
      }
    }
  } else {
    // Depressed cubic x^3 + p x + q with t = x - b / (3a).
    const T B = b / a, C = c / a, D = d / a;
    const T p = C - B * B / T(3);
    const T q = T(2) * B * B * B / T(27) - B * C / T(3) + D;
    const T shift = -B / T(3);
    const T disc = q * q / T(4) + p * p * p / T(27);
    if (disc > zero) {
      const T s = sqrt(disc);
      r[n++] = cbrt(-q / T(2) + s) + cbrt(-q / T(2) - s) + shift;
    } else if (p == zero) {
      r[n++] = shift;
    } else {
      const T m = T(2) * sqrt(-p / T(3));
      T arg = T(3) * q / (p * m);
      if (arg < T(-1)) arg = T(-1);
      if (arg > T(1)) arg = T(1);
      const T theta = acos(arg) / T(3);
      const T third = T(2) * acos(T(-1)) / T(3);  // 2 pi / 3
      for (int k = 0; k < 3; ++k) r[n++] = m * cos(theta - third * T(k)) + shift;
    }
  }
  int count = 0;
  for (int i = 0; i < n; ++i)
    if (r[i] >= lo && r[i] <= hi) roots[count++] = r[i];
  std::sort(roots.begin(), roots.begin() + count, [](const T& x, const T& y) { return x < y; });
  return count;
}

/// The textbook cubic V(t) = (x2 - x1) . ((x3 - x1) x (x4 - x1)), each point moving as
/// x(t) = x_t0 + t (x_t1 - x_t0) and the products expanded in t (relative positions and
/// relative velocities), as the lecture-note derivation computes it. Points x1..x4 are the
/// kind's volume rows (kinds::VertexFace::volume_rows: a, b, c, p; edge-edge a0, a1, b0, b1),
/// as in contact_polynomials.hpp's V. (The exact methods build V from relative displacements
/// instead; see docs/design.md, section 2.)
template <class Kind, class T>
contact::Poly<T, 3> textbook_volume(const std::array<Vec3T<T>, 8>& x) {
  const auto motion = [&x](int i) {
    return contact::PolyVec3<T, 1>{contact::linear_motion(x[i].x, x[i + 4].x),
                                   contact::linear_motion(x[i].y, x[i + 4].y),
                                   contact::linear_motion(x[i].z, x[i + 4].z)};
  };
  constexpr std::array<int, 4> order = Kind::volume_rows;
  const auto x1 = motion(order[0]), x2 = motion(order[1]), x3 = motion(order[2]), x4 = motion(order[3]);
  return contact::dot(x2 - x1, contact::cross(x3 - x1, x4 - x1));
}

/// The earliest root found to collide (as a double), or nullopt. eps = 0: the textbook method.
template <class T, class Query, class Inside>
std::optional<double> naive_toi(const Query& q, double eps, Inside&& inside) {
  std::array<Vec3T<T>, 8> x;
  const auto r = rows(q);
  for (int i = 0; i < 8; ++i) x[i] = to_number<T>(r[i]);
  const auto volume = textbook_volume<kinds::kind_of<Query>>(x);
  const T& c0 = volume.c[0];
  const T& c1 = volume.c[1];
  const T& c2 = volume.c[2];
  const T& c3 = volume.c[3];
  if (eps > 0) {  // nearly coplanar for all t: conservatively a collision
    using std::fabs;
    double scale = 0;
    for (const Vec3& p : r) scale = std::max({scale, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    const T bound(eps * std::max(scale * scale * scale, 1e-300));
    if (fabs(c0) <= bound && fabs(c1) <= bound && fabs(c2) <= bound && fabs(c3) <= bound) return 0.0;
  }
  std::array<T, 3> roots;
  const int n = cubic_roots_in(c3, c2, c1, c0, T(-eps), T(1 + eps), roots);
  for (int i = 0; i < n; ++i) {
    T t = roots[i];
    if (t < T(0)) t = T(0);
    if (t > T(1)) t = T(1);
    std::array<Vec3T<T>, 4> at;
    for (int k = 0; k < 4; ++k) at[k] = position_at(x[k], x[k + 4], t);
    if (inside(at, T(eps))) return to_double(t);
  }
  return std::nullopt;
}

/// VF inclusion at a root: p = a + beta (b - a) + gamma (c - a), all barycentrics >= -eps.
template <class T>
bool vertex_face_inside(const std::array<Vec3T<T>, 4>& at, const T& eps) {
  using contact::operator-;
  T beta, gamma;
  if (!least_squares(at[2] - at[1], at[3] - at[1], at[0] - at[1], beta, gamma)) return false;
  return beta >= -eps && gamma >= -eps && T(1) - beta - gamma >= -eps;
}

/// EE inclusion at a root: a0 + alpha (a1 - a0) = b0 + beta (b1 - b0), both in [-eps, 1 + eps].
template <class T>
bool edge_edge_inside(const std::array<Vec3T<T>, 4>& at, const T& eps) {
  using contact::operator-;
  T alpha, beta;
  if (!least_squares(at[1] - at[0], at[2] - at[3], at[2] - at[0], alpha, beta)) return false;
  const T hi = T(1) + eps;
  return alpha >= -eps && alpha <= hi && beta >= -eps && beta <= hi;
}

}  // namespace exactccd::baseline
