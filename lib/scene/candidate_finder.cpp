#include "scene/candidate_finder.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

#include "scene/parallel.hpp"

namespace exactccd::scene {
namespace {

/// Query items per chunk of work.
constexpr std::size_t kChunk = 256;

/// The pairs of items 0..n-1: emit(i, out) appends item i's pairs to `out`, sorted, each item's
/// first index increasing with i; the chunks' outputs are joined in chunk order, so the result
/// is sorted whatever thread ran which chunk.
template <class Emit>
std::vector<std::array<int, 2>> gather(std::size_t n, unsigned threads, Emit&& emit) {
  // Each chunk's pairs are found in its worker's scratch list and stored at their exact size,
  // so the chunks hold no spare capacity.
  std::vector<std::vector<std::array<int, 2>>> chunks((n + kChunk - 1) / kChunk), scratch(threads);
  parallel_chunks(n, threads, kChunk, [&](std::size_t begin, std::size_t end, unsigned w) {
    std::vector<std::array<int, 2>>& out = scratch[w];
    out.clear();
    for (std::size_t i = begin; i < end; ++i) emit(i, out);
    chunks[begin / kChunk].assign(out.begin(), out.end());
    return true;
  });
  std::vector<std::vector<std::array<int, 2>>>().swap(scratch);
  std::size_t total = 0;
  for (const auto& c : chunks) total += c.size();
  std::vector<std::array<int, 2>> all;
  all.reserve(total);
  for (auto& c : chunks) {
    all.insert(all.end(), c.begin(), c.end());
    std::vector<std::array<int, 2>>().swap(c);  // freed as it is copied
  }
  return all;
}

}  // namespace

BroadPhaseTrees::BroadPhaseTrees(const std::vector<Triangle>& triangles, const std::vector<Edge>& edges,
                                 const std::vector<int>& vertices, const std::vector<int>& points)
    : triangles_(triangles), edges_(edges), vertices_(vertices), points_(points) {}

Box BroadPhaseTrees::triangle_box(std::size_t t) const {
  const Triangle& tri = triangles_[t];
  return hull(hull(vertex_boxes_[tri[0]], vertex_boxes_[tri[1]]), vertex_boxes_[tri[2]]);
}

Box BroadPhaseTrees::edge_box(std::size_t e) const {
  return hull(vertex_boxes_[edges_[e][0]], vertex_boxes_[edges_[e][1]]);
}

void BroadPhaseTrees::fit(std::vector<Box> vertex_boxes, unsigned threads) {
  if (built_ && vertex_boxes.size() != vertex_boxes_.size())
    throw std::invalid_argument("BroadPhaseTrees::fit: the number of vertices changed");
  vertex_boxes_ = std::move(vertex_boxes);
  const auto triangle = [&](std::size_t t) { return triangle_box(t); };
  const auto edge = [&](std::size_t e) { return edge_box(e); };
  const auto point = [&](std::size_t i) { return point_box(i); };
  if (!built_) {
    triangle_tree_.build(triangles_.size(), triangle, threads);
    edge_tree_.build(edges_.size(), edge, threads);
    point_tree_.build(points_.size(), point, threads);
    built_ = true;
  } else {
    triangle_tree_.refit(triangles_.size(), triangle, threads);
    edge_tree_.refit(edges_.size(), edge, threads);
    point_tree_.refit(points_.size(), point, threads);
  }
}

Candidates BroadPhaseTrees::candidates(unsigned threads) const {
  if (!built_) throw std::logic_error("BroadPhaseTrees::candidates before fit");
  const auto sorted_tail = [](std::vector<std::array<int, 2>>& out, std::size_t from) {
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(from), out.end());
  };
  Candidates c;
  if (!triangles_.empty())
    c.vertex_face = gather(vertices_.size(), threads, [&](std::size_t i, std::vector<std::array<int, 2>>& out) {
      const int v = vertices_[i];
      const std::size_t from = out.size();
      triangle_tree_.query(vertex_boxes_[v], [&](int t) {
        const Triangle& tri = triangles_[t];
        if (tri[0] != v && tri[1] != v && tri[2] != v) out.push_back({v, t});
      });
      sorted_tail(out, from);
    });
  c.edge_edge = gather(edges_.size(), threads, [&](std::size_t i, std::vector<std::array<int, 2>>& out) {
    const Edge& a = edges_[i];
    const std::size_t from = out.size();
    edge_tree_.query(edge_box(i), [&](int j) {
      const Edge& b = edges_[j];
      if (j > static_cast<int>(i) && a[0] != b[0] && a[0] != b[1] && a[1] != b[0] && a[1] != b[1])
        out.push_back({static_cast<int>(i), j});
    });
    sorted_tail(out, from);
  });
  if (!points_.empty()) {
    // Isolated points are on no edge and distinct: no pair shares a vertex.
    c.point_edge = gather(points_.size(), threads, [&](std::size_t i, std::vector<std::array<int, 2>>& out) {
      const std::size_t from = out.size();
      edge_tree_.query(point_box(i), [&](int e) { out.push_back({points_[i], e}); });
      sorted_tail(out, from);
    });
    c.point_point = gather(points_.size(), threads, [&](std::size_t i, std::vector<std::array<int, 2>>& out) {
      const std::size_t from = out.size();
      point_tree_.query(point_box(i), [&](int j) {
        if (j > static_cast<int>(i)) out.push_back({points_[i], points_[j]});  // points ascending
      });
      sorted_tail(out, from);
    });
  }
  return c;
}

}  // namespace exactccd::scene
