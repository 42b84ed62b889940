#include "rigid/direction_stage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "contact/vec3_ops.hpp"
#include "kinds/primitive_kinds.hpp"
#include "rigid/rigid_frame.hpp"

namespace exactccd::rigid {
namespace {

using contact::cross;
using contact::operator-;

double largest(const Vec3& v) { return std::max(std::fabs(v.x), std::max(std::fabs(v.y), std::fabs(v.z))); }

/// R(q) as rows of fl(M(q)) and fl(|q|^2) (header, step 2).
struct Rotation {
  double m[3][3];
  double n2;
  explicit Rotation(const Quaternion& q) {
    const double ww = q.w * q.w, xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    n2 = ((ww + xx) + yy) + zz;
    m[0][0] = ((ww + xx) - yy) - zz, m[1][1] = ((ww - xx) + yy) - zz, m[2][2] = ((ww - xx) - yy) + zz;
    m[0][1] = 2 * (q.x * q.y - q.w * q.z), m[1][0] = 2 * (q.x * q.y + q.w * q.z);
    m[0][2] = 2 * (q.x * q.z + q.w * q.y), m[2][0] = 2 * (q.x * q.z - q.w * q.y);
    m[1][2] = 2 * (q.y * q.z - q.w * q.x), m[2][1] = 2 * (q.y * q.z + q.w * q.x);
  }
  Vec3 operator()(const Vec3& p) const {
    return {((m[0][0] * p.x + m[0][1] * p.y) + m[0][2] * p.z) / n2, ((m[1][0] * p.x + m[1][1] * p.y) + m[1][2] * p.z) / n2,
            ((m[2][0] * p.x + m[2][1] * p.y) + m[2][2] * p.z) / n2};
  }
};

/// The bound on the sagitta of a point of largest component `extent` (header, step 4), given
/// the body's c~ = fl(cos(Phi / 2)).
double sagitta_bound(double extent, double cosine) {
  if (!(cosine > 0x1p-20)) return 4 * extent;  // a long (or uncertain) arc: the ball
  return (2 * extent * ((1 - cosine) + 0x1p-49)) * (1 + 0x1p-50) + 0x1p-1070;
}

double cosine_of_half_angle(const Quaternion& a, const Quaternion& b) {
  const double dot = ((a.w * b.w + a.x * b.x) + a.y * b.y) + a.z * b.z;
  const double na = ((a.w * a.w + a.x * a.x) + a.y * a.y) + a.z * a.z, nb = ((b.w * b.w + b.x * b.x) + b.y * b.y) + b.z * b.z;
  return dot / std::sqrt(na * nb);
}

}  // namespace

template <class Query>
DirectionFrame<Query>::DirectionFrame(const Query& q) {
  constexpr int first = kinds::kind_of<Query>::first_points;
  const auto points = body_points(q);
  const Rotation ra[2] = {Rotation(q.a_t0.q), Rotation(q.a_t1.q)}, rb[2] = {Rotation(q.b_t0.q), Rotation(q.b_t1.q)};
  for (int t = 0; t < 2; ++t)
    for (int i = 0; i < 4; ++i) rotated_[t][i] = (i < first ? ra[t] : rb[t])(points[i]);
  const Vec3 o = q.a_t0.c;  // translations relative to A's c(0)
  translation_a_ = {Vec3{0, 0, 0}, q.a_t1.c - o};
  translation_b_ = {q.b_t0.c - o, q.b_t1.c - o};
  for (int i = 0; i < 4; ++i) extent_[i] = largest(points[i]);
  for (int t = 0; t < 2; ++t) {
    extent_y_ = std::max(extent_y_, std::max(largest(translation_a_[t]), largest(translation_b_[t])));
    for (int i = 0; i < 4; ++i) extent_y_ = std::max(extent_y_, largest(rotated_[t][i]));
  }
  cosine_a_ = cosine_of_half_angle(q.a_t0.q, q.a_t1.q);
  cosine_b_ = cosine_of_half_angle(q.b_t0.q, q.b_t1.q);
}

template <class Query>
bool DirectionFrame<Query>::certifies(const Vec3& n, unsigned used, double distance) const {
  constexpr int first = kinds::kind_of<Query>::first_points;
  // The projections of the translations and of the rotated points, bounded separately (header).
  const auto project = [&](const Vec3& v) { return (n.x * v.x + n.y * v.y) + n.z * v.z; };
  const double ta0 = project(translation_a_[0]), ta1 = project(translation_a_[1]);
  const double tb0 = project(translation_b_[0]), tb1 = project(translation_b_[1]);
  double a_lo = INFINITY, a_hi = -INFINITY, b_lo = INFINITY, b_hi = -INFINITY;
  for (int t = 0; t < 2; ++t)
    for (int i = 0; i < 4; ++i) {
      if (!(used >> i & 1)) continue;
      const double p = project(rotated_[t][i]);
      if (i < first)
        a_lo = std::min(a_lo, p), a_hi = std::max(a_hi, p);
      else
        b_lo = std::min(b_lo, p), b_hi = std::max(b_hi, p);
    }
  const double norm = std::sqrt((n.x * n.x + n.y * n.y) + n.z * n.z);
  const double threshold = (distance * norm) * (1 + 0x1p-47) + extent_y_ * 0x1p-41 + 0x1p-1060;
  return (std::min(tb0, tb1) + b_lo) - (std::max(ta0, ta1) + a_hi) > threshold ||
         (std::min(ta0, ta1) + a_lo) - (std::max(tb0, tb1) + b_hi) > threshold;
}

namespace {

/// Feature f's natural direction from positions x (any rounding), or nothing (zero, not finite).
std::optional<Vec3> natural_direction(const kinds::Feature& f, const std::array<Vec3, 4>& x) {
  const auto p = [&](int j) { return x[static_cast<std::size_t>(f.points[j])]; };
  Vec3 n{};
  switch (f.pair) {
    case kinds::FeaturePair::point_point: n = p(1) - p(0); break;
    case kinds::FeaturePair::point_edge: {  // e x (r x e), r x e normalised first (no overflow)
      const Vec3 e = p(2) - p(1), c = cross(p(0) - p(1), e);
      const double m = largest(c);
      if (!(m > 0 && std::isfinite(m))) return std::nullopt;
      n = cross(e, Vec3{c.x / m, c.y / m, c.z / m});
      break;
    }
    case kinds::FeaturePair::point_triangle: n = cross(p(2) - p(1), p(3) - p(1)); break;
    case kinds::FeaturePair::edge_edge: n = cross(p(1) - p(0), p(3) - p(2)); break;
  }
  const double m = largest(n);
  if (!(m > 0 && std::isfinite(m))) return std::nullopt;
  return Vec3{n.x / m, n.y / m, n.z / m};  // largest component +-1 (header, step 5)
}

}  // namespace

template <class Query>
bool DirectionFrame<Query>::separated(double d, unsigned used, const kinds::Feature* features,
                                      std::size_t feature_count) const {
  constexpr int first = kinds::kind_of<Query>::first_points;
  if (!std::isfinite(extent_y_)) return false;
  double extent_a = 0, extent_b = 0;
  for (int i = 0; i < 4; ++i)
    if (used >> i & 1) (i < first ? extent_a : extent_b) = std::max(i < first ? extent_a : extent_b, extent_[i]);
  const double distance = (d + sagitta_bound(extent_a, cosine_a_)) + sagitta_bound(extent_b, cosine_b_);
  for (int t = 0; t < 2; ++t) {
    std::array<Vec3, 4> x;  // rounded world positions at t (any rounding: only directions)
    for (int i = 0; i < 4; ++i) {
      const Vec3& c = i < first ? translation_a_[t] : translation_b_[t];
      x[i] = {c.x + rotated_[t][i].x, c.y + rotated_[t][i].y, c.z + rotated_[t][i].z};
    }
    for (std::size_t k = 0; k < feature_count; ++k)
      if (const auto n = natural_direction(features[k], x); n && certifies(*n, used, distance)) return true;
  }
  for (int axis = 0; axis < 3; ++axis)
    if (certifies(Vec3{axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0}, used, distance))
      return true;
  return false;
}

namespace {

/// The points of feature f's two parts (each on one body).
unsigned points_of(const kinds::Feature& f) {
  const int count = f.pair == kinds::FeaturePair::point_point ? 2 : f.pair == kinds::FeaturePair::point_edge ? 3 : 4;
  unsigned used = 0;
  for (int k = 0; k < count; ++k) used |= 1u << f.points[k];
  return used;
}

}  // namespace

template <class Query>
bool DirectionFrame<Query>::separated_beyond(double d) const {
  using Kind = kinds::kind_of<Query>;
  return separated(d, 0xFu, Kind::features.data(), Kind::features.size());
}

template <class Query>
bool DirectionFrame<Query>::feature_separated(double d, std::size_t feature) const {
  const kinds::Feature& f = kinds::kind_of<Query>::features[feature];
  return separated(d, points_of(f), &f, 1);
}

template class DirectionFrame<RigidVertexFaceQuery>;
template class DirectionFrame<RigidEdgeEdgeQuery>;

}  // namespace exactccd::rigid
