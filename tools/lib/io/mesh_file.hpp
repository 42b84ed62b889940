// Mesh files: which format a file holds, from its extension and its content (both must agree),
// and reading it as a triangle mesh: OBJ (io/obj.hpp), PLY, OFF and STL (io/mesh_formats.hpp).
// A reader for another format plugs into the table of formats in mesh_file.cpp.
#pragma once

#include <string>

#include "io/obj.hpp"

namespace exactccd::io {

/// The mesh formats recognised.
enum class MeshFormat {
  obj,  ///< Wavefront OBJ (read by read_obj)
  ply,  ///< Stanford PLY, ASCII or binary (read by read_ply)
  off,  ///< Object File Format, ASCII (read by read_off)
  stl,  ///< STL, ASCII or binary (read by read_stl; equal corners merged)
};

/// "OBJ", "PLY", "OFF" or "STL".
const char* mesh_format_name(MeshFormat format);

/// A triangle mesh as read from a file: vertex positions and 0-based triangles.
using TriangleMesh = ObjMesh;

/// The format of the mesh file at `path`: its extension (case-insensitive: .obj, .ply, .off,
/// .stl) and its first bytes (the PLY and OFF magic words, an ASCII STL's "solid", a binary
/// STL's size, text for OBJ) must name the same format. Throws InputError
/// "<path>: <reason>" when the file cannot be opened (missing, a directory, unreadable), the
/// extension is unknown or missing, or the content is of another format or of none (binary
/// data in an .obj file, a .ply file without the PLY header, ...).
MeshFormat detect_mesh_format(const std::string& path);

/// The mesh in the file at `path` (format from detect_mesh_format, read by read_obj, read_ply,
/// read_off or read_stl). Throws InputError for every reason of detect_mesh_format, "<path>: no
/// vertices" or "<path>: no faces" for a mesh without either, "<path>: byte offset N (...):
/// <reason>" for a malformed binary PLY or STL, and ParseError ("<path>:<line>: <reason>") for
/// a malformed text file or PLY header.
TriangleMesh read_mesh(const std::string& path);

}  // namespace exactccd::io
