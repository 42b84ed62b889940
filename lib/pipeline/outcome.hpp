// The one protocol of the filtered method's stages, for both questions it answers (contact,
// d = 0, and minimum separation, d > 0; docs/design.md, 5.0).
//
// A query goes through a list of stages, cheapest first. Each stage takes the query and its
// question (Work: the query, CcdParams, whether the TOI is asked) and returns an Outcome:
// decided (the primitives collide, with the TOI when the stage certified it, or they stay
// apart), or undecided; what it learned on the way (a root cell, the feature pairs proven
// apart, ...) it leaves in the Work's findings for the stages after it (the handover types
// live beside the stages that make and read them; each list's Findings gathers its stages').
// run_stages.hpp is the whole policy, block.hpp the same policy on blocks of lanes; the stage
// lists of each question are in lib/questions/.
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

/// The handover every stage list shares: GMP or CGAL was used on the way (an exact sign, the
/// contact probe's integer stage), so the deciding stage counts as `integer` (counted_with_gmp).
/// Each list's findings (a struct of the handovers of its stages, defined beside the stages that
/// make and read them: filter/, separation/, rigid/) derive from it.
struct GmpUse {
  bool used_gmp = false;  ///< GMP or CGAL was used by an earlier stage
};

/// The outcome `o` of a stage that counts as `integer` when GMP or CGAL was used on the way
/// (findings.used_gmp, by it or an earlier stage), else at its own counter.
inline Outcome counted_with_gmp(Outcome o, const GmpUse& findings) {
  if (findings.used_gmp) o.counted_as = &StageCounters::integer;
  return o;
}

/// A query on its way through the stages, with what the stages learned (Findings: the stage
/// list's handovers, each defined beside the stages that make and read it; a list says at its
/// definition which stage writes a field and which reads it).
template <class Query, class Findings>
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
  Findings findings{};  ///< what earlier stages learned

 private:
  const Query* current_;
  Query replacement_;  // storage for replace_query (left uninitialised until then)
};

}  // namespace exactccd::pipeline
