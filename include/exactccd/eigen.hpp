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

}  // namespace exactccd
