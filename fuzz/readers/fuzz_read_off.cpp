// libFuzzer target: io::read_off (and io::read_mesh on a .off file) on arbitrary bytes. Besides
// the checks of mesh_oracle.hpp: an accepted file has as many vertices as its counts line says
// and at least one triangle per face (the target's own reading of the keyword and counts).
// docs/fuzzing.md, section 5.
#include <cstddef>
#include <cstdint>

#include "fuzz/readers/mesh_oracle.hpp"
#include "fuzz/readers/mesh_writers.hpp"
#include "io/mesh_formats.hpp"

namespace exactccd::fuzzing {
namespace {

/// The counts: the two words after the keyword (the first word of the first line with words);
/// every word after the keyword is a number.
void check_counts(const io::TriangleMesh& mesh, std::string_view input) {
  std::vector<std::string> words;
  for (const std::vector<std::string>& line : words_per_line(input, '#'))
    words.insert(words.end(), line.begin(), line.end());
  require_numbers(words, 1, input);
  require(words.size() >= 3, "an accepted OFF file without its counts", input);
  require(accepted_integer(words[1], false, input) == static_cast<long long>(mesh.vertices.size()),
          "vertices read != the count " + words[1], input);
  require(accepted_integer(words[2], false, input) <= static_cast<long long>(mesh.triangles.size()),
          "fewer triangles than the faces " + words[2], input);
}

const MeshFormatUnderTest& off_format() {
  static const MeshFormatUnderTest format{io::read_off,
                                          ".off",
                                          Location::line,
                                          {[](std::ostream& out, const io::TriangleMesh& m) {
                                            write_off(out, m);
                                            return true;
                                          }},
                                          true,
                                          check_counts};
  return format;
}

}  // namespace
}  // namespace exactccd::fuzzing

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  exactccd::fuzzing::fuzz_mesh_reader(exactccd::fuzzing::off_format(), exactccd::fuzzing::as_text(data, size));
  return 0;
}
