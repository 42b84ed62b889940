// Shared by the example plug-ins: a plug-in entry point (include/exactccd/plugin.h) that
// answers with one of the methods of exactccd's tools (tools::Method: the library's exact
// methods or a non-robust baseline; built against the tools library, exactccd_tools).
#pragma once

#include <array>
#include <exception>

#include "exactccd/exactccd.hpp"
#include "kinds/primitive_kinds.hpp"
#include "methods/methods.hpp"

namespace exactccd::plugins {

/// The query in the plug-in ABI's 24 doubles (benchmark row order, x y z per point).
template <class Query>
Query query_from(const double q[24]) {
  std::array<Vec3, 8> r;
  for (std::size_t i = 0; i < 8; ++i) r[i] = {q[3 * i], q[3 * i + 1], q[3 * i + 2]};
  return from_rows<Query>(r);
}

/// The query of the kind Kind (a description of lib/kinds) in the plug-in ABI's doubles: its
/// points at t = 0 then t = 1, Kind::dimension coordinates each (plugin.h).
template <class Kind>
typename Kind::template Query<double> kind_query(const double* q) {
  using Query = typename Kind::template Query<double>;
  auto r = rows(Query{});
  for (std::size_t i = 0; i < r.size(); ++i) {
    r[i].x = q[Kind::dimension * i];
    r[i].y = q[Kind::dimension * i + 1];
    if constexpr (Kind::dimension == 3) r[i].z = q[3 * i + 2];
  }
  return from_rows<Query>(r);
}

/// 1 or 0: method's answer on the vertex-face query q; -1 if it threw (non-finite input).
inline int vertex_face_answer(const double q[24], tools::Method method) noexcept {
  try {
    return tools::ccd(query_from<VertexFaceQuery>(q), method) ? 1 : 0;
  } catch (const std::exception&) {
    return -1;
  }
}

/// 1 or 0: method's answer on the edge-edge query q; -1 if it threw (non-finite input).
inline int edge_edge_answer(const double q[24], tools::Method method) noexcept {
  try {
    return tools::ccd(query_from<EdgeEdgeQuery>(q), method) ? 1 : 0;
  } catch (const std::exception&) {
    return -1;
  }
}

/// 1 and the method's TOI (the lower end of its interval) in *toi, or 0; -1 if it threw.
template <class Query>
int toi_answer(const double q[24], double* toi, tools::Method method) noexcept {
  try {
    const auto t = tools::toi(query_from<Query>(q), method);
    if (!t) return 0;
    *toi = t->lo;
    return 1;
  } catch (const std::exception&) {
    return -1;
  }
}

}  // namespace exactccd::plugins
