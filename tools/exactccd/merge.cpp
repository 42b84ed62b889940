// exactccd merge: the report of a sharded run (compare or fuzz-against with --shard I/N
// --partial FILE) from its N partial files, byte-identical to the report of one run
// (partial.hpp; the cluster recipe in tools/cluster/).
#include <iostream>

#include "cli_common.hpp"
#include "partial.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "merge";
    c.usage = "usage: exactccd merge [--out DIR] PART...";
    c.description =
        "Prints the report of a run split into shards: PART... are the partial files that\n"
        "`exactccd compare ... --shard I/N --partial PART` or `exactccd fuzz-against ... --shard I/N\n"
        "--partial PART` wrote, one per shard I = 0..N-1, in any order. The output (and for\n"
        "fuzz-against the files written to DIR) is byte-for-byte that of the same command run\n"
        "once without --shard. The files must be the N shards of one run: the same command and\n"
        "settings, every shard exactly once; anything else is an error naming the files, and a\n"
        "truncated or malformed file is an error naming its line. (`check --shard` needs no merge:\n"
        "its --answers outputs concatenate.) The cluster recipe: tools/cluster/README.md.\n";
    c.options = {text_option("--out", "DIR", "", "fuzz-against: where to write the disagreements (created if missing)")};
    c.epilogue = "exit codes: 0 merged, 2 bad usage or malformed, missing or mismatched partial files, 1 internal error.\n";
    return c;
  }();
  return spec;
}

}  // namespace

int run_merge(int argc, char** argv) {
  const ParsedOptions options = parse_options(command(), argc, argv);
  if (options.help()) {
    std::cout << help_text(command());
    return kExitOk;
  }
  const std::vector<std::string>& paths = options.positionals();
  const Partial merged = merge_partials(paths);
  const std::string source = paths.front();
  const std::string out_dir = options.has("--out") ? options.text("--out") : "";
  if (merged.command == "compare") {
    if (!out_dir.empty()) throw UsageError("merge: --out is for fuzz-against partials; these are from compare");
    return merge_compare(merged, source);
  }
  if (merged.command == "fuzz-against") return merge_fuzz_against(merged, source, out_dir);
  throw UsageError("merge: " + source + " is from '" + merged.command + "', which has no partial results");
}

}  // namespace exactccd::cli
