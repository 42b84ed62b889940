// Readers of the mesh formats besides OBJ: PLY (ASCII and binary, either byte order), OFF
// (ASCII) and STL (ASCII and binary). Parsing only: no file is opened here (io::read_mesh
// picks the reader from the file's extension and content). Hand-written rather than CGAL's
// readers (CGAL/IO/PLY.h, read_polygon_soup) because those report a malformed file as a bare
// `false`, without the line or byte where it is malformed, and read `float` PLY coordinates
// through their own conversions; these readers name the line (text) or byte offset (binary)
// of every error and widen `float` coordinates to double exactly.
#pragma once

#include <iosfwd>
#include <string>

#include "io/obj.hpp"

namespace exactccd::io {

/// Parses a PLY mesh (format ascii, binary_little_endian or binary_big_endian 1.0). The
/// `vertex` element's `x`, `y`, `z` properties (type float/float32 or double/float64) are the
/// positions: `float` values are widened to double exactly (in ASCII files a `float` value is
/// the float nearest the decimal, as a binary file of the same mesh holds it); the `face`
/// element's list property `vertex_indices` (or `vertex_index`), with any integer count and
/// index types, gives the polygons, fan-triangulated as read_obj does. Every other element and
/// property (normals, colours, lists) is skipped by its declared type. ASCII files hold one
/// element per line. Throws ParseError ("<source>:<line>: reason") for a malformed header or
/// ASCII body, and InputError ("<source>: byte offset N (...): reason") for a malformed binary
/// body: an unknown type, missing x/y/z or face list, a wrong count of values, a non-finite
/// coordinate, an index out of range or repeated in a face, a face of fewer than 3 vertices, a
/// truncated file or data after the last element. A UTF-8 byte order mark before `ply` is
/// skipped; binary byte offsets count from the stream's first byte (the mark's too).
ObjMesh read_ply(std::istream& in, const std::string& source_name);

/// Parses an ASCII OFF mesh: the keyword (OFF, or COFF, NOFF, CNOFF, STOFF, ... whose extra
/// per-vertex values are checked as numbers and ignored), the counts `nv nf [ne]` (on the
/// keyword's line or the next), nv lines `x y z`, nf lines `n i0 ... i(n-1)` with 0-based
/// indices and an optional colour (up to 4 numbers). `#` starts a comment; blank lines are
/// skipped. Polygons are fan-triangulated. Throws ParseError naming the line on a wrong count,
/// a malformed or non-finite number, an index out of range or repeated, data after the last
/// face, 4OFF/nOFF (other dimensions) and binary OFF. A UTF-8 byte order mark is skipped.
ObjMesh read_off(std::istream& in, const std::string& source_name);

/// Parses an STL mesh, binary (80-byte header, little-endian uint32 count, 50-byte records of
/// float32 normal and corners: chosen when the size is exactly 84 + 50 count) or ASCII
/// (`solid ... facet normal ... outer loop vertex x y z (x3) endloop endfacet ... endsolid`).
/// STL stores corners, not indexed vertices: corners with exactly equal coordinates (==, so
/// -0 and +0 too) are merged into one vertex, numbered in order of first appearance; each
/// facet is one triangle. Float coordinates are widened exactly; ASCII coordinates are read as
/// the nearest doubles. Throws ParseError (ASCII: line) or InputError (binary: byte offset) on
/// a malformed file, a non-finite coordinate, or a facet two of whose corners coincide. The size
/// test comes first, on the bytes as they are (a binary header may start with anything); an
/// ASCII file may start with a UTF-8 byte order mark.
ObjMesh read_stl(std::istream& in, const std::string& source_name);

}  // namespace exactccd::io
