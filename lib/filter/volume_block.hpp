// Stage 1 of the contact question (volume_exclusion.hpp) on a block of queries at once, its
// block form (pipeline/block.hpp): the queries' coordinates in structure-of-arrays lanes, and
// per lane the same function as the per-query stage (volume_groups_of, then
// stage_one_verdict: the same operations in the same order, so the same rounded values, the
// same verdict and the same handover, bit for bit, at every SIMD level), evaluated with the
// vector instruction set numeric::simd_level() names.
#pragma once

#include <array>
#include <cstddef>

#include "numeric/simd_level.hpp"
#include "pipeline/block.hpp"

namespace exactccd::filter {

/// The groups of every lane's volume (VolumeGroups of volume_exclusion.hpp, one lane each):
/// threshold[lane], sum[m][lane], permanent[m][lane].
struct VolumeGroupLanes {
  alignas(64) std::array<double, pipeline::kLanes> threshold{};
  alignas(64) std::array<std::array<double, pipeline::kLanes>, 4> sum{};
  alignas(64) std::array<std::array<double, pipeline::kLanes>, 4> permanent{};
};

/// volume_groups(the query in lane i) for every lane i < lanes.size of a block of Query
/// (VertexFaceQuery or EdgeEdgeQuery), into `out`, with the instruction set of `level` (which
/// the CPU must support: numeric::simd_level() is one). The stage's intermediate values, for
/// the tests that hold the block form to the per-query one bit for bit.
template <class Query>
void volume_groups_block(const pipeline::QueryLanes<Query>& lanes, numeric::SimdLevel level, VolumeGroupLanes& out);

/// Stage 1's verdicts on a block: bit i of `excluded` is stage_one_verdict(lane i).excluded,
/// of `out_of_range` its out_of_range, for i < lanes.size.
struct VolumeLaneVerdicts {
  pipeline::LaneMask excluded = 0;      ///< V(t) != 0 on [0, 1] proved
  pipeline::LaneMask out_of_range = 0;  ///< the bound did not apply (a retry on the scaled query may decide)
};

/// Stage 1 on every lane of a block of Query, with the instruction set of `level` (as above).
template <class Query>
VolumeLaneVerdicts volume_exclusion_block(const pipeline::QueryLanes<Query>& lanes, numeric::SimdLevel level);

}  // namespace exactccd::filter
