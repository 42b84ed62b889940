// The plug-in of `exactccd fuzz-against` (include/exactccd/plugin.h): loaded with dlopen, its
// entry point for the run's kind and question looked up with dlsym, called on queries.
#pragma once

#include <string>

#include "exactccd/plugin.h"
#include "fuzz_against.hpp"

namespace exactccd::cli::fuzz {

/// A loaded plug-in and the entry point that answers the run's kind and question; unloaded on
/// destruction.
class Plugin {
 public:
  /// Loads `path` and finds, for `kind` and the question `params`, exactccd_plugin_<kind>_query,
  /// else (vf and ee, d = 0 and tmax = 1 only) the contact-only entry point with a time of
  /// impact, else the answer-only one. Throws UsageError naming the file or the missing symbol.
  Plugin(const std::string& path, const FuzzKind& kind, const CcdParams& params);
  ~Plugin();
  Plugin(const Plugin&) = delete;
  Plugin& operator=(const Plugin&) = delete;

  /// The plug-in's raw answer on a query (1 collision, 0 none, anything else an error); toi
  /// gets its time of impact, NaN when it reports none.
  int answer(const Rows& r, double& toi) const;

  /// True when the entry point can report times of impact (the _query or _toi ones).
  bool reports_toi() const { return entry_ != Entry::answer; }

  /// The symbol called.
  const std::string& symbol() const { return symbol_; }

 private:
  enum class Entry { query, toi, answer };
  void* find(const std::string& symbol) const;
  void* handle_ = nullptr;
  const FuzzKind& kind_;
  CcdParams params_;
  std::string symbol_;
  Entry entry_ = Entry::answer;
  exactccd_plugin_query_fn query_fn_ = nullptr;
  exactccd_plugin_toi_fn toi_fn_ = nullptr;
  exactccd_plugin_fn answer_fn_ = nullptr;
};

}  // namespace exactccd::cli::fuzz
