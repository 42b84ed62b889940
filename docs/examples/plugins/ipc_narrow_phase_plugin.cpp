// The IPC Toolkit's narrow phases as exactccd fuzz-against plug-ins (docs/fuzzing.md, section
// 2b). Documentation only: nothing in exactccd builds it, and nothing of the toolkit is in
// exactccd. It was compiled by hand beside the repository, against the toolkit's sources, once
// per narrow phase: IPC_NARROW_PHASE names the class wrapped, TightInclusionCCD or AdditiveCCD.
#include <exactccd/plugin.h>

#include <exception>

#include <ipc/ccd/additive_ccd.hpp>
#include <ipc/ccd/tight_inclusion_ccd.hpp>

namespace {

/// The narrow phase under test, constructed with the toolkit's defaults, except that
/// AdditiveCCD's default constructor iterates without limit (UNLIMITTED_ITERATIONS), with which
/// one point-point query of the run (a pair at d + 2^-62 moving apart, steps of about 1e-19 in
/// t) did not return in 120 s; it gets the toolkit's own AdditiveCCD::DEFAULT_MAX_ITERATIONS
/// (1e7), at which it reports a collision.
template <class NarrowPhase>
NarrowPhase make_narrow_phase() {
  return NarrowPhase();
}
template <>
ipc::AdditiveCCD make_narrow_phase<ipc::AdditiveCCD>() {
  return ipc::AdditiveCCD(ipc::AdditiveCCD::DEFAULT_MAX_ITERATIONS);
}

const ipc::NarrowPhaseCCD& narrow_phase() {
  static const ipc::IPC_NARROW_PHASE ccd = make_narrow_phase<ipc::IPC_NARROW_PHASE>();
  return ccd;
}

/// Point i (in the kind's row order) at time 0 or 1, as the toolkit's 2D-or-3D vector.
template <int Dimension>
ipc::VectorMax3d point(const double* q, int points, int i, int time) {
  const double* x = q + Dimension * (time * points + i);
  ipc::VectorMax3d v(Dimension);
  for (int k = 0; k < Dimension; ++k) v[k] = x[k];
  return v;
}

/// Point i at time 0 or 1 as a 3D vector (the toolkit's point-triangle and edge-edge take these).
Eigen::Vector3d point3(const double* q, int points, int i, int time) {
  const double* x = q + 3 * (time * points + i);
  return Eigen::Vector3d(x[0], x[1], x[2]);
}

/// Calls the toolkit, writes its time of impact and turns an exception into an error (-1).
template <class Call>
int answer(double* toi, Call call) noexcept {
  try {
    double t = 0;
    if (!call(t)) return 0;
    if (toi) *toi = t;
    return 1;
  } catch (const std::exception&) {
    return -1;
  }
}

}  // namespace

extern "C" {
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_vf_query(const double* q, double d, double T, double* toi) {
  const auto x = [&](int i, int time) { return point3(q, 4, i, time); };
  return answer(toi, [&](double& t) {
    return narrow_phase().point_triangle_ccd(x(0, 0), x(1, 0), x(2, 0), x(3, 0), x(0, 1), x(1, 1), x(2, 1),
                                             x(3, 1), t, d, T);
  });
}
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_ee_query(const double* q, double d, double T, double* toi) {
  const auto x = [&](int i, int time) { return point3(q, 4, i, time); };
  return answer(toi, [&](double& t) {
    return narrow_phase().edge_edge_ccd(x(0, 0), x(1, 0), x(2, 0), x(3, 0), x(0, 1), x(1, 1), x(2, 1), x(3, 1),
                                        t, d, T);
  });
}
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pe_query(const double* q, double d, double T, double* toi) {
  const auto x = [&](int i, int time) { return point<3>(q, 3, i, time); };
  return answer(toi, [&](double& t) {
    return narrow_phase().point_edge_ccd(x(0, 0), x(1, 0), x(2, 0), x(0, 1), x(1, 1), x(2, 1), t, d, T);
  });
}
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pp_query(const double* q, double d, double T, double* toi) {
  const auto x = [&](int i, int time) { return point<3>(q, 2, i, time); };
  return answer(toi, [&](double& t) {
    return narrow_phase().point_point_ccd(x(0, 0), x(1, 0), x(0, 1), x(1, 1), t, d, T);
  });
}
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pe2_query(const double* q, double d, double T, double* toi) {
  const auto x = [&](int i, int time) { return point<2>(q, 3, i, time); };
  return answer(toi, [&](double& t) {
    return narrow_phase().point_edge_ccd(x(0, 0), x(1, 0), x(2, 0), x(0, 1), x(1, 1), x(2, 1), t, d, T);
  });
}
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pp2_query(const double* q, double d, double T, double* toi) {
  const auto x = [&](int i, int time) { return point<2>(q, 2, i, time); };
  return answer(toi, [&](double& t) {
    return narrow_phase().point_point_ccd(x(0, 0), x(1, 0), x(0, 1), x(1, 1), t, d, T);
  });
}
}
