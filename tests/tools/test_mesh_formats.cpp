// The PLY, OFF and STL readers (tools/lib/io/mesh_formats.hpp) and io::read_mesh on them: every
// bundled tetrahedron (tests/data/meshes) is the OBJ tetrahedron; float coordinates are taken
// exactly; other properties are skipped by type; malformed files are errors naming the file
// and the line (text) or byte offset (binary), never an empty or partial mesh.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

#include "io/mesh_file.hpp"
#include "io/mesh_formats.hpp"

namespace exactccd::io {
namespace {

using Tri = std::array<int, 3>;

ObjMesh obj_tetra() {
  std::istringstream in("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  return read_obj(in, "tetra.obj");
}

/// text with the first occurrence of `from` (which must occur) replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("test text has no '" + from + "'");
  return text.replace(at, from.size(), to);
}

std::string mesh_path(const std::string& name) { return std::string(EXACTCCD_SOURCE_DIR) + "/tests/data/meshes/" + name; }

bool same_vertices(const ObjMesh& a, const ObjMesh& b) {
  if (a.vertices.size() != b.vertices.size()) return false;
  for (std::size_t i = 0; i < a.vertices.size(); ++i)
    if (!(a.vertices[i].x == b.vertices[i].x && a.vertices[i].y == b.vertices[i].y && a.vertices[i].z == b.vertices[i].z))
      return false;
  return true;
}

/// The triangles as corner coordinates, in order (for STL, whose vertex numbering is its own).
std::vector<std::array<std::array<double, 3>, 3>> geometry(const ObjMesh& m) {
  std::vector<std::array<std::array<double, 3>, 3>> out;
  for (const Tri& t : m.triangles) {
    std::array<std::array<double, 3>, 3> g;
    for (int c = 0; c < 3; ++c) {
      const Vec3& p = m.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(c)])];
      g[static_cast<std::size_t>(c)] = {p.x, p.y, p.z};
    }
    out.push_back(g);
  }
  return out;
}

TEST(MeshFormats, EveryBundledTetraIsTheObjTetra) {
  const ObjMesh obj = obj_tetra();
  for (const char* name : {"tetra.ply", "tetra-ascii.ply", "tetra-be.ply", "tetra.off"}) {
    SCOPED_TRACE(name);
    const TriangleMesh m = read_mesh(mesh_path(name));
    EXPECT_TRUE(same_vertices(m, obj));
    EXPECT_EQ(m.triangles, obj.triangles);
  }
  for (const char* name : {"tetra.stl", "tetra-ascii.stl"}) {
    SCOPED_TRACE(name);
    const TriangleMesh m = read_mesh(mesh_path(name));
    EXPECT_EQ(m.vertices.size(), 4u);  // 12 corners merged by exact coordinates
    EXPECT_EQ(geometry(m), geometry(obj));
  }
  EXPECT_EQ(detect_mesh_format(mesh_path("tetra-be.ply")), MeshFormat::ply);
}

// --- PLY built in memory ---------------------------------------------------------------------

template <class T>
void put(std::string& out, T value, bool big) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if (big)
    for (std::size_t i = sizeof(T); i-- > 0;) out.push_back(static_cast<char>(b[i]));
  else
    for (std::size_t i = 0; i < sizeof(T); ++i) out.push_back(static_cast<char>(b[i]));
}

ObjMesh ply(const std::string& bytes) {
  std::istringstream in(bytes);
  return read_ply(in, "m.ply");
}

std::string error_of(ObjMesh (*reader)(std::istream&, const std::string&), const std::string& bytes,
                     const std::string& name) {
  std::istringstream in(bytes);
  try {
    reader(in, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string ply_error(const std::string& bytes) { return error_of(read_ply, bytes, "m.ply"); }

/// A binary PLY of one quad (vertices 0.1f.. as float) with extra properties to skip.
std::string binary_quad(bool big, const char* coordinate_type = "float", const char* count_type = "uchar",
                        const char* index_type = "int") {
  std::string s = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\ncomment skipped\nelement vertex 4\nproperty " + coordinate_type + " x\nproperty uchar red\nproperty " +
                  coordinate_type + " y\nproperty " + coordinate_type + " z\nproperty list uchar short extra\n"
                  "element face 1\nproperty list " + count_type + " " + index_type + " vertex_indices\nproperty ushort flags\n"
                  "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  const float v[4][3] = {{0.1f, 0, 0}, {1, 0.2f, 0}, {1, 1, 1e-30f}, {0, 1, -3.5f}};
  for (const auto& p : v) {
    for (int c = 0; c < 3; ++c) {
      if (std::strcmp(coordinate_type, "float") == 0) put<float>(s, p[c], big);
      else put<double>(s, static_cast<double>(p[c]), big);
      if (c == 0) put<std::uint8_t>(s, 200, big);
    }
    put<std::uint8_t>(s, 2, big);
    put<std::int16_t>(s, -5, big);
    put<std::int16_t>(s, 7, big);
  }
  const auto count = [&](std::uint32_t n) {
    if (std::strcmp(count_type, "uchar") == 0) put<std::uint8_t>(s, static_cast<std::uint8_t>(n), big);
    else if (std::strcmp(count_type, "ushort") == 0) put<std::uint16_t>(s, static_cast<std::uint16_t>(n), big);
    else put<std::uint32_t>(s, n, big);
  };
  count(4);
  for (std::uint32_t i : {0u, 1u, 2u, 3u}) {
    if (std::strcmp(index_type, "int") == 0) put<std::int32_t>(s, static_cast<std::int32_t>(i), big);
    else put<std::uint32_t>(s, i, big);
  }
  put<std::uint16_t>(s, 9, big);
  put<std::int32_t>(s, 0, big);
  put<std::int32_t>(s, 1, big);
  return s;
}

TEST(MeshFormats, PlyBinaryBothByteOrdersFloatExactlyAndSkippedProperties) {
  for (bool big : {false, true})
    for (const char* type : {"float", "double"})
      for (const char* ct : {"uchar", "ushort", "uint"})
        for (const char* it : {"int", "uint"}) {
          SCOPED_TRACE(std::string(big ? "big " : "little ") + type + " " + ct + " " + it);
          const ObjMesh m = ply(binary_quad(big, type, ct, it));
          ASSERT_EQ(m.vertices.size(), 4u);
          EXPECT_EQ(m.vertices[0].x, static_cast<double>(0.1f));  // not 0.1
          EXPECT_NE(m.vertices[0].x, 0.1);
          EXPECT_EQ(m.vertices[1].y, static_cast<double>(0.2f));
          EXPECT_EQ(m.vertices[2].z, static_cast<double>(1e-30f));
          EXPECT_EQ(m.vertices[3].z, -3.5);
          EXPECT_EQ(m.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}}));  // the fan
        }
}

TEST(MeshFormats, PlyAsciiFloatIsTheFloatNearestTheDecimal) {
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty ";
  const std::string rest = " x\nproperty double y\nproperty double z\nelement face 1\nproperty list uchar uint vertex_index\nend_header\n"
                           "0.1 0.1 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const ObjMesh f = ply(head + "float" + rest);
  EXPECT_EQ(f.vertices[0].x, static_cast<double>(0.1f));
  EXPECT_EQ(f.vertices[0].y, 0.1);
  const ObjMesh d = ply(head + "double" + rest);
  EXPECT_EQ(d.vertices[0].x, 0.1);
  EXPECT_EQ(d.triangles, (std::vector<Tri>{{0, 1, 2}}));
}

TEST(MeshFormats, PlyBinaryErrorsNameTheByteOffset) {
  const std::string good = binary_quad(false);
  ASSERT_NO_THROW(ply(good));
  const std::size_t body = good.find("end_header\n") + 11;
  // Truncated: every proper prefix of the body is an error, never a mesh.
  for (std::size_t cut = body; cut < good.size(); cut += 3)
    EXPECT_NE(ply_error(good.substr(0, cut)), "") << cut;
  EXPECT_NE(ply_error(good.substr(0, good.size() - 2)).find("m.ply: byte offset"), std::string::npos);
  EXPECT_NE(ply_error(good.substr(0, good.size() - 2)).find("truncated"), std::string::npos);
  // A header ending the file without its newline (found by mutation under ASan: it read past
  // the end).
  EXPECT_NE(ply_error("ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                      "property float z\nend_header")
                .find("truncated"),
            std::string::npos);
  // Trailing data: the counts are wrong.
  EXPECT_NE(ply_error(good + "xx").find("2 bytes of data after the last element"), std::string::npos);
  // Non-finite coordinate: vertex 0's x is the first 4 bytes of the body.
  std::string nan = good;
  const float q = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nan[body], &q, 4);
  EXPECT_EQ(ply_error(nan), "m.ply: byte offset " + std::to_string(body) +
                                " (vertex 0 of 4, property x): coordinate is not finite (NaN or infinity)");
  // Index out of range: the face's first index, after 4 vertices of 18 bytes and the count.
  std::string range = good;
  const std::int32_t bad = 4;
  std::memcpy(&range[body + 4 * 18 + 1], &bad, 4);
  EXPECT_EQ(ply_error(range), "m.ply: byte offset " + std::to_string(body + 4 * 18) +
                                  " (face 0 of 1, property vertex_indices): face vertex index 4 out of range (the file has 4 "
                                  "vertices, indices from 0)");
  std::string negative = good;
  const std::int32_t minus = -1;
  std::memcpy(&negative[body + 4 * 18 + 1], &minus, 4);
  EXPECT_NE(ply_error(negative).find("face vertex index -1 out of range"), std::string::npos);
  std::string repeated = good;
  const std::int32_t one = 1;
  std::memcpy(&repeated[body + 4 * 18 + 1], &one, 4);
  EXPECT_NE(ply_error(repeated).find("degenerate face: vertex 1 appears twice"), std::string::npos);
}

TEST(MeshFormats, PlyHeaderAndAsciiErrorsNameTheLine) {
  const std::string ok = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                         "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  ASSERT_EQ(ply(ok).triangles.size(), 1u);
  const auto with = [&](const std::string& from, const std::string& to) {
    return ply_error(replaced(ok, from, to));
  };
  EXPECT_EQ(with("property float y", "property float16 y"), "m.ply:5: unknown property type 'float16'");
  EXPECT_EQ(with("list uchar int", "list float int"), "m.ply:8: list count type 'float' is not an integer type");
  EXPECT_EQ(with("property float z", "property int z"), "m.ply:3: vertex property z is not of type float or double");
  EXPECT_EQ(with("property float z\n", ""), "m.ply:3: the vertex element has no property z");
  EXPECT_EQ(with("vertex_indices", "indices"), "m.ply:7: the face element has no list property vertex_indices");
  EXPECT_EQ(with("format ascii 1.0", "format ascii 2.0"), "m.ply:2: unsupported PLY version '2.0' (expected 1.0)");
  EXPECT_EQ(with("end_header\n", ""), "m.ply:9: unknown PLY header keyword '0' (expected format, comment, obj_info, element, property or end_header)");
  EXPECT_EQ(with("element vertex 3", "element vertex 4"), "m.ply:13: too many values for element 'vertex' (4, expected 3)");
  EXPECT_EQ(with("element face 1", "element face 2"), "m.ply:13: the file ends after 1 of the 2 'face' elements");
  EXPECT_EQ(with("element vertex 3", "element vertex 2"), "m.ply:12: too many values for element 'face' (3, expected 1)");
  EXPECT_EQ(with("1 0 0\n", "1 0\n"), "m.ply:11: too few values for element 'vertex' (property z missing)");
  EXPECT_EQ(with("1 0 0\n", "1 0 0 0\n"), "m.ply:11: too many values for element 'vertex' (4, expected 3)");
  EXPECT_EQ(with("1 0 0\n", "1 nan 0\n"), "m.ply:11: coordinate y 'nan' is not finite");
  EXPECT_EQ(with("1 0 0\n", "1 1e50 0\n"), "m.ply:11: property y: value '1e50' is out of the range of float");
  EXPECT_EQ(with("3 0 1 2\n", "3 0 1 3\n"), "m.ply:13: face vertex index 3 out of range (the file has 3 vertices, indices from 0)");
  EXPECT_EQ(with("3 0 1 2\n", "2 0 1\n"), "m.ply:13: face with 2 vertices (expected at least 3)");
  EXPECT_EQ(with("3 0 1 2\n", "3 0 1 2\n0 0 0\n"), "m.ply:14: data after the last element (wrong element counts in the header?)");
  EXPECT_EQ(with("3 0 1 2\n", "256 0 1 2\n"), "m.ply:13: the count of list vertex_indices: value '256' is out of the range of its type");
}

// --- OFF and STL ----------------------------------------------------------------------------

std::string off_error(const std::string& text) { return error_of(read_off, text, "m.off"); }

TEST(MeshFormats, OffFormsAndErrors) {
  std::istringstream in("# comment\nCOFF 4 2 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n1 1 0 1 1 1\n0 1 0 1 1 1 1\n"
                        "4 0 1 2 3  0.5 0.5 0.5\n\n3 3 2 1 # end\n");
  const ObjMesh m = read_off(in, "m.off");
  EXPECT_EQ(m.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}, {3, 2, 1}}));
  const std::string ok = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(off_error(ok), "");
  const auto with = [&](const std::string& from, const std::string& to) {
    return off_error(replaced(ok, from, to));
  };
  EXPECT_EQ(with("3 0 1 2", "3 0 1 3"), "m.off:6: face vertex index 3 out of range (the file has 3 vertices, indices from 0)");
  EXPECT_EQ(with("1 0 0\n", "1 inf 0\n"), "m.off:4: coordinate 'inf' is not finite (NaN or infinity)");
  EXPECT_EQ(with("1 0 0\n", "1 0\n"), "m.off:4: vertex with 2 numbers (expected 3)");
  EXPECT_EQ(with("3 1 0", "3 2 0"), "m.off:6: the file ends after 1 of the 2 faces");
  EXPECT_EQ(with("3 1 0", "4 1 0"), "m.off:6: vertex with 4 numbers (expected 3)");
  EXPECT_EQ(with("3 0 1 2\n", "3 0 1 2\n3 0 1 2\n"), "m.off:7: data after the last face (wrong counts?)");
  EXPECT_EQ(with("OFF", "4OFF"), "m.off:1: '4OFF': OFF of another dimension than 3 is not supported");
  EXPECT_EQ(with("3 1 0", "x 1 0"), "m.off:2: expected the counts 'vertices faces [edges]' (non-negative integers)");
}

std::string stl_error(const std::string& bytes) { return error_of(read_stl, bytes, "m.stl"); }

TEST(MeshFormats, StlMergesCornersAndReportsErrors) {
  std::string bin(80, ' ');
  put<std::uint32_t>(bin, 2, false);
  const float facets[2][3][3] = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{-0.0f, 0, 0}, {0, 1, 0}, {0.1f, 0.1f, 1}}};
  for (const auto& f : facets) {
    for (int k = 0; k < 3; ++k) put<float>(bin, 0, false);
    for (const auto& p : f)
      for (float c : p) put<float>(bin, c, false);
    put<std::uint16_t>(bin, 0, false);
  }
  std::istringstream in(bin);
  const ObjMesh m = read_stl(in, "m.stl");
  EXPECT_EQ(m.vertices.size(), 4u);  // -0 and +0 merged
  EXPECT_EQ(m.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(m.vertices[3].x, static_cast<double>(0.1f));
  EXPECT_EQ(stl_error(bin.substr(0, bin.size() - 1)),
            "m.stl: byte offset 80: binary STL of 2 facets needs 184 bytes, the file has 183 (truncated or extended)");
  std::string nan = bin;
  const float q = std::numeric_limits<float>::infinity();
  std::memcpy(&nan[84 + 50 + 12 + 4], &q, 4);
  EXPECT_EQ(stl_error(nan), "m.stl: byte offset 150 (facet 1): coordinate is not finite (NaN or infinity)");
  std::string degenerate = bin;
  std::memcpy(&degenerate[84 + 24], &degenerate[84 + 12], 12);
  EXPECT_EQ(stl_error(degenerate), "m.stl: byte offset 84 (facet 0): degenerate facet: two corners are equal");
  const std::string ascii = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
  EXPECT_EQ(stl_error(ascii), "");
  std::string missing = ascii;
  missing.erase(missing.find("vertex 0 1 0\n"), 13);
  EXPECT_EQ(stl_error(missing), "m.stl:6: expected 'vertex', found 'endloop'");
  EXPECT_EQ(stl_error(ascii.substr(0, ascii.find("endsolid"))), "m.stl:8: the file ends before 'endsolid'");
  std::string bad = ascii;
  bad.replace(bad.find("vertex 1 0 0"), 12, "vertex 1 x 0");
  EXPECT_EQ(stl_error(bad), "m.stl:5: coordinate 'x' is not a number");
}

// --- Found by the reader fuzz targets (fuzz/readers/, docs/fuzzing.md section 5) -----------

/// `bytes` written to a file named `name` in the test's temporary directory; its path.
std::string temp_file(const std::string& name, const std::string& bytes) {
  const std::string path = ::testing::TempDir() + "exactccd-mesh-formats-" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

/// The error of read_mesh on `path` ("" when it reads).
std::string read_mesh_error(const std::string& path) {
  try {
    read_mesh(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// A binary STL of two triangles with the given 80-byte header (padded with spaces).
std::string binary_stl(const std::string& header) {
  std::string bin = (header + std::string(80, ' ')).substr(0, 80);
  put<std::uint32_t>(bin, 2, false);
  const float facets[2][3][3] = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  for (const auto& f : facets) {
    for (int k = 0; k < 3; ++k) put<float>(bin, 0, false);
    for (const auto& p : f)
      for (float c : p) put<float>(bin, c, false);
    put<std::uint16_t>(bin, 0, false);
  }
  return bin;
}

// A binary STL's 80-byte header is free: one starting with "ply" was refused as "the content
// is PLY, but the extension says STL", one starting with the bytes of a UTF-8 byte order mark
// lost them to the mark's skipping and was refused as "the content is not STL (binary data)".
TEST(MeshFormats, ReadMeshTakesBinaryStlWhateverItsHeaderStartsWith) {
  for (const std::string header : {"ply\nsome exporter", "\xEF\xBB\xBFheader", "OFF", "solid but binary"}) {
    SCOPED_TRACE(header);
    const std::string path = temp_file("header.stl", binary_stl(header));
    EXPECT_EQ(detect_mesh_format(path), MeshFormat::stl);
    const TriangleMesh m = read_mesh(path);
    EXPECT_EQ(m.vertices.size(), 4u);
    EXPECT_EQ(m.triangles, (std::vector<Tri>{{0, 1, 2}, {1, 2, 3}}));
  }
  // A PLY file named .stl is still reported as what it is.
  EXPECT_EQ(read_mesh_error(temp_file("really.stl", "ply\nformat ascii 1.0\nend_header\n")),
            ::testing::TempDir() + "exactccd-mesh-formats-really.stl: the content is PLY, but the extension says STL");
}

// A byte order mark before a binary PLY's header: read_mesh skipped it before the reader, whose
// byte offsets then counted from after the mark, 3 short of the file's.
TEST(MeshFormats, ByteOffsetsCountAByteOrderMark) {
  std::string nan = binary_quad(false);
  const std::size_t body = nan.find("end_header\n") + 11;
  const float q = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nan[body], &q, 4);
  const std::string path = temp_file("bom.ply", "\xEF\xBB\xBF" + nan);
  EXPECT_EQ(read_mesh_error(path), path + ": byte offset " + std::to_string(body + 3) +
                                       " (vertex 0 of 4, property x): coordinate is not finite (NaN or infinity)");
  // The readers themselves skip the mark where the content is text, as read_mesh did.
  EXPECT_EQ(ply_error("\xEF\xBB\xBF" + binary_quad(true)), "");
  EXPECT_EQ(off_error("\xEF\xBB\xBFOFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "");
  EXPECT_EQ(stl_error("\xEF\xBB\xBFsolid\nendsolid\n"), "");
}

// read_off reads comments and blank lines before the keyword, format detection did not: a
// valid OFF file starting with a comment was "not OFF (text without the OFF header)".
TEST(MeshFormats, OffStartingWithACommentIsOff) {
  const std::string path = temp_file("comment.off", "# made by hand\n\n  OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(detect_mesh_format(path), MeshFormat::off);
  EXPECT_EQ(read_mesh(path).triangles, (std::vector<Tri>{{0, 1, 2}}));
  EXPECT_EQ(read_mesh_error(temp_file("comment.obj", "# c\nOFF\n3 1\n")),
            ::testing::TempDir() + "exactccd-mesh-formats-comment.obj: the content is OFF, but the extension says OBJ");
}

// Found by fuzz_read_off's third long run: format detection looked for OFF's keyword in the
// first 4 kB only, so an OFF file whose comments fill them was "not OFF" to read_mesh while
// read_off reads it (the keyword is now found after comments of any length, and the words may
// hold any bytes, as read_off takes them).
TEST(MeshFormats, OffAfterALongCommentIsOff) {
  const std::string off = "OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  for (const std::size_t length : {4000, 4095, 4096, 5000, 100000}) {
    const std::string path = temp_file("long-comment.off", "# " + std::string(length, 'c') + "\n" + off);
    EXPECT_EQ(detect_mesh_format(path), MeshFormat::off) << length;
    EXPECT_EQ(read_mesh(path).triangles, (std::vector<Tri>{{0, 1, 2}})) << length;
  }
  const std::string many_comments = temp_file("comments.off", std::string(3000, '#') + "\n" + std::string(2000, '\n') + off);
  EXPECT_EQ(detect_mesh_format(many_comments), MeshFormat::off);
  // An OBJ file with a long comment stays OBJ; a long comment before no OFF keyword is not OFF.
  EXPECT_EQ(detect_mesh_format(temp_file("long-comment.obj", "# " + std::string(5000, 'c') + "\nv 0 0 0\n")),
            MeshFormat::obj);
  EXPECT_EQ(read_mesh_error(temp_file("long-comment-no-keyword.off", "# " + std::string(5000, 'c') + "\n3 1\n")),
            ::testing::TempDir() + "exactccd-mesh-formats-long-comment-no-keyword.off: the content is not OFF (text without the OFF header)");
}

// An empty OFF file's error named line 0 (lines are 1-based).
TEST(MeshFormats, EmptyOffNamesLineOne) { EXPECT_EQ(off_error(""), "m.off:1: empty OFF file"); }

// Found by fuzz_read_off's second long run: a count written "-0" was read as 0 ("OFF\n\n-0 0 03\n"
// was an empty mesh): a count has no minus sign, in OFF's counts line, an OFF face's vertex
// count and a PLY element count; "+3" still is 3.
TEST(MeshFormats, MinusZeroIsNoCount) {
  const std::string counts = "m.off:2: expected the counts 'vertices faces [edges]' (non-negative integers)";
  EXPECT_EQ(off_error("OFF\n-0 0 03\n"), counts);
  EXPECT_EQ(off_error("OFF\n0 -0\n"), counts);
  EXPECT_EQ(off_error("OFF\n3 1 -0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), counts);
  EXPECT_EQ(off_error("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n-0 0 1 2\n"),
            "m.off:6: the face's vertex count '-0' is not a non-negative integer");
  EXPECT_EQ(off_error("OFF\n+3 1\n0 0 0\n1 0 0\n0 1 0\n+3 0 1 2\n"), "");
  EXPECT_EQ(ply_error("ply\nformat ascii 1.0\nelement vertex -0\nproperty float x\nend_header\n"),
            "m.ply:3: expected 'element NAME COUNT' with COUNT a non-negative integer");
}

// Found by fuzz_read_off's long run: the readers skipped a leading '+' before std::from_chars,
// which then read "+-1" as -1 ("OFF\n+-0 0\n" was an empty mesh). A sign after the '+' is no
// number now, in every field of every text format; "+1" still is 1.
TEST(MeshFormats, PlusMinusIsNoNumber) {
  EXPECT_EQ(off_error("OFF\n+-0 0\n"), "m.off:2: expected the counts 'vertices faces [edges]' (non-negative integers)");
  const std::string off = "OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const auto off_with = [&](const std::string& from, const std::string& to) {
    return off_error(replaced(off, from, to));
  };
  EXPECT_EQ(off_with("1 0 0", "+-1 0 0"), "m.off:4: coordinate '+-1' is not a number");
  EXPECT_EQ(off_with("1 0 0", "++1 0 0"), "m.off:4: coordinate '++1' is not a number");
  EXPECT_EQ(off_with("3 0 1 2", "3 +-0 1 2"), "m.off:6: face vertex index '+-0' is not an integer");
  EXPECT_EQ(off_with("1 0 0", "+1 +0 -0"), "");
  const std::string ply_text = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty double y\nproperty double z\n"
                               "property char c\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                               "0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n";
  const auto ply_with = [&](const std::string& from, const std::string& to) {
    return ply_error(replaced(ply_text, from, to));
  };
  EXPECT_EQ(ply_with("1 0 0 1", "+-1 0 0 1"), "m.ply:12: property x: value '+-1' is not a number");
  EXPECT_EQ(ply_with("1 0 0 1", "1 +-0.5 0 1"), "m.ply:12: property y: value '+-0.5' is not a number");
  EXPECT_EQ(ply_with("1 0 0 1", "1 0 0 +-1"), "m.ply:12: property c: value '+-1' is not an integer");
  EXPECT_EQ(ply_with("3 0 1 2", "+-3 0 1 2"), "m.ply:14: the count of list vertex_indices: value '+-3' is not an integer");
  EXPECT_EQ(ply_with("1 0 0 1", "+1 +0 +0 +1"), "");
  EXPECT_EQ(stl_error("solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex +-1 0 0\nvertex 0 1 0\nendloop\n"
                      "endfacet\nendsolid\n"),
            "m.stl:5: coordinate '+-1' is not a number");
}

// Found by reading: the repeated-vertex check compared every pair of a polygon's vertices.
TEST(MeshFormats, LargePolygonsAreCheckedForRepeatedVertices) {
  constexpr int kVertices = 50000;
  std::string off = "OFF\n" + std::to_string(kVertices) + " 1\n", face = std::to_string(kVertices);
  for (int i = 0; i < kVertices; ++i) {
    off += std::to_string(i) + " " + std::to_string(i % 5) + " 0\n";
    face += " " + std::to_string(i);
  }
  std::istringstream in(off + face + "\n");
  EXPECT_EQ(read_off(in, "m.off").triangles.size(), static_cast<std::size_t>(kVertices - 2));
  std::string repeated = face;
  repeated.replace(repeated.rfind(' '), std::string::npos, " 12");  // the last index becomes 12
  EXPECT_EQ(off_error(off + repeated + "\n"), "m.off:" + std::to_string(kVertices + 3) + ": degenerate face: vertex 12 appears twice");
}

}  // namespace
}  // namespace exactccd::io
