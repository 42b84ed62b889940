// Stage 2 of the filtered method: interval arithmetic (CGAL::Interval_nt) on the polynomials
// of the contact rule. Isolates the roots of the volume V in [0, 1] by Bernstein subdivision
// and evaluates the in-plane rule over each isolating interval; decides whenever every sign
// it needs is certain, and otherwise says "uncertain" so that a later stage decides.
#pragma once

#include <optional>

#include "exactccd/types.hpp"

namespace exactccd::filter {

/// What a filter stage concluded about a query.
enum class Verdict { no_collision, collision, uncertain };

/// A dyadic cell [lo, hi] = [a 2^-k, (a + 1) 2^-k] of [0, 1] holding exactly one root of the
/// volume V, a simple one, with V's (nonzero) sign at lo; V's sign at hi is the opposite.
struct VolumeRootCell {
  double lo = 0, hi = 1;
  int sign_at_lo = 0;
};

/// A stage's conclusion and, for a collision, the earliest time of impact when the stage could
/// certify it (tightest double interval, as the public API promises). A collision without a
/// certified TOI may carry the cell of V's root that is the TOI (toi_cell), for a later stage
/// to narrow.
struct StageResult {
  StageResult() = default;
  /// A verdict and, for a collision, its certified TOI when known.
  StageResult(Verdict v, std::optional<TimeInterval> t = std::nullopt) : verdict(v), toi(t) {}

  Verdict verdict = Verdict::uncertain;
  std::optional<TimeInterval> toi;
  std::optional<VolumeRootCell> toi_cell;
};

/// Stage 2 for vertex-face. With want_toi, a collision's TOI is certified or left empty.
StageResult interval_stage(const VertexFaceQuery& q, bool want_toi);

/// Stage 2 for edge-edge. With want_toi, a collision's TOI is certified or left empty.
StageResult interval_stage(const EdgeEdgeQuery& q, bool want_toi);

}  // namespace exactccd::filter
