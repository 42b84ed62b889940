// The streamed scene step: the broad phase's pairs go to the narrow phase as they are found,
// per worker in batches small enough to stay in cache, and are never stored as a whole list.
//
// Each worker takes pieces of the trees' traversal (BroadPhaseTrees::pair_tasks) from a shared
// counter (parallel_chunks: dynamic, so a piece full of colliding pairs does not hold the other
// workers back), fills its batch with the pairs it finds and hands each full batch to `decide`
// (the narrow-phase question, narrow_phase.hpp) before it traverses on. Memory: one batch per
// worker, whatever the number of candidates. Between batches the loop checks whether to go on
// (decide returned false: an early exit; the place for a cancellation check too).
#pragma once

#include <time.h>

#include <chrono>
#include <cstddef>
#include <vector>

#include "scene/candidate_finder.hpp"
#include "scene/parallel.hpp"
#include "scene/step_stats.hpp"

namespace exactccd::scene {

/// Pairs per batch: 512 pairs (6 KiB) and the vertices of their queries stay in the first
/// cache levels while they are decided, and the traversal's stack and nodes stay warm in
/// between.
constexpr std::size_t kStreamBatch = 512;

/// CPU seconds of the calling thread (POSIX thread CPU-time clock): what a worker spent, not
/// counting the time the system gave other processes on a shared machine.
inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Calls decide(pair, worker) for every candidate pair of the trees (BroadPhaseTrees::visit),
/// on up to `threads` threads, until some call returns false (then every worker stops after
/// its current pair). `stats`, when not null, receives the candidate counts per kind and the
/// loop's times. decide must be safe to call from several workers at once (per-worker state
/// indexed by `worker`, below `threads`).
template <class Decide>
void stream_pairs(const BroadPhaseTrees& trees, unsigned threads, Decide&& decide, StepStats* stats = nullptr) {
  using Clock = std::chrono::steady_clock;
  const auto wall_start = Clock::now();
  const std::vector<PairTask> tasks = trees.pair_tasks(threads);
  struct alignas(64) Worker {
    std::vector<FoundPair> batch;
    std::array<std::size_t, 4> found{};
    double busy = 0, narrow = 0;
  };
  std::vector<Worker> workers(std::max(1u, threads));
  const unsigned ran = parallel_chunks(tasks.size(), threads, 1, [&](std::size_t begin, std::size_t end, unsigned w) {
    Worker& me = workers[w];
    const double busy_start = stats ? thread_cpu_seconds() : 0.0;
    me.batch.reserve(kStreamBatch);
    bool go_on = true;
    const auto flush = [&] {
      const double start = stats ? thread_cpu_seconds() : 0.0;
      for (const FoundPair& p : me.batch)
        if (!decide(p, w)) {
          go_on = false;
          break;
        }
      me.batch.clear();
      if (stats) me.narrow += thread_cpu_seconds() - start;
      return go_on;
    };
    for (std::size_t k = begin; k < end && go_on; ++k)
      trees.visit(tasks[k], [&](const FoundPair& p) {
        me.batch.push_back(p);
        ++me.found[static_cast<std::size_t>(p.kind)];
        return me.batch.size() < kStreamBatch || flush();
      });
    if (go_on) flush();
    if (stats) me.busy += thread_cpu_seconds() - busy_start;
    return go_on;
  });
  if (!stats) return;
  for (const Worker& w : workers) {
    for (std::size_t k = 0; k < 4; ++k) stats->candidates[k] += w.found[k];
    stats->traversal_thread_seconds += w.busy - w.narrow;
    stats->narrow_thread_seconds += w.narrow;
  }
  stats->stream_seconds += std::chrono::duration<double>(Clock::now() - wall_start).count();
  stats->workers = ran;
}

}  // namespace exactccd::scene
