// The narrow phase over the caller's own candidate pairs (exactccd/candidates.hpp): the
// CandidateSet as a range of the shared narrow phase (scene/narrow_phase.hpp), the one the
// scene functions run over their broad phase's candidates.
#include "exactccd/candidates.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <array>
#include <climits>
#include <stdexcept>
#include <string>

#include "numeric/fp_environment.hpp"
#include "scene/coplanar_blocks.hpp"
#include "scene/narrow_phase.hpp"
#include "scene/parallel.hpp"
#include "scene/scene_primitives.hpp"
#include "scene/time_bounds.hpp"

namespace exactccd {
namespace {

using scene::PairSides;

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("exactccd candidates: " + what);
}

/// The kinds in CollisionKind order (the order of the CandidateSet's lists and of the results).
constexpr std::array<CollisionKind, 4> kKinds{CollisionKind::vertex_face, CollisionKind::edge_edge,
                                              CollisionKind::point_edge, CollisionKind::point_point};
/// The lists' names, as in the messages and the Python keywords.
constexpr std::array<const char*, 4> kListNames{"vertex_face", "edge_edge", "point_edge", "point_point"};

/// Candidate `row` of a list whose rows are N vertex indices, the first `first` of them one side
/// and the others the other side ({vertex | a b c}, {a0 a1 | b0 b1}, {p | a b}, {p | q}), as a
/// pair of sides.
template <std::size_t N>
PairSides sides_of(CollisionKind kind, const std::array<int, N>& row, int first) {
  PairSides r;
  r.kind = kind;
  for (int i = 0; i < static_cast<int>(N); ++i) {
    scene::Side& s = r.side[i < first ? 0 : 1];
    s.v[static_cast<std::size_t>(s.n++)] = row[static_cast<std::size_t>(i)];
  }
  return r;
}

/// The size of side 0 of each kind's rows.
constexpr std::array<int, 4> kFirstSide{1, 2, 1, 1};

/// Checks list `list` (kKinds order) of N-index rows against n vertices (messages built only on
/// failure: this runs on every call).
template <std::size_t N>
void require_valid_rows(const std::vector<std::array<int, N>>& rows, std::size_t list, std::size_t n) {
  const auto which = [&](std::size_t i) { return std::string(kListNames[list]) + " candidate " + std::to_string(i); };
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (int v : rows[i])
      if (v < 0 || static_cast<std::size_t>(v) >= n)
        fail(which(i) + " has vertex index " + std::to_string(v) + ", out of range [0, " + std::to_string(n) + ")");
    const PairSides r = sides_of(kKinds[list], rows[i], kFirstSide[list]);
    for (int s = 0; s < 2; ++s)
      for (int a = 0; a < r.side[s].n; ++a)
        for (int b = 0; b < a; ++b)
          if (r.side[s].v[a] == r.side[s].v[b])
            fail(which(i) + ": its " + (r.side[s].n == 3 ? "triangle" : "edge") + " repeats vertex index " +
                 std::to_string(r.side[s].v[a]) + " (a degenerate element)");
    for (int a = 0; a < r.side[0].n; ++a)
      for (int b = 0; b < r.side[1].n; ++b)
        if (r.side[0].v[a] == r.side[1].v[b])
          fail(which(i) + ": its two sides share vertex index " + std::to_string(r.side[0].v[a]) +
               " (such a pair is within distance 0 at t = 0 by construction; exclude it from the candidates)");
  }
}

/// Whether a row's indices are in [0, n) and each side's (its first F indices, the others)
/// distinct: no degenerate element.
template <std::size_t F, std::size_t N>
bool valid_sides(const std::array<int, N>& row, std::size_t n) {
  bool ok = true;
  for (std::size_t i = 0; i < N; ++i) {
    ok &= row[i] >= 0 && static_cast<std::size_t>(row[i]) < n;
    for (std::size_t j = i < F ? 0 : F; j < i; ++j) ok &= row[i] != row[j];
  }
  return ok;
}

/// Whether the two sides of a row (its first F indices, the others) share no index.
template <std::size_t F, std::size_t N>
bool disjoint_sides(const std::array<int, N>& row) {
  bool ok = true;
  for (std::size_t i = F; i < N; ++i)
    for (std::size_t j = 0; j < F; ++j) ok &= row[i] != row[j];
  return ok;
}

#if defined(__SSE2__)
/// A side's exact swept box over [0, 1] in SSE2 registers: (x, y) in one, z in the low lane of
/// another, for the lower and the upper bounds.
struct SideBox {
  __m128d lo_xy, hi_xy, lo_z, hi_z;
};

/// The swept box of the vertices [begin, end) of a row at t0 and t1: minpd / maxpd (and their
/// scalar forms for z) give the exact min and max of finite doubles (the positions are checked
/// finite before any row is read; equal values of either sign of zero compare equal, so which
/// one is kept changes no comparison below).
template <std::size_t N>
SideBox side_box(const std::array<int, N>& row, std::size_t begin, std::size_t end, const Vec3* x0, const Vec3* x1) {
  SideBox box{};
  for (std::size_t i = begin; i < end; ++i) {
    const Vec3 &a = x0[row[i]], &b = x1[row[i]];
    const __m128d a_xy = _mm_loadu_pd(&a.x), b_xy = _mm_loadu_pd(&b.x);
    const __m128d a_z = _mm_load_sd(&a.z), b_z = _mm_load_sd(&b.z);
    const __m128d lo_xy = _mm_min_pd(a_xy, b_xy), hi_xy = _mm_max_pd(a_xy, b_xy);
    const __m128d lo_z = _mm_min_sd(a_z, b_z), hi_z = _mm_max_sd(a_z, b_z);
    if (i == begin) {
      box = {lo_xy, hi_xy, lo_z, hi_z};
    } else {
      box = {_mm_min_pd(box.lo_xy, lo_xy), _mm_max_pd(box.hi_xy, hi_xy), _mm_min_sd(box.lo_z, lo_z),
             _mm_max_sd(box.hi_z, hi_z)};
    }
  }
  return box;
}
#endif

/// Whether the exact swept boxes over [0, 1] of a row's two sides (its first F indices, the
/// others) are disjoint: the contact question's box test (tmax = 1, d = 0; vertex_boxes' exact
/// min and max of input coordinates, the hull of a side's vertices), written out for the row's
/// size so that a caller's list is one tight loop, in SSE2 where available (x86-64: two
/// coordinates per instruction; the same comparisons, so the same answer as the scalar form).
/// Comparisons of input doubles only: exact. NaN: minpd / maxpd would return their second
/// operand where std::min / std::max return their first, but no NaN reaches here (the
/// positions are validated finite first: checked_positions).
template <std::size_t F, std::size_t N>
bool disjoint_swept_boxes(const std::array<int, N>& row, const Vec3* x0, const Vec3* x1) {
#if defined(__SSE2__)
  const SideBox a = side_box(row, 0, F, x0, x1), b = side_box(row, F, N, x0, x1);
  const __m128d apart_xy = _mm_or_pd(_mm_cmplt_pd(a.hi_xy, b.lo_xy), _mm_cmplt_pd(b.hi_xy, a.lo_xy));
  const __m128d apart_z = _mm_or_pd(_mm_cmplt_sd(a.hi_z, b.lo_z), _mm_cmplt_sd(b.hi_z, a.lo_z));
  return (_mm_movemask_pd(apart_xy) | (_mm_movemask_pd(apart_z) & 1)) != 0;
#else
  // The hull of the vertices [begin, end) of the row at t0 and t1 (min and max are exact).
  const auto side_box = [&](std::size_t begin, std::size_t end) {
    scene::Box box = scene::empty_box();
    for (std::size_t i = begin; i < end; ++i) scene::add_vertex(box, x0[row[i]], x1[row[i]]);
    return box;
  };
  return !scene::overlap(side_box(0, F), side_box(F, N));
#endif
}

/// Whether the boxes over [0, tmax] grown by d of a row's two sides (its first F indices, the
/// others) are disjoint: the broad phase's test bound for bound (vertex_boxes: the exact swept
/// boxes for tmax = 1, add_vertex_until's certified ones otherwise; inflated(), which commutes
/// with the hull), so a pair within d in [0, tmax] never has disjoint boxes.
template <std::size_t F, std::size_t N>
bool disjoint_boxes(const std::array<int, N>& row, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                    const CcdParams& params) {
  if (params.contact_over_whole_step()) return disjoint_swept_boxes<F>(row, x0.data(), x1.data());
  scene::Box box[2];
  for (std::size_t s = 0; s < 2; ++s) box[s] = scene::empty_box();
  for (std::size_t i = 0; i < N; ++i) {
    const Vec3 &a = x0[static_cast<std::size_t>(row[i])], &b = x1[static_cast<std::size_t>(row[i])];
    if (params.whole_step())
      scene::add_vertex(box[i < F ? 0 : 1], a, b);
    else
      scene::add_vertex_until(box[i < F ? 0 : 1], a, b, params.tmax);
  }
  if (!params.contact_only())
    for (scene::Box& b : box) b = scene::inflated(b, params.min_distance);
  return !scene::overlap(box[0], box[1]);
}

/// A CandidateSet as one range of the shared narrow phase, the kinds' lists one after the other
/// in CollisionKind order, each candidate checked as it is read (scan(): indices and sides,
/// the box test, shared indices) against the positions.
struct CandidateSetRange {
  const CandidateSet& set;
  const std::vector<Vec3>& x0;
  const std::vector<Vec3>& x1;
  CcdParams params;
  std::array<std::size_t, 5> offsets{};

  CandidateSetRange(const CandidateSet& s, const std::vector<Vec3>& p0, const std::vector<Vec3>& p1,
                    const CcdParams& q)
      : set(s), x0(p0), x1(p1), params(q) {
    offsets[1] = set.vertex_face.size();
    offsets[2] = offsets[1] + set.edge_edge.size();
    offsets[3] = offsets[2] + set.point_edge.size();
    offsets[4] = offsets[3] + set.point_point.size();
  }

  std::size_t size() const { return offsets[4]; }

  /// The list (kKinds order) of candidate k.
  std::size_t list_of(std::size_t k) const {
    std::size_t i = 0;
    while (k >= offsets[i + 1]) ++i;
    return i;
  }

  /// Reads candidates [begin, end) in order, each checked as it is read (indices and sides,
  /// then the box test, then shared indices), and calls visit(sides, k) for those whose boxes
  /// overlap, at d = 0 visit(sides, k, resume) for those that the contact question's block
  /// stages do not prove apart (CoplanarBlocks: visited a block at a time, resuming after the
  /// block stages); false at the first invalid candidate or when visit returns false.
  template <class Visit>
  bool scan(std::size_t begin, std::size_t end, Visit&& visit) const {
    using Blocks = scene::CoplanarBlocks<std::size_t>;
    if (!Blocks::applies(params)) return scan_lists(begin, end, visit);
    const scene::PairTests<Vec3> tests(x0, x1, params);
    Blocks blocks(tests);
    const auto add = [&](const PairSides& r, std::size_t k) { return blocks.add(r, k, visit); };  // visit(r, k, resume)
    return scan_lists(begin, end, add) && blocks.flush(visit);
  }

  /// scan() without the batched stage.
  template <class Visit>
  bool scan_lists(std::size_t begin, std::size_t end, Visit& visit) const {
    while (begin < end) {
      const std::size_t i = list_of(begin), stop = std::min(end, offsets[i + 1]);
      const bool go_on = i == 0   ? scan_rows<1>(set.vertex_face, i, begin, stop, visit)
                         : i == 1 ? scan_rows<2>(set.edge_edge, i, begin, stop, visit)
                         : i == 2 ? scan_rows<1>(set.point_edge, i, begin, stop, visit)
                                  : scan_rows<1>(set.point_point, i, begin, stop, visit);
      if (!go_on) return false;
      begin = stop;
    }
    return true;
  }

  /// scan() within list `list` (candidates [begin, stop) of it), one loop per question's box
  /// test.
  template <std::size_t F, std::size_t N, class Visit>
  bool scan_rows(const std::vector<std::array<int, N>>& rows, std::size_t list, std::size_t begin, std::size_t stop,
                 Visit& visit) const {
    const std::array<int, N>* row = rows.data() + (begin - offsets[list]);
    const std::size_t n = x0.size();
    const bool contact = params.contact_over_whole_step();
    for (std::size_t k = begin; k < stop; ++k, ++row) {
      if (!valid_sides<F>(*row, n)) return false;
      // Sides sharing a vertex always have overlapping boxes (both hold its position at t =
      // 0), so a row found disjoint shares none: the check of shared indices can wait.
      if (contact ? disjoint_swept_boxes<F>(*row, x0.data(), x1.data()) : disjoint_boxes<F>(*row, x0, x1, params))
        continue;
      if (!disjoint_sides<F>(*row)) return false;
      if (!visit(sides_of(kKinds[list], *row, static_cast<int>(F)), k)) return false;
    }
    return true;
  }

  /// Candidate k as a CandidateCollision with the given time of impact.
  CandidateCollision collision(std::size_t k, const TimeInterval& toi) const {
    const std::size_t i = list_of(k);
    return {kKinds[i], k - offsets[i], toi};
  }
};

/// The validated question {d, tmax} of the options, after the positions (sizes, finite
/// coordinates: validate() of no candidates); the rows are checked as they are decided.
CcdParams checked_positions(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, const SceneOptions& options) {
  validate(options);
  validate(x0, x1, CandidateSet{});
  return {options.min_distance, options.tmax};
}

/// Hands every candidate to the question on options.threads threads, inside the call's
/// scene::with_threads (decide_checked_range:
/// each row checked as it is read, then its boxes, then the question's arithmetic); when the
/// loop stopped early, validates every row, so that an invalid one is reported (thrown) and
/// never answered.
template <class Question>
void decide(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, const CandidateSet& candidates,
            const SceneOptions& options, Question& question) {
  const CandidateSetRange range(candidates, x0, x1, {options.min_distance, options.tmax});
  if (!scene::decide_checked_range(range, scene::resolve_threads(options.threads), question))
    validate(x0, x1, candidates);
}

}  // namespace

CandidateSet candidates_from_elements(const std::vector<std::array<int, 3>>& faces,
                                      const std::vector<std::array<int, 2>>& edges,
                                      const std::vector<std::array<int, 2>>& vertex_face,
                                      const std::vector<std::array<int, 2>>& edge_edge,
                                      const std::vector<std::array<int, 2>>& point_edge,
                                      const std::vector<std::array<int, 2>>& point_point) {
  const auto element = [](int index, std::size_t count, const char* list, std::size_t i, const char* what) {
    if (index < 0 || static_cast<std::size_t>(index) >= count)
      fail(std::string(list) + " candidate " + std::to_string(i) + " has " + what + " index " + std::to_string(index) +
           ", out of range [0, " + std::to_string(count) + ")");
    return static_cast<std::size_t>(index);
  };
  CandidateSet c;
  c.vertex_face.reserve(vertex_face.size());
  for (std::size_t i = 0; i < vertex_face.size(); ++i) {
    const auto& f = faces[element(vertex_face[i][1], faces.size(), "vertex_face", i, "face")];
    c.vertex_face.push_back({vertex_face[i][0], f[0], f[1], f[2]});
  }
  c.edge_edge.reserve(edge_edge.size());
  for (std::size_t i = 0; i < edge_edge.size(); ++i) {
    const auto& a = edges[element(edge_edge[i][0], edges.size(), "edge_edge", i, "edge")];
    const auto& b = edges[element(edge_edge[i][1], edges.size(), "edge_edge", i, "edge")];
    c.edge_edge.push_back({a[0], a[1], b[0], b[1]});
  }
  c.point_edge.reserve(point_edge.size());
  for (std::size_t i = 0; i < point_edge.size(); ++i) {
    const auto& e = edges[element(point_edge[i][1], edges.size(), "point_edge", i, "edge")];
    c.point_edge.push_back({point_edge[i][0], e[0], e[1]});
  }
  c.point_point = point_point;
  return c;
}

void validate(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
              const CandidateSet& candidates) {
  const std::size_t n = positions_t0.size();
  if (positions_t1.size() != n)
    fail("positions_t0 has " + std::to_string(n) + " vertices but positions_t1 has " +
         std::to_string(positions_t1.size()));
  if (n > static_cast<std::size_t>(INT_MAX)) fail("more than INT_MAX vertices");
  scene::require_finite_positions(positions_t0, "positions_t0");
  scene::require_finite_positions(positions_t1, "positions_t1");
  require_valid_rows(candidates.vertex_face, 0, n);
  require_valid_rows(candidates.edge_edge, 1, n);
  require_valid_rows(candidates.point_edge, 2, n);
  require_valid_rows(candidates.point_point, 3, n);
}

std::vector<CandidateCollision> find_collisions(const std::vector<Vec3>& positions_t0,
                                                const std::vector<Vec3>& positions_t1,
                                                const CandidateSet& candidates, const SceneOptions& options) {
  const scene::SceneCall call(options.cancel);  // FP environment and SceneOptions::cancel
  const CcdParams params = checked_positions(positions_t0, positions_t1, options);
  const scene::PairTests<Vec3> tests(positions_t0, positions_t1, params);
  const unsigned threads = scene::resolve_threads(options.threads);
  auto found = scene::with_threads(threads, [&] {
    scene::CollectCollisions<Vec3, std::size_t> question(tests, threads, /*boxes_checked=*/true);
    decide(positions_t0, positions_t1, candidates, options, question);
    return question.take();
  });
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const CandidateSetRange range(candidates, positions_t0, positions_t1, params);
  std::vector<CandidateCollision> all;
  all.reserve(found.size());
  for (const auto& [k, toi] : found) all.push_back(range.collision(k, toi));
  return all;  // ascending k: by kind, then by position in the kind's list
}

std::optional<TimeInterval> earliest_toi(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
                                         const CandidateSet& candidates, const SceneOptions& options) {
  const scene::SceneCall call(options.cancel);  // FP environment and SceneOptions::cancel
  const CcdParams params = checked_positions(positions_t0, positions_t1, options);
  const scene::PairTests<Vec3> tests(positions_t0, positions_t1, params);
  scene::EarliestCollision<Vec3> question(tests, /*boxes_checked=*/true);
  scene::with_threads(scene::resolve_threads(options.threads),
                      [&] { decide(positions_t0, positions_t1, candidates, options, question); });
  return question.result();
}

std::optional<TimeInterval> earliest_toi(const std::vector<CandidateCollision>& collisions) {
  const scene::SceneCall call;  // the FP environment (not cancellable)
  return scene::earliest_of(collisions);
}

bool is_collision_free(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
                       const CandidateSet& candidates, const SceneOptions& options) {
  const scene::SceneCall call(options.cancel);  // FP environment and SceneOptions::cancel
  const CcdParams params = checked_positions(positions_t0, positions_t1, options);
  const scene::PairTests<Vec3> tests(positions_t0, positions_t1, params);
  scene::AnyCollision<Vec3> question(tests, /*boxes_checked=*/true);
  scene::with_threads(scene::resolve_threads(options.threads),
                      [&] { decide(positions_t0, positions_t1, candidates, options, question); });
  return !question.hit();
}

double max_collision_free_step(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
                               const CandidateSet& candidates, const SceneOptions& options) {
  return max_collision_free_step(earliest_toi(positions_t0, positions_t1, candidates, options), options.tmax);
}

}  // namespace exactccd
