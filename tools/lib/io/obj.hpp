// Wavefront OBJ triangle meshes: the vertex positions (`v x y z`) and faces (`f i j k ...`).
// Parsing and writing only: no file is opened here (the CLI opens files).
#pragma once

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

#include "exactccd/types.hpp"
#include "io/benchmark_csv.hpp"  // ParseError

namespace exactccd::io {

/// A triangle mesh read from an OBJ file: vertex positions in file order, triangles as 0-based
/// vertex indices.
struct ObjMesh {
  std::vector<Vec3> vertices;                  ///< positions, in the order of the `v` lines
  std::vector<std::array<int, 3>> triangles;   ///< 0-based indices, polygons fan-triangulated
};

/// Parses an OBJ mesh, strictly. Reads `v x y z` lines (a w, or an r g b colour, may follow:
/// checked as numbers, then ignored) and `f` lines of at least three vertex references, each
/// `i`, `i/t`, `i//n` or `i/t/n` with i a 1-based index or a negative index relative to the
/// vertices read so far (-1 is the last one); a polygon (v0, v1, ..., vk) becomes the fan
/// (v0, v1, v2), (v0, v2, v3), .... The other standard statements are checked and ignored:
/// vt, vn, vp (finite numbers), l and p (vertex references), o, g, s, mtllib, usemtl, and
/// comments after `#`. A UTF-8 byte order mark at the start is skipped. Coordinates are read
/// exactly as the nearest doubles (std::from_chars). Throws ParseError naming source_name and
/// the line on: any other keyword (free-form geometry included: it would be lost silently),
/// a malformed or non-finite number, a wrong count of coordinates or face vertices, an index
/// that is zero or not an integer, a reference of an f, l or p line to no vertex, texture vertex
/// (vt) or normal (vn) of the file (checked at the end of the file for positive indices, which
/// may refer forward), or a face that repeats a vertex (a degenerate face). An input without
/// vertices gives an empty mesh (io::read_mesh rejects that).
ObjMesh read_obj(std::istream& in, const std::string& source_name);

/// Writes vertices and triangles as OBJ (`v` lines with the shortest decimal that reads back as
/// the same double, then `f` lines with 1-based indices), after `comment` lines prefixed by `#`
/// when comment is not empty. read_obj reads back the same mesh.
void write_obj(std::ostream& out, const std::vector<Vec3>& vertices,
               const std::vector<std::array<int, 3>>& triangles, const std::string& comment = "");

}  // namespace exactccd::io
