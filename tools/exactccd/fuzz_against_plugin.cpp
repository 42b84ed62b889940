#include "fuzz_against_plugin.hpp"

#include <dlfcn.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

namespace exactccd::cli::fuzz {
namespace {

/// A function pointer from dlsym's void* (POSIX stores function pointers as void*).
template <class Fn>
Fn as_function(void* symbol) {
  static_assert(sizeof(void*) == sizeof(Fn), "dlsym returns functions as void*");
  Fn fn = nullptr;
  std::memcpy(&fn, &symbol, sizeof fn);
  return fn;
}

std::string question_text(const CcdParams& p) {
  char text[96];
  std::snprintf(text, sizeof text, "--min-distance %.17g --tmax %.17g", p.min_distance, p.tmax);
  return text;
}

}  // namespace

Plugin::Plugin(const std::string& path, const FuzzKind& kind, const CcdParams& params)
    : kind_(kind), params_(params) {
  // dlopen searches the library path for a bare name: "x.so" means the file ./x.so here.
  const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
  handle_ = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle_) {
    const char* why = dlerror();
    throw UsageError("fuzz-against: cannot load plug-in '" + path + "': " + (why ? why : "unknown error"));
  }
  const bool contact_only_ok = !kind.answer_symbol.empty() && params.contact_over_whole_step();
  if (void* f = find(kind.query_symbol)) {
    entry_ = Entry::query;
    symbol_ = kind.query_symbol;
    query_fn_ = as_function<exactccd_plugin_query_fn>(f);
  } else if (void* g = contact_only_ok ? find(kind.toi_symbol) : nullptr) {
    entry_ = Entry::toi;
    symbol_ = kind.toi_symbol;
    toi_fn_ = as_function<exactccd_plugin_toi_fn>(g);
  } else if (void* h = contact_only_ok ? find(kind.answer_symbol) : nullptr) {
    entry_ = Entry::answer;
    symbol_ = kind.answer_symbol;
    answer_fn_ = as_function<exactccd_plugin_fn>(h);
  } else {
    dlclose(handle_);
    const std::string needed = "int " + kind.query_symbol + "(const double* q, double min_distance, double tmax, double* toi)";
    if (contact_only_ok)
      throw UsageError("fuzz-against: plug-in '" + path + "' does not export the symbol " + kind.query_symbol + " nor " +
                       kind.answer_symbol + ", needed for --kind " + kind.short_name + " (see include/exactccd/plugin.h: " +
                       needed + ", or int " + kind.answer_symbol + "(const double q[24]) for d = 0 and tmax = 1)");
    throw UsageError("fuzz-against: plug-in '" + path + "' does not export the symbol " + kind.query_symbol +
                     ", needed for --kind " + kind.short_name + " " + question_text(params) +
                     (kind.answer_symbol.empty() ? "" : " (" + kind.answer_symbol + " answers only d = 0 and tmax = 1)") +
                     "; see include/exactccd/plugin.h: " + needed);
  }
}

Plugin::~Plugin() { dlclose(handle_); }

void* Plugin::find(const std::string& symbol) const {
  if (symbol.empty()) return nullptr;
  dlerror();
  return dlsym(handle_, symbol.c_str());
}

int Plugin::answer(const Rows& r, double& toi) const {
  double q[24] = {};
  const int d = kind_.dimension;
  for (int i = 0; i < 2 * kind_.points; ++i) {
    const Vec3& p = r[static_cast<std::size_t>(i)];
    q[d * i] = p.x;
    q[d * i + 1] = p.y;
    if (d == 3) q[d * i + 2] = p.z;
  }
  toi = std::numeric_limits<double>::quiet_NaN();
  switch (entry_) {
    case Entry::query: return query_fn_(q, params_.min_distance, params_.tmax, &toi);
    case Entry::toi: return toi_fn_(q, &toi);
    case Entry::answer: break;
  }
  return answer_fn_(q);
}

}  // namespace exactccd::cli::fuzz
