// OBJ input and output (tools/lib/io/obj.hpp): the accepted forms, fan triangulation, relative
// indices, exact round trips, and every error naming file and line.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "io/obj.hpp"

namespace exactccd::io {
namespace {

ObjMesh parse(const std::string& text) {
  std::istringstream in(text);
  return read_obj(in, "mesh.obj");
}

/// The ParseError message of parsing `text` ("" when it parses).
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

using Tri = std::array<int, 3>;

TEST(Obj, VerticesFacesAndIgnoredLines) {
  const ObjMesh m = parse(
      "# a comment\n"
      "mtllib scene.mtl\n"
      "o thing\n"
      "v 0 0 0\n"
      "v 1.5 -2 3e-3 1.0\n"  // w is ignored
      "v +4 5 6   # trailing comment\r\n"
      "vn 0 0 1\n"
      "vt 0.5 0.5\n"
      "\n"
      "  v 7 8 9\n"
      "s off\n"
      "usemtl red\n"
      "f 1 2 3\n"
      "f 1/1 2/1/1 4//1\n"
      "l 1 2\n");
  ASSERT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.vertices[1].x, 1.5);
  EXPECT_EQ(m.vertices[1].z, 3e-3);
  EXPECT_EQ(m.vertices[2].x, 4.0);
  EXPECT_EQ(m.vertices[3].z, 9.0);
  EXPECT_EQ(m.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 1, 3}}));
}

TEST(Obj, PolygonsNegativeAndForwardIndices) {
  const ObjMesh m = parse(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "f 1 2 3 4\n"       // a quad: (1 2 3), (1 3 4)
      "f -4 -3 -1\n"      // relative to the four vertices read so far
      "f 5 6 7 8 9\n"     // a pentagon over vertices defined below
      "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nv 0.5 1.5 1\n");
  EXPECT_EQ(m.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}, {0, 1, 3}, {4, 5, 6}, {4, 6, 7}, {4, 7, 8}}));
}

TEST(Obj, ExactRoundTrip) {
  const std::vector<Vec3> v = {{0.1, -0.0, 1e-310}, {1.0 / 3, 2.5e300, -7}, {0x1.fffffffffffffp-1, 5e-324, 42}};
  const std::vector<Tri> t = {{0, 1, 2}, {2, 1, 0}};
  std::stringstream s;
  write_obj(s, v, t, "two lines\nof comment");
  EXPECT_EQ(s.str().rfind("# two lines\n# of comment\nv ", 0), 0u) << s.str();
  const ObjMesh m = read_obj(s, "round-trip");
  ASSERT_EQ(m.vertices.size(), v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_EQ(m.vertices[i].x, v[i].x);
    EXPECT_EQ(std::signbit(m.vertices[i].y), std::signbit(v[i].y));
    EXPECT_EQ(m.vertices[i].y, v[i].y);
    EXPECT_EQ(m.vertices[i].z, v[i].z);
  }
  EXPECT_EQ(m.triangles, t);
}

TEST(Obj, ErrorsNameFileAndLine) {
  const std::string three = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(error_of(three + "f 1 2 3\n"), "");
  EXPECT_EQ(error_of("v 0 0\n"), "mesh.obj:1: vertex with 2 coordinates (expected x y z)");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 x 0\n"), "mesh.obj:2: coordinate 'x' is not a number");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 2z 0\n"), "mesh.obj:2: coordinate '2z' is not a number");
  EXPECT_EQ(error_of("v nan 0 0\n"), "mesh.obj:1: coordinate 'nan' is not finite (NaN or infinity)");
  EXPECT_EQ(error_of("v 0 -inf 0\n"), "mesh.obj:1: coordinate '-inf' is not finite (NaN or infinity)");
  EXPECT_EQ(error_of("v 0 0 1e400\n"), "mesh.obj:1: coordinate '1e400' is out of the range of double");
  EXPECT_EQ(error_of(three + "f 1 2\n"), "mesh.obj:4: face with 2 vertices (expected at least 3)");
  EXPECT_EQ(error_of(three + "f 1 2 0\n"), "mesh.obj:4: face vertex index 0 (OBJ indices start at 1)");
  EXPECT_EQ(error_of(three + "f 1 a 3\n"), "mesh.obj:4: face vertex 'a' does not start with an integer index");
  EXPECT_EQ(error_of(three + "f 1 /2 3\n"), "mesh.obj:4: face vertex '/2' does not start with an integer index");
  EXPECT_EQ(error_of(three + "f 1 2 3\nf 1 2 4\n"), "mesh.obj:5: face vertex 4 out of range (the file has 3 vertices)");
  EXPECT_EQ(error_of(three + "f -1 -2 -4\n"),
            "mesh.obj:4: face vertex -4 refers before the first vertex (3 vertices read so far)");
  EXPECT_EQ(error_of(three + "f 1 2 1\n"), "mesh.obj:4: degenerate face: vertex 1 appears twice");
  EXPECT_EQ(error_of(three + "f 1 2 3 -3\n"), "mesh.obj:4: degenerate face: vertex 1 appears twice");
}

TEST(Obj, StrictKeywordsAndNumbers) {
  const std::string three = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(error_of(three + "f 1 2 3\nvx 1 2 3\n"),
            "mesh.obj:5: unknown OBJ keyword 'vx' (expected v, vt, vn, vp, f, l, p, o, g, s, mtllib, usemtl or a "
            "# comment)");
  EXPECT_EQ(error_of("ply\n" + three), "mesh.obj:1: unknown OBJ keyword 'ply' (expected v, vt, vn, vp, f, l, p, o, g, "
                                        "s, mtllib, usemtl or a # comment)");
  EXPECT_EQ(error_of(three + "curv 0 1 1 2\n"),
            "mesh.obj:4: OBJ free-form geometry ('curv') is not supported (triangle and polygon faces only)");
  EXPECT_EQ(error_of("v 0 0 0 1 2\n"), "mesh.obj:1: vertex with 5 numbers (expected x y z, x y z w or x y z r g b)");
  EXPECT_EQ(error_of("v 0 0 0 w\n"), "mesh.obj:1: coordinate 'w' is not a number");
  EXPECT_EQ(error_of("v 0 0 0 0.5 0.5 inf\n"), "mesh.obj:1: coordinate 'inf' is not finite (NaN or infinity)");
  EXPECT_EQ(error_of("vn 0 1\n"), "mesh.obj:1: normal with 2 numbers (expected 3)");
  EXPECT_EQ(error_of("vt 0 1 2 3\n"), "mesh.obj:1: texture vertex with 4 numbers (expected 1 to 3)");
  EXPECT_EQ(error_of("vt 0.5 x\n"), "mesh.obj:1: coordinate 'x' is not a number");
  EXPECT_EQ(error_of("vp nan\n"), "mesh.obj:1: coordinate 'nan' is not finite (NaN or infinity)");
  EXPECT_EQ(error_of(three + "l 1\n"), "mesh.obj:4: line with 1 vertices (expected at least 2)");
  EXPECT_EQ(error_of(three + "p x\n"), "mesh.obj:4: face vertex 'x' does not start with an integer index");
  for (const char* bad : {"1/", "1/x", "1/0", "1//", "1//0", "1/2/", "1/2/x", "1/2/3/4"})
    EXPECT_EQ(error_of(three + "f " + bad + " 2 3\n"),
              std::string("mesh.obj:4: face vertex '") + bad +
                  "' is malformed (expected i, i/t, i//n or i/t/n, nonzero integers)")
        << bad;
  // The accepted forms.
  EXPECT_EQ(error_of(three + "f 1/1 2//2 3/3/3\nl 1 2 3\np 1\no x\ng a b\ns off\nmtllib m.mtl\nusemtl red\n"
                             "vt 0.5\nvt 0.5 0.5 0\nvt 0 0\nvn 0 0 1\nvn 0 1 0\nvn 1 0 0\nvp 0.5 0.5\nv 1 2 3 1\n"
                             "v 1 2 3 0.5 0.5 0.5\n"),
            "");
}

// Found by the reader fuzz target (fuzz/readers/fuzz_read_obj.cpp, docs/fuzzing.md section 5):
// references of l and p lines to no vertex, and of any line to no texture vertex or normal,
// were accepted (only the face vertices were checked).
TEST(Obj, ReferencesToMissingElementsAreErrors) {
  const std::string three = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(error_of(three + "f 1 2 3\nl 1 32\n"), "mesh.obj:5: line vertex 32 out of range (the file has 3 vertices)");
  EXPECT_EQ(error_of(three + "p 4\n"), "mesh.obj:4: point vertex 4 out of range (the file has 3 vertices)");
  EXPECT_EQ(error_of(three + "p -4\n"), "mesh.obj:4: point vertex -4 refers before the first vertex (3 vertices read so far)");
  EXPECT_EQ(error_of(three + "vt 0 0\nf 1/1 2/2 3/1\n"),
            "mesh.obj:5: face texture vertex 2 out of range (the file has 1 texture vertices)");
  EXPECT_EQ(error_of(three + "f 1//1 2//1 3//-1\nvn 0 0 1\n"),
            "mesh.obj:4: face normal -1 refers before the first normal (0 normals read so far)");
  EXPECT_EQ(error_of(three + "f 1 2 3\nl 1/7 2/1\nvt 0 0\n"),
            "mesh.obj:5: line texture vertex 7 out of range (the file has 1 texture vertices)");
  // Forward references to later lines stay allowed, and the first bad line is the one named.
  EXPECT_EQ(error_of("f 1/2/1 2/1/1 3/1/1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 1\nvn 0 0 1\n"), "");
  EXPECT_EQ(error_of(three + "f 1/1 2/1 3/1\nf 1/1 2/1 4/1\nl 9 1\nvt 0 0\n"),
            "mesh.obj:5: face vertex 4 out of range (the file has 3 vertices)");
}

// Found by fuzz_read_off (the same parsing as read_obj's): "+-1" was read as -1.
TEST(Obj, PlusMinusIsNoNumber) {
  EXPECT_EQ(error_of("v +-1 0 0\n"), "mesh.obj:1: coordinate '+-1' is not a number");
  EXPECT_EQ(error_of("v 0 0 0\nvt ++0.5\n"), "mesh.obj:2: coordinate '++0.5' is not a number");
  EXPECT_EQ(error_of("v +1 0 0\n"), "");
}

// Found by reading (the fuzz targets' inputs are too short to show it): the check that a face
// repeats no vertex compared every pair, minutes for a polygon of a million vertices. A
// polygon of 50 000 vertices is checked in linear-logarithmic time now, with the same answer.
TEST(Obj, LargePolygonsAreCheckedForRepeatedVertices) {
  constexpr int kVertices = 50000;
  std::string text, face = "f";
  for (int i = 1; i <= kVertices; ++i) {
    text += "v " + std::to_string(i) + " " + std::to_string(i % 7) + " 0\n";
    face += " " + std::to_string(i);
  }
  EXPECT_EQ(parse(text + face + "\n").triangles.size(), static_cast<std::size_t>(kVertices - 2));
  EXPECT_EQ(error_of(text + face + " 17 3\n"),
            "mesh.obj:" + std::to_string(kVertices + 1) + ": degenerate face: vertex 17 appears twice");
}

TEST(Obj, ByteOrderMarkLosesNoLine) {
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const ObjMesh with = parse("\xEF\xBB\xBF" + text), without = parse(text);
  EXPECT_EQ(with.vertices.size(), 3u);
  EXPECT_EQ(with.triangles, without.triangles);
  EXPECT_EQ(error_of("\xEF\xBB\xBFv 0 0\n"), "mesh.obj:1: vertex with 2 coordinates (expected x y z)");
}

}  // namespace
}  // namespace exactccd::io
