// A rigid query scaled exactly by powers of two before the filtered stages evaluate it
// (docs/design.md, 9.4): every length (translations, body points, d) by one power of two 2^s
// that brings the largest translation or point coordinate into [1, 2), and each body's two
// quaternions by the power of two that brings their largest component into [1, 2). The first
// multiplies every distance by 2^s (d with them: the question is unchanged), the second changes
// no rotation (R(s q) = R(q)). A product by a power of two is exact unless its result is
// subnormal (scaling down) or overflows (never: the results are below 2, or d, whose overflow
// leaves a d that no filter certifies); each subnormal result is checked by scaling it back,
// and an inexact one makes the query unusable here (the exact path answers it).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "exactccd/rigid.hpp"
#include "exactccd/stats.hpp"
#include "numeric/power_of_two.hpp"
#include "pipeline/outcome.hpp"
#include "rigid/exact_rigid.hpp"
#include "rigid/rigid_layout.hpp"

namespace exactccd::rigid {

/// The query and d scaled as in the file comment, or nullopt when a scaling is inexact.
template <class Query>
std::optional<std::pair<Query, double>> unit_scaled(const Query& query, double d) {
  Query q = query;
  bool exact = true;
  const auto scaled = [&](double v, const numeric::UnitScale& unit) {
    const double r = unit.apply(v);
    if (unit.s < 0 && std::fabs(r) < 0x1p-1022 && std::ldexp(r, -unit.s) != v) exact = false;
    return r;
  };
  // Lengths.
  double largest = 0;
  const auto note = [&](const Vec3& v) {
    largest = std::max(largest, std::max(std::fabs(v.x), std::max(std::fabs(v.y), std::fabs(v.z))));
  };
  for (const RigidPose* p : {&q.a_t0, &q.a_t1, &q.b_t0, &q.b_t1}) note(p->c);
  for (const Vec3& p : body_points(q)) note(p);
  double scaled_d = d;
  if (largest > 0) {
    const numeric::UnitScale unit = numeric::unit_scale(largest);
    const auto vec = [&](Vec3& v) { v = {scaled(v.x, unit), scaled(v.y, unit), scaled(v.z, unit)}; };
    for (RigidPose* p : {&q.a_t0, &q.a_t1, &q.b_t0, &q.b_t1}) vec(p->c);
    set_points(q, vec);
    scaled_d = scaled(d, unit);
    if (unit.s < 0 && scaled_d < 0x1p-1022 && std::ldexp(scaled_d, -unit.s) != d) exact = false;
  }
  // Quaternions, per body.
  for (const auto& [t0, t1] : {std::pair{&q.a_t0, &q.a_t1}, std::pair{&q.b_t0, &q.b_t1}}) {
    double m = 0;
    for (const Quaternion* r : {&t0->q, &t1->q})
      m = std::max(m, std::max(std::max(std::fabs(r->w), std::fabs(r->x)), std::max(std::fabs(r->y), std::fabs(r->z))));
    const numeric::UnitScale unit = numeric::unit_scale(m);  // m > 0: valid input
    for (Quaternion* r : {&t0->q, &t1->q})
      *r = {scaled(r->w, unit), scaled(r->x, unit), scaled(r->y, unit), scaled(r->z, unit)};
  }
  // A d that overflowed when scaled up is left to the exact path too (no filter would certify
  // anything with it, and none may meet a non-finite number in GMP).
  if (!exact || !std::isfinite(scaled_d)) return std::nullopt;
  return std::pair{q, scaled_d};
}

/// The first step of both rigid questions' stage lists: the Work's query and d unit scaled
/// (unit_scaled) into its replacement and question, for every later stage; where a scaling is
/// inexact, the exact path answers at once (counted `exact`).
struct RigidUnitScalingStage {
  static constexpr pipeline::Counter counter = &StageCounters::exact;  ///< only when it answers exactly
  /// Scales work.query() and the question's d; undecided unless the scaling is inexact.
  template <class Query, class Findings>
  pipeline::Outcome operator()(pipeline::Work<Query, Findings>& work) const {
    const auto scaled = unit_scaled(work.query(), work.question.params.min_distance);
    if (!scaled) return exact_outcome(work);  // an inexact scaling
    work.replacement() = scaled->first;
    work.use_replacement();
    work.question.params.min_distance = scaled->second;
    return pipeline::Outcome::undecided();
  }
};

}  // namespace exactccd::rigid
