#include "fuzz/readers/mesh_writers.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>
#include <string>

namespace exactccd::fuzzing {
namespace {

/// The shortest decimal that reads back as x.
std::string decimal(double x) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

/// The bytes of a value in the given byte order.
template <class T>
void put(std::ostream& out, T value, bool big_endian) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));  // the machine is little-endian (x86-64)
  for (std::size_t i = 0; i < sizeof(T); ++i) out.put(static_cast<char>(b[big_endian ? sizeof(T) - 1 - i : i]));
}

}  // namespace

void write_ply(std::ostream& out, const io::TriangleMesh& mesh, PlyEncoding encoding) {
  const char* format = encoding == PlyEncoding::ascii                  ? "ascii"
                       : encoding == PlyEncoding::binary_little_endian ? "binary_little_endian"
                                                                      : "binary_big_endian";
  out << "ply\nformat " << format << " 1.0\ncomment written by the reader fuzz targets\nelement vertex "
      << mesh.vertices.size() << "\nproperty double x\nproperty double y\nproperty double z\nelement face "
      << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  if (encoding == PlyEncoding::ascii) {
    for (const Vec3& v : mesh.vertices) out << decimal(v.x) << ' ' << decimal(v.y) << ' ' << decimal(v.z) << '\n';
    for (const auto& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    return;
  }
  const bool big = encoding == PlyEncoding::binary_big_endian;
  for (const Vec3& v : mesh.vertices)
    for (const double x : {v.x, v.y, v.z}) put(out, x, big);
  for (const auto& t : mesh.triangles) {
    put(out, std::uint8_t{3}, big);
    for (const int i : t) put(out, static_cast<std::int32_t>(i), big);
  }
}

void write_off(std::ostream& out, const io::TriangleMesh& mesh) {
  out << "OFF\n" << mesh.vertices.size() << ' ' << mesh.triangles.size() << " 0\n";
  for (const Vec3& v : mesh.vertices) out << decimal(v.x) << ' ' << decimal(v.y) << ' ' << decimal(v.z) << '\n';
  for (const auto& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

void write_stl_ascii(std::ostream& out, const io::TriangleMesh& mesh) {
  out << "solid fuzz\n";
  for (const auto& t : mesh.triangles) {
    out << "  facet normal 0 0 0\n    outer loop\n";
    for (const int i : t) {
      const Vec3& v = mesh.vertices[static_cast<std::size_t>(i)];
      out << "      vertex " << decimal(v.x) << ' ' << decimal(v.y) << ' ' << decimal(v.z) << '\n';
    }
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid fuzz\n";
}

bool write_stl_binary(std::ostream& out, const io::TriangleMesh& mesh) {
  for (const Vec3& v : mesh.vertices)
    for (const double x : {v.x, v.y, v.z})
      if (!(std::fabs(x) <= std::numeric_limits<float>::max()) || static_cast<double>(static_cast<float>(x)) != x)
        return false;  // (a double beyond the float range must not be converted: undefined)
  out << std::string(80, ' ');
  put(out, static_cast<std::uint32_t>(mesh.triangles.size()), false);
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) put(out, 0.0f, false);
    for (const int i : t) {
      const Vec3& v = mesh.vertices[static_cast<std::size_t>(i)];
      for (const double x : {v.x, v.y, v.z}) put(out, static_cast<float>(x), false);
    }
    put(out, std::uint16_t{0}, false);
  }
  return true;
}

}  // namespace exactccd::fuzzing
