// Writers of the mesh formats that tools/lib/io reads but does not write (PLY, OFF, STL; OBJ has
// io::write_obj): the reader fuzz targets' round trips (a mesh read, written and read again is the
// same mesh) and their seed generator. Every coordinate is written exactly: the shortest decimal
// that reads back as the same double, or the binary double (float for binary STL).
#pragma once

#include <iosfwd>

#include "io/mesh_file.hpp"

namespace exactccd::fuzzing {

/// The three encodings of PLY 1.0.
enum class PlyEncoding { ascii, binary_little_endian, binary_big_endian };

/// Writes `mesh` as PLY: element vertex (double x y z), element face (list uchar int
/// vertex_indices, one triangle each).
void write_ply(std::ostream& out, const io::TriangleMesh& mesh, PlyEncoding encoding);

/// Writes `mesh` as ASCII OFF: "OFF", the counts "nv nf 0", the vertices, "3 i j k" per triangle.
void write_off(std::ostream& out, const io::TriangleMesh& mesh);

/// Writes `mesh` as ASCII STL (normals 0 0 0, coordinates as shortest round-trip decimals).
void write_stl_ascii(std::ostream& out, const io::TriangleMesh& mesh);

/// Writes `mesh` as binary STL (80-byte header of spaces, count, float32 records with normal 0)
/// and returns true when every coordinate is exactly a float; else writes nothing, returns false.
bool write_stl_binary(std::ostream& out, const io::TriangleMesh& mesh);

}  // namespace exactccd::fuzzing
