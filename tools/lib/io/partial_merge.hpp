// Writing and merging the partial results of a sharded run (`--shard I/N --partial FILE`,
// `exactccd merge`: the cluster recipe of tools/cluster/; the format and its reader:
// partial.hpp). Here, not in the command line, so that the reader's fuzz target checks that a
// partial read back is written and merged alike (fuzz/readers/fuzz_read_partial.cpp).
#pragma once

#include <string>
#include <vector>

#include "io/partial.hpp"

namespace exactccd::io {

/// Writes `partial` to `path` atomically (AtomicOutputFile: nothing half-written). Throws
/// UsageError naming the path when it cannot be written, or a setting that cannot be recorded.
void write_partial(const std::string& path, const Partial& partial);

/// Merges the partials of one run: the same command and settings, the same N and total, every
/// shard 0..N-1 exactly once, each with the range --shard I/N gives. Returns the merged partial
/// (shard 0/1, range [0, total), the records in shard order). Throws UsageError naming the
/// files when they are not the shards of one run.
Partial merge_partials(const std::vector<std::string>& paths);

}  // namespace exactccd::io
