// libFuzzer target: io::read_partial and io::merge_partials (`exactccd merge`'s input, the
// partial files of a sharded compare or fuzz-against run) on arbitrary bytes in a file. Besides
// reader_oracle.hpp's checks: an accepted file has a shard I < N and a range BEGIN <= END <=
// TOTAL, and written back (io::write_partial) reads as the same partial; merging it alone gives
// its records when it is the whole run (shard 0 of 1, range [0, TOTAL)) and a usage error
// otherwise, holding no memory by the untrusted N. docs/fuzzing.md, section 5.
#include <cstddef>
#include <cstdint>

#include "fuzz/readers/reader_oracle.hpp"
#include "io/input_file.hpp"  // UsageError
#include "io/partial.hpp"
#include "io/partial_merge.hpp"  // the writing and merging the command line uses

namespace exactccd::fuzzing {
namespace {

bool same_partial(const io::Partial& a, const io::Partial& b) {
  if (a.command != b.command || a.settings != b.settings || a.shard_index != b.shard_index ||
      a.shard_count != b.shard_count || a.begin != b.begin || a.end != b.end || a.total != b.total ||
      a.records.size() != b.records.size())
    return false;
  for (std::size_t i = 0; i < a.records.size(); ++i)
    if (a.records[i].text != b.records[i].text) return false;
  return true;
}

void check_partial(const io::Partial& p, std::string_view input) {
  require(p.shard_index < p.shard_count && p.begin <= p.end && p.end <= p.total, "an impossible shard or range", input);
  static ScratchFile written_file("partial-written");
  try {
    io::write_partial(written_file.path(), p);
  } catch (const io::UsageError&) {
    return;  // a setting write_partial cannot record (it never writes such a file)
  }
  try {
    require(same_partial(p, io::read_partial(written_file.path())), "written back, the partial reads differently", input);
  } catch (const io::InputError& e) {
    fail(std::string("written back, the partial is refused: ") + e.what(), input);
  }
}

/// merge_partials of the one file: its records when it is the whole run (shard 0 of 1, range [0,
/// TOTAL)), else a UsageError (missing shards, or a range that is not the shard's).
void check_merge(const io::Partial& p, const std::string& path, std::string_view input) {
  const bool whole_run = p.shard_count == 1 && p.begin == 0 && p.end == p.total;
  const ReaderOutcome outcome = run_reader(
      [&] {
        try {
          const io::Partial m = io::merge_partials({path});
          require(whole_run && m.records.size() == p.records.size() && m.total == p.total,
                  "merging a part of a run, or merging loses records", input);
        } catch (const io::UsageError&) {
          require(!whole_run, "merging the whole run's only partial is refused", input);
        }
      },
      path, Location::line, input);
  require(outcome.accepted, "merge_partials refuses a file that read_partial accepted: " + outcome.error, input);
}

/// The file with a line "x" appended is refused ("text after 'end'").
void check_rejects_trailing_garbage(std::string_view input) {
  static ScratchFile file("partial-garbage");
  const std::string& path = file.write(std::string(input) + "\nx\n");
  try {
    io::read_partial(path);
  } catch (const io::InputError&) {
    return;
  }
  fail("the input with a line 'x' appended is accepted too", input);
}

}  // namespace
}  // namespace exactccd::fuzzing

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace exactccd::fuzzing;
  const std::string_view input = as_text(data, size);
  static ScratchFile file("partial");
  const std::string& path = file.write(input);
  exactccd::io::Partial p;
  const ReaderOutcome outcome =
      run_reader([&] { p = exactccd::io::read_partial(path); }, path, Location::line, input);
  if (!outcome.accepted) return 0;
  check_partial(p, input);
  check_merge(p, path, input);
  check_rejects_trailing_garbage(input);
  return 0;
}
