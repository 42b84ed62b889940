// libFuzzer target: io::read_stl (binary and ASCII; and io::read_mesh on a .stl file) on
// arbitrary bytes. Besides the checks of mesh_oracle.hpp (the round trips write ASCII STL, and
// binary STL when every coordinate is a float): an accepted binary file (84 + 50 n bytes) has n
// triangles, an accepted ASCII file one per `facet` line and numbers (is_number) in its facet
// and vertex lines (the target's own reading).
// docs/fuzzing.md, section 5.
#include <cstddef>
#include <cstdint>

#include "fuzz/readers/mesh_oracle.hpp"
#include "fuzz/readers/mesh_writers.hpp"
#include "io/mesh_formats.hpp"

namespace exactccd::fuzzing {
namespace {

void check_counts(const io::TriangleMesh& mesh, std::string_view input) {
  if (input.size() >= 84) {
    std::uint64_t n = 0;
    for (int i = 83; i >= 80; --i) n = n * 256 + static_cast<unsigned char>(input[static_cast<std::size_t>(i)]);
    if (input.size() == 84 + 50 * n) {
      require(mesh.triangles.size() == n, "a binary STL of " + std::to_string(n) + " facets read with another count", input);
      return;
    }
  }
  std::size_t facets = 0;
  for (const std::vector<std::string>& words : words_per_line(input, '\0')) {
    if (!words.empty() && words[0] == "facet") ++facets;
    if (!words.empty() && words[0] == "facet") require_numbers(words, 2, input);
    if (!words.empty() && words[0] == "vertex") require_numbers(words, 1, input);
  }
  require(mesh.triangles.size() == facets, "triangles read != the facet lines", input);
}

const MeshFormatUnderTest& stl_format() {
  static const MeshFormatUnderTest format{io::read_stl,
                                          ".stl",
                                          Location::line_or_byte,
                                          {[](std::ostream& out, const io::TriangleMesh& m) {
                                             write_stl_ascii(out, m);
                                             return true;
                                           },
                                           write_stl_binary},
                                          true,
                                          check_counts};
  return format;
}

}  // namespace
}  // namespace exactccd::fuzzing

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  exactccd::fuzzing::fuzz_mesh_reader(exactccd::fuzzing::stl_format(), exactccd::fuzzing::as_text(data, size));
  return 0;
}
