#include "rigid/contact_walk.hpp"

#include <optional>

#include "contact/contact_rule.hpp"
#include "numeric/root_narrowing.hpp"
#include "rigid/interval_frame.hpp"
#include "rigid/isolation_limits.hpp"
#include "rigid/positions.hpp"
#include "rigid/sign_at.hpp"

namespace exactccd::rigid {
namespace {

using pipeline::Outcome;

template <class Query>
class ContactWalk {
 public:
  ContactWalk(const Query& q, const IntervalFrame<Query>& frame, bool& used_gmp)
      : q_(q), frame_(frame), used_gmp_(used_gmp) {}

  /// V's exact sign at the double t (an interval, else double-double or GMP).
  int sign_at(double t) {
    if (const int s = numeric::interval_sign(frame_.volume().at(t)); s != contact::kUnknownSign) return s;
    const CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);  // double-double needs it
    return volume_sign_at(q_, t, used_gmp_);
  }

  /// The in-plane rule at the root in `cell`, the cell narrowed while it is uncertain.
  contact::Truth rule_at_root(RootCell& cell) {
    for (int attempt = 0;; ++attempt) {
      const auto boxes = cell.lo == cell.hi ? frame_.at(cell.lo) : frame_.boxes(cell.lo, cell.hi);
      const auto terms = value_terms<Query>(boxes);
      const contact::Truth t = contact::in_plane_contact(terms, [](const Interval& x) { return numeric::interval_sign(x); });
      if (t != contact::Truth::unknown || cell.lo == cell.hi || attempt == 24) return t;
      const double mid = cell.lo + (cell.hi - cell.lo) / 2;
      if (!(cell.lo < mid && mid < cell.hi)) return t;
      const int s = sign_at(mid);
      if (s == 0)
        cell = {mid, mid, 0};
      else
        (s == cell.sign_at_lo ? cell.lo : cell.hi) = mid;
    }
  }

  /// The tightest double interval around the root in `cell` (V's exact signs at doubles, the
  /// one narrowing: numeric/root_narrowing.hpp, by halving).
  TimeInterval tightest(const RootCell& cell) {
    numeric::Bisection halving;
    const auto sign = [&](double t) { return numeric::SignAt{sign_at(t)}; };
    return numeric::tightest_enclosure(cell.lo, cell.hi, cell.sign_at_lo, cell.lo, sign, halving);
  }

 private:
  const Query& q_;
  const IntervalFrame<Query>& frame_;
  bool& used_gmp_;
};

template <class Query>
Outcome walk(const Query& q, const IntervalFrame<Query>& frame, double tmax, bool want_toi, bool& used_gmp) {
  const bool narrow = want_toi || !CcdParams{0.0, tmax}.whole_step();
  ContactWalk<Query> w(q, frame, used_gmp);
  RootCells cells;  // V's roots, the exact sign of V at an end where its interval is uncertain
  const auto exact_sign_at_end = [&](int end) { return sign_class(w.sign_at(end == 0 ? 0.0 : 1.0)); };
  if (numeric::isolate_roots<5>(frame.volume().p.c, cells, true, kIsolationLimits, exact_sign_at_end) == Isolation::failed)
    return Outcome::undecided();
  for (RootCell cell : cells) {
    if (cell.lo > tmax) break;  // later roots are later still
    const contact::Truth t = w.rule_at_root(cell);
    if (t == contact::Truth::unknown) return Outcome::undecided();
    if (t == contact::Truth::no) continue;
    if (!narrow) return Outcome::collides(TimeInterval{cell.lo, cell.hi});
    const std::optional<TimeInterval> toi = pipeline::cut(w.tightest(cell), tmax);
    return toi ? Outcome::collides(toi) : Outcome::separate();
  }
  return Outcome::separate();
}

}  // namespace

Outcome contact_walk(const RigidVertexFaceQuery& q, const IntervalFrame<RigidVertexFaceQuery>& frame, double tmax,
                     bool want_toi, bool& used_gmp) {
  return walk(q, frame, tmax, want_toi, used_gmp);
}
Outcome contact_walk(const RigidEdgeEdgeQuery& q, const IntervalFrame<RigidEdgeEdgeQuery>& frame, double tmax,
                     bool want_toi, bool& used_gmp) {
  return walk(q, frame, tmax, want_toi, used_gmp);
}

}  // namespace exactccd::rigid
