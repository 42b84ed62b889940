// Rigid queries whose answer is a linear query's (docs/design.md 9.2, "a regression anchor"):
// with equal constant rotations the bodies only translate, and a translating body's points
// move on straight lines. Built from the bundled vertex-face and edge-edge data (every file of
// data/catalogue, data/families and data/sim): each body takes its points' positions at t0 as
// body points (rotated back by the constant rotation, which is a signed permutation here, so
// exactly), and translates by the motion of its first point (rounded to a double: the linear
// counterpart is built from the same numbers, exactly in rationals).
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "exactccd/rational.hpp"
#include "exactccd/rigid.hpp"
#include "io/benchmark_csv.hpp"

namespace exactccd::rigid_test {

/// A constant rotation under which coordinates permute and change sign exactly: R(q) v and its
/// inverse as functions, with the quaternions each body uses at t0 and t1 (same rotation,
/// different lengths and signs allowed).
struct ExactRotation {
  const char* name;
  Quaternion a0, a1, b0, b1;
  Vec3 (*inverse)(const Vec3&);  ///< R^T v
};

/// The rotations of the anchor: the identity, a quarter turn about x (R (x, y, z) = (x, -z, y))
/// with quaternions of changing length, and the half turn about (0, 1, 1) (R (x, y, z) =
/// (-x, z, y)) with q and -2q.
inline const std::vector<ExactRotation>& exact_rotations() {
  static const std::vector<ExactRotation> r{
      {"identity", {1, 0, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}, [](const Vec3& v) { return v; }},
      {"quarter_x", {1, 1, 0, 0}, {3, 3, 0, 0}, {2, 2, 0, 0}, {0.5, 0.5, 0, 0},
       [](const Vec3& v) { return Vec3{v.x, v.z, -v.y}; }},
      {"half_yz", {0, 0, 1, 1}, {0, 0, 1, 1}, {0, 0, -2, -2}, {0, 0, -2, -2},
       [](const Vec3& v) { return Vec3{-v.x, v.z, v.y}; }},
  };
  return r;
}

/// A rigid query and the linear query (rational rows, benchmark order) with the same answer.
template <class RigidQuery>
struct AnchorCase {
  std::string name;
  RigidQuery rigid;
  std::array<RationalVec3, 8> linear;  ///< points at t0 then at t1, the kind's order
};

/// The motion of one coordinate's first point, as a double (0 when it overflows).
inline double step(double from, double to) {
  const double d = to - from;
  return std::isfinite(d) ? d : 0.0;
}

/// The anchor case of a linear query's rows (doubles) under a rotation: A's points are the
/// kind's first `first` points.
template <class RigidQuery>
AnchorCase<RigidQuery> anchor_case(const std::string& name, const std::array<Vec3, 8>& rows, const ExactRotation& r,
                                   bool translate_b) {
  constexpr int first = std::is_same_v<RigidQuery, RigidVertexFaceQuery> ? 1 : 2;
  const Vec3 da{step(rows[0].x, rows[4].x), step(rows[0].y, rows[4].y), step(rows[0].z, rows[4].z)};
  const Vec3 db = translate_b ? Vec3{step(rows[first].x, rows[first + 4].x), step(rows[first].y, rows[first + 4].y),
                                     step(rows[first].z, rows[first + 4].z)}
                              : Vec3{0, 0, 0};
  AnchorCase<RigidQuery> c;
  c.name = name + " " + r.name + (translate_b ? " both" : " a");
  c.rigid.a_t0 = {{0, 0, 0}, r.a0};
  c.rigid.a_t1 = {da, r.a1};
  c.rigid.b_t0 = {{0, 0, 0}, r.b0};
  c.rigid.b_t1 = {db, r.b1};
  std::array<Vec3, 4> body;
  for (int i = 0; i < 4; ++i) body[i] = r.inverse(rows[i]);
  if constexpr (std::is_same_v<RigidQuery, RigidVertexFaceQuery>)
    c.rigid.p = body[0], c.rigid.a = body[1], c.rigid.b = body[2], c.rigid.c = body[3];
  else
    c.rigid.a0 = body[0], c.rigid.a1 = body[1], c.rigid.b0 = body[2], c.rigid.b1 = body[3];
  for (int i = 0; i < 4; ++i) {
    const Vec3& v = rows[i];
    const Vec3& d = i < first ? da : db;
    c.linear[i] = {mpq_class(v.x), mpq_class(v.y), mpq_class(v.z)};
    c.linear[i + 4] = {mpq_class(v.x) + d.x, mpq_class(v.y) + d.y, mpq_class(v.z) + d.z};
  }
  return c;
}

/// The rows (doubles) of every query of the bundled files of a kind ("vertex-face" or
/// "edge-edge" in the name), with names.
inline std::vector<std::pair<std::string, std::array<Vec3, 8>>> bundled_rows(const std::string& kind) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (const char* dir : {"catalogue", "families", "sim"})
    for (const auto& e : fs::directory_iterator(fs::path(EXACTCCD_SOURCE_DIR) / "data" / dir))
      if (e.path().extension() == ".csv" && e.path().filename().string().find(kind) != std::string::npos)
        files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<std::pair<std::string, std::array<Vec3, 8>>> out;
  for (const fs::path& f : files) {
    std::ifstream in(f);
    const io::BenchmarkQueries q = io::read_benchmark_csv(in, f.string());
    for (std::size_t i = 0; i < q.size(); ++i)
      if (const auto d = io::exact_double_rows(q.rows[i])) out.push_back({f.filename().string() + "#" + std::to_string(i), *d});
  }
  return out;
}

}  // namespace exactccd::rigid_test
