// The public entry points of rigid queries (include/exactccd/rigid.hpp): the floating-point
// environment, validation, dispatch to a method.
#include <string>

#include "exactccd/rigid.hpp"
#include "filter/fp_environment.hpp"
#include "rigid/exact_rigid.hpp"
#include "rigid/rigid_filter.hpp"
#include "rigid/rigid_frame.hpp"
#include "rigid/validation.hpp"

namespace exactccd {
namespace {

template <class Query>
std::string function_name(bool want_toi) {
  return "exactccd::rigid_" + std::string(rigid::kind_of<Query>::function) + (want_toi ? "_toi" : "_ccd");
}

/// One query by one method: its TOI when want_toi, else an enclosure of it (any interval) on
/// collision.
template <class Query>
std::optional<TimeInterval> answer(const Query& q, const CcdParams& params, Method method, bool want_toi,
                                   StageCounters* counters) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  rigid::validate(q, params, [&] { return function_name<Query>(want_toi); });
  switch (method) {
    case Method::filtered:
      return rigid::filtered(q, params, want_toi, counters);
    case Method::exact:
      return rigid::exact_toi(rigid::to_rational(q), RationalCcdParams{params.min_distance, params.tmax});
  }
  throw std::invalid_argument(function_name<Query>(want_toi) + ": unknown method " +
                              std::to_string(static_cast<int>(method)));
}

}  // namespace

bool rigid_vertex_face_ccd(const RigidVertexFaceQuery& q, const CcdParams& p, Method m) {
  return answer(q, p, m, false, nullptr).has_value();
}
bool rigid_vertex_face_ccd(const RigidVertexFaceQuery& q, const CcdParams& p, Method m, StageCounters& c) {
  return answer(q, p, m, false, &c).has_value();
}
std::optional<TimeInterval> rigid_vertex_face_toi(const RigidVertexFaceQuery& q, const CcdParams& p, Method m) {
  return answer(q, p, m, true, nullptr);
}
std::optional<TimeInterval> rigid_vertex_face_toi(const RigidVertexFaceQuery& q, const CcdParams& p, Method m,
                                                  StageCounters& c) {
  return answer(q, p, m, true, &c);
}
bool rigid_edge_edge_ccd(const RigidEdgeEdgeQuery& q, const CcdParams& p, Method m) {
  return answer(q, p, m, false, nullptr).has_value();
}
bool rigid_edge_edge_ccd(const RigidEdgeEdgeQuery& q, const CcdParams& p, Method m, StageCounters& c) {
  return answer(q, p, m, false, &c).has_value();
}
std::optional<TimeInterval> rigid_edge_edge_toi(const RigidEdgeEdgeQuery& q, const CcdParams& p, Method m) {
  return answer(q, p, m, true, nullptr);
}
std::optional<TimeInterval> rigid_edge_edge_toi(const RigidEdgeEdgeQuery& q, const CcdParams& p, Method m,
                                                StageCounters& c) {
  return answer(q, p, m, true, &c);
}

}  // namespace exactccd
