// Stage 1 of the contact question (volume_exclusion.hpp) on a block of queries at once: the
// queries' coordinates in structure-of-arrays lanes, the same certified test lane by lane
// (the same operations in the same order, so the same rounded values and the same answer as
// volume_excluded on each query, bit for bit, at every SIMD level), evaluated with the vector
// instruction set numeric::simd_level() names. Callers hand the queries it does not exclude to
// the question's stages (which start with the same stage 1 on the same query).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "exactccd/types.hpp"
#include "numeric/simd_level.hpp"

namespace exactccd::filter {

/// Queries per block: two AVX-512 registers' worth of lanes per coordinate.
constexpr std::size_t kVolumeBlock = 16;

/// A block of up to kVolumeBlock vertex-face or edge-edge queries: coordinate[r][c][lane] is
/// coordinate c (x, y, z) of row r (rows(q) order: the four points at t0, then at t1) of the
/// query in that lane. Lanes at and beyond `size` hold earlier or zero values: they are
/// evaluated and ignored (every lane is finite, so nothing traps or slows down).
struct VolumeBlock {
  alignas(64) std::array<std::array<std::array<double, kVolumeBlock>, 3>, 8> coordinate{};
  std::size_t size = 0;

  /// Puts a query's eight rows into lane `size` and counts it; the block must not be full.
  void push(const std::array<Vec3, 8>& rows);
  /// Whether every lane holds a query.
  bool full() const { return size == kVolumeBlock; }
};

/// The lanes i < block.size whose query (a Query: VertexFaceQuery or EdgeEdgeQuery, for the
/// kind's volume rows) volume_excluded proves never coplanar in [0, 1]: bit i of the result is
/// volume_excluded(the query in lane i). Evaluated with the instruction set of `level`, which the
/// CPU must support (numeric::simd_level() is one); the same bits at every level.
template <class Query>
std::uint32_t volume_excluded_block(const VolumeBlock& block, numeric::SimdLevel level);

}  // namespace exactccd::filter
