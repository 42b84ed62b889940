// The queries of a fuzz-against run: where each comes from (its group), the plug-in's answer
// against the exact one, and the shrinking of every disagreement.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "generators/fuzz_input.hpp"
#include "fuzz_against.hpp"
#include "fuzz_against_plugin.hpp"
#include "fuzz_against_report.hpp"

namespace exactccd::cli::fuzz {

/// Where the queries of a group come from.
enum class Source {
  contact_family,              ///< a degenerate family of tools/lib/generators/families.hpp (d = 0 sweep)
  separation_family,           ///< a minimum-separation family (tools/lib/generators/separation_families.hpp)
  random_contact_instance,     ///< families::random_instance
  random_separation_instance,  ///< separation_families::random_instance
  decoder,                     ///< the fuzzers' decoder on random bytes, one of its modes
  random_near,                 ///< separation_families::random_near
};

/// One group of the table.
struct Group {
  std::string name;
  Source source = Source::random_near;
  const families::Family* contact = nullptr;                ///< contact_family
  const separation_families::Family* separation = nullptr;  ///< separation_family
  fuzzing::Mode mode = fuzzing::Mode::grid;                 ///< decoder
};

/// The groups of a run: the family sweep's (one per family), the random instances', then the
/// plain random queries' groups.
struct Groups {
  std::vector<Group> list;
  std::size_t sweep_count = 0;        ///< groups 0 .. sweep_count - 1: the families swept
  /// The sweep's order: family after family at each (k, direction) when true (the separation
  /// families: a short run reaches every one), every (k, direction) of one family before the
  /// next when false (the contact families, as before the minimum separation).
  bool interleaved = false;
  std::size_t random_instance = 0;    ///< the random instances' group
  std::vector<std::size_t> plain;     ///< the plain random queries' groups, cycled over
  /// The group names, in order.
  std::vector<std::string> names() const;
};

/// The groups for a kind and question: at the contact question (d = 0; vf and ee) the
/// degenerate families, their random mix and the decoder's modes, as before the minimum
/// separation; else the kind's separation families, their random mix and random_near (and the
/// decoder's modes for vf and ee).
Groups make_groups(const FuzzKind& kind, const CcdParams& params);

/// Runs queries [begin, end) of the run against the plug-in: the tally of the report.
FuzzTally fuzz_queries(const FuzzRun& run, const FuzzKind& kind, const Plugin& plugin, const Groups& groups,
                       std::size_t begin, std::size_t end);

}  // namespace exactccd::cli::fuzz
