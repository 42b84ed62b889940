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
// The file format and its reader: io/partial.hpp; its writing and merging: io/partial_merge.hpp
// (here: their names in the command line's namespace).
#pragma once

#include <string>
#include <vector>

#include "io/lines.hpp"    // split_words
#include "cli_common.hpp"   // kMaxShards
#include "io/partial.hpp"  // Partial, read_partial and the records' fields
#include "io/partial_merge.hpp"  // write_partial, merge_partials

namespace exactccd::cli {

using io::hex_double;
using io::parse_count;
using io::parse_double;
using io::parse_int;
using io::Partial;
using io::PartialRecord;
using io::read_partial;
using io::split_words;

using io::merge_partials;
using io::write_partial;

// The reader's shard limit is the --shard option's.
static_assert(static_cast<long long>(io::kMaxPartialShards) == kMaxShards);

}  // namespace exactccd::cli
