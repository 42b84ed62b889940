// The streamed scene step: the broad phase's pairs go to the narrow phase as they are found,
// per worker in batches small enough to stay in cache, and are never stored as a whole list.
//
// Each worker takes pieces of the trees' traversal (BroadPhaseTrees::pair_tasks) as oneTBB hands
// them out (parallel_chunks: work stealing, so a piece full of colliding pairs does not hold
// the other workers back), fills its batch with the pairs it finds and hands each full batch to `decide`
// (the narrow-phase question, narrow_phase.hpp) before it traverses on. Memory: one batch per
// worker, whatever the number of candidates. Between batches the loop checks whether to go on
// (decide returned false: an early exit; the place for a cancellation check too).
#pragma once

#include <time.h>

#include <array>
#include <chrono>
#include <cstddef>
#include <utility>
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

/// A worker of the stream: its batch of found pairs (kStreamBatch reserved once), the pairs it
/// found per kind and its times. On a cache line of its own.
struct alignas(64) StreamWorker {
  std::vector<FoundPair> batch;   ///< the pairs found and not yet decided
  std::array<std::size_t, 4> found{};  ///< pairs found per kind
  double busy = 0, narrow = 0;    ///< thread CPU seconds in the loop, and deciding pairs
  bool ran = false;               ///< whether it took a piece of work
};

/// What stream_pairs needs besides the trees: the pieces of work and the workers. Kept by a
/// caller that streams again and again (SceneTrees, for SceneBroadPhase's line search): once
/// grown, a stream allocates nothing.
struct StreamBuffers {
  std::vector<PairTask> tasks;                    ///< BroadPhaseTrees::pair_tasks
  std::vector<BoxTree::NodePair> nodes, scratch;  ///< its node pairs per kind, and levels
  std::vector<StreamWorker> workers;              ///< one per worker slot
};

/// Adds the workers' candidate counts and CPU times to `stats`, the stream's wall time `wall`,
/// and sets the number of workers that took a piece of work.
inline void add_stream_stats(const std::vector<StreamWorker>& workers, std::chrono::steady_clock::duration wall,
                             StepStats& stats) {
  unsigned ran = 0;
  for (const StreamWorker& w : workers) {
    for (std::size_t k = 0; k < 4; ++k) stats.candidates[k] += w.found[k];
    stats.traversal_thread_seconds += w.busy - w.narrow;
    stats.narrow_thread_seconds += w.narrow;
    ran += w.ran ? 1 : 0;
  }
  stats.stream_seconds += std::chrono::duration<double>(wall).count();
  stats.workers = ran;
}

/// Calls decide(batch, worker) for every batch of candidate pairs of the trees
/// (BroadPhaseTrees::visit; a std::vector<FoundPair> of at most kStreamBatch pairs), on up to
/// `threads` threads, until some call returns false (then every worker stops after its current
/// batch), with `buffers` for the pieces of work and the workers' batches. `stats`, when not
/// null, receives the candidate counts per kind and the loop's times. decide must be safe to
/// call from several workers at once (per-worker state indexed by `worker`, below
/// worker_slots(threads) taken where stream_pair_batches is called).
template <class DecideBatch>
void stream_pair_batches(const BroadPhaseTrees& trees, unsigned threads, DecideBatch&& decide, StreamBuffers& buffers,
                         StepStats* stats = nullptr) {
  using Clock = std::chrono::steady_clock;
  const auto wall_start = Clock::now();
  trees.pair_tasks(threads, buffers.tasks, buffers.nodes, buffers.scratch);
  const std::vector<PairTask>& tasks = buffers.tasks;
  std::vector<StreamWorker>& workers = buffers.workers;
  if (workers.size() < worker_slots(threads)) workers.resize(worker_slots(threads));
  for (StreamWorker& w : workers) {  // every slot's batch reserved now: a slot's first piece allocates nothing
    w.batch.clear();
    w.batch.reserve(kStreamBatch);
    w.found = {};
    w.busy = w.narrow = 0;
    w.ran = false;
  }
  parallel_chunks(tasks.size(), threads, 1, [&](std::size_t begin, std::size_t end, unsigned w) {
    StreamWorker& me = workers[w];
    const double busy_start = stats ? thread_cpu_seconds() : 0.0;
    me.ran = true;
    bool go_on = true;
    const auto flush = [&] {
      const double start = stats ? thread_cpu_seconds() : 0.0;
      go_on = decide(std::as_const(me.batch), w);
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
  if (stats) add_stream_stats(workers, Clock::now() - wall_start, *stats);
}

/// stream_pair_batches with decide(pair, worker) called for each pair of a batch in turn (until
/// one call returns false).
template <class Decide>
void stream_pairs(const BroadPhaseTrees& trees, unsigned threads, Decide&& decide, StreamBuffers& buffers,
                  StepStats* stats = nullptr) {
  stream_pair_batches(
      trees, threads,
      [&](const std::vector<FoundPair>& batch, unsigned w) {
        for (const FoundPair& p : batch)
          if (!decide(p, w)) return false;
        return true;
      },
      buffers, stats);
}

}  // namespace exactccd::scene
