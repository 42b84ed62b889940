// The properties the mesh reader fuzz targets check on every input (docs/fuzzing.md, section 5),
// besides those of reader_oracle.hpp: a mesh a reader returns has finite coordinates and
// triangles of three distinct in-range vertices; written back in its format (mesh_writers.hpp)
// and read again it is the same mesh, bit for bit; the input with a line of garbage appended is
// rejected; and io::read_mesh on the same bytes in a file with the format's extension gives the
// same mesh or the same error (format detection and byte order marks included).
#pragma once

#include <functional>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz/readers/reader_oracle.hpp"
#include "io/mesh_file.hpp"

namespace exactccd::fuzzing {

/// A stream reader of one format (io::read_obj, io::read_ply, ...).
using MeshReader = std::function<io::TriangleMesh(std::istream&, const std::string&)>;
/// A writer of one format's encoding: writes the mesh, or returns false when it cannot hold it.
using MeshWriter = std::function<bool(std::ostream&, const io::TriangleMesh&)>;

/// One mesh format as the targets fuzz it.
struct MeshFormatUnderTest {
  MeshReader read;
  std::string extension;             ///< ".obj", ".ply", ...: the source name is "input" + extension
  Location where;                    ///< how its errors locate themselves
  std::vector<MeshWriter> writers;   ///< the round trips (each written mesh must read back equal)
  /// Whether read_mesh must accept a file that the stream reader accepted (with vertices and
  /// faces): false for OBJ, whose format detection refuses control characters that read_obj
  /// takes in comments and names.
  bool detection_complete = true;
  /// The format's own checks of an accepted input against the mesh read (the target's counts).
  std::function<void(const io::TriangleMesh&, std::string_view)> check_accepted;
};

/// Reads the input with the format's reader under run_reader and checks every property above
/// and the format's check_accepted: the whole of a mesh target's LLVMFuzzerTestOneInput.
void fuzz_mesh_reader(const MeshFormatUnderTest& format, std::string_view input);

/// fail() unless every coordinate is finite and every triangle has three distinct vertices of
/// the mesh.
void check_mesh_invariants(const io::TriangleMesh& mesh, std::string_view input);

/// Whether two meshes are the same: vertices bit for bit (the sign of zero too), same triangles.
bool same_mesh(const io::TriangleMesh& a, const io::TriangleMesh& b);

/// A count or index word of an accepted file, read by the target itself: an optional sign ('+',
/// or '-' when `negative_allowed`) and decimal digits, nothing else; fail() on anything else (a
/// reader accepted a malformed number).
long long accepted_integer(const std::string& word, bool negative_allowed, std::string_view input);

/// Whether `word` is a number as the text formats write them: one optional sign, digits with an
/// optional decimal point and exponent (1, -2.5, .5, 5., 1e-3, +4E+2), or inf, infinity, nan,
/// nan(chars) (any case; the readers refuse them where a value must be finite). The target's own grammar,
/// against which every number of an accepted file is checked: '+-1', '1..2', '0x10' are none.
bool is_number(const std::string& word);

/// fail() unless every word of `words` from `first` on is a number (is_number).
void require_numbers(const std::vector<std::string>& words, std::size_t first, std::string_view input);

/// The whitespace-separated words of each line of `text` (a UTF-8 byte order mark at the start
/// dropped, everything from `comment` on dropped when it is not '\0'): the targets' own count of
/// what a header announces, independent of the readers.
std::vector<std::vector<std::string>> words_per_line(std::string_view text, char comment);

}  // namespace exactccd::fuzzing
