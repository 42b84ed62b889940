// The separation walk: the minimum-separation question's interval stage (docs/design.md, 4b.3),
// the terms of separation_terms.hpp over time cells in interval arithmetic (term_enclosures.hpp).
//
// A cell is free of contact when every term is excluded on it (term_enclosures.hpp) or when a
// direction separates the primitives over it (separating_direction.hpp: the rows at the cell's
// ends, ProjectionFrame::over). The walk
//  0. goes through the cells in time order first with directions alone (every direction,
//     halving down to depth 3, i.e. eighths of [0, tmax]); the terms are built only at the first
//     cell no direction separates (most near misses never need them), and step 1 runs only if
//     that cell starts at 0 (otherwise [0, a] is free);
//  1. decides t = 0: a term certainly holding (f <= 0, every g > 0) gives TOI [0, 0];
//  2. goes through the cells of [0, tmax] in time order, splitting a cell while a term is not
//     excluded (and the primitives' own pair's direction does not separate it); cells where
//     every term is excluded are free of contact;
//  3. in the first cell where one term i is left, if its g are certainly > 0 on the cell, its f
//     certainly > 0 at the cell's start a and < 0 at its end b, and f' certainly != 0 on the
//     cell, then f_i has exactly one root t* in (a, b), every other term is excluded, [0, a] is
//     free: t* is the earliest contact (by 4b.2 it is a root of f_i where term i holds: f_i < 0
//     just after t*, g_i > 0). Narrowed to the tightest double interval by certain signs of f_i
//     at doubles (numeric/root_narrowing.hpp, distance_sign.hpp);
//  4. if all of [0, tmax] is free: no collision;
//  For the answer alone (no TOI asked), a term certainly holding at a cell's midpoint, or the
//  single sign change of step 3, ends the walk with "collides" (and an enclosure of the TOI,
//  not the tightest: no narrowing);
//  5. if the walk is undecided and every point lies in one plane, walks again without the
//     point-triangle and edge-edge terms (separation_walk.cpp, planar_walk).
// Anything else (a sign that intervals cannot certify: tangent passes, a root that is a double,
// two terms meeting at t*), or a walk past its cell budget (kMaxCells in separation_walk.cpp), is
// left undecided, and the exact path answers.
#pragma once

#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::separation {

/// The minimum-separation question's findings: GMP use (written by the contact probe and the
/// walk, read by the walk when it decides: counted `integer`) and the feature pairs no
/// direction keeps apart (`use`: written by the walk, read by ExactSeparationStage, whose exact
/// path leaves the others out: a pair a direction keeps farther than d apart over [0, 1] holds
/// nowhere).
struct SeparationFindings : pipeline::GmpUse {
  kinds::FeatureMask use = kinds::kAllFeatures;  ///< the feature pairs not proven apart
};

/// The walk for a query of any kind (file comment; the question valid, checked by the entry
/// point; round-to-nearest on entry: it installs upward rounding itself). Without want_toi only
/// whether the query collides is decided, and a collision's TOI is then an enclosure [lo, hi]
/// of the earliest time, not the tightest one. Hands over in `findings` the feature pairs a
/// direction keeps apart (use) and whether an exact sign needed GMP (used_gmp).
template <class Query>
pipeline::Outcome separation_walk(const Query& q, const pipeline::Question& question, SeparationFindings& findings);

/// The walk in the minimum-separation question's stage list; counted as `integer` when GMP was
/// used on the way (an exact sign here, or the contact probe before it).
struct SeparationWalkStage {
  static constexpr pipeline::Counter counter = &StageCounters::interval;  ///< counted as
  /// The walk on work.query().
  template <class Query, class Findings>
  pipeline::Outcome operator()(pipeline::Work<Query, Findings>& work) const {
    return pipeline::counted_with_gmp(separation_walk(work.query(), work.question, work.findings), work.findings);
  }
};

}  // namespace exactccd::separation
