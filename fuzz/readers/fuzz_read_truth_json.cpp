// libFuzzer target: io::read_truth_json (the Scalable CCD dataset's mma_bool files, `check` and
// `compare`'s truth) on arbitrary bytes. Besides reader_oracle.hpp's checks: the values of an
// accepted file are its words `true` and `false` in order (the target's own scan of the letters;
// a valid file has no other letters), and written back they read the same. docs/fuzzing.md, 5.
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <sstream>

#include "fuzz/readers/reader_oracle.hpp"
#include "io/truth_json.hpp"

namespace exactccd::fuzzing {
namespace {

/// The runs of letters of the input, as booleans (fail() on any other word).
std::vector<bool> words(std::string_view input) {
  std::vector<bool> out;
  std::string word;
  for (std::size_t i = 0; i <= input.size(); ++i) {
    if (i < input.size() && std::isalpha(static_cast<unsigned char>(input[i]))) {
      word.push_back(input[i]);
      continue;
    }
    if (word.empty()) continue;
    require(word == "true" || word == "false", "an accepted file holds the word '" + word + "'", input);
    out.push_back(word == "true");
    word.clear();
  }
  return out;
}

void check_values(const std::vector<bool>& values, std::string_view input) {
  require(values == words(input), "the values read are not the file's words true and false", input);
  std::ostringstream written;
  written << '[';
  for (std::size_t i = 0; i < values.size(); ++i) written << (i ? ", " : "") << (values[i] ? "true" : "false");
  written << "]\n";
  const auto read = [](std::istream& in) { return io::read_truth_json(in, "written.json"); };
  require(read_back(read, written.str(), input) == values, "written back, the values read differently", input);
}

}  // namespace
}  // namespace exactccd::fuzzing

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace exactccd::fuzzing;
  const std::string_view input = as_text(data, size);
  fuzz_stream_reader(exactccd::io::read_truth_json, "input.json", input,
                     [&](const std::vector<bool>& values) { check_values(values, input); });
  return 0;
}
