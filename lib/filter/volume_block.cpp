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

/// The groups and the verdict of every lane, one lane after the other: the per-query stage's
/// functions on each lane (volume_groups_of, stage_one_verdict), a loop of the same operations
/// on every lane that the compiler turns into vector instructions of the caller's target. It
/// writes to locals (copied out after it), which the compiler knows alias none of the lanes it
/// reads: written straight to the caller's arrays, the stores could alias the lanes, and the
/// run-time alias checks that would need exceed GCC's limit (the loop was not vectorized:
/// filter.simd_registers). The groups are copied out only when asked (the tests' view of the
/// stage's intermediate values); the stage itself needs the verdicts.
template <class Query>
[[gnu::always_inline]] inline void block_body(const pipeline::QueryLanes<Query>& b, VolumeGroupLanes* groups_out,
                                              VerdictLanes& verdicts_out) {
  VolumeGroupLanes groups;
  VerdictLanes verdicts;
  for (std::size_t i = 0; i < kLanes; ++i) {
    const auto row = [&](int r) {
      const auto& c = b.coordinate[static_cast<std::size_t>(r)];
      return Vec3{c[0][i], c[1][i], c[2][i]};
    };
    const VolumeGroups g = volume_groups_of<kinds::kind_of<Query>>(row);
    groups.threshold[i] = g.threshold;
    for (std::size_t m = 0; m < 4; ++m) {
      groups.sum[m][i] = g.sum[m];
      groups.permanent[m][i] = g.permanent[m];
    }
    bool excluded = false, out_of_range = false;
    stage_one_verdict(g, excluded, out_of_range);
    verdicts.excluded[i] = excluded ? 1.0 : 0.0;
    verdicts.out_of_range[i] = out_of_range ? 1.0 : 0.0;
  }
  verdicts_out = verdicts;
  if (groups_out) *groups_out = groups;
}

// One function per level and kind: the same body, compiled for that instruction set (flatten:
// every call inlined, so that the whole body is compiled for it). tests/filter's
// simd_registers check reads their code: the AVX-512 ones use zmm registers, the AVX2 ones ymm.
using VertexFaceLanes = pipeline::QueryLanes<VertexFaceQuery>;
using EdgeEdgeLanes = pipeline::QueryLanes<EdgeEdgeQuery>;
__attribute__((flatten, noinline)) void baseline(const VertexFaceLanes& b, VolumeGroupLanes* g, VerdictLanes& v) {
  block_body(b, g, v);
}
__attribute__((flatten, noinline)) void baseline(const EdgeEdgeLanes& b, VolumeGroupLanes* g, VerdictLanes& v) {
  block_body(b, g, v);
}
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((flatten, noinline, target("avx2"))) void avx2(const VertexFaceLanes& b, VolumeGroupLanes* g,
                                                             VerdictLanes& v) {
  block_body(b, g, v);
}
__attribute__((flatten, noinline, target("avx2"))) void avx2(const EdgeEdgeLanes& b, VolumeGroupLanes* g,
                                                             VerdictLanes& v) {
  block_body(b, g, v);
}
__attribute__((flatten, noinline, target("avx512f"))) void avx512(const VertexFaceLanes& b, VolumeGroupLanes* g,
                                                                  VerdictLanes& v) {
  block_body(b, g, v);
}
__attribute__((flatten, noinline, target("avx512f"))) void avx512(const EdgeEdgeLanes& b, VolumeGroupLanes* g,
                                                                  VerdictLanes& v) {
  block_body(b, g, v);
}
#endif

/// The block's verdicts (and groups, when `groups` is not null) at `level`.
template <class Query>
void run_at(const pipeline::QueryLanes<Query>& lanes, numeric::SimdLevel level, VolumeGroupLanes* groups,
            VerdictLanes& verdicts) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (level == numeric::SimdLevel::avx512) return avx512(lanes, groups, verdicts);
  if (level == numeric::SimdLevel::avx2) return avx2(lanes, groups, verdicts);
#endif
  baseline(lanes, groups, verdicts);
}

}  // namespace

template <class Query>
void volume_groups_block(const pipeline::QueryLanes<Query>& lanes, numeric::SimdLevel level, VolumeGroupLanes& out) {
  VerdictLanes unused;
  run_at(lanes, level, &out, unused);
}

template <class Query>
VolumeLaneVerdicts volume_exclusion_block(const pipeline::QueryLanes<Query>& lanes, numeric::SimdLevel level) {
  VerdictLanes v;
  run_at(lanes, level, nullptr, v);
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
