// libFuzzer target: io::read_ply (ASCII and both binary byte orders; and io::read_mesh on a .ply
// file) on arbitrary bytes. Besides the checks of mesh_oracle.hpp (the round trips write ASCII,
// little- and big-endian PLY): an accepted file has as many vertices as its header's `element
// vertex` count, at least one triangle per `element face`, and an ASCII body of numbers only
// (the target's own reading of the lines). docs/fuzzing.md, section 5.
#include <cstddef>
#include <cstdint>

#include "fuzz/readers/mesh_oracle.hpp"
#include "fuzz/readers/mesh_writers.hpp"
#include "io/mesh_formats.hpp"

namespace exactccd::fuzzing {
namespace {

/// The header's counts of `element vertex N` and `element face M`, from its lines' words.
void check_counts(const io::TriangleMesh& mesh, std::string_view input) {
  std::string vertices = "0", faces = "0";
  bool ascii = false, body = false;
  for (const std::vector<std::string>& words : words_per_line(input, '\0')) {
    if (body) {
      if (ascii) require_numbers(words, 0, input);  // an ASCII body holds numbers only
      continue;
    }
    body = words.size() == 1 && words[0] == "end_header";
    if (words.size() == 3 && words[0] == "format") ascii = words[1] == "ascii";
    if (words.size() == 3 && words[0] == "element" && words[1] == "vertex") vertices = words[2];
    if (words.size() == 3 && words[0] == "element" && words[1] == "face") faces = words[2];
  }
  require(accepted_integer(vertices, false, input) == static_cast<long long>(mesh.vertices.size()),
          "vertices read != the header's count " + vertices, input);
  require(accepted_integer(faces, false, input) <= static_cast<long long>(mesh.triangles.size()),
          "fewer triangles than the header's faces " + faces, input);
}

MeshWriter ply_writer(PlyEncoding encoding) {
  return [encoding](std::ostream& out, const io::TriangleMesh& m) {
    write_ply(out, m, encoding);
    return true;
  };
}

const MeshFormatUnderTest& ply_format() {
  static const MeshFormatUnderTest format{io::read_ply,
                                          ".ply",
                                          Location::line_or_byte,
                                          {ply_writer(PlyEncoding::ascii), ply_writer(PlyEncoding::binary_little_endian),
                                           ply_writer(PlyEncoding::binary_big_endian)},
                                          true,
                                          check_counts};
  return format;
}

}  // namespace
}  // namespace exactccd::fuzzing

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  exactccd::fuzzing::fuzz_mesh_reader(exactccd::fuzzing::ply_format(), exactccd::fuzzing::as_text(data, size));
  return 0;
}
