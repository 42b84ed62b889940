#include "fuzz/readers/mesh_oracle.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <sstream>

namespace exactccd::fuzzing {
namespace {

/// `message` with its leading `from` replaced by `to`.
std::string renamed(const std::string& message, const std::string& from, const std::string& to) {
  return message.compare(0, from.size(), from) == 0 ? to + message.substr(from.size()) : message;
}

/// The mesh read back from what `write` writes of `mesh`, compared with `mesh`.
void check_round_trip(const MeshFormatUnderTest& format, const MeshWriter& write, const io::TriangleMesh& mesh,
                      std::string_view input) {
  std::ostringstream out;
  if (!write(out, mesh)) return;
  const auto read = [&](std::istream& in) { return format.read(in, "written" + format.extension); };
  require(same_mesh(mesh, read_back(read, out.str(), input)),
          "the mesh written back reads as another mesh; written:\n" + out.str(), input);
}

/// io::read_mesh on the input in a file: the stream reader's mesh or error.
void check_read_mesh(const MeshFormatUnderTest& format, std::string_view input, bool accepted,
                     const io::TriangleMesh& mesh, const std::string& stream_error) {
  static ScratchFile file("mesh" + format.extension);  // a target fuzzes one format
  const std::string& path = file.write(input);
  io::TriangleMesh from_file;
  const ReaderOutcome outcome = run_reader([&] { from_file = io::read_mesh(path); }, path, Location::any, input);
  const bool file_accepted = outcome.accepted;
  const std::string& file_error = outcome.error;
  const std::string source = "input" + format.extension;
  if (file_accepted) {
    require(accepted, "read_mesh accepts what the stream reader refuses (" + stream_error + ")", input);
    require(same_mesh(from_file, mesh), "read_mesh and the stream reader read different meshes", input);
    return;
  }
  const bool has_mesh = accepted && !mesh.vertices.empty() && !mesh.triangles.empty();
  require(!has_mesh || !format.detection_complete,
          "the stream reader accepts a mesh that read_mesh refuses: " + file_error, input);
  // A reader's error (with a line or byte offset) must be the stream reader's, in the file's name.
  const bool located = file_error.compare(0, path.size() + 1, path + ":") == 0 &&
                       (std::isdigit(static_cast<unsigned char>(file_error[path.size() + 1])) ||
                        file_error.compare(path.size() + 1, 13, " byte offset ") == 0);
  if (located && !accepted)
    require(file_error == renamed(stream_error, source, path),
            "read_mesh and the stream reader give different errors:\n  " + file_error + "\n  " + stream_error, input);
}

}  // namespace

void check_mesh_invariants(const io::TriangleMesh& mesh, std::string_view input) {
  for (const Vec3& v : mesh.vertices)
    require(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z), "a non-finite coordinate", input);
  const auto n = static_cast<long long>(mesh.vertices.size());
  for (const auto& t : mesh.triangles) {
    for (const int i : t) require(i >= 0 && i < n, "a triangle index out of range: " + std::to_string(i), input);
    require(t[0] != t[1] && t[1] != t[2] && t[0] != t[2], "a triangle repeats a vertex", input);
  }
}

bool same_mesh(const io::TriangleMesh& a, const io::TriangleMesh& b) {
  if (a.vertices.size() != b.vertices.size() || a.triangles != b.triangles) return false;
  return a.vertices.empty() || std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vec3)) == 0;
}

long long accepted_integer(const std::string& word, bool negative_allowed, std::string_view input) {
  const bool negative = !word.empty() && word[0] == '-';
  const std::size_t first = !word.empty() && (word[0] == '+' || negative) ? 1 : 0;
  const std::size_t significant = std::min(word.find_first_not_of('0', first), word.size());
  bool ok = first < word.size() && word.size() - significant <= 18 && (!negative || negative_allowed);
  long long value = 0;
  for (std::size_t i = first; ok && i < word.size(); ++i) {
    ok = std::isdigit(static_cast<unsigned char>(word[i])) != 0;
    value = value * 10 + (word[i] - '0');
  }
  require(ok, "an accepted file holds the count or index '" + word + "', which is no such number", input);
  return negative ? -value : value;
}

bool is_number(const std::string& word) {
  std::size_t i = word.empty() || (word[0] != '+' && word[0] != '-') ? 0 : 1;
  std::string rest = word.substr(i);
  std::transform(rest.begin(), rest.end(), rest.begin(), [](unsigned char c) { return std::tolower(c); });
  if (rest == "inf" || rest == "infinity" || rest == "nan") return true;
  if (rest.compare(0, 4, "nan(") == 0 && rest.back() == ')')  // nan(n-char-sequence)
    return std::all_of(rest.begin() + 4, rest.end() - 1, [](unsigned char c) { return std::isalnum(c) || c == '_'; });
  const auto digits = [&] {
    const std::size_t from = i;
    while (i < word.size() && std::isdigit(static_cast<unsigned char>(word[i]))) ++i;
    return i - from;
  };
  std::size_t mantissa = digits();
  if (i < word.size() && word[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < word.size() && (word[i] == 'e' || word[i] == 'E')) {
    ++i;
    if (i < word.size() && (word[i] == '+' || word[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == word.size();
}

void require_numbers(const std::vector<std::string>& words, std::size_t first, std::string_view input) {
  for (std::size_t i = first; i < words.size(); ++i)
    require(is_number(words[i]), "an accepted file holds '" + words[i] + "' where a number belongs", input);
}

std::vector<std::vector<std::string>> words_per_line(std::string_view text, char comment) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::vector<std::vector<std::string>> out(1);
  std::string word;
  bool in_comment = false;
  const auto end_word = [&] {
    if (!word.empty()) out.back().push_back(word);
    word.clear();
  };
  for (const char c : text) {
    if (c == '\n') {
      end_word();
      out.emplace_back();
      in_comment = false;
    } else if (in_comment || (comment != '\0' && c == comment)) {
      end_word();
      in_comment = true;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      end_word();
    } else {
      word.push_back(c);
    }
  }
  end_word();
  return out;
}

void fuzz_mesh_reader(const MeshFormatUnderTest& format, std::string_view input) {
  const std::string source = "input" + format.extension;
  io::TriangleMesh mesh;
  const ReaderOutcome outcome = run_reader(
      [&] {
        std::istringstream in{std::string(input)};
        mesh = format.read(in, source);
      },
      source, format.where, input);
  const bool accepted = outcome.accepted;
  const std::string& stream_error = outcome.error;
  if (accepted) {
    check_mesh_invariants(mesh, input);
    format.check_accepted(mesh, input);
    for (const MeshWriter& write : format.writers) check_round_trip(format, write, mesh, input);
    check_rejects_trailing_garbage([&](std::istream& in) { format.read(in, source); }, input);
  }
  check_read_mesh(format, input, accepted, mesh, stream_error);
}

}  // namespace exactccd::fuzzing
