// exactccd: header-only overloads taking Eigen vectors (as Tight Inclusion and IPC Toolkit
// users hold their data). Include after Eigen; exactccd itself does not depend on Eigen.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "exactccd/ccd.hpp"

namespace exactccd {

/// The double point of an Eigen 3-vector.
inline Vec3 to_vec3(const Eigen::Ref<const Eigen::Vector3d>& v) { return {v.x(), v.y(), v.z()}; }

/// vertex_face_ccd with the four vertices at t = 0 (p_t0, a_t0, b_t0, c_t0) and t = 1.
inline bool vertex_face_ccd(const Eigen::Vector3d& p_t0, const Eigen::Vector3d& a_t0,
                            const Eigen::Vector3d& b_t0, const Eigen::Vector3d& c_t0,
                            const Eigen::Vector3d& p_t1, const Eigen::Vector3d& a_t1,
                            const Eigen::Vector3d& b_t1, const Eigen::Vector3d& c_t1,
                            Method method = Method::filtered) {
  return vertex_face_ccd(VertexFaceQuery{to_vec3(p_t0), to_vec3(a_t0), to_vec3(b_t0), to_vec3(c_t0),
                                         to_vec3(p_t1), to_vec3(a_t1), to_vec3(b_t1), to_vec3(c_t1)},
                         method);
}

/// edge_edge_ccd with the edges (a0, a1), (b0, b1) at t = 0 and t = 1.
inline bool edge_edge_ccd(const Eigen::Vector3d& a0_t0, const Eigen::Vector3d& a1_t0,
                          const Eigen::Vector3d& b0_t0, const Eigen::Vector3d& b1_t0,
                          const Eigen::Vector3d& a0_t1, const Eigen::Vector3d& a1_t1,
                          const Eigen::Vector3d& b0_t1, const Eigen::Vector3d& b1_t1,
                          Method method = Method::filtered) {
  return edge_edge_ccd(EdgeEdgeQuery{to_vec3(a0_t0), to_vec3(a1_t0), to_vec3(b0_t0), to_vec3(b1_t0),
                                     to_vec3(a0_t1), to_vec3(a1_t1), to_vec3(b0_t1), to_vec3(b1_t1)},
                       method);
}

/// vertex_face_toi with Eigen vectors; see vertex_face_ccd above for the argument order.
inline std::optional<TimeInterval> vertex_face_toi(
    const Eigen::Vector3d& p_t0, const Eigen::Vector3d& a_t0, const Eigen::Vector3d& b_t0,
    const Eigen::Vector3d& c_t0, const Eigen::Vector3d& p_t1, const Eigen::Vector3d& a_t1,
    const Eigen::Vector3d& b_t1, const Eigen::Vector3d& c_t1, Method method = Method::filtered) {
  return vertex_face_toi(VertexFaceQuery{to_vec3(p_t0), to_vec3(a_t0), to_vec3(b_t0), to_vec3(c_t0),
                                         to_vec3(p_t1), to_vec3(a_t1), to_vec3(b_t1), to_vec3(c_t1)},
                         method);
}

/// edge_edge_toi with Eigen vectors; see edge_edge_ccd above for the argument order.
inline std::optional<TimeInterval> edge_edge_toi(
    const Eigen::Vector3d& a0_t0, const Eigen::Vector3d& a1_t0, const Eigen::Vector3d& b0_t0,
    const Eigen::Vector3d& b1_t0, const Eigen::Vector3d& a0_t1, const Eigen::Vector3d& a1_t1,
    const Eigen::Vector3d& b0_t1, const Eigen::Vector3d& b1_t1, Method method = Method::filtered) {
  return edge_edge_toi(EdgeEdgeQuery{to_vec3(a0_t0), to_vec3(a1_t0), to_vec3(b0_t0), to_vec3(b1_t0),
                                     to_vec3(a0_t1), to_vec3(a1_t1), to_vec3(b0_t1), to_vec3(b1_t1)},
                       method);
}

/// The double point of an Eigen 2-vector.
inline Vec2 to_vec2(const Eigen::Ref<const Eigen::Vector2d>& v) { return {v.x(), v.y()}; }

/// vertex_face_ccd with a minimum separation and a time limit (see ccd.hpp, CcdParams).
inline bool vertex_face_ccd(const Eigen::Vector3d& p_t0, const Eigen::Vector3d& a_t0, const Eigen::Vector3d& b_t0,
                            const Eigen::Vector3d& c_t0, const Eigen::Vector3d& p_t1, const Eigen::Vector3d& a_t1,
                            const Eigen::Vector3d& b_t1, const Eigen::Vector3d& c_t1, const CcdParams& params,
                            Method method = Method::filtered) {
  return vertex_face_ccd(VertexFaceQuery{to_vec3(p_t0), to_vec3(a_t0), to_vec3(b_t0), to_vec3(c_t0),
                                         to_vec3(p_t1), to_vec3(a_t1), to_vec3(b_t1), to_vec3(c_t1)},
                         params, method);
}
/// vertex_face_toi with a minimum separation and a time limit.
inline std::optional<TimeInterval> vertex_face_toi(
    const Eigen::Vector3d& p_t0, const Eigen::Vector3d& a_t0, const Eigen::Vector3d& b_t0,
    const Eigen::Vector3d& c_t0, const Eigen::Vector3d& p_t1, const Eigen::Vector3d& a_t1,
    const Eigen::Vector3d& b_t1, const Eigen::Vector3d& c_t1, const CcdParams& params,
    Method method = Method::filtered) {
  return vertex_face_toi(VertexFaceQuery{to_vec3(p_t0), to_vec3(a_t0), to_vec3(b_t0), to_vec3(c_t0),
                                         to_vec3(p_t1), to_vec3(a_t1), to_vec3(b_t1), to_vec3(c_t1)},
                         params, method);
}
/// edge_edge_ccd with a minimum separation and a time limit.
inline bool edge_edge_ccd(const Eigen::Vector3d& a0_t0, const Eigen::Vector3d& a1_t0, const Eigen::Vector3d& b0_t0,
                          const Eigen::Vector3d& b1_t0, const Eigen::Vector3d& a0_t1, const Eigen::Vector3d& a1_t1,
                          const Eigen::Vector3d& b0_t1, const Eigen::Vector3d& b1_t1, const CcdParams& params,
                          Method method = Method::filtered) {
  return edge_edge_ccd(EdgeEdgeQuery{to_vec3(a0_t0), to_vec3(a1_t0), to_vec3(b0_t0), to_vec3(b1_t0),
                                     to_vec3(a0_t1), to_vec3(a1_t1), to_vec3(b0_t1), to_vec3(b1_t1)},
                       params, method);
}
/// edge_edge_toi with a minimum separation and a time limit.
inline std::optional<TimeInterval> edge_edge_toi(
    const Eigen::Vector3d& a0_t0, const Eigen::Vector3d& a1_t0, const Eigen::Vector3d& b0_t0,
    const Eigen::Vector3d& b1_t0, const Eigen::Vector3d& a0_t1, const Eigen::Vector3d& a1_t1,
    const Eigen::Vector3d& b0_t1, const Eigen::Vector3d& b1_t1, const CcdParams& params,
    Method method = Method::filtered) {
  return edge_edge_toi(EdgeEdgeQuery{to_vec3(a0_t0), to_vec3(a1_t0), to_vec3(b0_t0), to_vec3(b1_t0),
                                     to_vec3(a0_t1), to_vec3(a1_t1), to_vec3(b0_t1), to_vec3(b1_t1)},
                       params, method);
}
/// point_edge_ccd with the point p and the edge (a, b) at t = 0 and t = 1.
inline bool point_edge_ccd(const Eigen::Vector3d& p_t0, const Eigen::Vector3d& a_t0, const Eigen::Vector3d& b_t0,
                           const Eigen::Vector3d& p_t1, const Eigen::Vector3d& a_t1, const Eigen::Vector3d& b_t1,
                           const CcdParams& params = {}, Method method = Method::filtered) {
  return point_edge_ccd(
      PointEdgeQuery{to_vec3(p_t0), to_vec3(a_t0), to_vec3(b_t0), to_vec3(p_t1), to_vec3(a_t1), to_vec3(b_t1)},
      params, method);
}
/// point_edge_toi with Eigen vectors; see point_edge_ccd above for the argument order.
inline std::optional<TimeInterval> point_edge_toi(const Eigen::Vector3d& p_t0, const Eigen::Vector3d& a_t0,
                                                  const Eigen::Vector3d& b_t0, const Eigen::Vector3d& p_t1,
                                                  const Eigen::Vector3d& a_t1, const Eigen::Vector3d& b_t1,
                                                  const CcdParams& params = {}, Method method = Method::filtered) {
  return point_edge_toi(
      PointEdgeQuery{to_vec3(p_t0), to_vec3(a_t0), to_vec3(b_t0), to_vec3(p_t1), to_vec3(a_t1), to_vec3(b_t1)},
      params, method);
}
/// point_point_ccd with the points p and q at t = 0 and t = 1.
inline bool point_point_ccd(const Eigen::Vector3d& p_t0, const Eigen::Vector3d& q_t0, const Eigen::Vector3d& p_t1,
                            const Eigen::Vector3d& q_t1, const CcdParams& params = {},
                            Method method = Method::filtered) {
  return point_point_ccd(PointPointQuery{to_vec3(p_t0), to_vec3(q_t0), to_vec3(p_t1), to_vec3(q_t1)}, params,
                         method);
}
/// point_point_toi with Eigen vectors; see point_point_ccd above for the argument order.
inline std::optional<TimeInterval> point_point_toi(const Eigen::Vector3d& p_t0, const Eigen::Vector3d& q_t0,
                                                   const Eigen::Vector3d& p_t1, const Eigen::Vector3d& q_t1,
                                                   const CcdParams& params = {},
                                                   Method method = Method::filtered) {
  return point_point_toi(PointPointQuery{to_vec3(p_t0), to_vec3(q_t0), to_vec3(p_t1), to_vec3(q_t1)}, params,
                         method);
}
/// edge_edge_2d_toi with Eigen 2-vectors (a0, a1, b0, b1 at t = 0, then at t = 1).
inline std::optional<TimeInterval> edge_edge_2d_toi(
    const Eigen::Vector2d& a0_t0, const Eigen::Vector2d& a1_t0, const Eigen::Vector2d& b0_t0,
    const Eigen::Vector2d& b1_t0, const Eigen::Vector2d& a0_t1, const Eigen::Vector2d& a1_t1,
    const Eigen::Vector2d& b0_t1, const Eigen::Vector2d& b1_t1, const CcdParams& params = {},
    Method method = Method::filtered) {
  return edge_edge_2d_toi(EdgeEdge2dQuery{to_vec2(a0_t0), to_vec2(a1_t0), to_vec2(b0_t0), to_vec2(b1_t0),
                                          to_vec2(a0_t1), to_vec2(a1_t1), to_vec2(b0_t1), to_vec2(b1_t1)},
                          params, method);
}
/// point_edge_2d_toi with Eigen 2-vectors (p, a, b at t = 0, then at t = 1).
inline std::optional<TimeInterval> point_edge_2d_toi(const Eigen::Vector2d& p_t0, const Eigen::Vector2d& a_t0,
                                                     const Eigen::Vector2d& b_t0, const Eigen::Vector2d& p_t1,
                                                     const Eigen::Vector2d& a_t1, const Eigen::Vector2d& b_t1,
                                                     const CcdParams& params = {},
                                                     Method method = Method::filtered) {
  return point_edge_2d_toi(
      PointEdge2dQuery{to_vec2(p_t0), to_vec2(a_t0), to_vec2(b_t0), to_vec2(p_t1), to_vec2(a_t1), to_vec2(b_t1)},
      params, method);
}
/// point_point_2d_toi with Eigen 2-vectors (p, q at t = 0, then at t = 1).
inline std::optional<TimeInterval> point_point_2d_toi(const Eigen::Vector2d& p_t0, const Eigen::Vector2d& q_t0,
                                                      const Eigen::Vector2d& p_t1, const Eigen::Vector2d& q_t1,
                                                      const CcdParams& params = {},
                                                      Method method = Method::filtered) {
  return point_point_2d_toi(PointPoint2dQuery{to_vec2(p_t0), to_vec2(q_t0), to_vec2(p_t1), to_vec2(q_t1)}, params,
                            method);
}

}  // namespace exactccd
