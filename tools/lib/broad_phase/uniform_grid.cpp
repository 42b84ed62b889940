#include "broad_phase/uniform_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace exactccd::tools {
using scene::hull;  // the exact hull (min and max) of two boxes

double UniformGrid::mean_edge_extent(const std::vector<scene::Box>& vertex_boxes, const std::vector<scene::Edge>& edges) {
  double sum = 0;
  std::size_t counted = 0;
  for (const scene::Edge& e : edges) {
    const scene::Box b = hull(vertex_boxes[static_cast<std::size_t>(e[0])], vertex_boxes[static_cast<std::size_t>(e[1])]);
    const double extent = std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]});
    if (std::isfinite(extent)) sum += extent, ++counted;
  }
  return counted > 0 && sum > 0 ? sum / static_cast<double>(counted) : 1.0;
}

UniformGrid::UniformGrid(const std::vector<scene::Box>& vertex_boxes, const std::vector<scene::Triangle>& triangles,
                         const std::vector<scene::Edge>& edges, const std::vector<int>& vertices, double cell)
    : vertex_boxes_(vertex_boxes), triangles_(triangles), edges_(edges), vertices_(vertices) {
  if (!(cell > 0) || !std::isfinite(cell)) throw std::invalid_argument("UniformGrid: the cell side must be positive");
  // The grid spans the finite bounds of every vertex box (a primitive's box is their hull);
  // infinite bounds fall into the end cells by clamping.
  std::array<double, 3> lo{}, hi{};
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (const scene::Box& b : vertex_boxes)
    for (int k = 0; k < 3; ++k) {
      if (std::isfinite(b.lo[k])) lo[k] = std::min(lo[k], b.lo[k]);
      if (std::isfinite(b.hi[k])) hi[k] = std::max(hi[k], b.hi[k]);
    }
  inverse_cell_ = 1 / cell;
  for (int k = 0; k < 3; ++k) {
    if (!(lo[k] <= hi[k])) lo[k] = hi[k] = 0;
    origin_[k] = lo[k];
    // At most 2^20 cells per axis (keys fit in 60 bits); more would be a cell far too small.
    // Clamped as a double first: the quotient may overflow (a tiny cell), and converting a
    // double beyond the int64 range is undefined.
    const double span = std::floor((hi[k] - lo[k]) * inverse_cell_) + 1;
    cells_[k] = span < 0x1p20 ? std::max<std::int64_t>(1, static_cast<std::int64_t>(span)) : std::int64_t{1} << 20;
  }
  triangle_boxes_.resize(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) triangle_boxes_[t] = triangle_box(t);
  edge_boxes_.resize(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) edge_boxes_[e] = edge_box(e);
  triangle_cells_ = entries(triangles.size(), [&](std::size_t t) { return triangle_boxes_[t]; });
  edge_cells_ = entries(edges.size(), [&](std::size_t e) { return edge_boxes_[e]; });
  vertex_cells_ = entries(vertices.size(), [&](std::size_t v) { return vertex_boxes[static_cast<std::size_t>(vertices[v])]; });
}

std::array<std::int64_t, 3> UniformGrid::cell_of(const std::array<double, 3>& x) const {
  std::array<std::int64_t, 3> c{};
  for (int k = 0; k < 3; ++k) {
    const double q = std::floor((x[k] - origin_[k]) * inverse_cell_);  // monotone in x[k]
    c[k] = !(q > 0) ? 0 : q >= static_cast<double>(cells_[k] - 1) ? cells_[k] - 1 : static_cast<std::int64_t>(q);
  }
  return c;
}

std::uint64_t UniformGrid::key(const std::array<std::int64_t, 3>& c) const {
  return static_cast<std::uint64_t>(c[0] + cells_[0] * (c[1] + cells_[1] * c[2]));
}

template <class BoxOf>
std::vector<UniformGrid::Entry> UniformGrid::entries(std::size_t n, BoxOf&& box_of) const {
  std::vector<Entry> out;
  out.reserve(2 * n);
  for (std::size_t p = 0; p < n; ++p) {
    const scene::Box b = box_of(p);
    const auto from = cell_of(b.lo), to = cell_of(b.hi);
    std::int64_t covered = 1;
    for (int k = 0; k < 3; ++k) covered *= to[k] - from[k] + 1;
    if (covered > (std::int64_t{1} << 16))  // a box far larger than the cells (or unbounded): not this structure's case
      throw std::length_error("UniformGrid: a primitive's box covers more than 65536 cells");
    for (std::int64_t z = from[2]; z <= to[2]; ++z)
      for (std::int64_t y = from[1]; y <= to[1]; ++y)
        for (std::int64_t x = from[0]; x <= to[0]; ++x) out.push_back({key({x, y, z}), static_cast<int>(p)});
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool UniformGrid::owns(std::uint64_t cell_key, const scene::Box& a, const scene::Box& b) const {
  return key(cell_of({std::max(a.lo[0], b.lo[0]), std::max(a.lo[1], b.lo[1]), std::max(a.lo[2], b.lo[2])})) == cell_key;
}

scene::Box UniformGrid::triangle_box(std::size_t t) const {
  const scene::Triangle& tri = triangles_[t];
  return hull(hull(vertex_boxes_[static_cast<std::size_t>(tri[0])], vertex_boxes_[static_cast<std::size_t>(tri[1])]),
              vertex_boxes_[static_cast<std::size_t>(tri[2])]);
}

scene::Box UniformGrid::edge_box(std::size_t e) const {
  return hull(vertex_boxes_[static_cast<std::size_t>(edges_[e][0])], vertex_boxes_[static_cast<std::size_t>(edges_[e][1])]);
}

}  // namespace exactccd::tools
