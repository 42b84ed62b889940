#include "io/mesh_file.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <istream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "io/input_file.hpp"
#include "io/mesh_formats.hpp"

namespace exactccd::io {
namespace {

/// The first bytes of a file, as they are (`raw`) and after a UTF-8 byte order mark (`bytes`:
/// the text the text tests look at), and the file's size when known. A binary STL's 80-byte
/// header is free, so it may start with the bytes of a mark: its test looks at the raw bytes.
struct FilePrefix {
  std::string raw;
  std::string bytes;
  std::optional<std::uintmax_t> size;
  std::string first_word;  ///< after blank space and `#` comment lines, however long (first_word_of)
};

constexpr std::size_t kPrefixBytes = 4096;
const std::string kByteOrderMark = "\xEF\xBB\xBF";  // UTF-8

bool starts_with(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

/// "ply" on its own first line.
bool is_ply(const FilePrefix& p) {
  return starts_with(p.bytes, "ply\n") || starts_with(p.bytes, "ply\r") || p.bytes == "ply";
}

/// The first word of `in`, after blank space and `#` comments (as read_off reads them: a `#`
/// where a word would start comments out the rest of its line), at most 16 characters, read as
/// a stream: a comment may be longer than the prefix (a 5 kB first comment once made an OFF
/// file "not OFF"; found by fuzz_read_off).
std::string first_word_of(std::istream& in) {
  const auto space = [](int c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; };
  for (int c = in.get(); c != std::char_traits<char>::eof(); c = in.get()) {
    if (space(c)) continue;
    if (c == '#') {
      in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
      continue;
    }
    std::string word(1, static_cast<char>(c));
    for (c = in.peek(); word.size() < 16 && c != std::char_traits<char>::eof() && !space(c) && c != '#'; c = in.peek())
      word += static_cast<char>(in.get());
    return word;
  }
  return {};
}

/// The first word, after blank lines and `#` comments, is OFF with its optional prefixes (ST, C,
/// N, 4, n: e.g. COFF, NOFF, STOFF).
bool is_off(const FilePrefix& p) {
  const std::string& word = p.first_word;
  if (word.size() < 3 || word.size() > 8 || word.compare(word.size() - 3, 3, "OFF") != 0) return false;
  return std::all_of(word.begin(), word.end() - 3, [](char c) { return std::string("STCN4n").find(c) != std::string::npos; });
}

/// A binary STL: an 80-byte header, a little-endian triangle count n, then n 50-byte records.
bool is_binary_stl(const FilePrefix& p) {
  if (!p.size || p.raw.size() < 84) return false;
  std::uint64_t n = 0;
  for (int i = 3; i >= 0; --i) n = n * 256 + static_cast<unsigned char>(p.raw[80 + static_cast<std::size_t>(i)]);
  return *p.size == 84 + 50 * n;
}

/// An ASCII STL: "solid" as the first word.
bool is_ascii_stl(const FilePrefix& p) {
  return starts_with(p.bytes, "solid") && (p.bytes.size() == 5 || std::isspace(static_cast<unsigned char>(p.bytes[5])));
}

bool is_stl(const FilePrefix& p) { return is_binary_stl(p) || is_ascii_stl(p); }

/// Bytes that no text file holds (NUL and most control characters).
bool is_binary(const FilePrefix& p) {
  return std::any_of(p.bytes.begin(), p.bytes.end(), [](char ch) {
    const auto c = static_cast<unsigned char>(ch);
    return c == 0 || (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v');
  });
}

/// Text: anything that is no other format is read as OBJ, whose strict reader names the
/// first line that is not OBJ (file:line).
bool is_obj(const FilePrefix& p) { return !is_binary(p); }

/// One recognised format: its name, extensions, content test and reader (nullptr: recognised
/// but not read yet; a reader for it plugs in here).
struct FormatEntry {
  MeshFormat format;
  const char* name;
  std::vector<std::string> extensions;  // lower case, with the dot
  bool (*content_matches)(const FilePrefix&);
  TriangleMesh (*read)(std::istream&, const std::string& source);
};

const std::vector<FormatEntry>& formats() {
  static const std::vector<FormatEntry> table = {
      // The specific magic words first: OBJ, the most permissive test, comes last.
      {MeshFormat::ply, "PLY", {".ply"}, is_ply, read_ply},
      {MeshFormat::stl, "STL", {".stl"}, is_stl, read_stl},
      {MeshFormat::off, "OFF", {".off"}, is_off, read_off},
      {MeshFormat::obj, "OBJ", {".obj"}, is_obj, read_obj},
  };
  return table;
}

const FormatEntry& entry(MeshFormat format) {
  for (const FormatEntry& e : formats())
    if (e.format == format) return e;
  return formats().back();
}

std::string known_extensions() {
  std::string out;
  for (const FormatEntry& e : formats())
    for (const std::string& x : e.extensions) out += (out.empty() ? "" : ", ") + x;
  return out;
}

FilePrefix read_prefix(const std::string& path) {
  InputFile file(path, ByteOrderMark::keep);
  FilePrefix p;
  p.raw.resize(kPrefixBytes);
  file.stream().read(p.raw.data(), static_cast<std::streamsize>(kPrefixBytes));
  p.raw.resize(static_cast<std::size_t>(file.stream().gcount()));
  file.check_read();
  p.bytes = starts_with(p.raw, kByteOrderMark) ? p.raw.substr(kByteOrderMark.size()) : p.raw;
  InputFile words(path, ByteOrderMark::skip);
  p.first_word = first_word_of(words.stream());
  words.check_read();
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec) p.size = size;
  return p;
}

}  // namespace

const char* mesh_format_name(MeshFormat format) { return entry(format).name; }

MeshFormat detect_mesh_format(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const FormatEntry* by_name = nullptr;
  for (const FormatEntry& e : formats())
    if (std::find(e.extensions.begin(), e.extensions.end(), extension) != e.extensions.end()) by_name = &e;
  const FilePrefix prefix = read_prefix(path);  // opening errors come first (missing, directory)
  if (!by_name)
    throw InputError(path, (extension.empty() ? std::string("no file extension")
                                              : "unknown mesh file extension '" + extension + "'") +
                               " (expected " + known_extensions() + ")");
  // The extension's format first when its test is specific: a binary STL's free 80-byte header
  // may begin with another format's magic word ("ply", "OFF"). OBJ's test (text) is not
  // specific: a PLY or OFF file named .obj is reported as what it is.
  if (by_name->format != MeshFormat::obj && by_name->content_matches(prefix)) return by_name->format;
  for (const FormatEntry& e : formats()) {
    if (!e.content_matches(prefix)) continue;
    if (&e == by_name) return e.format;
    // Another format's magic word (or binary STL size), or plain text where a binary or
    // magic-word format was expected.
    if (e.format != MeshFormat::obj)
      throw InputError(path, std::string("the content is ") + e.name + ", but the extension says " + by_name->name);
    break;
  }
  throw InputError(path, std::string("the content is not ") + by_name->name + " (" +
                             (is_binary(prefix) ? "binary data" : "text without the " + std::string(by_name->name) + " header") +
                             ")");
}

TriangleMesh read_mesh(const std::string& path) {
  const FormatEntry& format = entry(detect_mesh_format(path));
  if (!format.read) throw InputError(path, std::string(format.name) + " meshes are not supported yet (convert to OBJ)");
  // The readers skip a byte order mark where their content is text (a binary STL's header may
  // start with its bytes), so that a binary file's byte offsets in errors are the file's.
  InputFile file(path, ByteOrderMark::keep);
  TriangleMesh mesh = format.read(file.stream(), path);
  file.check_read();
  if (mesh.vertices.empty()) throw InputError(path, "no vertices (an empty mesh)");
  if (mesh.triangles.empty()) throw InputError(path, "no faces (a mesh needs at least one triangle)");
  return mesh;
}

}  // namespace exactccd::io
