// The anchor of docs/scene.md's side-by-side measurement: one step of a mesh as the Scalable CCD
// CPU pipeline runs it. The harness's own source only: nothing in this repository builds or links
// it, nor the peer projects it calls (the figures were taken with it built by hand beside the
// repository against Scalable CCD 8f9347c and Tight Inclusion ca9a8c2, docs/scene.md). Broad phase:
// Scalable CCD's sort and sweep on oneTBB (vertex boxes from both frames, edge and face boxes their
// hulls; vertex-face pairs by two-list sweep, edge-edge by one-list sweep, pairs sharing a vertex
// dropped). Narrow phase: Tight Inclusion's CPU vertexFaceCCD / edgeEdgeCCD (tolerance 1e-6,
// 10^6 iterations, distance errors computed per query, breadth-first), in tbb::parallel_for,
// each query's t_max the earliest time of impact found so far (as IPC Toolkit's
// compute_collision_free_stepsize runs it). Prints one JSON line: candidates per kind, the
// earliest time of impact, and wall times.
//
//   scalable_ccd_step T0.(ply|obj) T1.(ply|obj) [--threads N]
#include <scalable_ccd/broad_phase/aabb.hpp>
#include <scalable_ccd/broad_phase/sort_and_sweep.hpp>
#include <tight_inclusion/ccd.hpp>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Mesh {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
};

template <class T>
T read_binary(std::istream& in, bool big_endian) {
  unsigned char b[sizeof(T)];
  if (!in.read(reinterpret_cast<char*>(b), sizeof(T))) throw std::runtime_error("truncated PLY");
  if (big_endian) std::reverse(b, b + sizeof(T));
  T x;
  std::memcpy(&x, b, sizeof(T));
  return x;
}

// Binary PLY with float or double x y z and a list of int or uint faces (uchar count), as the
// Scalable CCD dataset ships its frames.
Mesh read_ply(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line, format;
  long nv = 0, nf = 0;
  bool vertex_double = false, index_uchar_count = true;
  std::string element;
  while (std::getline(in, line) && line != "end_header") {
    std::istringstream s(line);
    std::string word;
    s >> word;
    if (word == "format") s >> format;
    if (word == "element") {
      s >> element;
      (element == "vertex" ? nv : nf) = 0;
      s >> (element == "vertex" ? nv : nf);
    }
    if (word == "property" && element == "vertex") {
      std::string type;
      s >> type;
      vertex_double = type == "double" || type == "float64";
    }
    if (word == "property" && element == "face") {
      std::string list, count;
      s >> list >> count;
      index_uchar_count = count == "uchar" || count == "uint8";
    }
  }
  if (format != "binary_big_endian" && format != "binary_little_endian") throw std::runtime_error(path + ": not binary PLY");
  const bool big = format == "binary_big_endian";
  Mesh m{Eigen::MatrixXd(nv, 3), Eigen::MatrixXi(nf, 3)};
  for (long i = 0; i < nv; ++i)
    for (int k = 0; k < 3; ++k)
      m.V(i, k) = vertex_double ? read_binary<double>(in, big) : read_binary<float>(in, big);
  for (long f = 0; f < nf; ++f) {
    const int n = index_uchar_count ? read_binary<std::uint8_t>(in, big) : read_binary<int>(in, big);
    if (n != 3) throw std::runtime_error(path + ": not a triangle mesh");
    for (int k = 0; k < 3; ++k) m.F(f, k) = read_binary<int>(in, big);
  }
  return m;
}

// OBJ with `v x y z` and triangle `f a b c` lines (1-based, possibly a/b/c), as exactccd
// generate scene writes them.
Mesh read_obj(const std::string& path) {
  std::ifstream in(path);
  std::vector<double> v;
  std::vector<int> f;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string word;
    s >> word;
    if (word == "v") {
      double x, y, z;
      s >> x >> y >> z;
      v.insert(v.end(), {x, y, z});
    } else if (word == "f") {
      for (int k = 0; k < 3; ++k) {
        std::string corner;
        s >> corner;
        f.push_back(std::stoi(corner.substr(0, corner.find('/'))) - 1);
      }
    }
  }
  Mesh m{Eigen::MatrixXd(static_cast<long>(v.size() / 3), 3), Eigen::MatrixXi(static_cast<long>(f.size() / 3), 3)};
  for (long i = 0; i < m.V.rows(); ++i)
    for (int k = 0; k < 3; ++k) m.V(i, k) = v[3 * i + k];
  for (long i = 0; i < m.F.rows(); ++i)
    for (int k = 0; k < 3; ++k) m.F(i, k) = f[3 * i + k];
  return m;
}

Mesh read_mesh(const std::string& path) {
  return path.size() > 4 && path.substr(path.size() - 4) == ".obj" ? read_obj(path) : read_ply(path);
}

Eigen::MatrixXi unique_edges(const Eigen::MatrixXi& F) {
  std::vector<std::pair<int, int>> e;
  for (long f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      e.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  Eigen::MatrixXi E(static_cast<long>(e.size()), 2);
  for (long i = 0; i < E.rows(); ++i) E(i, 0) = e[i].first, E(i, 1) = e[i].second;
  return E;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: scalable_ccd_step T0 T1 [--threads N]\n");
    return 2;
  }
  int threads = 0;
  for (int i = 3; i + 1 < argc; ++i)
    if (std::string(argv[i]) == "--threads") threads = std::stoi(argv[i + 1]);
  std::unique_ptr<tbb::global_control> control;
  if (threads > 0)
    control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  const Mesh m0 = read_mesh(argv[1]), m1 = read_mesh(argv[2]);
  const auto start = std::chrono::steady_clock::now();
  const Eigen::MatrixXi E = unique_edges(m0.F);
  std::vector<scalable_ccd::AABB> vertex_boxes, edge_boxes, face_boxes;
  scalable_ccd::build_vertex_boxes(m0.V, m1.V, vertex_boxes);
  scalable_ccd::build_edge_boxes(vertex_boxes, E, edge_boxes);
  scalable_ccd::build_face_boxes(vertex_boxes, m0.F, face_boxes);
  std::vector<std::pair<int, int>> vf, ee;
  int axis = 0;
  scalable_ccd::sort_and_sweep(vertex_boxes, face_boxes, axis, vf);
  axis = 0;
  scalable_ccd::sort_and_sweep(edge_boxes, axis, ee);
  const double broad = seconds_since(start);

  const auto narrow_start = std::chrono::steady_clock::now();
  std::atomic<double> earliest{1.0};
  std::atomic<long> hits{0};
  const auto lower = [&](double toi) {
    for (double current = earliest.load(); toi < current && !earliest.compare_exchange_weak(current, toi);) {
    }
  };
  const auto row = [](const Eigen::MatrixXd& V, int i) { return ticcd::Vector3(V.row(i).transpose()); };
  const ticcd::Array3 err(-1, -1, -1);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vf.size()), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t k = r.begin(); k < r.end(); ++k) {
      const int v = vf[k].first, f = vf[k].second;
      double toi = 0, tolerance_out = 0;
      if (ticcd::vertexFaceCCD(row(m0.V, v), row(m0.V, m0.F(f, 0)), row(m0.V, m0.F(f, 1)), row(m0.V, m0.F(f, 2)),
                               row(m1.V, v), row(m1.V, m0.F(f, 0)), row(m1.V, m0.F(f, 1)), row(m1.V, m0.F(f, 2)), err,
                               0.0, toi, 1e-6, earliest.load(), 1000000, tolerance_out, false,
                               ticcd::CCDRootFindingMethod::BREADTH_FIRST_SEARCH)) {
        ++hits;
        lower(toi);
      }
    }
  });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ee.size()), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t k = r.begin(); k < r.end(); ++k) {
      const int a = ee[k].first, b = ee[k].second;
      double toi = 0, tolerance_out = 0;
      if (ticcd::edgeEdgeCCD(row(m0.V, E(a, 0)), row(m0.V, E(a, 1)), row(m0.V, E(b, 0)), row(m0.V, E(b, 1)),
                             row(m1.V, E(a, 0)), row(m1.V, E(a, 1)), row(m1.V, E(b, 0)), row(m1.V, E(b, 1)), err, 0.0,
                             toi, 1e-6, earliest.load(), 1000000, tolerance_out, false,
                             ticcd::CCDRootFindingMethod::BREADTH_FIRST_SEARCH)) {
        ++hits;
        lower(toi);
      }
    }
  });
  const double narrow = seconds_since(narrow_start);
  std::printf("{\"vertices\": %ld, \"triangles\": %ld, \"vf_candidates\": %zu, \"ee_candidates\": %zu, "
              "\"hits_below_running_earliest\": %ld, \"earliest_toi\": %.17g, \"broad_s\": %.4f, \"narrow_s\": %.4f, "
              "\"step_s\": %.4f, \"threads\": %d}\n",
              static_cast<long>(m0.V.rows()), static_cast<long>(m0.F.rows()), vf.size(), ee.size(), hits.load(),
              earliest.load(), broad, narrow, broad + narrow, threads);
  return 0;
}
