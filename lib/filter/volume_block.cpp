#include "filter/volume_block.hpp"

#include "filter/volume_exclusion.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd::filter {
namespace {

/// volume_excluded on one lane: volume_exclusion's computation (the same cross terms,
/// determinants, group sums, threshold and bound: volume_exclusion.hpp's proof), written
/// without its early returns so that every lane does the same operations; a lane is excluded
/// iff all four group signs are certified and equal, which is volume_exclusion's `excluded`
/// (the early returns there only stop at the first group that is not).
[[gnu::always_inline]] inline bool lane_excluded(const Vec3& u0, const Vec3& u1, const Vec3& v0, const Vec3& v1,
                                                 const Vec3& w0, const Vec3& w1) {
  const double threshold = underflow_threshold(u0, u1, v0, v1, w0, w1);
  const CrossTerms c00 = cross_terms(v0, w0), c11 = cross_terms(v1, w1), c10 = cross_terms(v1, w0),
                   c01 = cross_terms(v0, w1);
  const RoundedDeterminant d000 = rounded_determinant(u0, c00), d111 = rounded_determinant(u1, c11);
  const RoundedDeterminant d100 = rounded_determinant(u1, c00), d010 = rounded_determinant(u0, c10),
                           d001 = rounded_determinant(u0, c01);
  const RoundedDeterminant d110 = rounded_determinant(u1, c10), d101 = rounded_determinant(u1, c01),
                           d011 = rounded_determinant(u0, c11);
  const double sum[4] = {d000.value, d100.value + d010.value + d001.value, d110.value + d101.value + d011.value,
                         d111.value};
  const double permanent[4] = {d000.permanent, d100.permanent + d010.permanent + d001.permanent,
                               d110.permanent + d101.permanent + d011.permanent, d111.permanent};
  bool positive = true, negative = true;
  for (int m = 0; m < 4; ++m) {
    // certified_group_sign: +1 iff in range and sum > tau, -1 iff in range and sum < -tau.
    const bool in_range = permanent[m] >= threshold;
    const double tau = group_error_bound(permanent[m]);
    positive = positive & in_range & (sum[m] > tau);
    negative = negative & in_range & (sum[m] < -tau);
  }
  return positive | negative;
}

/// Each lane's answer, 1 (excluded) or 0, as a double: the comparisons' masks select it
/// directly (with bool or 64-bit integer answers GCC 12 found the SSE2 loop unprofitable, and a
/// bool array kept AVX2 to 16-byte vectors).
using Excluded = std::array<double, kVolumeBlock>;

/// The block's lanes, one after the other: a loop of the same operations on every lane, which
/// the compiler turns into vector instructions of the caller's target.
template <class Kind>
[[gnu::always_inline]] inline void block_body(const VolumeBlock& b, Excluded& excluded) {
  constexpr auto v = Kind::volume_rows;
  constexpr int n = Kind::points;  // the row of a point at t1 is n rows after its row at t0
  for (std::size_t i = 0; i < kVolumeBlock; ++i) {
    const auto row = [&](int r) {
      const auto& c = b.coordinate[static_cast<std::size_t>(r)];
      return Vec3{c[0][i], c[1][i], c[2][i]};
    };
    const bool lane = lane_excluded(
        rounded_difference(row(v[1]), row(v[0])), rounded_difference(row(v[1] + n), row(v[0] + n)),
        rounded_difference(row(v[2]), row(v[0])), rounded_difference(row(v[2] + n), row(v[0] + n)),
        rounded_difference(row(v[3]), row(v[0])), rounded_difference(row(v[3] + n), row(v[0] + n)));
    excluded[i] = lane ? 1.0 : 0.0;
  }
}

// One function per level and kind: the same body, compiled for that instruction set (flatten:
// every call inlined, so that the whole body is compiled for it).
using VertexFace = kinds::kind_of<VertexFaceQuery>;
using EdgeEdge = kinds::kind_of<EdgeEdgeQuery>;
__attribute__((flatten, noinline)) void baseline(const VolumeBlock& b, Excluded& e, const VertexFace*) {
  block_body<VertexFace>(b, e);
}
__attribute__((flatten, noinline)) void baseline(const VolumeBlock& b, Excluded& e, const EdgeEdge*) {
  block_body<EdgeEdge>(b, e);
}
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((flatten, target("avx2"))) void avx2(const VolumeBlock& b, Excluded& e, const VertexFace*) {
  block_body<VertexFace>(b, e);
}
__attribute__((flatten, target("avx2"))) void avx2(const VolumeBlock& b, Excluded& e, const EdgeEdge*) {
  block_body<EdgeEdge>(b, e);
}
__attribute__((flatten, target("avx512f"))) void avx512(const VolumeBlock& b, Excluded& e, const VertexFace*) {
  block_body<VertexFace>(b, e);
}
__attribute__((flatten, target("avx512f"))) void avx512(const VolumeBlock& b, Excluded& e, const EdgeEdge*) {
  block_body<EdgeEdge>(b, e);
}
#endif

}  // namespace

void VolumeBlock::push(const std::array<Vec3, 8>& rows) {
  for (std::size_t r = 0; r < 8; ++r) {
    coordinate[r][0][size] = rows[r].x;
    coordinate[r][1][size] = rows[r].y;
    coordinate[r][2][size] = rows[r].z;
  }
  ++size;
}

template <class Query>
std::uint32_t volume_excluded_block(const VolumeBlock& block, numeric::SimdLevel level) {
  const kinds::kind_of<Query>* kind = nullptr;
  Excluded excluded;
#if defined(__x86_64__) && defined(__GNUC__)
  if (level == numeric::SimdLevel::avx512)
    avx512(block, excluded, kind);
  else if (level == numeric::SimdLevel::avx2)
    avx2(block, excluded, kind);
  else
#endif
    baseline(block, excluded, kind);
  std::uint32_t mask = 0;
  for (std::size_t i = 0; i < block.size; ++i)
    if (excluded[i] != 0) mask |= std::uint32_t{1} << i;
  return mask;
}

template std::uint32_t volume_excluded_block<VertexFaceQuery>(const VolumeBlock&, numeric::SimdLevel);
template std::uint32_t volume_excluded_block<EdgeEdgeQuery>(const VolumeBlock&, numeric::SimdLevel);

}  // namespace exactccd::filter
