#include "io/mesh_formats.hpp"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <istream>
#include <iterator>
#include <map>
#include <sstream>
#include <system_error>
#include <tuple>
#include <vector>

#include "io/decimal.hpp"
#include "io/polygon.hpp"

namespace exactccd::io {
namespace {

std::string slurp(std::istream& in) {
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Where the text of `data` starts: after a UTF-8 byte order mark, if it has one.
std::size_t text_start(const std::string& data) { return data.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0; }

std::vector<std::string> split(const std::string& line) {
  std::istringstream ss(line);
  std::vector<std::string> out;
  for (std::string t; ss >> t;) out.push_back(t);
  return out;
}

/// Lines of a text with their 1-based numbers, CR stripped.
class LineReader {
 public:
  LineReader(const std::string& text, std::size_t pos = 0, std::size_t first_line = 1)
      : text_(text), pos_(pos), line_(first_line - 1) {}
  bool next(std::string& line) {
    if (pos_ >= text_.size()) return false;
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    line = text_.substr(pos_, end - pos_);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    pos_ = end + 1;
    ++line_;
    return true;
  }
  std::size_t line() const { return line_; }
  std::size_t pos() const { return pos_; }

 private:
  const std::string& text_;
  std::size_t pos_;
  std::size_t line_;
};

/// A decimal as a double (an optional leading '+'); `finite` requires a finite value.
double parse_double(const std::string& token, const std::string& source, std::size_t line, const char* what,
                    bool finite = true) {
  const char* first = token.data();
  const char* last = first + token.size();
  first = after_plus_sign(first, last);
  double value = 0;
  const auto [end, error] = std::from_chars(first, last, value);
  if (error == std::errc::result_out_of_range)
    throw ParseError(source, line, std::string(what) + " '" + token + "' is out of the range of double");
  if (error != std::errc() || end != last)
    throw ParseError(source, line, std::string(what) + " '" + token + "' is not a number");
  if (finite && !std::isfinite(value))
    throw ParseError(source, line, std::string(what) + " '" + token + "' is not finite (NaN or infinity)");
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

/// Checks a polygon (0-based indices) and appends its fan triangles. `where` prefixes errors.
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

// ---------------------------------------------------------------------------------- PLY

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

/// An ASCII value of type t, or an error message.
bool parse_ascii(const std::string& token, PlyType t, PlyValue& v, std::string& error) {
  if (is_float(t)) {
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

}  // namespace

ObjMesh read_ply(std::istream& in, const std::string& source) {
  const std::string data = slurp(in);
  LineReader lines(data, text_start(data));  // binary offsets count from byte 0, the mark too
  std::string line;
  if (!lines.next(line) || line != "ply") throw ParseError(source, 1, "not a PLY file (the first line is not 'ply')");
  enum class Format { none, ascii, little, big } format = Format::none;
  std::vector<PlyElement> elements;
  bool ended = false;
  while (lines.next(line)) {
    const std::size_t n = lines.line();
    const std::vector<std::string> t = split(line);
    if (t.empty()) continue;
    if (t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "end_header") {
      if (t.size() != 1) throw ParseError(source, n, "end_header followed by other words");
      ended = true;
      break;
    }
    if (t[0] == "format") {
      if (format != Format::none) throw ParseError(source, n, "a second format line");
      if (t.size() != 3) throw ParseError(source, n, "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      if (t[1] == "ascii") format = Format::ascii;
      else if (t[1] == "binary_little_endian") format = Format::little;
      else if (t[1] == "binary_big_endian") format = Format::big;
      else throw ParseError(source, n, "unknown PLY format '" + t[1] + "' (expected ascii, binary_little_endian or binary_big_endian)");
      if (t[2] != "1.0") throw ParseError(source, n, "unsupported PLY version '" + t[2] + "' (expected 1.0)");
      continue;
    }
    if (t[0] == "element") {
      long long count = 0;
      if (t.size() != 3 || !parse_count(t[2], count))
        throw ParseError(source, n, "expected 'element NAME COUNT' with COUNT a non-negative integer");
      for (const PlyElement& e : elements)
        if (e.name == t[1]) throw ParseError(source, n, "a second element '" + t[1] + "' (first on line " + std::to_string(e.line) + ")");
      elements.push_back({t[1], static_cast<std::uint64_t>(count), n, {}});
      continue;
    }
    if (t[0] == "property") {
      if (elements.empty()) throw ParseError(source, n, "property before any element");
      PlyProperty p;
      if (t.size() >= 2 && t[1] == "list") {
        if (t.size() != 5) throw ParseError(source, n, "expected 'property list COUNT_TYPE ITEM_TYPE NAME'");
        if (!ply_type(t[2], p.count_type)) throw ParseError(source, n, "unknown property type '" + t[2] + "'");
        if (!ply_type(t[3], p.type)) throw ParseError(source, n, "unknown property type '" + t[3] + "'");
        if (is_float(p.count_type)) throw ParseError(source, n, "list count type '" + t[2] + "' is not an integer type");
        p.list = true;
        p.name = t[4];
      } else {
        if (t.size() != 3) throw ParseError(source, n, "expected 'property TYPE NAME'");
        if (!ply_type(t[1], p.type)) throw ParseError(source, n, "unknown property type '" + t[1] + "'");
        p.name = t[2];
      }
      for (const PlyProperty& q : elements.back().properties)
        if (q.name == p.name) throw ParseError(source, n, "a second property '" + p.name + "' in element '" + elements.back().name + "'");
      elements.back().properties.push_back(p);
      continue;
    }
    throw ParseError(source, n, "unknown PLY header keyword '" + t[0] + "' (expected format, comment, obj_info, element, property or end_header)");
  }
  if (!ended) throw ParseError(source, lines.line(), "the header has no end_header line");
  if (format == Format::none) throw ParseError(source, lines.line(), "the header has no format line");

  // Which properties hold the mesh.
  const PlyElement* vertex = nullptr;
  const PlyElement* face = nullptr;
  for (const PlyElement& e : elements) {
    if (e.name == "vertex") vertex = &e;
    if (e.name == "face") face = &e;
  }
  if (!vertex) throw ParseError(source, lines.line(), "no 'vertex' element in the header");
  if (vertex->count > static_cast<std::uint64_t>(INT_MAX)) throw ParseError(source, vertex->line, "more than INT_MAX vertices");
  int xyz[3] = {-1, -1, -1};
  for (std::size_t i = 0; i < vertex->properties.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (vertex->properties[i].name == std::string(1, "xyz"[c])) {
        if (vertex->properties[i].list || !is_float(vertex->properties[i].type))
          throw ParseError(source, vertex->line, std::string("vertex property ") + "xyz"[c] + " is not of type float or double");
        xyz[c] = static_cast<int>(i);
      }
  for (int c = 0; c < 3; ++c)
    if (xyz[c] < 0) throw ParseError(source, vertex->line, std::string("the vertex element has no property ") + "xyz"[c]);
  int indices = -1;
  if (face) {
    for (std::size_t i = 0; i < face->properties.size(); ++i)
      if (face->properties[i].name == "vertex_indices" || face->properties[i].name == "vertex_index") {
        if (!face->properties[i].list || is_float(face->properties[i].type))
          throw ParseError(source, face->line, "face property " + face->properties[i].name + " is not a list of integers");
        indices = static_cast<int>(i);
      }
    if (indices < 0) throw ParseError(source, face->line, "the face element has no list property vertex_indices");
  }

  ObjMesh mesh;
  std::vector<std::vector<long long>> faces;
  std::vector<std::size_t> face_where;  // line (ASCII) or byte offset (binary) of each face
  std::vector<long long> poly;
  const auto is_vertex = [&](const PlyElement& e) { return &e == vertex; };
  const auto is_face = [&](const PlyElement& e) { return &e == face; };

  if (format == Format::ascii) {
    for (const PlyElement& e : elements) {
      if (e.properties.empty()) continue;
      for (std::uint64_t k = 0; k < e.count; ++k) {
        std::vector<std::string> t;
        do {
          if (!lines.next(line))
            throw ParseError(source, lines.line(), "the file ends after " + std::to_string(k) + " of the " +
                                                       std::to_string(e.count) + " '" + e.name + "' elements");
          t = split(line);
        } while (t.empty());
        const std::size_t n = lines.line();
        std::size_t at = 0;
        Vec3 position{0, 0, 0};
        const auto take = [&](PlyType type, const std::string& what) {
          if (at >= t.size())
            throw ParseError(source, n, "too few values for element '" + e.name + "' (" + what + " missing)");
          PlyValue v;
          std::string error;
          if (!parse_ascii(t[at], type, v, error)) throw ParseError(source, n, what + ": " + error);
          ++at;
          return v;
        };
        for (std::size_t p = 0; p < e.properties.size(); ++p) {
          const PlyProperty& prop = e.properties[p];
          if (!prop.list) {
            const PlyValue v = take(prop.type, "property " + prop.name);
            if (is_vertex(e))
              for (int c = 0; c < 3; ++c)
                if (static_cast<int>(p) == xyz[c]) {
                  if (!std::isfinite(v.f)) throw ParseError(source, n, "coordinate " + prop.name + " '" + t[at - 1] + "' is not finite");
                  (c == 0 ? position.x : c == 1 ? position.y : position.z) = v.f;
                }
            continue;
          }
          const long long count = take(prop.count_type, "the count of list " + prop.name).i;
          if (count < 0) throw ParseError(source, n, "negative count of list " + prop.name);
          const bool keep = is_face(e) && static_cast<int>(p) == indices;
          if (keep) poly.clear();
          for (long long j = 0; j < count; ++j) {
            const PlyValue v = take(prop.type, "item of list " + prop.name);
            if (keep) poly.push_back(v.i);
          }
          if (keep) {
            faces.push_back(poly);
            face_where.push_back(n);
          }
        }
        if (at != t.size())
          throw ParseError(source, n, "too many values for element '" + e.name + "' (" + std::to_string(t.size()) +
                                          ", expected " + std::to_string(at) + ")");
        if (is_vertex(e)) mesh.vertices.push_back(position);
      }
    }
    while (lines.next(line))
      if (!split(line).empty()) throw ParseError(source, lines.line(), "data after the last element (wrong element counts in the header?)");
    for (std::size_t i = 0; i < faces.size(); ++i)
      add_polygon(mesh, faces[i], mesh.vertices.size(),
                  [&](const std::string& why) { throw ParseError(source, face_where[i], why); });
    return mesh;
  }

  // Binary.
  const bool big = format == Format::big;
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  const std::size_t size = data.size();
  std::size_t offset = std::min(lines.pos(), size);  // end_header may end the file without a newline
  const auto fail = [&](std::size_t at, const std::string& where, const std::string& why) {
    throw InputError(source, "byte offset " + std::to_string(at) + " (" + where + "): " + why);
  };
  for (const PlyElement& e : elements) {
    if (e.properties.empty()) continue;
    for (std::uint64_t k = 0; k < e.count; ++k) {
      Vec3 position{0, 0, 0};
      const auto where = [&](const PlyProperty& prop) {
        return e.name + " " + std::to_string(k) + " of " + std::to_string(e.count) + ", property " + prop.name;
      };
      const auto read = [&](PlyType type, const PlyProperty& prop) {
        const std::size_t n = type_size(type);
        if (size - offset < n)
          fail(offset, where(prop), "truncated: the file ends " + std::to_string(size - offset) + " bytes into a " +
                                        std::to_string(n) + "-byte value (wrong counts in the header?)");
        const PlyValue v = decode(bytes + offset, type, big);
        offset += n;
        return v;
      };
      for (std::size_t p = 0; p < e.properties.size(); ++p) {
        const PlyProperty& prop = e.properties[p];
        const std::size_t at = offset;
        if (!prop.list) {
          const PlyValue v = read(prop.type, prop);
          if (is_vertex(e))
            for (int c = 0; c < 3; ++c)
              if (static_cast<int>(p) == xyz[c]) {
                if (!std::isfinite(v.f)) fail(at, where(prop), "coordinate is not finite (NaN or infinity)");
                (c == 0 ? position.x : c == 1 ? position.y : position.z) = v.f;
              }
          continue;
        }
        const long long count = read(prop.count_type, prop).i;
        if (count < 0) fail(at, where(prop), "negative list count " + std::to_string(count));
        const bool keep = is_face(e) && static_cast<int>(p) == indices;
        if (!keep) {
          const std::uint64_t skip = static_cast<std::uint64_t>(count) * type_size(prop.type);
          if (size - offset < skip) fail(offset, where(prop), "truncated: the file ends inside the list");
          offset += static_cast<std::size_t>(skip);
          continue;
        }
        poly.clear();
        for (long long j = 0; j < count; ++j) poly.push_back(read(prop.type, prop).i);
        add_polygon(mesh, poly, vertex->count, [&](const std::string& why) { fail(at, where(prop), why); });
      }
      if (is_vertex(e)) mesh.vertices.push_back(position);
    }
  }
  if (offset != size)
    fail(offset, "end of the last element",
         std::to_string(size - offset) + " bytes of data after the last element (wrong element counts in the header?)");
  return mesh;
}

// ---------------------------------------------------------------------------------- OFF

ObjMesh read_off(std::istream& in, const std::string& source) {
  const std::string data = slurp(in);
  LineReader lines(data, text_start(data));
  std::string line;
  // The next line with tokens (comments removed); false at the end.
  const auto next_tokens = [&](std::vector<std::string>& t) {
    while (lines.next(line)) {
      t = split(line.substr(0, line.find('#')));
      if (!t.empty()) return true;
    }
    return false;
  };
  std::vector<std::string> t;
  // Line 1 for an empty file (it has no line; ParseError lines are 1-based).
  if (!next_tokens(t)) throw ParseError(source, std::max<std::size_t>(lines.line(), 1), "empty OFF file");
  const std::string keyword = t[0];
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
    throw ParseError(source, lines.line(), "not an OFF file (the first word is '" + keyword + "')");
  const std::string prefix = keyword.substr(0, keyword.size() - 3);
  if (prefix.find('4') != std::string::npos || prefix.find('n') != std::string::npos)
    throw ParseError(source, lines.line(), "'" + keyword + "': OFF of another dimension than 3 is not supported");
  std::size_t extra_min = 0, extra_max = 0;
  std::string rest = prefix;
  if (rest.rfind("ST", 0) == 0) { extra_min += 2; extra_max += 2; rest = rest.substr(2); }
  if (rest.rfind("C", 0) == 0) { extra_min += 3; extra_max += 4; rest = rest.substr(1); }
  if (rest.rfind("N", 0) == 0) { extra_min += 3; extra_max += 3; rest = rest.substr(1); }
  if (!rest.empty()) throw ParseError(source, lines.line(), "unknown OFF keyword '" + keyword + "'");
  t.erase(t.begin());
  if (!t.empty() && t[0] == "BINARY") throw ParseError(source, lines.line(), "binary OFF is not supported");
  if (t.empty() && !next_tokens(t)) throw ParseError(source, lines.line(), "the file ends before the counts line");
  long long nv = 0, nf = 0, ne = 0;
  if (t.size() < 2 || t.size() > 3 || !parse_count(t[0], nv) || !parse_count(t[1], nf) ||
      (t.size() == 3 && !parse_count(t[2], ne)))
    throw ParseError(source, lines.line(), "expected the counts 'vertices faces [edges]' (non-negative integers)");
  if (nv > INT_MAX) throw ParseError(source, lines.line(), "more than INT_MAX vertices");
  ObjMesh mesh;
  for (long long i = 0; i < nv; ++i) {
    if (!next_tokens(t))
      throw ParseError(source, lines.line(), "the file ends after " + std::to_string(i) + " of the " + std::to_string(nv) + " vertices");
    const std::size_t n = lines.line();
    if (t.size() < 3 + extra_min || t.size() > 3 + extra_max)
      throw ParseError(source, n, "vertex with " + std::to_string(t.size()) + " numbers (expected " +
                                      std::to_string(3 + extra_min) +
                                      (extra_max != extra_min ? " to " + std::to_string(3 + extra_max) : "") + ")");
    for (std::size_t k = 3; k < t.size(); ++k) parse_double(t[k], source, n, "value", false);
    mesh.vertices.push_back({parse_double(t[0], source, n, "coordinate"), parse_double(t[1], source, n, "coordinate"),
                             parse_double(t[2], source, n, "coordinate")});
  }
  std::vector<long long> poly;
  for (long long i = 0; i < nf; ++i) {
    if (!next_tokens(t))
      throw ParseError(source, lines.line(), "the file ends after " + std::to_string(i) + " of the " + std::to_string(nf) + " faces");
    const std::size_t n = lines.line();
    long long count = 0;
    if (!parse_count(t[0], count)) throw ParseError(source, n, "the face's vertex count '" + t[0] + "' is not a non-negative integer");
    if (t.size() < static_cast<std::size_t>(count) + 1 || t.size() > static_cast<std::size_t>(count) + 5)
      throw ParseError(source, n, "face of " + std::to_string(count) + " vertices with " + std::to_string(t.size() - 1) +
                                      " numbers (expected the indices and at most a 4-number colour)");
    poly.clear();
    for (long long k = 1; k <= count; ++k) {
      long long v = 0;
      if (!parse_integer(t[static_cast<std::size_t>(k)], v))
        throw ParseError(source, n, "face vertex index '" + t[static_cast<std::size_t>(k)] + "' is not an integer");
      poly.push_back(v);
    }
    for (std::size_t k = static_cast<std::size_t>(count) + 1; k < t.size(); ++k) parse_double(t[k], source, n, "colour value");
    add_polygon(mesh, poly, mesh.vertices.size(), [&](const std::string& why) { throw ParseError(source, n, why); });
  }
  if (next_tokens(t)) throw ParseError(source, lines.line(), "data after the last face (wrong counts?)");
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

}  // namespace

ObjMesh read_stl(std::istream& in, const std::string& source) {
  const std::string data = slurp(in);
  ObjMesh mesh;
  CornerMerger merge(mesh);
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  if (data.size() >= 84) {
    const std::uint64_t n = decode(bytes + 80, PlyType::u32, false).i;
    if (data.size() == 84 + 50 * n) {
      for (std::uint64_t f = 0; f < n; ++f) {
        const std::size_t at = static_cast<std::size_t>(84 + 50 * f);
        std::array<int, 3> tri{};
        for (int c = 0; c < 3; ++c) {
          Vec3 p;
          double* xyz[3] = {&p.x, &p.y, &p.z};
          for (int k = 0; k < 3; ++k) {
            const std::size_t o = at + 12 + 12 * static_cast<std::size_t>(c) + 4 * static_cast<std::size_t>(k);
            *xyz[k] = decode(bytes + o, PlyType::f32, false).f;
            if (!std::isfinite(*xyz[k]))
              throw InputError(source, "byte offset " + std::to_string(o) + " (facet " + std::to_string(f) +
                                           "): coordinate is not finite (NaN or infinity)");
          }
          tri[static_cast<std::size_t>(c)] = merge.add(p);
        }
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
          throw InputError(source, "byte offset " + std::to_string(at) + " (facet " + std::to_string(f) +
                                       "): degenerate facet: two corners are equal");
        mesh.triangles.push_back(tri);
      }
      return mesh;
    }
  }
  // Not binary: ASCII, after a byte order mark if there is one.
  if (data.compare(text_start(data), 5, "solid") != 0) {
    if (data.size() >= 84)
      throw InputError(source, "byte offset 80: binary STL of " + std::to_string(decode(bytes + 80, PlyType::u32, false).i) +
                                   " facets needs " + std::to_string(84 + 50 * static_cast<std::uint64_t>(decode(bytes + 80, PlyType::u32, false).i)) +
                                   " bytes, the file has " + std::to_string(data.size()) + " (truncated or extended)");
    throw InputError(source, "byte offset 0: neither ASCII STL ('solid') nor binary STL (shorter than 84 bytes)");
  }
  // ASCII: a keyword stream, checked line by line.
  LineReader lines(data, text_start(data));
  std::string line;
  enum class State { solid, facet_or_end, outer, vertex, endloop, endfacet, done } state = State::solid;
  std::array<int, 3> tri{};
  int corner = 0;
  while (lines.next(line)) {
    const std::size_t n = lines.line();
    const std::vector<std::string> t = split(line);
    if (t.empty()) continue;
    const auto expect = [&](const char* what) {
      throw ParseError(source, n, "expected " + std::string(what) + ", found '" + t[0] + "'");
    };
    switch (state) {
      case State::solid:
        if (t[0] != "solid") expect("'solid'");
        state = State::facet_or_end;
        break;
      case State::facet_or_end:
        if (t[0] == "endsolid") {
          state = State::done;
          break;
        }
        if (t[0] != "facet") expect("'facet' or 'endsolid'");
        if (t.size() != 5 || t[1] != "normal") throw ParseError(source, n, "expected 'facet normal NX NY NZ'");
        for (int k = 2; k < 5; ++k) parse_double(t[static_cast<std::size_t>(k)], source, n, "normal component", false);
        state = State::outer;
        break;
      case State::outer:
        if (t.size() != 2 || t[0] != "outer" || t[1] != "loop") expect("'outer loop'");
        state = State::vertex;
        corner = 0;
        break;
      case State::vertex: {
        if (t[0] != "vertex") expect("'vertex'");
        if (t.size() != 4) throw ParseError(source, n, "expected 'vertex X Y Z'");
        const Vec3 p{parse_double(t[1], source, n, "coordinate"), parse_double(t[2], source, n, "coordinate"),
                     parse_double(t[3], source, n, "coordinate")};
        tri[static_cast<std::size_t>(corner)] = merge.add(p);
        if (++corner == 3) state = State::endloop;
        break;
      }
      case State::endloop:
        if (t.size() != 1 || t[0] != "endloop") expect("'endloop' (a facet has three vertices)");
        state = State::endfacet;
        break;
      case State::endfacet:
        if (t.size() != 1 || t[0] != "endfacet") expect("'endfacet'");
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
          throw ParseError(source, n, "degenerate facet: two corners are equal");
        mesh.triangles.push_back(tri);
        state = State::facet_or_end;
        break;
      case State::done:
        throw ParseError(source, n, "data after 'endsolid'");
    }
  }
  if (state != State::done) throw ParseError(source, lines.line(), "the file ends before 'endsolid'");
  return mesh;
}

}  // namespace exactccd::io
