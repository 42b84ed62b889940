// libFuzzer target: io::read_answers (`exactccd compare --answers` and `--toi`) on arbitrary
// bytes, in both modes. Besides reader_oracle.hpp's checks: an accepted file has one answer per
// non-blank line, a time of impact exactly for the colliding answers of --toi (in [0, 1]: the
// query's time interval is [0, tmax] with tmax <= 1), and
// written back (io::write_answers) reads as the same answers. docs/fuzzing.md, section 5.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <sstream>

#include "fuzz/readers/reader_oracle.hpp"
#include "io/answers.hpp"

namespace exactccd::fuzzing {
namespace {

bool same_answers(const std::vector<io::TheirAnswer>& a, const std::vector<io::TheirAnswer>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].collides != b[i].collides || a[i].toi.has_value() != b[i].toi.has_value() ||
        (a[i].toi && std::memcmp(&*a[i].toi, &*b[i].toi, sizeof(double)) != 0))
      return false;
  return true;
}

void check_answers(const std::vector<io::TheirAnswer>& answers, bool with_toi, std::string_view input) {
  const std::string_view body = input.substr(0, 3) == "\xEF\xBB\xBF" ? input.substr(3) : input;
  require(answers.size() == nonblank_lines(body), "answers != the non-blank lines", input);
  for (const io::TheirAnswer& a : answers)
    require(a.toi.has_value() == (with_toi && a.collides) && (!a.toi || (*a.toi >= 0 && *a.toi <= 1)),
            "a time of impact where there must be none, or a missing one or one outside [0, 1]", input);
  std::ostringstream written;
  io::write_answers(written, answers);
  const auto read = [&](std::istream& in) { return io::read_answers(in, "written.txt", with_toi); };
  require(same_answers(answers, read_back(read, written.str(), input)),
          "written back, the answers read differently:\n" + written.str(), input);
}

void check_mode(std::string_view input, bool with_toi) {
  const auto read = [with_toi](std::istream& in, const std::string& source) {
    return io::read_answers(in, source, with_toi);
  };
  fuzz_stream_reader(read, "input.txt", input,
                     [&](const std::vector<io::TheirAnswer>& answers) { check_answers(answers, with_toi, input); });
}

}  // namespace
}  // namespace exactccd::fuzzing

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input = exactccd::fuzzing::as_text(data, size);
  exactccd::fuzzing::check_mode(input, false);
  exactccd::fuzzing::check_mode(input, true);
  return 0;
}
