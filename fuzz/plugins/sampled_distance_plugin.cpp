// Example plug-in for `exactccd fuzz-against` (include/exactccd/plugin.h) with a plausible
// mistake: a minimum-separation CCD that checks the distance at sampled times only. It is
// written the way a first version of a narrow phase often is, self-contained (only plugin.h):
// the closed primitives' Euclidean distance in doubles (closest points by Voronoi regions) at 17
// evenly spaced times t = tmax i / 16, and a collision at the first sample within min_distance,
// reported as the time of impact. Between two samples it is blind: a pair that comes within d
// and leaves again (a tangency at d, a fast pass) is missed, and a pair that stays within d is
// reported at the next sample, after the real time (an unsafe time of impact). docs/fuzzing.md
// shows what `fuzz-against --min-distance D` reports on it.
#include <algorithm>
#include <cmath>

#include "exactccd/plugin.h"

namespace {

struct V {
  double x, y, z;
};
V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V operator*(V a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double length(V a) { return std::sqrt(dot(a, a)); }
double clamp01(double s) { return std::min(1.0, std::max(0.0, s)); }

double point_segment(V p, V a, V b) {
  const V ab = b - a;
  const double l = dot(ab, ab);
  return length(p - (a + ab * (l > 0 ? clamp01(dot(p - a, ab) / l) : 0.0)));
}

/// The closest point of the triangle to p, by the Voronoi region of p.
V closest_on_triangle(V p, V a, V b, V c) {
  const V ab = b - a, ac = c - a, ap = p - a, bp = p - b, cp = p - c;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap), d3 = dot(ab, bp), d4 = dot(ac, bp), d5 = dot(ab, cp),
               d6 = dot(ac, cp);
  if (d1 <= 0 && d2 <= 0) return a;
  if (d3 >= 0 && d4 <= d3) return b;
  if (d6 >= 0 && d5 <= d6) return c;
  const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double sum = va + vb + vc;
  return a + ab * (vb / sum) + ac * (vc / sum);
}

double point_triangle(V p, V a, V b, V c) {
  const V n = {(b - a).y * (c - a).z - (b - a).z * (c - a).y, (b - a).z * (c - a).x - (b - a).x * (c - a).z,
               (b - a).x * (c - a).y - (b - a).y * (c - a).x};
  if (dot(n, n) == 0)  // a degenerate triangle: its hull is covered by its edges
    return std::min({point_segment(p, a, b), point_segment(p, b, c), point_segment(p, c, a)});
  return length(p - closest_on_triangle(p, a, b, c));
}

/// The distance of segments (p1, q1) and (p2, q2): the closest parameters, clamped.
double segment_segment(V p1, V q1, V p2, V q2) {
  const V d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  if (a == 0) return point_segment(p1, p2, q2);
  if (e == 0) return point_segment(p2, p1, q1);
  const double b = dot(d1, d2), c = dot(d1, r), denominator = a * e - b * b;
  double s = denominator != 0 ? clamp01((b * f - c * e) / denominator) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = clamp01(-c / a);
  } else if (t > 1) {
    t = 1;
    s = clamp01((b - c) / a);
  }
  return length((p1 + d1 * s) - (p2 + d2 * t));
}

/// The points of a kind with `Points` points of `Dimension` coordinates at time t.
template <int Points, int Dimension>
void points_at(const double* q, double t, V* out) {
  for (int i = 0; i < Points; ++i) {
    const double* a = q + Dimension * i;
    const double* b = q + Dimension * (Points + i);
    const auto at = [&](int k) { return k < Dimension ? a[k] + t * (b[k] - a[k]) : 0.0; };
    out[i] = {at(0), at(1), at(2)};
  }
}

/// THE MISTAKE: the distance is checked at 17 sampled times only.
template <int Points, int Dimension, class Distance>
int sampled(const double* q, double min_distance, double tmax, double* toi, Distance distance) {
  constexpr int kIntervals = 16;
  for (int i = 0; i <= kIntervals; ++i) {
    const double t = tmax * i / kIntervals;
    V x[4];
    points_at<Points, Dimension>(q, t, x);
    if (distance(x) <= min_distance) {
      if (toi) *toi = t;
      return 1;
    }
  }
  return 0;
}

double vf(const V* x) { return point_triangle(x[0], x[1], x[2], x[3]); }
double ee(const V* x) { return segment_segment(x[0], x[1], x[2], x[3]); }
double pe(const V* x) { return point_segment(x[0], x[1], x[2]); }
double pp(const V* x) { return length(x[0] - x[1]); }

}  // namespace

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_vf_query(const double* q, double d, double tmax, double* toi) {
  return sampled<4, 3>(q, d, tmax, toi, vf);
}

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_ee_query(const double* q, double d, double tmax, double* toi) {
  return sampled<4, 3>(q, d, tmax, toi, ee);
}

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pe_query(const double* q, double d, double tmax, double* toi) {
  return sampled<3, 3>(q, d, tmax, toi, pe);
}

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pp_query(const double* q, double d, double tmax, double* toi) {
  return sampled<2, 3>(q, d, tmax, toi, pp);
}

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_ee2_query(const double* q, double d, double tmax, double* toi) {
  return sampled<4, 2>(q, d, tmax, toi, ee);
}

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pe2_query(const double* q, double d, double tmax, double* toi) {
  return sampled<3, 2>(q, d, tmax, toi, pe);
}

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pp2_query(const double* q, double d, double tmax, double* toi) {
  return sampled<2, 2>(q, d, tmax, toi, pp);
}
