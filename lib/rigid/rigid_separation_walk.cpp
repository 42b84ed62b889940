// The interval stage of the rigid minimum-separation question (d > 0; docs/design.md, 9.4), the
// walk of separation/separation_walk.hpp on the rigid model's terms. On the normalized
// query, in interval arithmetic, the feature-pair terms (separation_terms.hpp) of the scaled
// positions (interval_frame.hpp; d D(t) in place of d: each term is the true one times a
// positive power of D, 9.1) are evaluated
// - at a double t from the positions' thin enclosures;
// - over a cell T = [a, b] from their enclosures over T with slopes (forward differentiation,
//   Dual): a value enclosure (met with the mean-value form f(m) + f'(T) (T - m)) and a slope.
// A term is excluded on a cell when its f is certainly > 0 or one of its g certainly <= 0 there.
//  1. t = 0: a term certainly holding gives TOI [0, 0]; unless every term certainly fails, the
//     query is undecided.
//  2. The cells of [0, tmax] in time order (halved down to depth 40, at most 2048 cells), each term excluded on a
//     cell not examined again in its halves. In the first cell where one term is left, with its
//     g certainly positive over the cell, f certainly > 0 at the cell's start and < 0 at its end,
//     and f' of certain sign over the cell, f has exactly one root t*, where the term holds, every
//     earlier time being free of contact (earlier cells excluded, f > 0 before t* in this one):
//     t* is the TOI (4b.2), narrowed to adjacent doubles by f's exact signs at doubles
//     (intervals, else double-double, else GMP: sign_at.hpp; numeric/root_narrowing.hpp). Without the TOI asked, that cell, or
//     a term certainly holding at a cell's midpoint, ends the walk: a collision.
//  3. Every cell excluded: no collision. Anything else: undecided (the exact path answers).
#include "rigid/rigid_separation_walk.hpp"

#include <cstdint>
#include <optional>

#include "kinds/primitive_kinds.hpp"
#include "numeric/root_narrowing.hpp"
#include "rigid/direction_stage.hpp"
#include "rigid/interval_frame.hpp"
#include "rigid/positions.hpp"
#include "rigid/sign_at.hpp"
#include "contact/separation_terms.hpp"

namespace exactccd::rigid {
namespace {

using pipeline::Outcome;

/// A term's polynomials' values (f first, then its g) at a time or over a cell.
template <class R>
struct TermValues {
  std::array<R, 5> value;
  int count = 0;
};

/// Every used feature's term from positions `point` (R: Interval or Dual) and d D.
template <class Kind, class R>
std::array<TermValues<R>, Kind::features.size()> terms_of(const std::array<Vec3T<R>, 4>& point, const R& dD,
                                                         std::uint32_t open) {
  std::array<TermValues<R>, Kind::features.size()> out;
  const ValueMotion<R> motion(point);
  const auto rel = [&](int i, int j) { return motion.rel(i, j); };
  const R dd = dD * dD;
  for (std::size_t k = 0; k < Kind::features.size(); ++k) {
    if (!(open >> k & 1)) continue;
    contact::feature_condition(Kind::features[k], rel, dd, [&](const R& f, const auto&... g) {
      out[k].value[0] = f;
      int i = 1;
      ((out[k].value[i++] = g), ...);
      out[k].count = i;
    });
  }
  return out;
}

template <class Query>
class RigidSeparationWalk {
 public:
  using Kind = kinds::kind_of<Query>;
  static constexpr int kMaxDepth = 40;
  /// The most cells one walk examines: a term within rounding of holding over a long stretch
  /// (a distance staying near d) would otherwise split every cell down to the depth limit.
  static constexpr int kMaxCells = 2048;

  RigidSeparationWalk(const Query& q, const DirectionFrame<Query>& directions, const IntervalFrame<Query>& frame,
                      double d, double tmax, bool want_toi, bool& used_gmp)
      : q_(q), directions_(directions), d_(d), tmax_(tmax), want_toi_(want_toi), frame_(frame), used_gmp_(used_gmp) {}

  Outcome run() {
    const std::uint32_t all = terms_not_kept_apart();
    if (all == 0) return Outcome::separate();
    if (const std::optional<Outcome> at_zero = decide_zero(all)) return *at_zero;
    // 2. The cells in time order (a stack of right halves).
    std::array<Cell, kMaxDepth + 2> stack;
    int top = 0;
    stack[top++] = {0.0, tmax_, 0, all};
    for (int cells = 1; top > 0; ++cells) {
      if (cells > kMaxCells) return Outcome::undecided();
      const Cell cell = stack[--top];
      std::uint32_t open = 0;
      if (const std::optional<Outcome> r = examine(cell, open)) return *r;
      if (open == 0) continue;  // free of contact
      const double m = cell.a + (cell.b - cell.a) / 2;
      if (cell.depth >= kMaxDepth || !(cell.a < m && m < cell.b)) return Outcome::undecided();
      stack[top++] = {m, cell.b, cell.depth + 1, open};  // the right half after the left one
      stack[top++] = {cell.a, m, cell.depth + 1, open};
    }
    return Outcome::separate();  // 3. every cell excluded
  }

 private:
  /// A time cell [a, b] of the walk, with the terms not excluded on its parent (bit k: feature k).
  struct Cell {
    double a, b;
    int depth;
    std::uint32_t open;
  };

  /// The feature pairs whose parts no direction keeps farther than d apart over the step (a
  /// pair kept apart holds nowhere: its term is left out; direction_stage.hpp).
  std::uint32_t terms_not_kept_apart() const {
    const CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);  // the direction bound assumes it
    std::uint32_t all = 0;
    for (std::size_t k = 0; k < Kind::features.size(); ++k)
      if (!directions_.feature_separated(d_, k)) all |= std::uint32_t{1} << k;
    return all;
  }

  /// 1. t = 0: a term certainly holding is a collision at 0; unless every term certainly fails
  /// there, undecided; otherwise nothing (the walk goes on).
  std::optional<Outcome> decide_zero(std::uint32_t all) {
    const auto at0 = terms_at(0.0, all);
    bool all_fail = true;
    for (std::size_t k = 0; k < Kind::features.size(); ++k) {
      if (!(all >> k & 1)) continue;
      if (holds(at0[k])) return Outcome::collides(TimeInterval{0.0, 0.0});
      all_fail = all_fail && fails(at0[k]);
    }
    if (!all_fail) return Outcome::undecided();
    return std::nullopt;
  }

  /// 2. One cell: a decision (a collision found, or its TOI narrowed), or nothing with `open` the
  /// terms not excluded on it (0: the cell is free of contact).
  std::optional<Outcome> examine(const Cell& cell, std::uint32_t& open) {
    const double m = cell.a + (cell.b - cell.a) / 2;
    const auto mid = terms_at(m, cell.open);
    if (!want_toi_) {  // a term certainly holding at the midpoint: a collision there or before
      for (std::size_t k = 0; k < Kind::features.size(); ++k)
        if ((cell.open >> k & 1) && holds(mid[k])) return Outcome::collides(TimeInterval{0.0, m});
    }
    const auto over = terms_over(cell.a, cell.b, m, mid, cell.open);
    int alive = -1, alive_count = 0;
    for (std::size_t k = 0; k < Kind::features.size(); ++k)
      if ((cell.open >> k & 1) && !excluded(over[k])) {
        open |= std::uint32_t{1} << k;
        alive = static_cast<int>(k);
        ++alive_count;
      }
    if (alive_count == 1 && single_root(over[static_cast<std::size_t>(alive)], static_cast<std::size_t>(alive), cell)) {
      if (!want_toi_) return Outcome::collides(TimeInterval{cell.a, cell.b});
      return narrow(Kind::features[static_cast<std::size_t>(alive)], cell.a, cell.b);
    }
    return std::nullopt;
  }

  /// 3. The term `t` (feature k) over the cell: its g certainly positive, its f certainly > 0 at
  /// the start, < 0 at the end, of certain slope: f has exactly one root there, where the term
  /// holds.
  bool single_root(const TermValues<Dual>& t, std::size_t k, const Cell& cell) const {
    for (int i = 1; i < t.count; ++i)
      if (!(t.value[i].value.inf() > 0)) return false;
    const Interval& slope = t.value[0].slope;
    if (!(slope.inf() > 0 || slope.sup() < 0)) return false;
    const std::uint32_t only = std::uint32_t{1} << k;
    return terms_at(cell.a, only)[k].value[0].inf() > 0 && terms_at(cell.b, only)[k].value[0].sup() < 0;
  }

  std::array<TermValues<Interval>, Kind::features.size()> terms_at(double t, std::uint32_t open) const {
    return terms_of<Kind>(frame_.at(t), Interval(d_) * frame_.D_at(t), open);
  }

  /// The terms over [a, b]: value enclosures met with the mean-value form about m (where the
  /// terms are `mid`), and slopes.
  std::array<TermValues<Dual>, Kind::features.size()> terms_over(
      double a, double b, double m, const std::array<TermValues<Interval>, Kind::features.size()>& mid,
      std::uint32_t open) const {
    auto over = terms_of<Kind>(frame_.over(a, b), Dual{Interval(d_), Interval(0)} * frame_.D_over(a, b), open);
    const Interval cell(a, b), offset = cell - Interval(m);
    for (std::size_t k = 0; k < Kind::features.size(); ++k)
      for (int i = 0; i < over[k].count; ++i) {
        Dual& v = over[k].value[i];
        v.value = meet(v.value, mid[k].value[i] + v.slope * offset);
      }
    return over;
  }

  static bool holds(const TermValues<Interval>& t) {
    if (t.count == 0 || !(t.value[0].sup() <= 0)) return false;
    for (int i = 1; i < t.count; ++i)
      if (!(t.value[i].inf() > 0)) return false;
    return true;
  }
  static bool fails(const TermValues<Interval>& t) {
    if (t.value[0].inf() > 0) return true;
    for (int i = 1; i < t.count; ++i)
      if (t.value[i].sup() <= 0) return true;
    return false;
  }
  static bool excluded(const TermValues<Dual>& t) {
    if (t.value[0].value.inf() > 0) return true;
    for (int i = 1; i < t.count; ++i)
      if (t.value[i].value.sup() <= 0) return true;
    return false;
  }

  /// f's exact sign at the double t: intervals (a certain nonzero sign), else double-double or GMP.
  int sign_at(const kinds::Feature& f, std::size_t k, double t) {
    const int s = numeric::certain_sign(terms_at(t, std::uint32_t{1} << k)[k].value[0]);
    if (s != 0) return s;
    const CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    return distance_sign_at(q_, f, d_, t, used_gmp_);
  }

  /// The tightest double interval around f's single root in (a, b) (f(a) > 0 > f(b)): f's exact
  /// signs at doubles, by the one narrowing (numeric/root_narrowing.hpp).
  Outcome narrow(const kinds::Feature& f, double a, double b) {
    std::size_t k = 0;
    while (&Kind::features[k] != &f) ++k;
    numeric::Bisection halving;
    const auto sign = [&](double t) { return numeric::SignAt{sign_at(f, k, t)}; };
    return Outcome::collides(numeric::tightest_enclosure(a, b, 1, a, sign, halving));
  }

  const Query& q_;
  const DirectionFrame<Query>& directions_;
  double d_, tmax_;
  bool want_toi_;
  const IntervalFrame<Query>& frame_;
  bool& used_gmp_;
};

}  // namespace

Outcome rigid_separation_walk(const RigidVertexFaceQuery& q, const DirectionFrame<RigidVertexFaceQuery>& directions,
                        const IntervalFrame<RigidVertexFaceQuery>& frame, double d, double tmax, bool want_toi,
                        bool& used_gmp) {
  return RigidSeparationWalk<RigidVertexFaceQuery>(q, directions, frame, d, tmax, want_toi, used_gmp).run();
}
Outcome rigid_separation_walk(const RigidEdgeEdgeQuery& q, const DirectionFrame<RigidEdgeEdgeQuery>& directions,
                        const IntervalFrame<RigidEdgeEdgeQuery>& frame, double d, double tmax, bool want_toi,
                        bool& used_gmp) {
  return RigidSeparationWalk<RigidEdgeEdgeQuery>(q, directions, frame, d, tmax, want_toi, used_gmp).run();
}

}  // namespace exactccd::rigid
