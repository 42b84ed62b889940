// The result of the rigid interval walks (contact_walk.hpp, separation_walk.hpp): decided
// (collides, with the TOI when certified, or separate) or undecided, and whether GMP was used.
// rigid_filter.cpp's IntervalStage turns it into the pipeline's Outcome (docs/design.md, 9.4).
#pragma once

#include <optional>

#include "exactccd/types.hpp"

namespace exactccd::rigid {

/// What a stage concluded about a query.
struct StageResult {
  enum class Answer { undecided, collides, separate };
  Answer answer = Answer::undecided;
  /// With collides: the tightest TOI when asked (else any enclosure of the earliest time).
  std::optional<TimeInterval> toi;
  /// GMP was used on the way (an exact sign): counted as `integer`.
  bool used_gmp = false;

  static StageResult undecided(bool used_gmp = false) { return {Answer::undecided, std::nullopt, used_gmp}; }
  static StageResult separate(bool used_gmp = false) { return {Answer::separate, std::nullopt, used_gmp}; }
  static StageResult collides(const TimeInterval& toi, bool used_gmp = false) { return {Answer::collides, toi, used_gmp}; }
  bool decided() const { return answer != Answer::undecided; }
};

}  // namespace exactccd::rigid
