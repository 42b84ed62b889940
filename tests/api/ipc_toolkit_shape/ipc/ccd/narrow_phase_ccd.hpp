// NOT the IPC Toolkit: a stand-in for its header src/ipc/ccd/narrow_phase_ccd.hpp, with an
// interface of the same shape, so that tests/api/test_ipc_toolkit.cpp compiles and runs
// exactccd/ipc_toolkit.hpp on machines without the toolkit (CI: the project's dependencies are
// Debian packages, and the toolkit is not one). Copied in shape from ipc-sim/ipc-toolkit at
// commit b40e9c07 (src/ipc/ccd/narrow_phase_ccd.hpp and the aliases it uses from
// src/ipc/utils/eigen_ext.hpp): the four pure virtual methods with the same parameter types,
// names, defaults and const-ness, the virtual destructor, and the public member
// conservative_rescaling. A change of those signatures in the toolkit must be copied here.
#pragma once

#include <Eigen/Core>

namespace Eigen {
/// As the toolkit's eigen_ext.hpp: a const reference to a const Eigen::Ref.
template <typename T>
using ConstRef = const Ref<const T>&;
}  // namespace Eigen

namespace ipc {

/// As the toolkit's eigen_ext.hpp: a vector of at most 3 doubles (2D or 3D points).
using VectorMax3d = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 3, 1>;

/// The toolkit's narrow-phase CCD interface (same shape).
class NarrowPhaseCCD {
 public:
  NarrowPhaseCCD() = default;
  virtual ~NarrowPhaseCCD() = default;

  virtual bool point_point_ccd(Eigen::ConstRef<VectorMax3d> p0_t0, Eigen::ConstRef<VectorMax3d> p1_t0,
                               Eigen::ConstRef<VectorMax3d> p0_t1, Eigen::ConstRef<VectorMax3d> p1_t1, double& toi,
                               const double min_distance = 0.0, const double tmax = 1.0) const = 0;

  virtual bool point_edge_ccd(Eigen::ConstRef<VectorMax3d> p_t0, Eigen::ConstRef<VectorMax3d> e0_t0,
                              Eigen::ConstRef<VectorMax3d> e1_t0, Eigen::ConstRef<VectorMax3d> p_t1,
                              Eigen::ConstRef<VectorMax3d> e0_t1, Eigen::ConstRef<VectorMax3d> e1_t1, double& toi,
                              const double min_distance = 0.0, const double tmax = 1.0) const = 0;

  virtual bool point_triangle_ccd(Eigen::ConstRef<Eigen::Vector3d> p_t0, Eigen::ConstRef<Eigen::Vector3d> t0_t0,
                                  Eigen::ConstRef<Eigen::Vector3d> t1_t0, Eigen::ConstRef<Eigen::Vector3d> t2_t0,
                                  Eigen::ConstRef<Eigen::Vector3d> p_t1, Eigen::ConstRef<Eigen::Vector3d> t0_t1,
                                  Eigen::ConstRef<Eigen::Vector3d> t1_t1, Eigen::ConstRef<Eigen::Vector3d> t2_t1,
                                  double& toi, const double min_distance = 0.0, const double tmax = 1.0) const = 0;

  virtual bool edge_edge_ccd(Eigen::ConstRef<Eigen::Vector3d> ea0_t0, Eigen::ConstRef<Eigen::Vector3d> ea1_t0,
                             Eigen::ConstRef<Eigen::Vector3d> eb0_t0, Eigen::ConstRef<Eigen::Vector3d> eb1_t0,
                             Eigen::ConstRef<Eigen::Vector3d> ea0_t1, Eigen::ConstRef<Eigen::Vector3d> ea1_t1,
                             Eigen::ConstRef<Eigen::Vector3d> eb0_t1, Eigen::ConstRef<Eigen::Vector3d> eb1_t1,
                             double& toi, const double min_distance = 0.0, const double tmax = 1.0) const = 0;

  double conservative_rescaling;  // uninitialised in the toolkit too
};

}  // namespace ipc
