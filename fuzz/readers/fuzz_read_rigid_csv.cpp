// libFuzzer target: io::read_rigid_csv on arbitrary bytes. Besides reader_oracle.hpp's checks:
// an accepted file has one query per non-blank, non-comment line, at increasing lines, every
// number finite and both bodies' motions valid (rigid::invalid_motion), and written back
// (io::write_rigid_csv, hex floats) reads as the same numbers, bit for bit. docs/fuzzing.md, 5.
#include <cstddef>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <sstream>

#include "exactccd/rigid.hpp"
#include "fuzz/readers/reader_oracle.hpp"
#include "io/rigid_csv.hpp"
#include "rigid/validation.hpp"

namespace exactccd::fuzzing {
namespace {

/// Lines whose first non-blank character exists and is not '#' (a byte order mark dropped).
std::size_t query_lines(std::string_view input) {
  if (input.substr(0, 3) == "\xEF\xBB\xBF") input.remove_prefix(3);
  std::size_t count = 0;
  std::size_t start = 0;
  while (start <= input.size()) {
    const std::size_t end = std::min(input.find('\n', start), input.size());
    const std::string_view line = input.substr(start, end - start);
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first != std::string_view::npos && line[first] != '#') ++count;
    start = end + 1;
  }
  return count;
}

bool same_queries(const io::RigidQueries& a, const io::RigidQueries& b) {
  return a.size() == b.size() && a.truth == b.truth &&
         (a.size() == 0 || std::memcmp(a.numbers.data(), b.numbers.data(), a.size() * sizeof(a.numbers[0])) == 0);
}

void check_queries(const io::RigidQueries& q, std::string_view input) {
  require(q.size() == query_lines(input), "queries != the lines that are neither blank nor comments", input);
  require(q.truth.size() == q.size() && q.lines.size() == q.size(), "truth or lines of another count", input);
  for (std::size_t i = 0; i < q.size(); ++i) {
    require(q.lines[i] >= 1 && q.lines[i] <= line_count(input) && (i == 0 || q.lines[i] > q.lines[i - 1]),
            "query lines out of order or range", input);
    for (const double x : q.numbers[i]) require(std::isfinite(x), "a non-finite number", input);
    const auto query = rigid::from_numbers<RigidVertexFaceQuery>(q.numbers[i].data());
    require(!rigid::invalid_motion(query.a_t0, query.a_t1) && !rigid::invalid_motion(query.b_t0, query.b_t1),
            "an invalid motion accepted", input);
  }
  std::ostringstream written;
  io::write_rigid_csv(written, q, {"round trip"});
  const auto read = [](std::istream& in) { return io::read_rigid_csv(in, "written.csv"); };
  require(same_queries(q, read_back(read, written.str(), input)),
          "written back, the queries read differently:\n" + written.str(), input);
}

}  // namespace
}  // namespace exactccd::fuzzing

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace exactccd::fuzzing;
  const std::string_view input = as_text(data, size);
  fuzz_stream_reader(exactccd::io::read_rigid_csv, "input.csv", input,
                     [&](const exactccd::io::RigidQueries& q) { check_queries(q, input); });
  return 0;
}
