#include "separation/separation_walk.hpp"

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "kinds/primitive_kinds.hpp"
#include "numeric/root_narrowing.hpp"
#include "separation/distance_sign.hpp"
#include "separation/separating_direction.hpp"
#include "separation/term_enclosures.hpp"

namespace exactccd::separation {
namespace {

using pipeline::Outcome;

constexpr int kMaxDepth = 48;        // cells of width tmax 2^-48; narrower ones go to the exact path
constexpr int kSeparationDepth = 3;  // the direction-only cells: eighths of [0, tmax]
/// The most cells one walk examines before handing the query to the exact path (as the rigid
/// walk's kMaxCells). The depth limit alone does not bound the work: near a tangential contact
/// (a distance growing like (t - t*)^2, with d negligible against the coordinates) the
/// primitives' direction separates a cell of width w only at a distance of about sqrt(w) from
/// t*, and the terms cannot exclude it (f within rounding of 0, or every coefficient infinite
/// when the coordinates are beyond 2^512), so some 2^(k/2) cells are examined at each depth k:
/// about 2^25 before the first cell at kMaxDepth ends the walk (seconds; the exact path takes
/// milliseconds). Measured on the bundled data sets (catalogue, families, sim, kinds; d 1e-6,
/// 1e-3, 1e-2; tmax 1, 0.5): every decided walk examined at most 10177 cells.
constexpr long kMaxCells = 16384;

/// True when every point of x lies in one plane (exactly, in GMP rationals): the points minus
/// the first span at most a plane.
template <std::size_t N>
bool coplanar(const std::array<Vec3, N>& x) {
  std::array<std::array<mpq_class, 3>, N> v;
  for (std::size_t i = 0; i < N; ++i)
    v[i] = {mpq_class(x[i].x) - mpq_class(x[0].x), mpq_class(x[i].y) - mpq_class(x[0].y),
            mpq_class(x[i].z) - mpq_class(x[0].z)};
  for (std::size_t i = 1; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j) {
      const std::array<mpq_class, 3> n{mpq_class(v[i][1] * v[j][2] - v[i][2] * v[j][1]),
                                       mpq_class(v[i][2] * v[j][0] - v[i][0] * v[j][2]),
                                       mpq_class(v[i][0] * v[j][1] - v[i][1] * v[j][0])};
      if (sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0) continue;
      for (std::size_t k = 1; k < N; ++k)
        if (sgn(mpq_class(n[0] * v[k][0] + n[1] * v[k][1] + n[2] * v[k][2])) != 0) return false;
      return true;  // n spans the normal of the plane through x[0], x[i], x[j]: all lie in it
    }
  return true;  // all on one line: in a plane
}

/// A cell [a, b] of [0, tmax] on the walk's stack, with the terms not excluded on its parent
/// (bit i: term i): a term excluded on a cell holds nowhere in it, so nowhere in its halves,
/// and is not examined again there.
struct Cell {
  double a, b;
  int depth;
  std::uint32_t open;
};

/// The walk of separation_walk.hpp for one query of the kind.
template <class Kind>
class SeparationWalk {
 public:
  static constexpr std::size_t N = 2 * Kind::points;
  static_assert(Kind::features.size() <= std::tuple_size_v<kinds::FeatureMask>);

  SeparationWalk(const std::array<Vec3, N>& x, const pipeline::Question& question, SeparationFindings& findings)
      : x_(x), d_(question.params.min_distance), tmax_(question.params.tmax), want_toi_(question.want_toi),
        frame_(x, d_), findings_(findings) {}

  /// Steps 0-4, then step 5 when undecided.
  Outcome run() {
    const Outcome first = walk(~std::uint32_t{0});  // every term (bits beyond them unused)
    if (first.answer != Outcome::Answer::undecided || zero_undecided_) return first;
    return planar_walk(first);
  }

 private:
  const std::array<Vec3, N> x_;
  const double d_, tmax_;
  const bool want_toi_;
  const ProjectionFrame<N> frame_;
  SeparationFindings& findings_;
  // Upward rounding (for Interval_nt) is installed when the terms are built: the directions
  // before that are certified in any rounding mode (separating_direction.hpp).
  std::optional<CGAL::Protect_FPU_rounding<true>> upward_;
  std::vector<SlopedTerm> terms_;
  std::array<int, Kind::features.size()> feature_of_term_{};
  bool built_ = false;
  bool zero_undecided_ = false;  // step 1 could not decide t = 0

  /// Builds the terms of the feature pairs no direction keeps apart (findings.use), and with
  /// `at_zero` decides t = 0 (step 1). An outcome when that decides the query (or leaves it
  /// undecided); nothing when the walk goes on.
  std::optional<Outcome> build_terms(bool at_zero) {
    built_ = true;
    upward_.emplace();
    std::size_t used = 0;
    for (std::size_t f = 0; f < Kind::features.size(); ++f)
      if ((findings_.use[f] = !feature_separated<Kind>(frame_, Kind::features[f])))
        feature_of_term_[used++] = static_cast<int>(f);
    if (used == 0) return Outcome::separate();
    terms_.reserve(used);
    std::array<Vec3T<Interval>, N> xi;
    for (std::size_t i = 0; i < N; ++i) xi[i] = {Interval(x_[i].x), Interval(x_[i].y), Interval(x_[i].z)};
    contact::for_each_term<Kind>(xi, Interval(d_) * Interval(d_), findings_.use.data(),
                        [&](contact::Term<Interval>&& t) { terms_.emplace_back(std::move(t)); });
    if (!at_zero) return std::nullopt;
    return decide_at_zero();
  }

  /// Step 1: a term certainly holding at 0 gives TOI [0, 0]; every term certainly failing there
  /// lets the walk go on; anything else is left to the exact path (step 5 needs t = 0 decided).
  std::optional<Outcome> decide_at_zero() {
    bool all_fail_at_zero = true;
    for (const SlopedTerm& term : terms_) {
      if (holds(term.term, Interval(0))) return Outcome::collides(TimeInterval{0.0, 0.0});
      all_fail_at_zero = all_fail_at_zero && excluded(term, 0.0, 0.0);
    }
    if (all_fail_at_zero) return std::nullopt;
    zero_undecided_ = true;
    return Outcome::undecided();
  }

  /// Step 0 and the direction test of step 2: a direction keeps the primitives apart over the
  /// cell. Before the terms exist every direction is tried; then only the primitives' own
  /// pair's (cheap, and the one that separates most cells).
  bool separated(const Cell& cell) const {
    if (cell.depth == 0) return false;
    const ProjectionFrame<N> over = frame_.over(cell.a, cell.b);
    return built_ ? primitives_separated<Kind>(over, true, 1) : primitives_separated<Kind>(over, false);
  }

  /// The terms of `open` not excluded on the cell (a bit each).
  std::uint32_t alive_on(const Cell& cell, std::uint32_t open) const {
    std::uint32_t alive = 0;
    for (std::size_t i = 0; i < terms_.size(); ++i)
      if ((open >> i & 1) && !excluded(terms_[i], cell.a, cell.b)) alive |= std::uint32_t{1} << i;
    return alive;
  }

  /// For the answer alone: a term certainly holding at the cell's midpoint m is a collision at
  /// m or before ([0, m] encloses the earliest time).
  std::optional<Outcome> holds_at_midpoint(const Cell& cell) const {
    const double m = cell.a + (cell.b - cell.a) / 2;
    for (std::size_t i = 0; i < terms_.size(); ++i)
      if ((cell.open >> i & 1) && holds(terms_[i].term, Interval(m))) return Outcome::collides(TimeInterval{0.0, m});
    return std::nullopt;
  }

  /// Step 3's narrowing: the root of term i's f in the cell (single_entry), to adjacent doubles
  /// by its exact signs at doubles (double-double, which needs round-to-nearest: installed for
  /// this scope, upward rounding restored on return).
  Outcome narrowed_root(const Cell& cell, int i) {
    const kinds::Feature& feature = Kind::features[feature_of_term_[i]];
    const CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    bool used_integers = false;
    const auto sign = [&](double m) {
      double approximation = 0;
      const int s = distance_sign_at(feature, x_, d_, m, &approximation, used_integers);
      return numeric::SignAt{s, approximation};
    };
    const auto approximate = [&](double t) {
      double f = 0;
      certified_distance_sign(feature, x_, d_, t, &f);
      return f;
    };
    numeric::RegulaFalsi<decltype(approximate)> chooser(approximate);
    const double guess = root_guess(feature, x_, d_, cell.a, cell.b);
    const TimeInterval toi = numeric::tightest_enclosure(cell.a, cell.b, 1, guess, sign, chooser);
    findings_.used_gmp = findings_.used_gmp || used_integers;  // an exact zero is always found in integers
    return Outcome::collides(toi);
  }

  /// Steps 2-4 over the terms whose bits are set in `initial` (before the terms are built: step 0).
  Outcome walk(std::uint32_t initial) {
    std::array<Cell, kMaxDepth + 2> stack;  // right halves wait below left ones: time order
    int top = 0;
    stack[top++] = {0.0, tmax_, 0, initial};
    for (long cells = 1; top > 0; ++cells) {
      if (cells > kMaxCells) return Outcome::undecided();  // the exact path decides
      const Cell cell = stack[--top];
      if (separated(cell)) continue;
      const double m = cell.a + (cell.b - cell.a) / 2;
      if (!built_) {
        if (cell.depth < kSeparationDepth && cell.a < m && m < cell.b) {
          stack[top++] = {m, cell.b, cell.depth + 1, cell.open};
          stack[top++] = {cell.a, m, cell.depth + 1, cell.open};
          continue;
        }
        // [0, cell.a] is free (its cells were separated): t = 0 needs deciding only when this
        // cell starts at 0.
        if (const auto decided = build_terms(cell.a == 0)) return *decided;
      }
      if (!want_toi_)
        if (const auto decided = holds_at_midpoint(cell)) return *decided;
      const std::uint32_t alive = alive_on(cell, cell.open);
      if (alive == 0) continue;  // free of contact
      if ((alive & (alive - 1)) == 0) {  // one term left: a simple sign change of f (step 3)?
        int i = 0;
        while (!(alive >> i & 1)) ++i;
        if (single_entry(terms_[static_cast<std::size_t>(i)], cell.a, cell.b))
          return want_toi_ ? narrowed_root(cell, i) : Outcome::collides(TimeInterval{cell.a, cell.b});
      }
      if (cell.depth >= kMaxDepth || !(cell.a < m && m < cell.b)) return Outcome::undecided();
      stack[top++] = {m, cell.b, cell.depth + 1, alive};  // right half, examined after the left one
      stack[top++] = {cell.a, m, cell.depth + 1, alive};
    }
    return Outcome::separate();  // 4. every cell of [0, tmax] is free
  }

  /// Step 5 (coplanar queries): when every point lies in one fixed plane at t0 and at t1 (so at
  /// every t), the point-triangle and edge-edge terms never hold first at a t > 0, and the walk
  /// runs again without them. Their normal (n, or w) is normal to the plane or zero, and the
  /// vector to the other point (p - a, or r) lies in it, so h = 0 and f = -d^2 |n|^2 (d > 0
  /// here): f(t) = 0 only where n(t) = 0, where every g (a multiple of n) is 0 and the term
  /// fails. By 4b.2 (docs/design.md) the earliest t* > 0 of S is a root of the f of a term
  /// holding there, so not of these terms: at t* another term holds, and the walk without them
  /// finds the same t* (t* = 0 was ruled out in step 1, with every term), or no t* when S is
  /// empty (the walk's terms are a subset). Such queries (a 2D query, z = 0; a simulation in a
  /// plane) reach here when their edges or triangle become degenerate (n = 0) inside
  /// [0, tmax]: every g of the term vanishes there and intervals cannot exclude it. The plane
  /// test is exact (GMP rationals: counted as integer signs).
  Outcome planar_walk(const Outcome& first) {
    std::uint32_t planar = 0;
    for (std::size_t i = 0; i < terms_.size(); ++i) {
      const kinds::FeaturePair pair = Kind::features[static_cast<std::size_t>(feature_of_term_[i])].pair;
      if (pair == kinds::FeaturePair::point_triangle || pair == kinds::FeaturePair::edge_edge) planar |= std::uint32_t{1} << i;
    }
    if (planar == 0 || !(Kind::dimension == 2 || coplanar(x_))) return first;
    const std::uint32_t all = (std::uint32_t{1} << terms_.size()) - 1;
    const Outcome again = walk(all & ~planar);
    if (again.answer == Outcome::Answer::undecided) return first;
    if (Kind::dimension == 3) findings_.used_gmp = true;  // the plane test
    return again;
  }
};

}  // namespace

template <class Query>
pipeline::Outcome separation_walk(const Query& q, const pipeline::Question& question, SeparationFindings& findings) {
  using Kind = kinds::kind_of<Query>;
  return SeparationWalk<Kind>(contact::points3<double>(q), question, findings).run();
}

// The walk for every kind of the minimum-separation question (kinds::for_each_kind).
template pipeline::Outcome separation_walk(const VertexFaceQuery&, const pipeline::Question&, SeparationFindings&);
template pipeline::Outcome separation_walk(const EdgeEdgeQuery&, const pipeline::Question&, SeparationFindings&);
template pipeline::Outcome separation_walk(const PointEdgeQuery&, const pipeline::Question&, SeparationFindings&);
template pipeline::Outcome separation_walk(const PointPointQuery&, const pipeline::Question&, SeparationFindings&);
template pipeline::Outcome separation_walk(const EdgeEdge2dQuery&, const pipeline::Question&, SeparationFindings&);
template pipeline::Outcome separation_walk(const PointEdge2dQuery&, const pipeline::Question&, SeparationFindings&);
template pipeline::Outcome separation_walk(const PointPoint2dQuery&, const pipeline::Question&, SeparationFindings&);

}  // namespace exactccd::separation
