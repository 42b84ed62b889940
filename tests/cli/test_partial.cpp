// The partial files of sharded runs (tools/lib/io/partial.hpp) as `exactccd merge` reads them:
// the regressions of the reader fuzz target fuzz/readers/fuzz_read_partial.cpp (docs/fuzzing.md,
// section 5). The merge of real runs is tests/cli/cli_merge.cmake's.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "cli_common.hpp"
#include "io/input_file.hpp"
#include "partial.hpp"

namespace exactccd::cli {
namespace {

/// `text` in a file of the test's temporary directory; its path.
std::string partial_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "exactccd-partial-" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

/// The message of the io::InputError or UsageError that merging `paths` throws ("" if none).
std::string merge_error(const std::vector<std::string>& paths) {
  try {
    merge_partials(paths);
  } catch (const io::InputError& e) {
    return e.what();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

std::string partial(const std::string& shard, const std::string& range) {
  return "exactccd-partial 1\ncommand compare\nsetting mode answers\n" + shard + "\n" + range + "\nfp 0\nend 1\n";
}

TEST(Partial, ReadsAndMergesTheOnlyShard) {
  const std::string path = partial_file("whole", partial("shard 0 1", "range 0 4 4"));
  const Partial p = merge_partials({path});
  EXPECT_EQ(p.total, 4u);
  ASSERT_EQ(p.records.size(), 1u);
  EXPECT_EQ(p.records[0].text, "fp 0");
}

// A shard count N beyond what --shard allows was accepted, and merging the file reserved memory
// for N shards: 800 GB for "shard 5 100000000000" (an allocation failure under the sanitizers).
TEST(Partial, ShardCountsBeyondTheOptionsLimitAreErrors) {
  const std::string path = partial_file("huge-n", partial("shard 5 100000000000", "range 0 0 0"));
  EXPECT_EQ(merge_error({path}), path + ":4: shard 5 of 100000000000: expected 0 <= I < N <= 1000000");
}

// The largest N: one file of a million shards is a usage error listing some missing shards,
// not a message of a million numbers (nor memory by N).
TEST(Partial, MissingShardsAreListedBriefly) {
  const std::string path = partial_file("many", partial("shard 0 1000000", "range 0 0 0"));
  EXPECT_EQ(merge_error({path}), "merge: missing shards (of 1000000): 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, ... (999999 in all)");
}

// A TOTAL whose product with N would wrap around in merge_partials' shard ranges.
TEST(Partial, TotalsThatWouldOverflowAreErrors) {
  const std::string path = partial_file("huge-total", partial("shard 0 1", "range 0 0 18446744073709551615"));
  EXPECT_NE(merge_error({path}).find(path + ":5: range: expected BEGIN <= END <= TOTAL <= "), std::string::npos);
}

// Found by the fuzz target: a file ending early named the line after its last ("line 3" of a
// file of two lines).
TEST(Partial, AnEarlyEndNamesTheLastLine) {
  const std::string path = partial_file("short", "exactccd-partial 1\ncommand compare\n");
  EXPECT_EQ(merge_error({path}), path + ":2: unexpected end of file, expected 'setting KEY VALUE' or 'shard I N' (a "
                                        "truncated partial file?)");
  const std::string empty = partial_file("empty", "");
  EXPECT_EQ(merge_error({empty}), empty + ":1: unexpected end of file, expected the header 'exactccd-partial 1' (a "
                                          "truncated partial file?)");
}

}  // namespace
}  // namespace exactccd::cli
