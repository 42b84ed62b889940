// The property the libFuzzer targets check on every decoded query (and
// tests/datasets/test_fuzz_regressions.cpp on the committed corpus): the filtered method answers
// exactly as the exact (CGAL) reference, with the identical time of impact (both are the
// tightest double interval of the same exact time, so they must be bit-identical), each
// method's ccd agrees with its toi, and the filtered answer does not depend on the order of
// the triangle's vertices or of the edges. The fuzzers print a violation (the query in hex
// floats and as a benchmark CSV) and abort().
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "exactccd/exactccd.hpp"
#include "generators/fuzz_input.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd::fuzzing {

/// "[lo, hi]" in hex floats, or "none".
inline std::string toi_string(const std::optional<TimeInterval>& t) {
  if (!t) return "none";
  char buf[96];
  std::snprintf(buf, sizeof buf, "[%a, %a]", t->lo, t->hi);
  return buf;
}

/// A TOI the contract allows: 0 <= lo <= hi <= 1 and hi is lo or the double after it.
inline bool well_formed(const std::optional<TimeInterval>& t) {
  if (!t) return true;
  return 0.0 <= t->lo && t->lo <= t->hi && t->hi <= 1.0 &&
         (t->hi == t->lo || t->hi == std::nextafter(t->lo, 2.0));
}

/// Equal TOIs: both absent, or both bounds equal.
inline bool same_toi(const std::optional<TimeInterval>& a, const std::optional<TimeInterval>& b) {
  return a.has_value() == b.has_value() && (!a || *a == *b);
}

/// The same query with the triangle's vertices b and c exchanged: by the contract, the answer
/// and TOI are unchanged. (One overload per kind: the kind's symmetry.)
inline VertexFaceQuery reordered(VertexFaceQuery q) {
  std::swap(q.b_t0, q.c_t0);
  std::swap(q.b_t1, q.c_t1);
  return q;
}

/// The same query with the two edges exchanged: the answer and TOI are unchanged.
inline EdgeEdgeQuery reordered(EdgeEdgeQuery q) {
  std::swap(q.a0_t0, q.b0_t0);
  std::swap(q.a1_t0, q.b1_t0);
  std::swap(q.a0_t1, q.b0_t1);
  std::swap(q.a1_t1, q.b1_t1);
  return q;
}

/// Checks the property (see the file comment) on one finite query of the kind: nullopt when it
/// holds, else a report: what failed, the query in hex floats, both methods' answers and TOIs,
/// and the query as a benchmark CSV with the exact answer as truth.
template <class Query>
std::optional<std::string> find_violation(const Rows& r) {
  using Kind = kinds::kind_of<Query>;
  const Query q = from_rows<Query>(r);
  const bool filtered = ccd(q, Method::filtered);
  const bool exact = ccd(q, Method::exact);
  const std::optional<TimeInterval> filtered_toi = toi(q, Method::filtered);
  const std::optional<TimeInterval> exact_toi = toi(q, Method::exact);
  const char* what = nullptr;
  if (filtered != exact) {
    what = "filtered and exact answers differ";
  } else if (!same_toi(filtered_toi, exact_toi)) {
    what = "filtered and exact TOIs differ";
  } else if (filtered != filtered_toi.has_value()) {
    what = "filtered ccd and toi disagree on the answer";
  } else if (exact != exact_toi.has_value()) {
    what = "exact ccd and toi disagree on the answer";
  } else if (!well_formed(exact_toi)) {
    what = "the exact TOI is not a tightest interval in [0, 1]";
  } else {
    const Query s = reordered(q);
    if (ccd(s, Method::filtered) != filtered || !same_toi(toi(s, Method::filtered), filtered_toi))
      what = "the filtered answer or TOI changes when the triangle's vertices / the edges are reordered";
  }
  if (!what) return std::nullopt;
  return std::string("exactccd fuzz: ") + what + " on a " + std::string(Kind::name) + " query\n" +
         hex_rows<Kind>(r) + "filtered: ccd " + (filtered ? "1" : "0") + ", toi " +
         toi_string(filtered_toi) + "\nexact:    ccd " + (exact ? "1" : "0") + ", toi " +
         toi_string(exact_toi) + "\nas a benchmark CSV (truth = the exact answer; replay with " +
         "`exactccd check --kind " + std::string(Kind::short_name) + "`):\n" + benchmark_csv(r, exact);
}

/// The exponent spread above which the fuzzers skip a query (fuzz_input.hpp,
/// exponent_spread): 400 bits by default, else the environment variable
/// EXACTCCD_FUZZ_MAX_SPREAD. All-subnormal queries, the 2^996 and 2^-1060 catalogue copies
/// and the families up to k = 400 at unit scale pass the default. Any value >= 2097 (the
/// largest spread of two finite doubles; the smoke_full_range tests use 2200) is the
/// full-range configuration: nothing is skipped, the wide family placements and per-axis scale
/// edits included; but a unit-scale query with one subnormal coordinate costs ~1 s under the
/// sanitizers, and the throughput drops from ~250 to ~15 inputs per second (docs/fuzzing.md).
inline int max_exponent_spread() {
  static const int limit = [] {
    const char* v = std::getenv("EXACTCCD_FUZZ_MAX_SPREAD");
    return v ? std::atoi(v) : 400;
  }();
  return limit;
}

/// One fuzzer input: decode, skip non-finite and too widely spread queries, check; on a
/// violation print it to stderr and abort() (libFuzzer then saves the input).
template <class Query>
void fuzz_one(const std::uint8_t* data, std::size_t size) {
  const Rows r = decode<kinds::kind_of<Query>>(data, size);
  if (!all_finite(r) || exponent_spread(r) > max_exponent_spread()) return;
  if (const auto report = find_violation<Query>(r)) {
    std::fprintf(stderr, "\n==== %s", report->c_str());
    std::fflush(stderr);
    std::abort();
  }
}

}  // namespace exactccd::fuzzing
