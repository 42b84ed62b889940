// The one check every mesh reader makes on a polygon's vertex list: no vertex twice.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace exactccd::io {

/// The first index of `vertices` that appeared earlier in the list (the polygon is then
/// degenerate), or nullopt. O(n log n): a polygon of a million vertices is checked at once,
/// where comparing every pair would take minutes; the work memory is 16 bytes per vertex.
template <class Index>
std::optional<Index> first_repeated_vertex(const std::vector<Index>& vertices) {
  constexpr std::size_t kPairwise = 16;  // below this, comparing pairs is cheaper than sorting
  if (vertices.size() <= kPairwise) {
    for (std::size_t i = 1; i < vertices.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (vertices[i] == vertices[j]) return vertices[i];
    return std::nullopt;
  }
  // (index, position) sorted: in each run of one index, the second position is where it
  // repeats first; the smallest such position is the answer of the pairwise loop above.
  std::vector<std::pair<Index, std::size_t>> sorted;
  sorted.reserve(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) sorted.emplace_back(vertices[i], i);
  std::sort(sorted.begin(), sorted.end());
  std::optional<std::size_t> first;
  for (std::size_t k = 1; k < sorted.size(); ++k)
    if (sorted[k].first == sorted[k - 1].first && (k < 2 || sorted[k - 2].first != sorted[k].first) &&
        (!first || sorted[k].second < *first))
      first = sorted[k].second;
  if (!first) return std::nullopt;
  return vertices[*first];
}

}  // namespace exactccd::io
