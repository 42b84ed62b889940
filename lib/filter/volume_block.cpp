#include "filter/volume_block.hpp"

#include "filter/volume_exclusion.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd::filter {
namespace {

using pipeline::kLanes;

/// Each lane's verdict flags as doubles, 1 or 0: the comparisons' masks select them directly
/// (with bool or 64-bit integer answers GCC 12 found the SSE2 loop unprofitable, and a bool
/// array kept AVX2 to 16-byte vectors).
struct VerdictLanes {
  alignas(64) std::array<double, kLanes> excluded;
  alignas(64) std::array<double, kLanes> out_of_range;
};

/// The groups of every lane, one after the other: the per-query stage's function on each lane,
/// a loop of the same operations on every lane that the compiler turns into vector instructions
/// of the caller's target.
template <class Query>
[[gnu::always_inline]] inline void groups_body(const pipeline::QueryLanes<Query>& b, VolumeGroupLanes& out) {
  for (std::size_t i = 0; i < kLanes; ++i) {
    const auto row = [&](int r) {
      const auto& c = b.coordinate[static_cast<std::size_t>(r)];
      return Vec3{c[0][i], c[1][i], c[2][i]};
    };
    const VolumeGroups g = volume_groups_of<kinds::kind_of<Query>>(row);
    out.threshold[i] = g.threshold;
    for (std::size_t m = 0; m < 4; ++m) {
      out.sum[m][i] = g.sum[m];
      out.permanent[m][i] = g.permanent[m];
    }
  }
}

/// The verdict of every lane from its groups (stage_one_verdict per lane).
[[gnu::always_inline]] inline void verdict_body(const VolumeGroupLanes& g, VerdictLanes& out) {
  for (std::size_t i = 0; i < kLanes; ++i) {
    const VolumeGroups lane{g.threshold[i],
                            {g.sum[0][i], g.sum[1][i], g.sum[2][i], g.sum[3][i]},
                            {g.permanent[0][i], g.permanent[1][i], g.permanent[2][i], g.permanent[3][i]}};
    bool excluded = false, out_of_range = false;
    stage_one_verdict(lane, excluded, out_of_range);
    out.excluded[i] = excluded ? 1.0 : 0.0;
    out.out_of_range[i] = out_of_range ? 1.0 : 0.0;
  }
}

/// Both loops: the groups, then the verdicts. Each loop writes to a local of its own (copied
/// out after it), which the compiler knows aliases none of its inputs: written straight to the
/// caller's arrays, the stores could alias the lanes read, and the run-time alias checks that
/// would need exceed GCC's limit (the loops were not vectorized: filter.simd_registers).
template <class Query>
[[gnu::always_inline]] inline void block_body(const pipeline::QueryLanes<Query>& b, VolumeGroupLanes& g,
                                              VerdictLanes* verdicts) {
  VolumeGroupLanes groups;
  groups_body(b, groups);
  if (verdicts) {
    VerdictLanes v;
    verdict_body(groups, v);
    *verdicts = v;
  }
  g = groups;
}

// One function per level and kind: the same body, compiled for that instruction set (flatten:
// every call inlined, so that the whole body is compiled for it). tests/filter's
// simd_registers check reads their code: the AVX-512 ones use zmm registers, the AVX2 ones ymm.
using VertexFaceLanes = pipeline::QueryLanes<VertexFaceQuery>;
using EdgeEdgeLanes = pipeline::QueryLanes<EdgeEdgeQuery>;
__attribute__((flatten, noinline)) void baseline(const VertexFaceLanes& b, VolumeGroupLanes& g, VerdictLanes* v) {
  block_body(b, g, v);
}
__attribute__((flatten, noinline)) void baseline(const EdgeEdgeLanes& b, VolumeGroupLanes& g, VerdictLanes* v) {
  block_body(b, g, v);
}
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((flatten, noinline, target("avx2"))) void avx2(const VertexFaceLanes& b, VolumeGroupLanes& g,
                                                             VerdictLanes* v) {
  block_body(b, g, v);
}
__attribute__((flatten, noinline, target("avx2"))) void avx2(const EdgeEdgeLanes& b, VolumeGroupLanes& g,
                                                             VerdictLanes* v) {
  block_body(b, g, v);
}
__attribute__((flatten, noinline, target("avx512f"))) void avx512(const VertexFaceLanes& b, VolumeGroupLanes& g,
                                                                  VerdictLanes* v) {
  block_body(b, g, v);
}
__attribute__((flatten, noinline, target("avx512f"))) void avx512(const EdgeEdgeLanes& b, VolumeGroupLanes& g,
                                                                  VerdictLanes* v) {
  block_body(b, g, v);
}
#endif

/// The block's groups (and verdicts, when `verdicts` is not null) at `level`.
template <class Query>
void run_at(const pipeline::QueryLanes<Query>& lanes, numeric::SimdLevel level, VolumeGroupLanes& g,
            VerdictLanes* verdicts) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (level == numeric::SimdLevel::avx512) return avx512(lanes, g, verdicts);
  if (level == numeric::SimdLevel::avx2) return avx2(lanes, g, verdicts);
#endif
  baseline(lanes, g, verdicts);
}

}  // namespace

template <class Query>
void volume_groups_block(const pipeline::QueryLanes<Query>& lanes, numeric::SimdLevel level, VolumeGroupLanes& out) {
  run_at(lanes, level, out, nullptr);
}

template <class Query>
VolumeLaneVerdicts volume_exclusion_block(const pipeline::QueryLanes<Query>& lanes, numeric::SimdLevel level) {
  VolumeGroupLanes g;
  VerdictLanes v;
  run_at(lanes, level, g, &v);
  VolumeLaneVerdicts mask;
  for (std::size_t i = 0; i < lanes.size; ++i) {
    if (v.excluded[i] != 0) mask.excluded |= pipeline::LaneMask{1} << i;
    if (v.out_of_range[i] != 0) mask.out_of_range |= pipeline::LaneMask{1} << i;
  }
  return mask;
}

template void volume_groups_block(const pipeline::QueryLanes<VertexFaceQuery>&, numeric::SimdLevel, VolumeGroupLanes&);
template void volume_groups_block(const pipeline::QueryLanes<EdgeEdgeQuery>&, numeric::SimdLevel, VolumeGroupLanes&);
template VolumeLaneVerdicts volume_exclusion_block(const pipeline::QueryLanes<VertexFaceQuery>&, numeric::SimdLevel);
template VolumeLaneVerdicts volume_exclusion_block(const pipeline::QueryLanes<EdgeEdgeQuery>&, numeric::SimdLevel);

}  // namespace exactccd::filter
