// The exact minimum-separation path: GMP rationals for the terms of separation_terms.hpp,
// CGAL's Algebraic_kernel_d_1 for their roots and for exact signs at those roots.
#pragma once

#include <array>
#include <optional>

#include "exactccd/rational.hpp"
#include "exactccd/types.hpp"

namespace exactccd::separation {

/// Which of a kind's feature pairs (kinds::Feature, at most 9) take part: mask[f] for the f-th.
using FeatureMask = std::array<bool, 9>;

/// The earliest t in [0, tmax] with dist(A(t), B(t)) <= d, exactly (d = params.min_distance,
/// tmax = params.tmax, validated by the caller), in the tightest double interval, or nullopt.
/// Also for d = 0 (an independent computation of the contact answer: the tests compare it
/// with exact::toi).
std::optional<TimeInterval> exact_toi(const RationalVertexFaceQuery& q, const RationalCcdParams& params);
/// See exact_toi(const RationalVertexFaceQuery&, const RationalCcdParams&).
std::optional<TimeInterval> exact_toi(const RationalEdgeEdgeQuery& q, const RationalCcdParams& params);
/// See exact_toi(const RationalVertexFaceQuery&, const RationalCcdParams&).
std::optional<TimeInterval> exact_toi(const RationalPointEdgeQuery& q, const RationalCcdParams& params);
/// See exact_toi(const RationalVertexFaceQuery&, const RationalCcdParams&).
std::optional<TimeInterval> exact_toi(const RationalPointPointQuery& q, const RationalCcdParams& params);
/// See exact_toi(const RationalVertexFaceQuery&, const RationalCcdParams&).
std::optional<TimeInterval> exact_toi(const RationalEdgeEdge2dQuery& q, const RationalCcdParams& params);
/// See exact_toi(const RationalVertexFaceQuery&, const RationalCcdParams&).
std::optional<TimeInterval> exact_toi(const RationalPointEdge2dQuery& q, const RationalCcdParams& params);
/// See exact_toi(const RationalVertexFaceQuery&, const RationalCcdParams&).
std::optional<TimeInterval> exact_toi(const RationalPointPoint2dQuery& q, const RationalCcdParams& params);

/// exact_toi with only the feature pairs f with use[f]: the same answer whenever every pair left
/// out holds nowhere in [0, tmax] (S of docs/design.md 4b.2 is the same set; the filtered
/// method leaves out the pairs a separating direction keeps apart, feature_separated).
std::optional<TimeInterval> exact_toi(const RationalVertexFaceQuery& q, const RationalCcdParams& params, const FeatureMask& use);
/// See exact_toi(const RationalVertexFaceQuery&, const RationalCcdParams&, const FeatureMask&).
std::optional<TimeInterval> exact_toi(const RationalEdgeEdgeQuery& q, const RationalCcdParams& params, const FeatureMask& use);
/// See exact_toi(const RationalVertexFaceQuery&, const RationalCcdParams&, const FeatureMask&).
std::optional<TimeInterval> exact_toi(const RationalPointEdgeQuery& q, const RationalCcdParams& params, const FeatureMask& use);
/// See exact_toi(const RationalVertexFaceQuery&, const RationalCcdParams&, const FeatureMask&).
std::optional<TimeInterval> exact_toi(const RationalPointPointQuery& q, const RationalCcdParams& params, const FeatureMask& use);
/// See exact_toi(const RationalVertexFaceQuery&, const RationalCcdParams&, const FeatureMask&).
std::optional<TimeInterval> exact_toi(const RationalEdgeEdge2dQuery& q, const RationalCcdParams& params, const FeatureMask& use);
/// See exact_toi(const RationalVertexFaceQuery&, const RationalCcdParams&, const FeatureMask&).
std::optional<TimeInterval> exact_toi(const RationalPointEdge2dQuery& q, const RationalCcdParams& params, const FeatureMask& use);
/// See exact_toi(const RationalVertexFaceQuery&, const RationalCcdParams&, const FeatureMask&).
std::optional<TimeInterval> exact_toi(const RationalPointPoint2dQuery& q, const RationalCcdParams& params, const FeatureMask& use);

}  // namespace exactccd::separation
