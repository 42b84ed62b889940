// The one protocol of the filtered method's stages, for both questions it answers (contact,
// d = 0, and minimum separation, d > 0; docs/design.md, 5.0).
//
// A query goes through a list of stages, cheapest first. Each stage takes the query and its
// question (Work: the query, CcdParams, whether the TOI is asked) and returns an Outcome:
// decided (the primitives collide, with the TOI when the stage certified it, or they stay
// apart), or undecided; what it learned on the way (a root cell, the feature pairs proven
// apart, ...) it leaves in the Work's findings for the stages after it. run_stages.hpp is the
// whole policy; the stage lists of each question are in lib/questions/.
#pragma once

#include <cstdint>
#include <optional>

#include "exactccd/ccd.hpp"
#include "exactccd/stats.hpp"
#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd::pipeline {

/// What a question asks of a query: the primitives within params.min_distance at some t in
/// [0, params.tmax]; with want_toi, also the earliest such t (the tightest double interval).
struct Question {
  CcdParams params;
  bool want_toi = false;
};

/// A counter of StageCounters (a pointer to the member), or nullptr for none.
using Counter = std::uint64_t StageCounters::*;

/// What a stage concluded about a query: the one result type of every stage.
struct Outcome {
  /// The answer, when the stage decided it.
  enum class Answer : std::uint8_t { undecided, collides, separate };
  Answer answer = Answer::undecided;
  /// With `collides`: the TOI when the stage certified it: the tightest double interval when
  /// the question asks for the TOI, else any enclosure of the earliest time (or nothing).
  std::optional<TimeInterval> toi;
  /// The counter at which a query this outcome decides is counted, when not the stage's own
  /// (a stage that had to use GMP counts as `integer`).
  Counter counted_as = nullptr;

  /// Not decided: the next stage takes the query.
  static Outcome undecided() { return {}; }
  /// The primitives stay apart (farther than d over [0, tmax]).
  static Outcome separate() { return {Answer::separate, std::nullopt, nullptr}; }
  /// The primitives collide; `toi` as above.
  static Outcome collides(std::optional<TimeInterval> toi = std::nullopt) { return {Answer::collides, toi, nullptr}; }
};

/// The TOI restricted to [0, tmax]: the exact time t lies in [lo, hi] (lo == hi, or lo < t < hi
/// with no double between them), so for a double tmax, t <= tmax iff hi <= tmax (or lo <= tmax
/// when lo == hi == t).
inline std::optional<TimeInterval> cut(const std::optional<TimeInterval>& t, double tmax) {
  if (!t) return t;
  const bool within = t->lo == t->hi ? t->lo <= tmax : t->hi <= tmax;
  return within ? t : std::nullopt;
}

/// A dyadic cell [lo, hi] of [0, 1] holding exactly one root of the contact volume V, a simple
/// one, with V's (nonzero) sign at lo (the opposite at hi).
struct VolumeRootCell {
  double lo = 0, hi = 1;
  int sign_at_lo = 0;
};

/// A polynomial of the contact rule other than V, named so that a later stage can build it
/// exactly from the query: one of the in-plane polynomials (contact::visit_in_plane_poly's
/// index in_plane >= 0), or else coordinate `coordinate` of the relative motion from row `from`
/// to row `to` of the query (contact::relative_motion: linear; a factor of V in the interval
/// stage's factored view).
struct RulePoly {
  int in_plane = -1;
  int from = 0, to = 0, coordinate = 0;
};

/// A root cell of a polynomial `poly` of the contact rule other than V: the open cell (lo, hi)
/// of doubles holds exactly one root t* of it, a simple one, with its (nonzero) sign sign_at_lo
/// at lo (the opposite at hi); the rule holds at t*; and every other candidate time where
/// contact holds or is undecided is >= later_from. So t* is the TOI when the tightest double
/// interval around it ends at or before later_from.
struct RuleRootCell {
  double lo = 0, hi = 1;
  int sign_at_lo = 0;
  RulePoly poly;
  double later_from = 0;
};

/// What the stages learned about a query and hand over to the later ones. Each stage list
/// (lib/questions/) says at its list which stage writes a field and which reads it.
struct Findings {
  /// Contact: the TOI is V's simple root in this cell (the interval stage proved the collision
  /// and isolated the root, but did not narrow it to adjacent doubles).
  std::optional<VolumeRootCell> toi_cell;
  /// Contact, V identically zero or factored: the TOI is the root in this cell of a polynomial
  /// of the rule if it is no later than the cell's later_from (the interval stage proved the
  /// collision there and isolated the root, but did not narrow it to adjacent doubles).
  std::optional<RuleRootCell> rule_toi_cell;
  /// Contact: the static volume filter could not apply its bound (underflow guard or overflow):
  /// worth retrying on the query scaled towards 1.
  bool volume_out_of_range = false;
  /// Minimum separation: the feature pairs not proven apart (a pair a direction keeps farther
  /// than d apart over [0, 1] holds nowhere; the exact path leaves it out).
  kinds::FeatureMask use = kinds::kAllFeatures;
  /// GMP or CGAL was used on the way (an exact sign, the contact probe's integer stage): the
  /// deciding stage counts as `integer` (counted_with_gmp).
  bool used_gmp = false;
};

/// The outcome `o` of a stage that counts as `integer` when GMP or CGAL was used on the way
/// (findings.used_gmp, by it or an earlier stage), else at its own counter.
inline Outcome counted_with_gmp(Outcome o, const Findings& findings) {
  if (findings.used_gmp) o.counted_as = &StageCounters::integer;
  return o;
}

/// A query on its way through the stages.
template <class Query>
class Work {
 public:
  /// The query `q` (referred to, not copied: it must outlive the Work) asked `question`, counted
  /// in `counters` (may be null).
  Work(const Query& q, const Question& question, StageCounters* counters)
      : question(question), counters(counters), current_(&q) {}
  Work(const Query&&, const Question&, StageCounters*) = delete;  ///< not from a temporary
  Work(const Work&) = delete;
  Work& operator=(const Work&) = delete;

  /// The query as the stages see it.
  const Query& query() const { return *current_; }
  /// Storage for an exactly equivalent query (the same answer and TOI: a power-of-two scaling)
  /// that a stage writes; use_replacement() makes the later stages see it.
  Query& replacement() { return replacement_; }
  /// The later stages see replacement() as the query.
  void use_replacement() { current_ = &replacement_; }

  Question question;  ///< what is asked
  StageCounters* counters = nullptr;  ///< where the deciding stage is counted (may be null)
  /// An earlier stage proved a collision; the later ones only narrow its TOI.
  bool collides = false;
  Findings findings;  ///< what earlier stages learned

 private:
  const Query* current_;
  Query replacement_;  // storage for replace_query (left uninitialised until then)
};

}  // namespace exactccd::pipeline
