// What every query set of `exactccd generate` shares, whatever the motion model: answering the
// candidates of a scene, keeping some of them, and writing a file with no half-written state.
#pragma once

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "scenes/sim_queries.hpp"  // select_queries

namespace exactccd::cli {

/// The truth of a scene's candidates and the ones a query set keeps.
struct Selection {
  std::vector<bool> truth;        ///< of every candidate, in candidate order
  std::size_t positives = 0;      ///< how many candidates collide
  std::vector<std::size_t> kept;  ///< scene::select_queries' choice (ascending)
};

/// Answers every candidate (collides(candidate), on `threads` threads: the same answers for every
/// count) and keeps scene::select_queries(truth, max_queries) of them (0: all).
template <class Query, class Collides>
Selection answer_and_select(const std::vector<Query>& candidates, std::size_t max_queries, unsigned threads,
                            const Collides& collides) {
  std::vector<char> collide(candidates.size());  // char: one writer per element
  parallel_for(0, candidates.size(), threads, [&](std::size_t i) { collide[i] = collides(candidates[i]); },
               "generate");
  Selection s;
  s.truth.assign(collide.begin(), collide.end());
  for (const bool t : s.truth) s.positives += t;
  s.kept = scene::select_queries(s.truth, max_queries);
  return s;
}

/// Writes a query file through a temporary renamed when complete (`write` writes its text; a
/// failed run leaves no half-written file), then prints "PATH: N queries, P positives" and
/// `note` on stdout (truth: the file's truth column).
void write_query_file(const std::string& path, const std::vector<bool>& truth, const std::string& note,
                      const std::function<void(std::ostream&)>& write);

}  // namespace exactccd::cli
