#include "io/obj.hpp"

#include <array>
#include <charconv>
#include <climits>
#include <cmath>
#include <istream>
#include <ostream>
#include <sstream>
#include <system_error>
#include <utility>

#include "io/decimal.hpp"
#include "io/lines.hpp"
#include "io/polygon.hpp"

namespace exactccd::io {
namespace {

/// A finite double written as a decimal (an optional leading '+' allowed); throws ParseError.
double parse_coordinate(const std::string& token, const std::string& source, std::size_t line) {
  const char* first = token.data();
  const char* last = first + token.size();
  first = after_plus_sign(first, last);
  double value = 0;
  const auto [end, error] = std::from_chars(first, last, value);
  if (error == std::errc::result_out_of_range)
    throw ParseError(source, line, "coordinate '" + token + "' is out of the range of double");
  if (error != std::errc() || end != last)
    throw ParseError(source, line, "coordinate '" + token + "' is not a number");
  if (!std::isfinite(value))
    throw ParseError(source, line, "coordinate '" + token + "' is not finite (NaN or infinity)");
  return value;
}

/// A whole token as a long, or false.
bool parse_long(const std::string& s, long& value) {
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  return !s.empty() && error == std::errc() && end == s.data() + s.size();
}

/// A reference `i`, `i/t`, `i//n` or `i/t/n` as written: i, t and n (0 when absent); i is
/// nonzero, and t and n, when present, must be nonzero integers too.
using Reference = std::array<long, 3>;

Reference parse_reference(const std::string& token, const std::string& source, std::size_t line) {
  const std::string index = token.substr(0, token.find('/'));
  Reference r{0, 0, 0};
  if (!parse_long(index, r[0]))
    throw ParseError(source, line, "face vertex '" + token + "' does not start with an integer index");
  if (r[0] == 0) throw ParseError(source, line, "face vertex index 0 (OBJ indices start at 1)");
  if (index.size() < token.size()) {  // "/t", "//n", "/t/n"
    const std::string rest = token.substr(index.size() + 1);
    const auto slash = rest.find('/');
    const std::string texture = rest.substr(0, slash);
    const std::string normal = slash == std::string::npos ? "" : rest.substr(slash + 1);
    const bool texture_ok = texture.empty() ? slash != std::string::npos : parse_long(texture, r[1]) && r[1] != 0;
    const bool normal_ok = slash == std::string::npos || (parse_long(normal, r[2]) && r[2] != 0);
    if (!texture_ok || !normal_ok)
      throw ParseError(source, line,
                       "face vertex '" + token + "' is malformed (expected i, i/t, i//n or i/t/n, nonzero integers)");
  }
  return r;
}

/// Checks that tokens t[1..] are between `least` and `most` finite numbers; `what` names them.
void check_numbers(const std::vector<std::string>& t, std::size_t least, std::size_t most, const char* what,
                   const std::string& source, std::size_t line) {
  const std::size_t count = t.size() - 1;
  if (count < least || count > most)
    throw ParseError(source, line,
                     std::string(what) + " with " + std::to_string(count) + " numbers (expected " +
                         std::to_string(least) + (least == most ? "" : " to " + std::to_string(most)) + ")");
  for (std::size_t i = 1; i < t.size(); ++i) parse_coordinate(t[i], source, line);
}

/// The OBJ statements of free-form geometry (curves and surfaces): not read, so an error
/// rather than a mesh silently missing them.
bool is_free_form_statement(const std::string& keyword) {
  for (const char* k : {"cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole",
                        "scrv", "sp", "end", "con"})
    if (keyword == k) return true;
  return false;
}

/// Statements read or harmlessly ignored: their arguments do not change the mesh.
bool is_ignored_statement(const std::string& keyword) {
  for (const char* k : {"o", "g", "s", "mtllib", "usemtl"})
    if (keyword == k) return true;
  return false;
}

/// A face as read: 0-based indices (positive references checked at the end of the file).
struct Face {
  std::vector<long> vertices;
  std::size_t line;
};

/// What a reference names: vertices (v), texture vertices (vt) and normals (vn), by position
/// in Reference.
constexpr const char* kElement[3] = {"vertex", "texture vertex", "normal"};
constexpr const char* kElements[3] = {"vertices", "texture vertices", "normals"};

/// The references of the f, l and p lines against the v, vt and vn lines: a negative index
/// counts back from the elements read so far (checked at once), a positive one may name an
/// element of a later line (checked at the end of the file, when the counts are known). An OBJ
/// file naming an element it lacks is malformed, whether the mesh uses the element (vertices)
/// or not (texture vertices and normals).
class References {
 public:
  explicit References(const std::string& source) : source_(source) {}
  /// One more element of kind 0 (v), 1 (vt) or 2 (vn).
  void count(int element) { ++count_[element]; }
  /// Checks reference r of a `statement` (face, line, point) on `line`; returns the 0-based
  /// vertex index it names.
  long resolve(const Reference& r, const char* statement, std::size_t line) {
    for (int e = 0; e < 3; ++e) {
      if (r[e] < 0 && count_[e] + r[e] < 0)
        throw ParseError(source_, line,
                         std::string(statement) + " " + kElement[e] + " " + std::to_string(r[e]) + " refers before the first " +
                             kElement[e] + " (" + std::to_string(count_[e]) + " " + kElements[e] + " read so far)");
      if (r[e] > count_[e]) forward_.push_back({r[e], e, statement, line});
    }
    return r[0] < 0 ? count_[0] + r[0] : r[0] - 1;
  }
  /// At the end of the file: throws for the first forward reference past the elements read.
  void check_forward() const {
    for (const Forward& f : forward_)
      if (f.index > count_[f.element])
        throw ParseError(source_, f.line,
                         std::string(f.statement) + " " + kElement[f.element] + " " + std::to_string(f.index) +
                             " out of range (the file has " + std::to_string(count_[f.element]) + " " +
                             kElements[f.element] + ")");
  }

 private:
  struct Forward {
    long index;
    int element;
    const char* statement;
    std::size_t line;
  };
  const std::string& source_;
  long count_[3] = {0, 0, 0};
  std::vector<Forward> forward_;
};

/// An OBJ file being read statement by statement: the vertices, the faces (triangulated at the
/// end, once every forward reference is known to name an element of the file) and the counts
/// the references are checked against. Errors name the current line of `lines`.
class ObjReader {
 public:
  explicit ObjReader(const LineReader& lines) : lines_(lines), references_(lines.source()) {}

  /// One statement: a line's words (its comment cut).
  void statement(const std::vector<std::string>& t) {
    if (t[0] == "v") {
      vertex(t);
    } else if (t[0] == "vt" || t[0] == "vp") {
      check_numbers(t, 1, 3, t[0] == "vt" ? "texture vertex" : "parameter vertex", source(), line());
      if (t[0] == "vt") references_.count(1);
    } else if (t[0] == "vn") {
      check_numbers(t, 3, 3, "normal", source(), line());
      references_.count(2);
    } else if (t[0] == "l" || t[0] == "p") {
      line_or_point(t);
    } else if (is_ignored_statement(t[0])) {
      return;
    } else if (is_free_form_statement(t[0])) {
      lines_.fail("OBJ free-form geometry ('" + t[0] + "') is not supported (triangle and polygon faces only)");
    } else if (t[0] != "f") {
      lines_.fail("unknown OBJ keyword '" + t[0] +
                  "' (expected v, vt, vn, vp, f, l, p, o, g, s, mtllib, usemtl or a # comment)");
    } else {
      face(t);
    }
  }

  /// The mesh, after the last statement: the faces fan-triangulated.
  ObjMesh finish() {
    references_.check_forward();  // every index is in range from here on
    for (const Face& f : faces_)
      for (std::size_t i = 2; i < f.vertices.size(); ++i)
        mesh_.triangles.push_back({static_cast<int>(f.vertices[0]), static_cast<int>(f.vertices[i - 1]),
                                   static_cast<int>(f.vertices[i])});
    return std::move(mesh_);
  }

 private:
  const std::string& source() const { return lines_.source(); }
  std::size_t line() const { return lines_.line(); }

  /// `v x y z`, with a w or an r g b colour checked and ignored.
  void vertex(const std::vector<std::string>& t) {
    if (t.size() < 4) lines_.fail("vertex with " + std::to_string(t.size() - 1) + " coordinates (expected x y z)");
    if (t.size() != 4 && t.size() != 5 && t.size() != 7)
      lines_.fail("vertex with " + std::to_string(t.size() - 1) + " numbers (expected x y z, x y z w or x y z r g b)");
    if (mesh_.vertices.size() >= static_cast<std::size_t>(INT_MAX)) lines_.fail("more than INT_MAX vertices");
    for (std::size_t i = 4; i < t.size(); ++i) parse_coordinate(t[i], source(), line());
    mesh_.vertices.push_back({parse_coordinate(t[1], source(), line()), parse_coordinate(t[2], source(), line()),
                              parse_coordinate(t[3], source(), line())});
    references_.count(0);
  }

  /// `l` (at least 2 vertices) or `p` (at least 1): references checked, nothing kept.
  void line_or_point(const std::vector<std::string>& t) {
    const bool is_line = t[0] == "l";
    const std::size_t least = is_line ? 2 : 1;
    if (t.size() - 1 < least)
      lines_.fail(std::string(is_line ? "line" : "point") + " with " + std::to_string(t.size() - 1) +
                  " vertices (expected at least " + std::to_string(least) + ")");
    for (std::size_t i = 1; i < t.size(); ++i)
      references_.resolve(parse_reference(t[i], source(), line()), is_line ? "line" : "point", line());
  }

  /// `f` with at least three vertex references, none repeated.
  void face(const std::vector<std::string>& t) {
    if (t.size() < 4) lines_.fail("face with " + std::to_string(t.size() - 1) + " vertices (expected at least 3)");
    Face f{{}, line()};
    for (std::size_t i = 1; i < t.size(); ++i)
      f.vertices.push_back(references_.resolve(parse_reference(t[i], source(), line()), "face", line()));
    if (const auto repeated = first_repeated_vertex(f.vertices))
      lines_.fail("degenerate face: vertex " + std::to_string(*repeated + 1) + " appears twice");
    faces_.push_back(std::move(f));
  }

  const LineReader& lines_;
  ObjMesh mesh_;
  std::vector<Face> faces_;
  References references_;
};

}  // namespace

ObjMesh read_obj(std::istream& in, const std::string& source_name) {
  LineReader lines(in, source_name, '#');
  ObjReader reader(lines);
  for (std::vector<std::string> t; lines.next_words(t);) reader.statement(t);
  return reader.finish();
}

void write_obj(std::ostream& out, const std::vector<Vec3>& vertices,
               const std::vector<std::array<int, 3>>& triangles, const std::string& comment) {
  if (!comment.empty()) {
    std::istringstream lines(comment);
    for (std::string l; std::getline(lines, l);) out << "# " << l << "\n";
  }
  char buf[64];
  const auto number = [&](double x) {
    const auto result = std::to_chars(buf, buf + sizeof buf, x);  // shortest round trip
    return std::string(buf, result.ptr);
  };
  for (const Vec3& v : vertices) out << "v " << number(v.x) << " " << number(v.y) << " " << number(v.z) << "\n";
  for (const auto& t : triangles) out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
}

}  // namespace exactccd::io
