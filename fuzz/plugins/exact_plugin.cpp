// Example plug-in for `exactccd fuzz-against` (include/exactccd/plugin.h): exactccd itself, through
// its public API (exactccd::toi with CcdParams, the default Method::filtered), for every kind and
// every question. fuzz-against compares it with the reference path (Method::exact): it must find
// nothing (CTest cli.fuzz_against_separation), and it shows the shape of a wrapper of any code.
#include <exception>

#include "exactccd/plugin.h"
#include "plugin_support.hpp"

namespace {

/// 1 and the exact time of impact's lower bound lo (<= the exact time: safe) in *toi, 0, or -1
/// when the library refuses the input.
template <class Kind>
int answer(const double* q, double min_distance, double tmax, double* toi) noexcept {
  try {
    const auto t = exactccd::toi(exactccd::plugins::kind_query<Kind>(q), exactccd::CcdParams{min_distance, tmax});
    if (!t) return 0;
    if (toi) *toi = t->lo;
    return 1;
  } catch (const std::exception&) {
    return -1;
  }
}

}  // namespace

namespace kinds = exactccd::kinds;

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_vf_query(const double* q, double d, double tmax, double* toi) {
  return answer<kinds::VertexFace>(q, d, tmax, toi);
}

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_ee_query(const double* q, double d, double tmax, double* toi) {
  return answer<kinds::EdgeEdge>(q, d, tmax, toi);
}

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pe_query(const double* q, double d, double tmax, double* toi) {
  return answer<kinds::PointEdge>(q, d, tmax, toi);
}

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pp_query(const double* q, double d, double tmax, double* toi) {
  return answer<kinds::PointPoint>(q, d, tmax, toi);
}

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_ee2_query(const double* q, double d, double tmax, double* toi) {
  return answer<kinds::EdgeEdge2d>(q, d, tmax, toi);
}

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pe2_query(const double* q, double d, double tmax, double* toi) {
  return answer<kinds::PointEdge2d>(q, d, tmax, toi);
}

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pp2_query(const double* q, double d, double tmax, double* toi) {
  return answer<kinds::PointPoint2d>(q, d, tmax, toi);
}
