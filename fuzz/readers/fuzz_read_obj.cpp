// libFuzzer target: io::read_obj (and io::read_mesh on a .obj file) on arbitrary bytes. Besides
// the checks of mesh_oracle.hpp: an accepted file has as many vertices as `v` lines and as many
// triangles as its `f` lines' fans, and every reference of its f, l and p lines names an existing
// v, vt or vn line (the target's own reading of the lines). docs/fuzzing.md, section 5.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/readers/mesh_oracle.hpp"
#include "io/obj.hpp"

namespace exactccd::fuzzing {
namespace {

/// The `v` lines and the triangles of the `f` lines' fans, counted from the words, and the
/// numbers of the v, vt, vn and vp lines.
void check_counts(const io::TriangleMesh& mesh, std::string_view input) {
  std::size_t vertices = 0, triangles = 0;
  for (const std::vector<std::string>& words : words_per_line(input, '#')) {
    if (words.empty()) continue;
    if (words[0] == "v") ++vertices;
    if (words[0] == "f") triangles += words.size() - 3;
    if (words[0] == "v" || words[0] == "vt" || words[0] == "vn" || words[0] == "vp") require_numbers(words, 1, input);
  }
  require(mesh.vertices.size() == vertices, "vertices read != the v lines", input);
  require(mesh.triangles.size() == triangles, "triangles read != the f lines' fans", input);
}

/// Every reference of the f, l and p lines (`v`, `v/t`, `v//n`, `v/t/n`) names an existing
/// vertex, texture vertex and normal: a positive index at most the file's count of v, vt or vn
/// lines, a negative one at most the count so far. An OBJ file referring to elements it lacks
/// is malformed, whether the reader uses them (v) or not (vt, vn).
void check_references(std::string_view input) {
  const std::vector<std::vector<std::string>> lines = words_per_line(input, '#');
  const char* kinds[3] = {"v", "vt", "vn"};
  long long total[3] = {0, 0, 0}, so_far[3] = {0, 0, 0};
  for (const auto& words : lines)
    for (int k = 0; k < 3; ++k) total[k] += !words.empty() && words[0] == kinds[k];
  for (const auto& words : lines) {
    if (words.empty()) continue;
    for (int k = 0; k < 3; ++k) so_far[k] += words[0] == kinds[k];
    if (words[0] != "f" && words[0] != "l" && words[0] != "p") continue;
    for (std::size_t w = 1; w < words.size(); ++w) {
      std::size_t start = 0;
      for (int k = 0; k < 3 && start <= words[w].size(); ++k) {
        const std::size_t slash = std::min(words[w].find('/', start), words[w].size());
        const std::string part = words[w].substr(start, slash - start);
        start = slash + 1;
        if (part.empty()) continue;
        const long long r = accepted_integer(part, true, input);
        require(r > 0 ? r <= total[k] : -r <= so_far[k],
                std::string("an accepted reference ") + words[w] + " names no " + kinds[k] + " line", input);
      }
    }
  }
}

const MeshFormatUnderTest& obj_format() {
  static const MeshFormatUnderTest format{
      io::read_obj,
      ".obj",
      Location::line,
      {[](std::ostream& out, const io::TriangleMesh& m) {
        io::write_obj(out, m.vertices, m.triangles, "round trip");
        return true;
      }},
      false,
      [](const io::TriangleMesh& mesh, std::string_view input) {
        check_counts(mesh, input);
        check_references(input);
      }};
  return format;
}

}  // namespace
}  // namespace exactccd::fuzzing

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  exactccd::fuzzing::fuzz_mesh_reader(exactccd::fuzzing::obj_format(), exactccd::fuzzing::as_text(data, size));
  return 0;
}
