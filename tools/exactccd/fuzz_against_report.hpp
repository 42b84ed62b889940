// What the report of a fuzz-against run is made of (FuzzTally), as partial records for a
// sharded run (partial.hpp) and back, and the report itself: the table on stdout and the
// files written to the output directory.
#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <vector>

#include "fuzz_against.hpp"
#include "partial.hpp"

namespace exactccd::cli::fuzz {

/// One row of the table: a group of queries.
struct Row {
  std::size_t queries = 0, collide = 0, fp = 0, fn = 0, errors = 0;
  std::size_t shared = 0;  ///< collisions both find, with the plug-in's time of impact
  std::size_t unsafe = 0;  ///< of those, times after the exact one
  std::size_t early = 0;   ///< of those, times more than the early factor before the exact one
  std::set<int> ks;        ///< family sweep: k at which some instance disagreed
  /// Adds another row's counts (and k).
  void add(const Row& other);
};

/// What the report of a run is made of, for a range of its queries (the whole run, or one
/// shard): the table's rows per group, the times of impact and the disagreements in query order.
struct FuzzTally {
  std::vector<Row> groups;
  std::vector<double> gaps;  ///< lo - T of every safe time of impact
  /// A time of impact that is unsafe or early.
  struct Toi {
    std::size_t index = 0, group = 0;
    double their_toi = 0;
    TimeInterval exact{};
    Rows rows{};
  };
  std::vector<Toi> unsafe, early;
  /// A disagreement, shrunk.
  struct Disagreement {
    std::size_t index = 0, group = 0;
    bool truth = false, family = false, toward = false;
    int k = 0;
    Rows shrunk{};
    std::string note;
  };
  std::vector<Disagreement> disagreements;
};

/// "-1, 23..60": a sorted set of k as ranges.
std::string k_ranges(const std::set<int>& ks);

/// The tally as partial records (group rows, then the times of impact and the disagreements).
void add_records(const FuzzTally& t, Partial& p);

/// The tally of merged records (shards in order: rows add up, the rest concatenates). Throws
/// io::ParseError naming the file and line of a malformed record.
FuzzTally tally_from_records(const Partial& p, std::size_t group_count);

/// What the report prints besides the tally.
struct ReportContext {
  const FuzzRun& run;
  const FuzzKind& kind;
  const std::vector<std::string>& group_names;
  std::string symbol;  ///< the plug-in's entry point
  bool reports_toi = false;
};

/// Prints the report of a whole run and writes its files to run.out_dir (the help describes
/// both).
void report_fuzz(const ReportContext& c, const FuzzTally& t);

}  // namespace exactccd::cli::fuzz
