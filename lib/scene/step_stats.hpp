// Where a scene step's time goes (exactccd scene --stats): filled by the streamed scene
// functions when asked for (a null pointer costs nothing).
#pragma once

#include <array>
#include <cstddef>

namespace exactccd::scene {

/// Counters and times of one streamed scene call.
struct StepStats {
  /// Broad-phase candidates found, per kind in CollisionKind order (vertex-face, edge-edge,
  /// point-edge, point-point): every pair whose boxes overlap, whether or not it was decided
  /// (earliest_toi and is_collision_free drop or stop early).
  std::array<std::size_t, 4> candidates{};
  /// Wall seconds before the pairs stream: validation, topology (unique edges), vertex boxes, the
  /// trees built (or refitted).
  double setup_seconds = 0;
  /// Wall seconds of the streamed loop (tree traversal and narrow phase together, in parallel).
  double stream_seconds = 0;
  /// CPU seconds of the loop's tree traversal, summed over the workers (thread CPU-time clock).
  double traversal_thread_seconds = 0;
  /// CPU seconds of the loop's narrow phase (the batches of pairs decided), summed over the
  /// workers (thread CPU-time clock).
  double narrow_thread_seconds = 0;
  /// Workers of the loop.
  unsigned workers = 0;
};

}  // namespace exactccd::scene
