// Example plug-in for `exactccd fuzz-against` (include/exactccd/plugin.h): the textbook
// method with a Bridson-style tolerance (tools::Method::naive_tolerance), conservative: it trades
// false negatives for false positives. docs/fuzzing.md shows what fuzz-against finds in it.
#include "exactccd/plugin.h"
#include "plugin_support.hpp"

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_vf(const double q[24]) {
  return exactccd::plugins::vertex_face_answer(q, exactccd::tools::Method::naive_tolerance);
}

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_ee(const double q[24]) {
  return exactccd::plugins::edge_edge_answer(q, exactccd::tools::Method::naive_tolerance);
}

// The same method's time of impact (the optional entry points of plugin.h).
extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_vf_toi(const double q[24], double* toi) {
  return exactccd::plugins::toi_answer<exactccd::VertexFaceQuery>(q, toi, exactccd::tools::Method::naive_tolerance);
}

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_ee_toi(const double q[24], double* toi) {
  return exactccd::plugins::toi_answer<exactccd::EdgeEdgeQuery>(q, toi, exactccd::tools::Method::naive_tolerance);
}
