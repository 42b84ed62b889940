#include "baseline/naive_ccd.hpp"

#include <algorithm>
#include <cmath>

#include "contact/contact_polynomials.hpp"

namespace exactccd::baseline {
namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 at(const Vec3& x0, const Vec3& x1, double t) {
  return {x0.x + t * (x1.x - x0.x), x0.y + t * (x1.y - x0.y), x0.z + t * (x1.z - x0.z)};
}

/// Least-squares solve of [m0 m1] z = r via the 2x2 normal equations (M^T M) z = M^T r.
/// Returns false when M^T M is exactly singular.
bool least_squares(const Vec3& m0, const Vec3& m1, const Vec3& r, double& z0, double& z1) {
  using contact::dot;
  const double a = dot(m0, m0), b = dot(m0, m1), c = dot(m1, m1);
  const double r0 = dot(m0, r), r1 = dot(m1, r);
  const double det = a * c - b * b;
  if (det == 0) return false;
  z0 = (c * r0 - b * r1) / det;
  z1 = (a * r1 - b * r0) / det;
  return true;
}

int volume_roots(const contact::Poly<double, 3>& volume, double roots[3]) {
  const auto& v = volume.c;
  return naive_cubic_roots_in_unit_interval(v[3], v[2], v[1], v[0], roots);
}

}  // namespace

int naive_cubic_roots_in_unit_interval(double a, double b, double c, double d, double roots[3]) {
  double r[3];
  int n = 0;
  if (a == 0) {
    if (b == 0) {
      if (c == 0) return 0;  // constant: no isolated root
      r[n++] = -d / c;
    } else {
      const double disc = c * c - 4 * b * d;
      if (disc >= 0) {
        const double s = std::sqrt(disc);
        r[n++] = (-c - s) / (2 * b);
        r[n++] = (-c + s) / (2 * b);
      }
    }
  } else {
    // Depressed cubic x^3 + p x + q with t = x - b / (3a).
    const double B = b / a, C = c / a, D = d / a;
    const double p = C - B * B / 3;
    const double q = 2 * B * B * B / 27 - B * C / 3 + D;
    const double shift = -B / 3;
    const double disc = q * q / 4 + p * p * p / 27;
    if (disc > 0) {
      const double s = std::sqrt(disc);
      r[n++] = std::cbrt(-q / 2 + s) + std::cbrt(-q / 2 - s) + shift;
    } else if (p == 0) {
      r[n++] = shift;
    } else {
      const double m = 2 * std::sqrt(-p / 3);
      const double arg = std::clamp(3 * q / (p * m), -1.0, 1.0);
      const double theta = std::acos(arg) / 3;
      for (int k = 0; k < 3; ++k) r[n++] = m * std::cos(theta - 2 * kPi * k / 3) + shift;
    }
  }
  int count = 0;
  for (int i = 0; i < n; ++i)
    if (r[i] >= 0 && r[i] <= 1) roots[count++] = r[i];
  std::sort(roots, roots + count);
  return count;
}

std::optional<double> naive_vertex_face_toi(const VertexFaceQuery& q) {
  double roots[3];
  const int n = volume_roots(contact::polynomials(q).volume(), roots);
  for (int i = 0; i < n; ++i) {
    const double t = roots[i];
    const Vec3 p = at(q.p_t0, q.p_t1, t), a = at(q.a_t0, q.a_t1, t);
    const Vec3 b = at(q.b_t0, q.b_t1, t), c = at(q.c_t0, q.c_t1, t);
    using contact::operator-;
    double beta, gamma;
    if (!least_squares(b - a, c - a, p - a, beta, gamma)) continue;
    if (beta >= 0 && gamma >= 0 && 1 - beta - gamma >= 0) return t;
  }
  return std::nullopt;
}

std::optional<double> naive_edge_edge_toi(const EdgeEdgeQuery& q) {
  double roots[3];
  const int n = volume_roots(contact::polynomials(q).volume(), roots);
  for (int i = 0; i < n; ++i) {
    const double t = roots[i];
    const Vec3 a0 = at(q.a0_t0, q.a0_t1, t), a1 = at(q.a1_t0, q.a1_t1, t);
    const Vec3 b0 = at(q.b0_t0, q.b0_t1, t), b1 = at(q.b1_t0, q.b1_t1, t);
    using contact::operator-;
    double alpha, beta;  // a0 + alpha (a1 - a0) = b0 + beta (b1 - b0)
    if (!least_squares(a1 - a0, b0 - b1, b0 - a0, alpha, beta)) continue;
    if (alpha >= 0 && alpha <= 1 && beta >= 0 && beta <= 1) return t;
  }
  return std::nullopt;
}

}  // namespace exactccd::baseline
