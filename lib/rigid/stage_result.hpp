// The result of one filtered stage of a rigid query: decided (collides, with the TOI when the
// stage certified it, or separate) or undecided. The same shape as the one pipeline protocol of
// issue 22 (pipeline::Outcome: undecided / collides / separate, the TOI, GMP use); when that
// protocol lands, these stages return its Outcome and rigid_filter.cpp's stage order becomes a
// stage list (docs/design.md, 9.4).
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
