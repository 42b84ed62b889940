// exactccd: a narrow phase for the IPC Toolkit (ipc-sim/ipc-toolkit), header-only.
//
// exactccd::ExactNarrowPhaseCCD implements the toolkit's abstract ipc::NarrowPhaseCCD
// (src/ipc/ccd/narrow_phase_ccd.hpp) with exactccd's exact answers, so that a simulator built
// on the toolkit can pass it wherever the toolkit takes a narrow phase (e.g.
// ipc::compute_collision_free_stepsize). Include it only where the toolkit's headers are on the
// include path: it includes <ipc/ccd/narrow_phase_ccd.hpp>. exactccd itself does not depend on
// the toolkit or on Eigen; this header needs both (and links exactccd::exactccd).
//
// Semantics of every method (docs/ipc_toolkit.md compares them with Tight Inclusion's):
// - returns true iff the two primitives come within distance <= min_distance at some t in
//   [0, tmax], decided exactly (exactccd's contract: closed primitives, degenerate ones are
//   their hulls, every finite double);
// - when true, `toi` is the largest double at which the pair is certainly not yet within
//   min_distance: with [lo, hi] the tightest double interval holding the exact time of impact
//   T, toi = lo when lo < hi (then lo < T), and the double just below lo when lo == hi (T is
//   the double lo itself); 0 when lo == 0 (the pair starts within min_distance, or reaches it
//   before the smallest positive double). So 0 <= toi < T whenever T > 0, and toi >= the
//   double just below lo: moving by toi keeps the pair apart, and IPC's line search stays
//   collision-free without any rescaling (conservative_rescaling is set to 1);
// - when false, toi = tmax (the motion over [0, tmax] is collision-free);
// - points of 2 coordinates (point_point_ccd, point_edge_ccd with VectorMax3d of size 2) are
//   the plane's kinds (exactccd's *_2d queries);
// - const, no state: safe to call from many threads at once, as the toolkit does;
// - throws std::invalid_argument for a NaN or infinite coordinate, a min_distance that is
//   negative or not finite, a tmax outside (0, 1], or points of mixed or unsupported sizes.
#pragma once

#include <ipc/ccd/narrow_phase_ccd.hpp>

#include <cmath>
#include <initializer_list>
#include <optional>
#include <stdexcept>

#include "exactccd/ccd.hpp"

namespace exactccd {

/// The IPC Toolkit's narrow phase answered exactly by exactccd (see the top of this file).
class ExactNarrowPhaseCCD : public ipc::NarrowPhaseCCD {
 public:
  /// A narrow phase with nothing to set (exact answers need no tolerance or iteration limit);
  /// conservative_rescaling is 1: the time of impact is already below the exact one.
  ExactNarrowPhaseCCD() { conservative_rescaling = 1.0; }

  /// The largest double at which a pair whose exact time of impact lies in the tightest double
  /// interval [lo, hi] is certainly not yet in contact: lo when lo < hi, the double just below
  /// lo when lo == hi, and 0 when lo == 0.
  static double safe_toi(const TimeInterval& t) {
    if (t.lo <= 0) return 0.0;
    return t.lo < t.hi ? t.lo : std::nextafter(t.lo, 0.0);
  }

  /// Point-point CCD (3D, or 2D when the points have 2 coordinates).
  bool point_point_ccd(Eigen::ConstRef<ipc::VectorMax3d> p0_t0, Eigen::ConstRef<ipc::VectorMax3d> p1_t0,
                       Eigen::ConstRef<ipc::VectorMax3d> p0_t1, Eigen::ConstRef<ipc::VectorMax3d> p1_t1,
                       double& toi, const double min_distance = 0.0, const double tmax = 1.0) const override {
    const CcdParams params{min_distance, tmax};
    if (dimension({&p0_t0, &p1_t0, &p0_t1, &p1_t1}) == 2)
      return answer(point_point_2d_toi(PointPoint2dQuery{v2(p0_t0), v2(p1_t0), v2(p0_t1), v2(p1_t1)}, params),
                    toi, tmax);
    return answer(point_point_toi(PointPointQuery{v3(p0_t0), v3(p1_t0), v3(p0_t1), v3(p1_t1)}, params), toi, tmax);
  }

  /// Point-edge CCD (3D, or 2D when the points have 2 coordinates).
  bool point_edge_ccd(Eigen::ConstRef<ipc::VectorMax3d> p_t0, Eigen::ConstRef<ipc::VectorMax3d> e0_t0,
                      Eigen::ConstRef<ipc::VectorMax3d> e1_t0, Eigen::ConstRef<ipc::VectorMax3d> p_t1,
                      Eigen::ConstRef<ipc::VectorMax3d> e0_t1, Eigen::ConstRef<ipc::VectorMax3d> e1_t1,
                      double& toi, const double min_distance = 0.0, const double tmax = 1.0) const override {
    const CcdParams params{min_distance, tmax};
    if (dimension({&p_t0, &e0_t0, &e1_t0, &p_t1, &e0_t1, &e1_t1}) == 2)
      return answer(point_edge_2d_toi(PointEdge2dQuery{v2(p_t0), v2(e0_t0), v2(e1_t0), v2(p_t1), v2(e0_t1),
                                                       v2(e1_t1)},
                                      params),
                    toi, tmax);
    return answer(
        point_edge_toi(PointEdgeQuery{v3(p_t0), v3(e0_t0), v3(e1_t0), v3(p_t1), v3(e0_t1), v3(e1_t1)}, params), toi,
        tmax);
  }

  /// Point-triangle (vertex-face) CCD.
  bool point_triangle_ccd(Eigen::ConstRef<Eigen::Vector3d> p_t0, Eigen::ConstRef<Eigen::Vector3d> t0_t0,
                          Eigen::ConstRef<Eigen::Vector3d> t1_t0, Eigen::ConstRef<Eigen::Vector3d> t2_t0,
                          Eigen::ConstRef<Eigen::Vector3d> p_t1, Eigen::ConstRef<Eigen::Vector3d> t0_t1,
                          Eigen::ConstRef<Eigen::Vector3d> t1_t1, Eigen::ConstRef<Eigen::Vector3d> t2_t1, double& toi,
                          const double min_distance = 0.0, const double tmax = 1.0) const override {
    const VertexFaceQuery q{v3(p_t0), v3(t0_t0), v3(t1_t0), v3(t2_t0), v3(p_t1), v3(t0_t1), v3(t1_t1), v3(t2_t1)};
    return answer(vertex_face_toi(q, CcdParams{min_distance, tmax}), toi, tmax);
  }

  /// Edge-edge CCD.
  bool edge_edge_ccd(Eigen::ConstRef<Eigen::Vector3d> ea0_t0, Eigen::ConstRef<Eigen::Vector3d> ea1_t0,
                     Eigen::ConstRef<Eigen::Vector3d> eb0_t0, Eigen::ConstRef<Eigen::Vector3d> eb1_t0,
                     Eigen::ConstRef<Eigen::Vector3d> ea0_t1, Eigen::ConstRef<Eigen::Vector3d> ea1_t1,
                     Eigen::ConstRef<Eigen::Vector3d> eb0_t1, Eigen::ConstRef<Eigen::Vector3d> eb1_t1, double& toi,
                     const double min_distance = 0.0, const double tmax = 1.0) const override {
    const EdgeEdgeQuery q{v3(ea0_t0), v3(ea1_t0), v3(eb0_t0), v3(eb1_t0),
                          v3(ea0_t1), v3(ea1_t1), v3(eb0_t1), v3(eb1_t1)};
    return answer(edge_edge_toi(q, CcdParams{min_distance, tmax}), toi, tmax);
  }

 private:
  /// Writes toi (safe_toi, or tmax without a collision) and returns whether there is one.
  static bool answer(const std::optional<TimeInterval>& t, double& toi, double tmax) {
    toi = t ? safe_toi(*t) : tmax;
    return t.has_value();
  }

  /// The common size (2 or 3) of the points; std::invalid_argument for mixed or other sizes.
  static Eigen::Index dimension(std::initializer_list<const Eigen::Ref<const ipc::VectorMax3d>*> points) {
    const Eigen::Index n = (*points.begin())->size();
    for (const auto* p : points)
      if (p->size() != n || (n != 2 && n != 3))
        throw std::invalid_argument("exactccd::ExactNarrowPhaseCCD: points must all have 2 or all 3 coordinates");
    return n;
  }

  template <class V>
  static Vec3 v3(const V& v) {
    return Vec3{v[0], v[1], v[2]};
  }

  template <class V>
  static Vec2 v2(const V& v) {
    return Vec2{v[0], v[1]};
  }
};

}  // namespace exactccd
