// The parts of `exactccd fuzz-against` shared by its files: fuzz_against.cpp (the command),
// fuzz_against_kind.cpp (the kinds at run time), fuzz_against_plugin.cpp (loading and calling
// the plug-in), fuzz_against_queries.cpp (generating, answering and shrinking the queries) and
// fuzz_against_report.cpp (the report, its partial records and the output files).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "generators/families.hpp"
#include "generators/separation_families.hpp"
#include "io/benchmark_csv.hpp"

namespace exactccd::cli::fuzz {

/// A query of any kind: its 2 * points rows (the rest zero), z = 0 in the plane.
using Rows = std::array<Vec3, 8>;

/// A kind as fuzz-against needs it at run time, derived from its description in lib/kinds
/// (fuzz_kind: names, point counts, the plug-in symbols, the exact answers, the generators).
struct FuzzKind {
  QueryKind kind;
  std::string name;        ///< "vertex-face": file names
  std::string short_name;  ///< "vf": --kind
  int points = 0;          ///< points per time
  int dimension = 3;       ///< coordinates per point
  io::QueryLayout layout;  ///< its benchmark files' layout
  std::array<std::string, 8> row_names;  ///< "p_t0", ...: the first 2 * points
  /// exactccd_plugin_<short_name>_query (plugin.h): the entry point for any question.
  std::string query_symbol;
  /// The contact-only entry points (plugin.h: d = 0, tmax = 1); empty for kinds without.
  std::string answer_symbol, toi_symbol;
  /// The exact answer and time of impact (the reference path, Method::exact).
  bool (*exact_answer)(const Rows&, const CcdParams&) = nullptr;
  std::optional<TimeInterval> (*exact_toi)(const Rows&, const CcdParams&) = nullptr;
  /// The exact degeneracy categories joined by '+' (exactccd compare's labels); nullptr for
  /// kinds without.
  std::string (*categories)(const Rows&) = nullptr;
  /// The contact question's generators (vf, ee): the degenerate families, their random mix and
  /// the fuzzers' decoder; empty / nullptr for the other kinds.
  std::vector<const families::Family*> contact_families;
  families::Instance (*random_contact_instance)(std::mt19937_64&) = nullptr;
  Rows (*decode)(const std::uint8_t*, std::size_t) = nullptr;
  /// The minimum-separation families of the kind (tools/lib/generators/separation_families.hpp).
  std::vector<const separation_families::Family*> separation_families;

  /// Coordinates per query: 2 * points * dimension.
  int coordinates() const { return 2 * points * dimension; }
};

/// The run-time description of a kind.
const FuzzKind& fuzz_kind(QueryKind kind);

/// The settings of a run.
struct FuzzRun {
  std::string plugin_path;
  std::size_t queries = 0;
  std::uint64_t seed = 0;
  std::string out_dir;
  unsigned threads = 1;
  bool shrinking = true;
  std::size_t shard_index = 0, shard_count = 1;
  std::string partial_path;  ///< write the partial results here instead of the report
  CcdParams params;          ///< the question: --min-distance and --tmax
  double early_factor = 2;   ///< a time of impact T is early when early_factor T < the exact one

  /// The contact question of the benchmark (d = 0, tmax = 1): what the contact-only entry
  /// points answer.
  bool contact_question() const { return params.contact_over_whole_step(); }
};

/// The random generator of query i of a run for one of its uses (tag): a run is reproducible
/// and independent of --threads and --shard.
std::mt19937_64 query_rng(std::uint64_t seed, std::size_t i, std::uint32_t tag);

}  // namespace exactccd::cli::fuzz
