#include "io/mesh_formats.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <istream>
#include <iterator>
#include <map>
#include <streambuf>
#include <system_error>
#include <tuple>
#include <vector>

#include "io/decimal.hpp"
#include "io/lines.hpp"
#include "io/polygon.hpp"

namespace exactccd::io {
namespace {

using Words = std::vector<std::string>;

/// The rest of the stream: the binary formats are read from memory.
std::string slurp(std::istream& in) {
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Where the text of `data` starts: after a UTF-8 byte order mark, if it has one.
std::size_t text_start(const std::string& data) { return data.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0; }

/// A stream over bytes already in memory, without copying them: the lines of an ASCII STL file,
/// which read_stl holds whole to test its size first.
class BytesStream : private std::streambuf, public std::istream {
 public:
  explicit BytesStream(const std::string& bytes) : std::istream(this) {
    // A streambuf never writes into its get area (putting back another character fails).
    char* first = const_cast<char*>(bytes.data());
    setg(first, first, first + bytes.size());
  }
};

/// A decimal as a double (an optional leading '+'); `finite` requires a finite value. Errors
/// name the current line of `lines`.
double parse_double(const std::string& token, const LineReader& lines, const char* what, bool finite = true) {
  const char* first = token.data();
  const char* last = first + token.size();
  first = after_plus_sign(first, last);
  double value = 0;
  const auto [end, error] = std::from_chars(first, last, value);
  if (error == std::errc::result_out_of_range)
    lines.fail(std::string(what) + " '" + token + "' is out of the range of double");
  if (error != std::errc() || end != last) lines.fail(std::string(what) + " '" + token + "' is not a number");
  if (finite && !std::isfinite(value))
    lines.fail(std::string(what) + " '" + token + "' is not finite (NaN or infinity)");
  return value;
}

bool parse_integer(const std::string& token, long long& value) {
  const char* first = token.data();
  const char* last = first + token.size();
  first = after_plus_sign(first, last);
  const auto [end, error] = std::from_chars(first, last, value);
  return first != last && error == std::errc() && end == last;
}

/// A count (an element count, OFF's counts, a face's vertex count): digits with an optional
/// leading '+', never a minus sign ("-0" is no count, though from_chars reads it as 0).
bool parse_count(const std::string& token, long long& value) {
  return !token.empty() && token[0] != '-' && parse_integer(token, value) && value >= 0;
}

/// Checks a polygon (0-based indices) and appends its fan triangles; `fail(reason)` throws the
/// format's error (it says where).
template <class Fail>
void add_polygon(ObjMesh& mesh, const std::vector<long long>& poly, std::size_t vertex_count, Fail fail) {
  if (poly.size() < 3) fail("face with " + std::to_string(poly.size()) + " vertices (expected at least 3)");
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (poly[i] < 0 || static_cast<unsigned long long>(poly[i]) >= vertex_count)
      fail("face vertex index " + std::to_string(poly[i]) + " out of range (the file has " +
           std::to_string(vertex_count) + " vertices, indices from 0)");
  if (const auto repeated = first_repeated_vertex(poly))
    fail("degenerate face: vertex " + std::to_string(*repeated) + " appears twice");
  for (std::size_t i = 2; i < poly.size(); ++i)
    mesh.triangles.push_back({static_cast<int>(poly[0]), static_cast<int>(poly[i - 1]), static_cast<int>(poly[i])});
}

// ---------------------------------------------------------------------------------- PLY types

enum class PlyType { i8, u8, i16, u16, i32, u32, f32, f64 };

bool ply_type(const std::string& name, PlyType& t) {
  static const std::pair<const char*, PlyType> names[] = {
      {"char", PlyType::i8},    {"int8", PlyType::i8},     {"uchar", PlyType::u8},   {"uint8", PlyType::u8},
      {"short", PlyType::i16},  {"int16", PlyType::i16},   {"ushort", PlyType::u16}, {"uint16", PlyType::u16},
      {"int", PlyType::i32},    {"int32", PlyType::i32},   {"uint", PlyType::u32},   {"uint32", PlyType::u32},
      {"float", PlyType::f32},  {"float32", PlyType::f32}, {"double", PlyType::f64}, {"float64", PlyType::f64}};
  for (const auto& [n, type] : names)
    if (name == n) {
      t = type;
      return true;
    }
  return false;
}

std::size_t type_size(PlyType t) {
  switch (t) {
    case PlyType::i8: case PlyType::u8: return 1;
    case PlyType::i16: case PlyType::u16: return 2;
    case PlyType::i32: case PlyType::u32: case PlyType::f32: return 4;
    case PlyType::f64: return 8;
  }
  return 1;
}

bool is_float(PlyType t) { return t == PlyType::f32 || t == PlyType::f64; }

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::f64;  // the value type (a list's item type)
  bool list = false;
  PlyType count_type = PlyType::u8;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::size_t line = 0;
  std::vector<PlyProperty> properties;
};

/// A value read from the body: integer types in `i`, float types in `f` (floats widened).
struct PlyValue {
  long long i = 0;
  double f = 0;
};

/// The value of type t at p, in the given byte order (STL's binary numbers too).
PlyValue decode(const unsigned char* p, PlyType t, bool big_endian) {
  unsigned char b[8];
  const std::size_t n = type_size(t);
  for (std::size_t k = 0; k < n; ++k) b[k] = big_endian ? p[n - 1 - k] : p[k];  // little-endian in b
  std::uint64_t u = 0;
  for (std::size_t k = n; k-- > 0;) u = (u << 8) | b[k];
  PlyValue v;
  switch (t) {
    case PlyType::i8: v.i = static_cast<std::int8_t>(u); break;
    case PlyType::u8: v.i = static_cast<long long>(u); break;
    case PlyType::i16: v.i = static_cast<std::int16_t>(u); break;
    case PlyType::u16: v.i = static_cast<long long>(u); break;
    case PlyType::i32: v.i = static_cast<std::int32_t>(u); break;
    case PlyType::u32: v.i = static_cast<long long>(u); break;
    case PlyType::f32: {
      const auto bits = static_cast<std::uint32_t>(u);
      float x;
      std::memcpy(&x, &bits, 4);
      v.f = static_cast<double>(x);  // exact
      break;
    }
    case PlyType::f64: std::memcpy(&v.f, &u, 8); break;
  }
  return v;
}

/// An ASCII value of float type t (float: the float nearest the decimal, widened), or an error
/// message.
bool parse_ascii_float(const std::string& token, PlyType t, PlyValue& v, std::string& error) {
  const char* first = token.data();
  const char* last = first + token.size();
  first = after_plus_sign(first, last);
  std::errc ec;
  const char* end;
  if (t == PlyType::f32) {
    float x = 0;
    const auto r = std::from_chars(first, last, x);
    ec = r.ec;
    end = r.ptr;
    v.f = x;
  } else {
    const auto r = std::from_chars(first, last, v.f);
    ec = r.ec;
    end = r.ptr;
  }
  if (ec == std::errc::result_out_of_range) {
    error = "value '" + token + "' is out of the range of " + (t == PlyType::f32 ? "float" : "double");
    return false;
  }
  if (ec != std::errc() || end != last) {
    error = "value '" + token + "' is not a number";
    return false;
  }
  return true;
}

/// An ASCII value of integer type t, within the type's range, or an error message.
bool parse_ascii_integer(const std::string& token, PlyType t, PlyValue& v, std::string& error) {
  if (!parse_integer(token, v.i)) {
    error = "value '" + token + "' is not an integer";
    return false;
  }
  long long lo = 0, hi = 0;
  switch (t) {
    case PlyType::i8: lo = -128; hi = 127; break;
    case PlyType::u8: hi = 255; break;
    case PlyType::i16: lo = -32768; hi = 32767; break;
    case PlyType::u16: hi = 65535; break;
    case PlyType::i32: lo = INT32_MIN; hi = INT32_MAX; break;
    default: hi = UINT32_MAX; break;
  }
  if (v.i < lo || v.i > hi) {
    error = "value '" + token + "' is out of the range of its type";
    return false;
  }
  return true;
}

/// An ASCII value of type t, or an error message.
bool parse_ascii(const std::string& token, PlyType t, PlyValue& v, std::string& error) {
  return is_float(t) ? parse_ascii_float(token, t, v, error) : parse_ascii_integer(token, t, v, error);
}

// ---------------------------------------------------------------------------------- PLY header

enum class PlyFormat { none, ascii, little, big };

/// What the header declares: the body's encoding and its elements in order.
struct PlyHeader {
  PlyFormat format = PlyFormat::none;
  std::vector<PlyElement> elements;
};

/// `format ascii|binary_little_endian|binary_big_endian 1.0`, once.
void read_format_line(const Words& t, const LineReader& lines, PlyHeader& header) {
  if (header.format != PlyFormat::none) lines.fail("a second format line");
  if (t.size() != 3) lines.fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
  if (t[1] == "ascii") header.format = PlyFormat::ascii;
  else if (t[1] == "binary_little_endian") header.format = PlyFormat::little;
  else if (t[1] == "binary_big_endian") header.format = PlyFormat::big;
  else lines.fail("unknown PLY format '" + t[1] + "' (expected ascii, binary_little_endian or binary_big_endian)");
  if (t[2] != "1.0") lines.fail("unsupported PLY version '" + t[2] + "' (expected 1.0)");
}

/// `element NAME COUNT`, each name once.
void read_element_line(const Words& t, const LineReader& lines, PlyHeader& header) {
  long long count = 0;
  if (t.size() != 3 || !parse_count(t[2], count))
    lines.fail("expected 'element NAME COUNT' with COUNT a non-negative integer");
  for (const PlyElement& e : header.elements)
    if (e.name == t[1]) lines.fail("a second element '" + t[1] + "' (first on line " + std::to_string(e.line) + ")");
  header.elements.push_back({t[1], static_cast<std::uint64_t>(count), lines.line(), {}});
}

/// The property of `property TYPE NAME` or `property list COUNT_TYPE ITEM_TYPE NAME`.
PlyProperty property_of(const Words& t, const LineReader& lines) {
  PlyProperty p;
  if (t.size() >= 2 && t[1] == "list") {
    if (t.size() != 5) lines.fail("expected 'property list COUNT_TYPE ITEM_TYPE NAME'");
    if (!ply_type(t[2], p.count_type)) lines.fail("unknown property type '" + t[2] + "'");
    if (!ply_type(t[3], p.type)) lines.fail("unknown property type '" + t[3] + "'");
    if (is_float(p.count_type)) lines.fail("list count type '" + t[2] + "' is not an integer type");
    p.list = true;
    p.name = t[4];
  } else {
    if (t.size() != 3) lines.fail("expected 'property TYPE NAME'");
    if (!ply_type(t[1], p.type)) lines.fail("unknown property type '" + t[1] + "'");
    p.name = t[2];
  }
  return p;
}

/// A property of the last element, each name once per element.
void read_property_line(const Words& t, const LineReader& lines, PlyHeader& header) {
  if (header.elements.empty()) lines.fail("property before any element");
  PlyElement& element = header.elements.back();
  const PlyProperty p = property_of(t, lines);
  for (const PlyProperty& q : element.properties)
    if (q.name == p.name) lines.fail("a second property '" + p.name + "' in element '" + element.name + "'");
  element.properties.push_back(p);
}

/// One header line's words; true for end_header.
bool read_header_line(const Words& t, const LineReader& lines, PlyHeader& header) {
  if (t[0] == "comment" || t[0] == "obj_info") return false;
  if (t[0] == "end_header") {
    if (t.size() != 1) lines.fail("end_header followed by other words");
    return true;
  }
  if (t[0] == "format") read_format_line(t, lines, header);
  else if (t[0] == "element") read_element_line(t, lines, header);
  else if (t[0] == "property") read_property_line(t, lines, header);
  else lines.fail("unknown PLY header keyword '" + t[0] + "' (expected format, comment, obj_info, element, property or end_header)");
  return false;
}

/// The header, from the `ply` line to end_header (`lines` is then at the body).
PlyHeader read_ply_header(LineReader& lines) {
  std::string first;
  if (!lines.next(first) || first != "ply") throw ParseError(lines.source(), 1, "not a PLY file (the first line is not 'ply')");
  PlyHeader header;
  bool ended = false;
  for (Words t; !ended && lines.next_words(t);) ended = read_header_line(t, lines, header);
  if (!ended) lines.fail("the header has no end_header line");
  if (header.format == PlyFormat::none) lines.fail("the header has no format line");
  return header;
}

// ---------------------------------------------------------------------------------- PLY layout

/// Where the mesh is in the elements: the vertex element and its x, y, z properties, the face
/// element (or none) and its list of vertex indices.
struct PlyLayout {
  const PlyElement* vertex = nullptr;
  const PlyElement* face = nullptr;
  int xyz[3] = {-1, -1, -1};
  int indices = -1;
  /// Which coordinate property p of the vertex element holds (-1: none).
  int coordinate(const PlyElement& e, std::size_t p) const {
    if (&e != vertex) return -1;
    for (int c = 0; c < 3; ++c)
      if (static_cast<int>(p) == xyz[c]) return c;
    return -1;
  }
  /// Whether property p of element e is the face's vertex indices.
  bool is_indices(const PlyElement& e, std::size_t p) const { return &e == face && static_cast<int>(p) == indices; }
};

/// The vertex element's x, y and z: float or double, each there.
void find_coordinates(const PlyElement& vertex, const std::string& source, PlyLayout& layout) {
  for (std::size_t i = 0; i < vertex.properties.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (vertex.properties[i].name == std::string(1, "xyz"[c])) {
        if (vertex.properties[i].list || !is_float(vertex.properties[i].type))
          throw ParseError(source, vertex.line, std::string("vertex property ") + "xyz"[c] + " is not of type float or double");
        layout.xyz[c] = static_cast<int>(i);
      }
  for (int c = 0; c < 3; ++c)
    if (layout.xyz[c] < 0) throw ParseError(source, vertex.line, std::string("the vertex element has no property ") + "xyz"[c]);
}

/// The face element's list of integer vertex indices (vertex_indices or vertex_index).
void find_indices(const PlyElement& face, const std::string& source, PlyLayout& layout) {
  for (std::size_t i = 0; i < face.properties.size(); ++i)
    if (face.properties[i].name == "vertex_indices" || face.properties[i].name == "vertex_index") {
      if (!face.properties[i].list || is_float(face.properties[i].type))
        throw ParseError(source, face.line, "face property " + face.properties[i].name + " is not a list of integers");
      layout.indices = static_cast<int>(i);
    }
  if (layout.indices < 0) throw ParseError(source, face.line, "the face element has no list property vertex_indices");
}

/// Which elements and properties hold the mesh; errors name the element's line (or, for a
/// missing vertex element, the last header line).
PlyLayout find_layout(const PlyHeader& header, const LineReader& lines) {
  PlyLayout layout;
  for (const PlyElement& e : header.elements) {
    if (e.name == "vertex") layout.vertex = &e;
    if (e.name == "face") layout.face = &e;
  }
  if (!layout.vertex) lines.fail("no 'vertex' element in the header");
  if (layout.vertex->count > static_cast<std::uint64_t>(INT_MAX))
    throw ParseError(lines.source(), layout.vertex->line, "more than INT_MAX vertices");
  find_coordinates(*layout.vertex, lines.source(), layout);
  if (layout.face) find_indices(*layout.face, lines.source(), layout);
  return layout;
}

// ---------------------------------------------------------------------------------- PLY ASCII body

/// The faces of an ASCII body, kept until every vertex is read, with their lines.
struct PlyAsciiFaces {
  std::vector<std::vector<long long>> faces;
  std::vector<std::size_t> lines;
};

/// The values of one ASCII element line, taken in order.
class AsciiValues {
 public:
  AsciiValues(const Words& t, const LineReader& lines, const PlyElement& e) : t_(t), lines_(lines), e_(e) {}
  /// The next value, of type `type`; `what` names it in errors.
  PlyValue take(PlyType type, const std::string& what) {
    if (at_ >= t_.size()) lines_.fail("too few values for element '" + e_.name + "' (" + what + " missing)");
    PlyValue v;
    std::string error;
    if (!parse_ascii(t_[at_], type, v, error)) lines_.fail(what + ": " + error);
    ++at_;
    return v;
  }
  /// The word of the last value taken.
  const std::string& last() const { return t_[at_ - 1]; }
  /// Throws unless every value was taken.
  void check_all_taken() const {
    if (at_ != t_.size())
      lines_.fail("too many values for element '" + e_.name + "' (" + std::to_string(t_.size()) + ", expected " +
                  std::to_string(at_) + ")");
  }

 private:
  const Words& t_;
  const LineReader& lines_;
  const PlyElement& e_;
  std::size_t at_ = 0;
};

/// A list property's values; the face's vertex indices are kept in `faces`.
void read_ascii_list(AsciiValues& values, const PlyProperty& prop, bool keep, const LineReader& lines,
                     PlyAsciiFaces& faces) {
  const long long count = values.take(prop.count_type, "the count of list " + prop.name).i;
  if (count < 0) lines.fail("negative count of list " + prop.name);
  std::vector<long long> poly;
  for (long long j = 0; j < count; ++j) {
    const PlyValue v = values.take(prop.type, "item of list " + prop.name);
    if (keep) poly.push_back(v.i);
  }
  if (!keep) return;
  faces.faces.push_back(std::move(poly));
  faces.lines.push_back(lines.line());
}

/// One element's line: its properties in order, a vertex's position appended to the mesh.
void read_ascii_record(const Words& t, const LineReader& lines, const PlyElement& e, const PlyLayout& layout,
                       ObjMesh& mesh, PlyAsciiFaces& faces) {
  AsciiValues values(t, lines, e);
  Vec3 position{0, 0, 0};
  for (std::size_t p = 0; p < e.properties.size(); ++p) {
    const PlyProperty& prop = e.properties[p];
    if (prop.list) {
      read_ascii_list(values, prop, layout.is_indices(e, p), lines, faces);
      continue;
    }
    const PlyValue v = values.take(prop.type, "property " + prop.name);
    const int c = layout.coordinate(e, p);
    if (c < 0) continue;
    if (!std::isfinite(v.f)) lines.fail("coordinate " + prop.name + " '" + values.last() + "' is not finite");
    (c == 0 ? position.x : c == 1 ? position.y : position.z) = v.f;
  }
  values.check_all_taken();
  if (&e == layout.vertex) mesh.vertices.push_back(position);
}

/// An ASCII body: one line per element, nothing after the last; the faces checked at the end.
void read_ascii_body(LineReader& lines, const PlyHeader& header, const PlyLayout& layout, ObjMesh& mesh) {
  PlyAsciiFaces faces;
  Words t;
  for (const PlyElement& e : header.elements) {
    if (e.properties.empty()) continue;
    for (std::uint64_t k = 0; k < e.count; ++k) {
      if (!lines.next_words(t))
        lines.fail("the file ends after " + std::to_string(k) + " of the " + std::to_string(e.count) + " '" + e.name +
                   "' elements");
      read_ascii_record(t, lines, e, layout, mesh, faces);
    }
  }
  if (lines.next_words(t)) lines.fail("data after the last element (wrong element counts in the header?)");
  for (std::size_t i = 0; i < faces.faces.size(); ++i)
    add_polygon(mesh, faces.faces[i], mesh.vertices.size(),
                [&](const std::string& why) { throw ParseError(lines.source(), faces.lines[i], why); });
}

// ---------------------------------------------------------------------------------- PLY binary body

/// The bytes of a binary body, read in order; errors give the byte offset in the stream.
class BinaryBody {
 public:
  /// `bytes` start at byte `base` of the stream (after the header).
  BinaryBody(const std::string& bytes, std::size_t base, bool big_endian, const std::string& source)
      : bytes_(bytes), base_(base), big_(big_endian), source_(source) {}
  /// The stream offset of the next byte.
  std::size_t at() const { return base_ + read_; }
  /// The bytes left.
  std::size_t left() const { return bytes_.size() - read_; }
  /// The next value of type `type`; `where` (a function giving the text) names it in errors.
  template <class Where>
  PlyValue read(PlyType type, const Where& where) {
    const std::size_t n = type_size(type);
    if (left() < n)
      fail(at(), where(), "truncated: the file ends " + std::to_string(left()) + " bytes into a " + std::to_string(n) +
                              "-byte value (wrong counts in the header?)");
    const PlyValue v = decode(reinterpret_cast<const unsigned char*>(bytes_.data()) + read_, type, big_);
    read_ += n;
    return v;
  }
  /// Skips `count` bytes (or throws at the end of the file).
  template <class Where>
  void skip(std::uint64_t count, const Where& where) {
    if (left() < count) fail(at(), where(), "truncated: the file ends inside the list");
    read_ += static_cast<std::size_t>(count);
  }
  /// Throws InputError "<source>: byte offset <offset> (<where>): <why>".
  [[noreturn]] void fail(std::size_t offset, const std::string& where, const std::string& why) const {
    throw InputError(source_, "byte offset " + std::to_string(offset) + " (" + where + "): " + why);
  }

 private:
  const std::string& bytes_;
  std::size_t base_;
  std::size_t read_ = 0;
  bool big_;
  const std::string& source_;
};

/// A list property: the face's vertex indices checked and triangulated, any other list skipped.
template <class Where>
void read_binary_list(BinaryBody& body, const PlyProperty& prop, bool keep, const Where& where,
                      std::size_t vertex_count, ObjMesh& mesh) {
  const std::size_t at = body.at();
  const long long count = body.read(prop.count_type, where).i;
  if (count < 0) body.fail(at, where(), "negative list count " + std::to_string(count));
  if (!keep) {
    body.skip(static_cast<std::uint64_t>(count) * type_size(prop.type), where);
    return;
  }
  std::vector<long long> poly;
  for (long long j = 0; j < count; ++j) poly.push_back(body.read(prop.type, where).i);
  add_polygon(mesh, poly, vertex_count, [&](const std::string& why) { body.fail(at, where(), why); });
}

/// Element k of e: its properties in order, a vertex's position appended to the mesh.
void read_binary_record(BinaryBody& body, const PlyElement& e, std::uint64_t k, const PlyLayout& layout, ObjMesh& mesh) {
  Vec3 position{0, 0, 0};
  for (std::size_t p = 0; p < e.properties.size(); ++p) {
    const PlyProperty& prop = e.properties[p];
    const auto where = [&] {
      return e.name + " " + std::to_string(k) + " of " + std::to_string(e.count) + ", property " + prop.name;
    };
    if (prop.list) {
      read_binary_list(body, prop, layout.is_indices(e, p), where, layout.vertex->count, mesh);
      continue;
    }
    const std::size_t at = body.at();
    const PlyValue v = body.read(prop.type, where);
    const int c = layout.coordinate(e, p);
    if (c < 0) continue;
    if (!std::isfinite(v.f)) body.fail(at, where(), "coordinate is not finite (NaN or infinity)");
    (c == 0 ? position.x : c == 1 ? position.y : position.z) = v.f;
  }
  if (&e == layout.vertex) mesh.vertices.push_back(position);
}

/// A binary body: every element's records, and not a byte more.
void read_binary_body(BinaryBody& body, const PlyHeader& header, const PlyLayout& layout, ObjMesh& mesh) {
  for (const PlyElement& e : header.elements) {
    if (e.properties.empty()) continue;
    for (std::uint64_t k = 0; k < e.count; ++k) read_binary_record(body, e, k, layout, mesh);
  }
  if (body.left() != 0)
    body.fail(body.at(), "end of the last element",
              std::to_string(body.left()) + " bytes of data after the last element (wrong element counts in the header?)");
}

}  // namespace

ObjMesh read_ply(std::istream& in, const std::string& source) {
  LineReader lines(in, source);  // binary offsets count from byte 0, the byte order mark too
  const PlyHeader header = read_ply_header(lines);
  const PlyLayout layout = find_layout(header, lines);
  ObjMesh mesh;
  if (header.format == PlyFormat::ascii) {
    read_ascii_body(lines, header, layout, mesh);
    return mesh;
  }
  const std::string bytes = slurp(in);
  BinaryBody body(bytes, lines.offset(), header.format == PlyFormat::big, source);
  read_binary_body(body, header, layout, mesh);
  return mesh;
}

// ---------------------------------------------------------------------------------- OFF

namespace {

/// How many numbers follow x y z on an OFF vertex line (the keyword's ST, C and N prefixes).
struct OffExtras {
  std::size_t least = 0, most = 0;
};

/// The keyword (the first word of `t`, then erased): OFF with its prefixes; 4OFF, nOFF and binary
/// OFF refused.
OffExtras read_off_keyword(Words& t, const LineReader& lines) {
  const std::string keyword = t[0];
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
    lines.fail("not an OFF file (the first word is '" + keyword + "')");
  const std::string prefix = keyword.substr(0, keyword.size() - 3);
  if (prefix.find('4') != std::string::npos || prefix.find('n') != std::string::npos)
    lines.fail("'" + keyword + "': OFF of another dimension than 3 is not supported");
  OffExtras extras;
  std::string rest = prefix;
  if (rest.rfind("ST", 0) == 0) { extras.least += 2; extras.most += 2; rest = rest.substr(2); }
  if (rest.rfind("C", 0) == 0) { extras.least += 3; extras.most += 4; rest = rest.substr(1); }
  if (rest.rfind("N", 0) == 0) { extras.least += 3; extras.most += 3; rest = rest.substr(1); }
  if (!rest.empty()) lines.fail("unknown OFF keyword '" + keyword + "'");
  t.erase(t.begin());
  if (!t.empty() && t[0] == "BINARY") lines.fail("binary OFF is not supported");
  return extras;
}

struct OffCounts {
  long long vertices = 0, faces = 0;
};

/// The counts `nv nf [ne]`: the rest of the keyword's line, or the next line with words.
OffCounts read_off_counts(Words& t, LineReader& lines) {
  if (t.empty() && !lines.next_words(t)) lines.fail("the file ends before the counts line");
  OffCounts counts;
  long long edges = 0;
  if (t.size() < 2 || t.size() > 3 || !parse_count(t[0], counts.vertices) || !parse_count(t[1], counts.faces) ||
      (t.size() == 3 && !parse_count(t[2], edges)))
    lines.fail("expected the counts 'vertices faces [edges]' (non-negative integers)");
  if (counts.vertices > INT_MAX) lines.fail("more than INT_MAX vertices");
  return counts;
}

/// A vertex line: x y z and the keyword's extra numbers (checked, then ignored).
void read_off_vertex(const Words& t, const LineReader& lines, const OffExtras& extras, ObjMesh& mesh) {
  if (t.size() < 3 + extras.least || t.size() > 3 + extras.most)
    lines.fail("vertex with " + std::to_string(t.size()) + " numbers (expected " + std::to_string(3 + extras.least) +
               (extras.most != extras.least ? " to " + std::to_string(3 + extras.most) : "") + ")");
  for (std::size_t k = 3; k < t.size(); ++k) parse_double(t[k], lines, "value", false);
  mesh.vertices.push_back({parse_double(t[0], lines, "coordinate"), parse_double(t[1], lines, "coordinate"),
                           parse_double(t[2], lines, "coordinate")});
}

/// A face line: `n i0 ... i(n-1)` and at most a 4-number colour; the polygon fan-triangulated.
void read_off_face(const Words& t, const LineReader& lines, ObjMesh& mesh) {
  long long count = 0;
  if (!parse_count(t[0], count)) lines.fail("the face's vertex count '" + t[0] + "' is not a non-negative integer");
  if (t.size() < static_cast<std::size_t>(count) + 1 || t.size() > static_cast<std::size_t>(count) + 5)
    lines.fail("face of " + std::to_string(count) + " vertices with " + std::to_string(t.size() - 1) +
               " numbers (expected the indices and at most a 4-number colour)");
  std::vector<long long> poly;
  for (long long k = 1; k <= count; ++k) {
    long long v = 0;
    if (!parse_integer(t[static_cast<std::size_t>(k)], v))
      lines.fail("face vertex index '" + t[static_cast<std::size_t>(k)] + "' is not an integer");
    poly.push_back(v);
  }
  for (std::size_t k = static_cast<std::size_t>(count) + 1; k < t.size(); ++k) parse_double(t[k], lines, "colour value");
  add_polygon(mesh, poly, mesh.vertices.size(), [&](const std::string& why) { lines.fail(why); });
}

}  // namespace

ObjMesh read_off(std::istream& in, const std::string& source) {
  LineReader lines(in, source, '#');
  Words t;
  // Line 1 for an empty file (it has no line; ParseError lines are 1-based).
  if (!lines.next_words(t)) throw ParseError(source, std::max<std::size_t>(lines.line(), 1), "empty OFF file");
  const OffExtras extras = read_off_keyword(t, lines);
  const OffCounts counts = read_off_counts(t, lines);
  ObjMesh mesh;
  for (long long i = 0; i < counts.vertices; ++i) {
    if (!lines.next_words(t))
      lines.fail("the file ends after " + std::to_string(i) + " of the " + std::to_string(counts.vertices) + " vertices");
    read_off_vertex(t, lines, extras, mesh);
  }
  for (long long i = 0; i < counts.faces; ++i) {
    if (!lines.next_words(t))
      lines.fail("the file ends after " + std::to_string(i) + " of the " + std::to_string(counts.faces) + " faces");
    read_off_face(t, lines, mesh);
  }
  if (lines.next_words(t)) lines.fail("data after the last face (wrong counts?)");
  return mesh;
}

// ---------------------------------------------------------------------------------- STL

namespace {

/// Merges corners by exact coordinates (== on each; -0 and +0 are equal).
class CornerMerger {
 public:
  explicit CornerMerger(ObjMesh& mesh) : mesh_(mesh) {}
  int add(const Vec3& p) {
    // Keys with +0 for -0: operator< treats them as equal anyway.
    const auto key = std::make_tuple(p.x, p.y, p.z);
    const auto [it, inserted] = index_.emplace(key, static_cast<int>(mesh_.vertices.size()));
    if (inserted) mesh_.vertices.push_back(p);
    return it->second;
  }

 private:
  ObjMesh& mesh_;
  std::map<std::tuple<double, double, double>, int> index_;
};

bool has_equal_corners(const std::array<int, 3>& tri) {
  return tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2];
}

/// The facet count in a binary STL's header (bytes 80 to 83; data.size() >= 84).
std::uint64_t binary_facet_count(const std::string& data) {
  return static_cast<std::uint64_t>(decode(reinterpret_cast<const unsigned char*>(data.data()) + 80, PlyType::u32, false).i);
}

/// Whether `data` is a binary STL: exactly 84 + 50 * (its facet count) bytes.
bool is_binary_stl(const std::string& data) {
  return data.size() >= 84 && data.size() == 84 + 50 * binary_facet_count(data);
}

/// Corner c of binary facet f (its record at byte `at`): three finite float32 coordinates.
Vec3 binary_corner(const std::string& data, std::size_t at, int c, std::uint64_t f, const std::string& source) {
  Vec3 p;
  double* xyz[3] = {&p.x, &p.y, &p.z};
  for (int k = 0; k < 3; ++k) {
    const std::size_t o = at + 12 + 12 * static_cast<std::size_t>(c) + 4 * static_cast<std::size_t>(k);
    *xyz[k] = decode(reinterpret_cast<const unsigned char*>(data.data()) + o, PlyType::f32, false).f;
    if (!std::isfinite(*xyz[k]))
      throw InputError(source, "byte offset " + std::to_string(o) + " (facet " + std::to_string(f) +
                                   "): coordinate is not finite (NaN or infinity)");
  }
  return p;
}

/// The facets of a binary STL (is_binary_stl), each a triangle of merged corners.
void read_binary_stl(const std::string& data, const std::string& source, ObjMesh& mesh) {
  CornerMerger merge(mesh);
  const std::uint64_t n = binary_facet_count(data);
  for (std::uint64_t f = 0; f < n; ++f) {
    const std::size_t at = static_cast<std::size_t>(84 + 50 * f);
    std::array<int, 3> tri{};
    for (int c = 0; c < 3; ++c) tri[static_cast<std::size_t>(c)] = merge.add(binary_corner(data, at, c, f, source));
    if (has_equal_corners(tri))
      throw InputError(source, "byte offset " + std::to_string(at) + " (facet " + std::to_string(f) +
                                   "): degenerate facet: two corners are equal");
    mesh.triangles.push_back(tri);
  }
}

/// Throws unless `data` (no binary STL) starts as an ASCII STL, with "solid".
void check_ascii_stl_start(const std::string& data, const std::string& source) {
  if (data.compare(text_start(data), 5, "solid") == 0) return;
  if (data.size() >= 84)
    throw InputError(source, "byte offset 80: binary STL of " + std::to_string(binary_facet_count(data)) +
                                 " facets needs " + std::to_string(84 + 50 * binary_facet_count(data)) +
                                 " bytes, the file has " + std::to_string(data.size()) + " (truncated or extended)");
  throw InputError(source, "byte offset 0: neither ASCII STL ('solid') nor binary STL (shorter than 84 bytes)");
}

/// An ASCII STL's keyword stream, one line's words at a time:
/// solid (facet normal N N N / outer loop / vertex X Y Z (x3) / endloop / endfacet)* endsolid.
class AsciiStl {
 public:
  AsciiStl(const LineReader& lines, ObjMesh& mesh) : lines_(lines), mesh_(mesh), merge_(mesh) {}
  /// The next line's words, in the state the previous lines left.
  void read(const Words& t) {
    switch (state_) {
      case State::solid: solid(t); break;
      case State::facet_or_end: facet_or_end(t); break;
      case State::outer: outer(t); break;
      case State::vertex: vertex(t); break;
      case State::endloop: endloop(t); break;
      case State::endfacet: endfacet(t); break;
      case State::done: lines_.fail("data after 'endsolid'");
    }
  }
  /// Whether endsolid was read.
  bool done() const { return state_ == State::done; }

 private:
  enum class State { solid, facet_or_end, outer, vertex, endloop, endfacet, done };

  [[noreturn]] void expected(const Words& t, const char* what) const {
    lines_.fail("expected " + std::string(what) + ", found '" + t[0] + "'");
  }
  void solid(const Words& t) {
    if (t[0] != "solid") expected(t, "'solid'");
    state_ = State::facet_or_end;
  }
  void facet_or_end(const Words& t) {
    if (t[0] == "endsolid") {
      state_ = State::done;
      return;
    }
    if (t[0] != "facet") expected(t, "'facet' or 'endsolid'");
    if (t.size() != 5 || t[1] != "normal") lines_.fail("expected 'facet normal NX NY NZ'");
    for (std::size_t k = 2; k < 5; ++k) parse_double(t[k], lines_, "normal component", false);
    state_ = State::outer;
  }
  void outer(const Words& t) {
    if (t.size() != 2 || t[0] != "outer" || t[1] != "loop") expected(t, "'outer loop'");
    state_ = State::vertex;
    corner_ = 0;
  }
  void vertex(const Words& t) {
    if (t[0] != "vertex") expected(t, "'vertex'");
    if (t.size() != 4) lines_.fail("expected 'vertex X Y Z'");
    const Vec3 p{parse_double(t[1], lines_, "coordinate"), parse_double(t[2], lines_, "coordinate"),
                 parse_double(t[3], lines_, "coordinate")};
    tri_[static_cast<std::size_t>(corner_)] = merge_.add(p);
    if (++corner_ == 3) state_ = State::endloop;
  }
  void endloop(const Words& t) {
    if (t.size() != 1 || t[0] != "endloop") expected(t, "'endloop' (a facet has three vertices)");
    state_ = State::endfacet;
  }
  void endfacet(const Words& t) {
    if (t.size() != 1 || t[0] != "endfacet") expected(t, "'endfacet'");
    if (has_equal_corners(tri_)) lines_.fail("degenerate facet: two corners are equal");
    mesh_.triangles.push_back(tri_);
    state_ = State::facet_or_end;
  }

  const LineReader& lines_;
  ObjMesh& mesh_;
  CornerMerger merge_;
  State state_ = State::solid;
  std::array<int, 3> tri_{};
  int corner_ = 0;
};

}  // namespace

ObjMesh read_stl(std::istream& in, const std::string& source) {
  const std::string data = slurp(in);
  ObjMesh mesh;
  if (is_binary_stl(data)) {  // the size test first, on the bytes as they are
    read_binary_stl(data, source, mesh);
    return mesh;
  }
  check_ascii_stl_start(data, source);
  BytesStream text(data);
  LineReader lines(text, source);
  AsciiStl stl(lines, mesh);
  for (Words t; lines.next_words(t);) stl.read(t);
  if (!stl.done()) lines.fail("the file ends before 'endsolid'");
  return mesh;
}

}  // namespace exactccd::io
