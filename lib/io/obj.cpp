#include "io/obj.hpp"

#include <charconv>
#include <climits>
#include <cmath>
#include <istream>
#include <ostream>
#include <sstream>
#include <system_error>

namespace exactccd::io {
namespace {

/// The whitespace-separated tokens of a line, without a trailing `#` comment.
std::vector<std::string> tokens(const std::string& line) {
  std::istringstream ss(line.substr(0, line.find('#')));
  std::vector<std::string> out;
  for (std::string t; ss >> t;) out.push_back(t);
  return out;
}

/// A finite double written as a decimal (an optional leading '+' allowed); throws ParseError.
double parse_coordinate(const std::string& token, const std::string& source, std::size_t line) {
  const char* first = token.data();
  const char* last = first + token.size();
  if (first != last && *first == '+') ++first;
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

/// A face vertex reference `i`, `i/t`, `i//n` or `i/t/n`: its index i (1-based or negative).
long parse_reference(const std::string& token, const std::string& source, std::size_t line) {
  const std::string index = token.substr(0, token.find('/'));
  long value = 0;
  const auto [end, error] = std::from_chars(index.data(), index.data() + index.size(), value);
  if (index.empty() || error != std::errc() || end != index.data() + index.size())
    throw ParseError(source, line, "face vertex '" + token + "' does not start with an integer index");
  if (value == 0) throw ParseError(source, line, "face vertex index 0 (OBJ indices start at 1)");
  return value;
}

/// A face as read: 0-based indices (positive references not yet checked against the count).
struct Face {
  std::vector<long> vertices;
  std::size_t line;
};

}  // namespace

ObjMesh read_obj(std::istream& in, const std::string& source_name) {
  ObjMesh mesh;
  std::vector<Face> faces;
  std::size_t line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    const std::vector<std::string> t = tokens(line);
    if (t.empty()) continue;
    if (t[0] == "v") {
      if (t.size() < 4)
        throw ParseError(source_name, line_number,
                         "vertex with " + std::to_string(t.size() - 1) + " coordinates (expected x y z)");
      if (mesh.vertices.size() >= static_cast<std::size_t>(INT_MAX))
        throw ParseError(source_name, line_number, "more than INT_MAX vertices");
      mesh.vertices.push_back({parse_coordinate(t[1], source_name, line_number),
                               parse_coordinate(t[2], source_name, line_number),
                               parse_coordinate(t[3], source_name, line_number)});
    } else if (t[0] == "f") {
      if (t.size() < 4)
        throw ParseError(source_name, line_number,
                         "face with " + std::to_string(t.size() - 1) + " vertices (expected at least 3)");
      Face f{{}, line_number};
      const long count = static_cast<long>(mesh.vertices.size());
      for (std::size_t i = 1; i < t.size(); ++i) {
        const long r = parse_reference(t[i], source_name, line_number);
        if (r < 0 && count + r < 0)
          throw ParseError(source_name, line_number,
                           "face vertex " + std::to_string(r) + " refers before the first vertex (" +
                               std::to_string(count) + " vertices read so far)");
        f.vertices.push_back(r < 0 ? count + r : r - 1);
      }
      for (std::size_t i = 0; i < f.vertices.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
          if (f.vertices[i] == f.vertices[j])
            throw ParseError(source_name, line_number,
                             "degenerate face: vertex " + std::to_string(f.vertices[i] + 1) + " appears twice");
      faces.push_back(std::move(f));
    }
  }
  const long count = static_cast<long>(mesh.vertices.size());
  for (const Face& f : faces) {
    for (long v : f.vertices)
      if (v >= count)
        throw ParseError(source_name, f.line,
                         "face vertex " + std::to_string(v + 1) + " out of range (the file has " +
                             std::to_string(count) + " vertices)");
    for (std::size_t i = 2; i < f.vertices.size(); ++i)
      mesh.triangles.push_back({static_cast<int>(f.vertices[0]), static_cast<int>(f.vertices[i - 1]),
                                static_cast<int>(f.vertices[i])});
  }
  return mesh;
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
