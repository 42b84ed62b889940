// Partial results of a sharded run (`--shard I/N --partial FILE`) and their merge
// (`exactccd merge`): the cluster recipe of tools/cluster/.
//
// A command whose report is not a concatenation of per-query lines (compare's quantiles,
// fuzz-against's table and output directory) writes, per shard, the data its report is made
// of: counts, lines and values, in query order. `exactccd merge` reads the shards, checks that
// they are the N shards of one run, concatenates their records in shard order and prints the
// report with the same code as a single run: the single run also builds its report from these
// records, so the two outputs are byte-identical by construction (doubles are written as hex
// floats and read back exactly), and tests/cli/cli_merge.cmake checks it.
//
// The file format and its reader: io/partial.hpp.
#pragma once

#include <string>
#include <vector>

#include "io/lines.hpp"    // split_words
#include "io/partial.hpp"  // Partial, read_partial and the records' fields

namespace exactccd::cli {

using io::hex_double;
using io::parse_count;
using io::parse_double;
using io::parse_int;
using io::Partial;
using io::PartialRecord;
using io::read_partial;
using io::split_words;

/// Writes `partial` to `path` atomically (AtomicOutputFile: nothing half-written).
void write_partial(const std::string& path, const Partial& partial);

/// Merges the partials of one run: the same command and settings, the same N and total, every
/// shard 0..N-1 exactly once, each with the range --shard I/N gives. Returns the merged partial
/// (shard 0/1, range [0, total), the records in shard order). Throws UsageError naming the
/// files when they are not the shards of one run.
Partial merge_partials(const std::vector<std::string>& paths);

}  // namespace exactccd::cli
