// The rigid motion model in the CLI (issue 24): `check --motion rigid` and `bench --motion rigid`
// over files of lib/io/rigid_csv.hpp. The subcommands parse their options and hand over here.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "io/rigid_csv.hpp"

namespace exactccd::cli {

/// The `--motion linear|rigid` option.
OptionSpec motion_option();
/// True when --motion rigid was given.
bool rigid_motion(const ParsedOptions& options);

/// A loaded rigid query file.
struct RigidDataset {
  std::string path;
  QueryKind kind;
  io::RigidQueries queries;
};

/// The kind of a rigid file: --kind (vf or ee only), else vertex-face / edge-edge in the path.
/// Throws UsageError for another kind or when neither says.
QueryKind rigid_kind(const std::optional<QueryKind>& given, const std::string& path);

/// Reads a rigid file: io::InputError when missing, unreadable or without queries,
/// io::ParseError ("file:line: reason") when malformed.
RigidDataset load_rigid_dataset(const std::string& path, const std::optional<QueryKind>& kind);

/// Query i of a dataset by a library method (filtered or exact): its TOI when want_toi, else
/// any enclosure on collision.
std::optional<TimeInterval> run_rigid_query(const RigidDataset& d, std::size_t i, Method method, StageCounters* counters,
                                            bool want_toi, const CcdParams& params);

/// The library method of a --method value: filtered or exact; a baseline is a UsageError
/// (the baselines answer linear queries only).
Method rigid_method(tools::Method m);

/// `check --motion rigid` with check's parsed options.
int run_rigid_check(const ParsedOptions& options);

/// `bench --motion rigid` with bench's parsed options: per file and d, the rigid filtered method's
/// mean and median time per query against the linear filtered method on the linearised queries
/// (ratio of the means, one run, interleaved), FP/FN, queries decided with GMP or CGAL.
int run_rigid_bench(const ParsedOptions& options, const std::vector<double>& distances, bool relative, double tmax);

/// `generate rigid`: the degenerate rigid families (d = 0) and the tumbling-body sets into DIR
/// (rigid-families-{vertex-face,edge-edge}.csv, rigid-sim-<scene>-{vertex-face,edge-edge}.csv),
/// at most max_queries per sim file (0: all), truth computed on `threads` threads.
int generate_rigid(std::uint64_t seed, std::size_t max_queries, unsigned threads, const std::string& out);

}  // namespace exactccd::cli
