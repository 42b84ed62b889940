#include "rigid/coplanar_walk.hpp"

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <optional>

#include "contact/contact_rule.hpp"
#include "contact/interval_oracle.hpp"
#include "numeric/root_narrowing.hpp"
#include "rigid/isolation_limits.hpp"
#include "rigid/rigid_frame.hpp"
#include "rigid/sign_at.hpp"

namespace exactccd::rigid {
namespace {

using I = numeric::Interval;
using pipeline::Outcome;
using IQuery = RigidEdgeEdgeQueryT<I>;
using Orientation = contact::Poly<I, 10>;
using contact::exactly_zero;

IQuery to_intervals(const RigidEdgeEdgeQuery& q) {
  const auto pose = [](const RigidPose& p) {
    return RigidPoseT<I>{{I(p.c.x), I(p.c.y), I(p.c.z)}, {I(p.q.w), I(p.q.x), I(p.q.y), I(p.q.z)}};
  };
  const auto point = [](const Vec3& v) { return Vec3T<I>{I(v.x), I(v.y), I(v.z)}; };
  return {pose(q.a_t0), pose(q.a_t1), pose(q.b_t0), pose(q.b_t1), point(q.a0), point(q.a1), point(q.b0), point(q.b1)};
}

/// The coordinate k of the header's certificate, or -1.
int plane_axis(const ScaledFrame<I>& f) {
  for (int k = 0; k < 3; ++k) {
    const auto coordinate = [&](int i) -> const contact::Poly<I, 5>& {
      const auto& p = f.position[i];
      return k == 0 ? p.x : k == 1 ? p.y : p.z;
    };
    bool same = true;
    for (int i = 1; i < 4 && same; ++i) same = exactly_zero(coordinate(i) - coordinate(0));
    if (same) return k;
  }
  return -1;
}

/// A candidate: its cell, what the rule said there and the endpoint whose orientation defines
/// it (-1: t = 0).
struct Candidate {
  RootCell cell;
  contact::Truth truth;
  int endpoint;
};

/// The tightest double cell around the candidate's root: its orientation's exact signs at
/// doubles (sign_at.hpp, in round-to-nearest), by the one narrowing (numeric/root_narrowing.hpp),
/// as contact_walk.cpp's narrowing of V's roots.
RootCell tightest(const RigidEdgeEdgeQuery& q, const Candidate& candidate, int axis, bool& used_gmp) {
  const RootCell& cell = candidate.cell;
  const CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
  numeric::Bisection halving;
  const auto sign = [&](double t) { return numeric::SignAt{orientation_sign_at(q, candidate.endpoint, axis, t, used_gmp)}; };
  const TimeInterval t = numeric::tightest_enclosure(cell.lo, cell.hi, cell.sign_at_lo, cell.lo, sign, halving);
  return {t.lo, t.hi, t.lo == t.hi ? 0 : cell.sign_at_lo};
}

/// The rule at the root of `o` in `cell` (o counted as zero there), the cell halved by o's
/// certain sign at its midpoint while the rule is uncertain (up to 40 times).
template <class Terms>
contact::Truth rule_at_root(const Terms& P, const Orientation* o, RootCell& cell) {
  for (int attempt = 0;; ++attempt) {
    const contact::IntervalSignOracle oracle{I(cell.lo, cell.hi), o};
    const contact::Truth t = contact::in_plane_contact(P, oracle);
    if (t != contact::Truth::unknown || o == nullptr || cell.lo == cell.hi || attempt == 40) return t;
    const double mid = cell.lo + (cell.hi - cell.lo) / 2;
    if (!(cell.lo < mid && mid < cell.hi)) return t;
    const int s = numeric::interval_sign((*o)(I(mid)));
    if (s == contact::kUnknownSign) return t;
    if (s == 0)
      cell = {mid, mid, 0};  // an exact zero: the root itself
    else
      (s == cell.sign_at_lo ? cell.lo : cell.hi) = mid;
  }
}

}  // namespace

Outcome coplanar_walk(const RigidEdgeEdgeQuery& q, double tmax, bool want_toi, bool& used_gmp) {
  const IQuery iq = to_intervals(q);
  const ScaledFrame<I> frame = scaled_frame(iq);
  const int k = plane_axis(frame);
  if (k < 0) return Outcome::undecided();
  const auto P = contact_terms<IQuery>(frame);
  boost::container::small_vector<Candidate, 16> candidates;
  RootCell start{0.0, 0.0, 0};
  candidates.push_back({start, rule_at_root(P, nullptr, start), -1});
  for (int i = 0; i < 4; ++i) {
    const auto& cross = P.endpoint_on_edge(i).cross;
    const Orientation& o = k == 0 ? cross.x : k == 1 ? cross.y : cross.z;
    RootCells cells;
    const auto no_exact_sign = [](int) { return SignClass::unknown; };
    if (numeric::isolate_roots<10>(o.c, cells, true, kIsolationLimits, no_exact_sign) == Isolation::failed)
      return Outcome::undecided();
    for (RootCell cell : cells) {
      if (cell.lo > tmax) break;  // later roots are later still
      const contact::Truth t = rule_at_root(P, &o, cell);
      candidates.push_back({cell, t, i});
    }
  }
  // A collision: a candidate certainly in contact within [0, tmax]; the earliest such by lo.
  const Candidate* contact_at = nullptr;
  bool all_no = true;
  for (const Candidate& c : candidates) {
    all_no = all_no && c.truth == contact::Truth::no;
    if (c.truth == contact::Truth::yes && c.cell.hi <= tmax && (!contact_at || c.cell.lo < contact_at->cell.lo))
      contact_at = &c;
  }
  if (all_no) return Outcome::separate();  // the claim: no candidate, no contact
  if (!want_toi && contact_at) return Outcome::collides(TimeInterval{0.0, contact_at->cell.hi});  // holds the earliest time
  // The earliest contact: each candidate not certainly out of contact narrowed to the tightest
  // double interval around its root (its orientation's exact signs); the one certainly in
  // contact that starts first, when every other such candidate starts at or after its end (its
  // root is then no earlier).
  boost::container::small_vector<Candidate, 16> open;
  for (const Candidate& c : candidates) {
    if (c.truth == contact::Truth::no) continue;
    open.push_back(c);
    if (c.endpoint >= 0) open.back().cell = tightest(q, c, k, used_gmp);
  }
  const Candidate* first = nullptr;
  for (const Candidate& c : open)
    if (c.truth == contact::Truth::yes && (!first || c.cell.lo < first->cell.lo)) first = &c;
  if (!first) return Outcome::undecided();
  for (const Candidate& c : open)
    if (&c != first && c.cell.lo < first->cell.hi) return Outcome::undecided();
  const std::optional<TimeInterval> toi = pipeline::cut(TimeInterval{first->cell.lo, first->cell.hi}, tmax);
  return toi ? Outcome::collides(toi) : Outcome::separate();
}

}  // namespace exactccd::rigid
