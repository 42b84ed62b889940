// The protocol of the filtered method on blocks of queries (docs/architecture.md, "The block
// protocol"): the same stage list as one query's (run_stages.hpp), run on up to kLanes queries
// of one kind and one question at once.
//
// A stage may have a block form besides its per-query one:
//   template <class Query, class Findings>
//   LaneDecisions block(const QueryLanes<Query>& lanes, const Question& question,
//                       std::array<Findings, kLanes>& findings) const;
// deciding lanes [0, lanes.size) together (in vector registers: the same operations as the
// per-query form on each lane, so the same answers bit for bit) and writing each lane's
// handover into findings[lane] as the per-query form writes it into Work::findings.
//
// Running a list over a block runs its leading stages that have a block form on the lanes still
// open, each time packing the undecided lanes to the front (so that the next block stage works
// on them only); each lane that is still open then goes through the per-query stages, starting
// at the first stage without a block form, never again at one it passed, with the findings its
// block stages handed over. Each lane is counted as run_stages counts a query.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <utility>

#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"
#include "pipeline/outcome.hpp"
#include "pipeline/run_stages.hpp"

namespace exactccd::pipeline {

/// Queries per block: two AVX-512 registers' worth of double lanes per coordinate.
constexpr std::size_t kLanes = 16;
/// One bit per lane, lane i at bit i.
using LaneMask = std::uint32_t;

/// The lanes [0, n) as a mask.
constexpr LaneMask first_lanes(std::size_t n) {
  return n >= 32 ? ~LaneMask{0} : (LaneMask{1} << n) - 1u;
}

/// Up to kLanes queries of one kind in structure-of-arrays lanes: coordinate[r][c][lane] is
/// coordinate c of row r (rows(q) order: the points at t0, then at t1) of the query in that
/// lane. Lanes at and beyond `size` hold earlier or zero values: block stages evaluate them and
/// ignore the result (every lane is finite, so nothing traps or slows down).
template <class Query>
struct QueryLanes {
  using Kind = kinds::kind_of<Query>;
  static constexpr std::size_t rows = 2 * static_cast<std::size_t>(Kind::points);  ///< rows per query
  static constexpr std::size_t dimension = Kind::dimension;                          ///< coordinates per row
  using Point = std::conditional_t<dimension == 3, Vec3, Vec2>;

  alignas(64) std::array<std::array<std::array<double, kLanes>, dimension>, rows> coordinate{};
  std::size_t size = 0;  ///< the lanes in use

  /// Puts a query's rows into lane `size` and counts it; the block must not be full.
  void push(const std::array<Point, rows>& r) {
    for (std::size_t i = 0; i < rows; ++i) set_row(i, size, r[i]);
    ++size;
  }
  /// Puts query q into lane `size`.
  void push(const Query& q) { push(exactccd::rows(q)); }
  /// Whether every lane holds a query.
  bool full() const { return size == kLanes; }

  /// The query in `lane`.
  Query query(std::size_t lane) const {
    std::array<Point, rows> r;
    for (std::size_t i = 0; i < rows; ++i) r[i] = row(i, lane);
    return from_rows<Query>(r);
  }

  /// Copies lane `from` into lane `to` (packing).
  void move_lane(std::size_t from, std::size_t to) {
    for (auto& row_coordinates : coordinate)
      for (auto& c : row_coordinates) c[to] = c[from];
  }

 private:
  Point row(std::size_t r, std::size_t lane) const {
    if constexpr (dimension == 3)
      return {coordinate[r][0][lane], coordinate[r][1][lane], coordinate[r][2][lane]};
    else
      return {coordinate[r][0][lane], coordinate[r][1][lane]};
  }
  void set_row(std::size_t r, std::size_t lane, const Point& p) {
    coordinate[r][0][lane] = p.x;
    coordinate[r][1][lane] = p.y;
    if constexpr (dimension == 3) coordinate[r][2][lane] = p.z;
  }
};

/// What a stage's block form decided: lanes whose primitives stay apart, lanes that collide
/// (without a certified TOI: as Outcome::collides() of the per-query form); the others stay open.
struct LaneDecisions {
  LaneMask separate = 0;  ///< Outcome::separate()
  LaneMask collides = 0;  ///< Outcome::collides(), no TOI
};

/// Whether Stage has a block form for queries of type Query with findings of type Findings.
template <class Stage, class Query, class Findings, class = void>
struct HasBlockForm : std::false_type {};
template <class Stage, class Query, class Findings>
struct HasBlockForm<Stage, Query, Findings,
                    std::void_t<decltype(std::declval<const Stage&>().block(
                        std::declval<const QueryLanes<Query>&>(), std::declval<const Question&>(),
                        std::declval<std::array<Findings, kLanes>&>()))>> : std::true_type {};

/// The number of leading stages of List (a StageList) that have a block form: the per-query
/// stages of a block's lanes start at this index.
template <class List, class Query, class Findings, std::size_t I = 0>
constexpr std::size_t block_prefix_length() {
  if constexpr (I < List::size) {
    if constexpr (HasBlockForm<typename List::template StageAt<I>, Query, Findings>::value)
      return block_prefix_length<List, Query, Findings, I + 1>();
    else
      return I;
  } else {
    return I;
  }
}

/// A block after its block stages: per lane (in the order the lanes were pushed), the answer
/// when they decided it, else where its per-query stages resume (its findings, and whether a
/// collision is already proved).
template <class Findings>
struct BlockPrefix {
  LaneMask open = 0;                                       ///< lanes the block stages left open
  std::array<std::optional<TimeInterval>, kLanes> answer;  ///< decided lanes: as run_stages answers
  std::array<Findings, kLanes> findings;                   ///< open lanes: what the block stages learned
  std::array<bool, kLanes> collides{};                     ///< open lanes: a collision is proved
};

namespace detail {

/// Takes a block stage's decision about lane i (pushed as lane `origin`, whose collision flag is
/// `collides`), counted as StageRun counts a query; true when the lane's answer is now known
/// (then in prefix.answer[origin], and the lane closed in prefix.open).
template <class Findings>
bool decide_lane(const LaneDecisions& d, std::size_t i, std::size_t origin, Counter counter, const Question& question,
                 StageCounters* counters, bool& collides, BlockPrefix<Findings>& prefix) {
  const LaneMask bit = LaneMask{1} << i;
  const Outcome o = (d.separate & bit)   ? Outcome::separate()
                    : (d.collides & bit) ? Outcome::collides()
                                         : Outcome::undecided();
  StageRun run;
  if (!run.take(o, counter, question, counters, collides)) return false;
  prefix.answer[origin] = run.result();
  prefix.open &= ~(LaneMask{1} << origin);
  return true;
}

/// The open lanes of a block after its first block stage, packed to the front for the next
/// ones: their coordinates, findings, collision flags and the lane each was pushed in.
template <class Query, class Findings>
struct PackedBlock {
  QueryLanes<Query> lanes;
  std::array<Findings, kLanes> findings{};
  std::array<bool, kLanes> collides{};
  std::array<std::uint8_t, kLanes> origin{};

  /// The lanes `prefix` left open, in order.
  PackedBlock(const QueryLanes<Query>& all, const BlockPrefix<Findings>& prefix) {
    for (std::size_t i = 0; i < all.size; ++i) {
      if (!(prefix.open >> i & 1u)) continue;
      lanes.push(all.query(i));
      findings[lanes.size - 1] = prefix.findings[i];
      collides[lanes.size - 1] = prefix.collides[i];
      origin[lanes.size - 1] = static_cast<std::uint8_t>(i);
    }
  }

  /// Takes a block stage's decisions for every lane and packs the lanes still open.
  void take(const LaneDecisions& d, Counter counter, const Question& question, StageCounters* counters,
            BlockPrefix<Findings>& prefix) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < lanes.size; ++i) {
      if (decide_lane(d, i, origin[i], counter, question, counters, collides[i], prefix)) continue;
      if (kept != i) {
        lanes.move_lane(i, kept);
        findings[kept] = findings[i];
        collides[kept] = collides[i];
        origin[kept] = origin[i];
      }
      ++kept;
    }
    lanes.size = kept;
  }

  /// Hands the open lanes' findings and flags back to `prefix`, in the lanes they were pushed in.
  void give_back(BlockPrefix<Findings>& prefix) const {
    for (std::size_t i = 0; i < lanes.size; ++i) {
      prefix.findings[origin[i]] = findings[i];
      prefix.collides[origin[i]] = collides[i];
    }
  }
};

/// Runs block stages I, I + 1, ..., End - 1 on the packed block.
template <std::size_t I, std::size_t End, class List, class Query, class Findings>
void run_packed_stages(const List& list, const Question& question, StageCounters* counters,
                       PackedBlock<Query, Findings>& b, BlockPrefix<Findings>& prefix) {
  if constexpr (I < End) {
    if (b.lanes.size == 0) return;
    const LaneDecisions d = list.template at<I>().block(b.lanes, question, b.findings);
    b.take(d, List::template StageAt<I>::counter, question, counters, prefix);
    run_packed_stages<I + 1, End>(list, question, counters, b, prefix);
  }
}

}  // namespace detail

/// The block stages of `list` (its leading stages with a block form) on `lanes`, asked
/// `question`, each lane counted in `counters` (may be null) where a block stage decides it.
/// The first runs on `lanes` in place; the lanes it leaves open are packed for the next.
template <class Findings, class Query, class... Stage>
BlockPrefix<Findings> run_block_prefix(const StageList<Stage...>& list, const QueryLanes<Query>& lanes,
                                       const Question& question, StageCounters* counters) {
  using List = StageList<Stage...>;
  constexpr std::size_t end = block_prefix_length<List, Query, Findings>();
  BlockPrefix<Findings> prefix;
  prefix.open = first_lanes(lanes.size);
  if constexpr (end > 0) {
    const LaneDecisions d = list.template at<0>().block(lanes, question, prefix.findings);
    // No lane has a collision proved yet: a lane proved apart is answered (nullopt, as the
    // array holds) and counted at the stage, as StageRun::take does, without going through it.
    const LaneMask separate = d.separate & prefix.open;
    if (counters && List::template StageAt<0>::counter)
      counters->*(List::template StageAt<0>::counter) += static_cast<std::uint64_t>(__builtin_popcount(separate));
    prefix.open &= ~separate;
    for (LaneMask decided = d.collides & prefix.open; decided != 0; decided &= decided - 1) {
      const std::size_t i = static_cast<std::size_t>(__builtin_ctz(decided));  // the lowest lane decided
      detail::decide_lane(d, i, i, List::template StageAt<0>::counter, question, counters, prefix.collides[i], prefix);
    }
    if constexpr (end > 1) {
      if (prefix.open == 0) return prefix;
      detail::PackedBlock<Query, Findings> packed(lanes, prefix);
      detail::run_packed_stages<1, end>(list, question, counters, packed, prefix);
      packed.give_back(prefix);
    }
  }
  return prefix;
}

/// The answer to `question` of q, the query in an open lane of a block whose block stages left
/// it with `findings` and `collides`: the per-query stages of `list` from the first without a
/// block form (counted in `counters`). A lane whose collision is proved answers at once when
/// the TOI is not asked.
template <class Query, class Findings, class... Stage>
std::optional<TimeInterval> resume(const StageList<Stage...>& list, const Query& q, const Question& question,
                                   StageCounters* counters, const Findings& findings, bool collides) {
  constexpr std::size_t first = block_prefix_length<StageList<Stage...>, Query, Findings>();
  if (collides && !question.want_toi) return kCollisionWithoutToi;
  Work<Query, Findings> work{q, question, counters};
  work.findings = findings;
  work.collides = collides;
  return list.template run<first>(work);
}

/// Runs `list` on every lane of `lanes` with `question` (the block stages, then each open lane
/// through the per-query ones: run_block_prefix, resume), each lane counted in `counters` (may
/// be null), and calls sink(lane, answer) for lanes 0, 1, ..., size - 1 in order, the answer as
/// run_stages gives it.
template <class Findings, class Query, class... Stage, class Sink>
void run_block(const StageList<Stage...>& list, const QueryLanes<Query>& lanes, const Question& question,
               StageCounters* counters, Sink&& sink) {
  const BlockPrefix<Findings> prefix = run_block_prefix<Findings>(list, lanes, question, counters);
  for (std::size_t i = 0; i < lanes.size; ++i) {
    if (!(prefix.open >> i & 1u)) {
      sink(i, prefix.answer[i]);
      continue;
    }
    sink(i, resume(list, lanes.query(i), question, counters, prefix.findings[i], prefix.collides[i]));
  }
}

/// Runs `list` on queries[0, count) with `question`, in blocks of kLanes queries when the list
/// has block stages for Query (run_block), else query by query (a block without block stages is
/// its lanes one by one), each counted in `counters` (may be null); sink(i, answer) for every i
/// in order, the answer as run_stages gives it.
template <class Findings, class Query, class... Stage, class Sink>
void run_batch(const StageList<Stage...>& list, const Query* queries, std::size_t count, const Question& question,
               StageCounters* counters, Sink&& sink) {
  if constexpr (block_prefix_length<StageList<Stage...>, Query, Findings>() == 0) {
    for (std::size_t i = 0; i < count; ++i) {
      Work<Query, Findings> work{queries[i], question, counters};
      sink(i, list.run(work));
    }
  } else {
    QueryLanes<Query> lanes;
    for (std::size_t first = 0; first < count; first += kLanes) {
      lanes.size = 0;
      for (std::size_t i = first; i < count && i < first + kLanes; ++i) lanes.push(queries[i]);
      run_block<Findings>(list, lanes, question, counters,
                          [&](std::size_t lane, const std::optional<TimeInterval>& answer) { sink(first + lane, answer); });
    }
  }
}

}  // namespace exactccd::pipeline
