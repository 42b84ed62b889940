#include "scene/candidate_finder.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

#include "scene/parallel.hpp"

namespace exactccd::scene {
namespace {

/// Pieces of work per thread of a pair traversal (some cost far more than others).
constexpr std::size_t kTasksPerThread = 32;

/// Every overlapping pair of primitives of trees a and b (or of a with itself, b == &a) that
/// keep(i, j) accepts, as make(i, j), sorted ascending. The traversal finds each pair once
/// (BoxTree::pairs_from); on up to `threads` threads, each worker's pairs in a list of its own,
/// sorted there, then merged: the result does not depend on the threads.
template <class Keep, class Make>
std::vector<std::array<int, 2>> tree_pairs(const BoxTree& a, const BoxTree& b, unsigned threads, Keep&& keep,
                                           Make&& make) {
  const std::vector<BoxTree::NodePair> tasks = a.pair_tasks(b, threads > 1 ? kTasksPerThread * threads : 1);
  std::vector<PerWorker<std::vector<std::array<int, 2>>>> per_worker(worker_slots(threads));
  parallel_chunks(tasks.size(), threads, 1, [&](std::size_t begin, std::size_t end, unsigned w) {
    std::vector<std::array<int, 2>>& out = per_worker[w].value;
    for (std::size_t k = begin; k < end; ++k)
      a.pairs_from(b, tasks[k], [&](int i, int j) {
        if (keep(i, j)) out.push_back(make(i, j));
      });
    return true;
  });
  std::vector<std::vector<std::array<int, 2>>> found;  // the workers' lists, in slot order
  for (auto& w : per_worker)
    if (!w.value.empty()) found.push_back(std::move(w.value));
  if (found.empty()) return {};
  parallel_chunks(found.size(), threads, 1, [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t w = begin; w < end; ++w) std::sort(found[w].begin(), found[w].end());
    return true;
  });
  std::vector<std::array<int, 2>> all = std::move(found[0]);
  for (std::size_t w = 1; w < found.size(); ++w) {
    std::vector<std::array<int, 2>> merged(all.size() + found[w].size());
    std::merge(all.begin(), all.end(), found[w].begin(), found[w].end(), merged.begin());
    std::vector<std::array<int, 2>>().swap(found[w]);
    all.swap(merged);
  }
  return all;
}

}  // namespace

BroadPhaseTrees::BroadPhaseTrees(const std::vector<Triangle>& triangles, const std::vector<Edge>& edges,
                                 const std::vector<int>& vertices, const std::vector<int>& points)
    : triangles_(triangles), edges_(edges), vertices_(vertices), points_(points) {}

void BroadPhaseTrees::fit(std::vector<Box> vertex_boxes, unsigned threads) {
  if (built_ && vertex_boxes.size() != vertex_boxes_.size())
    throw std::invalid_argument("BroadPhaseTrees::fit: the number of vertices changed");
  vertex_boxes_ = std::move(vertex_boxes);
  fit_trees(threads);
}

void BroadPhaseTrees::refit(unsigned threads) {
  if (!built_) throw std::logic_error("BroadPhaseTrees::refit before fit");
  if (vertex_boxes_.size() != float_boxes_.size())
    throw std::invalid_argument("BroadPhaseTrees::refit: the number of vertices changed");
  fit_trees(threads);
}

void BroadPhaseTrees::fit_trees(unsigned threads) {
  // The trees' float boxes from the vertices' float boxes: float_box rounds every bound
  // outwards by a monotone map (float_below, float_above), so the float hull of the vertices'
  // float boxes is exactly float_box of the hull of their boxes (min and max commute with a
  // monotone map), the box the tree needs (float_box.hpp), at one conversion per vertex. Kept
  // between fits (a refit then allocates nothing).
  float_boxes_.resize(vertex_boxes_.size());
  parallel_ranges(float_boxes_.size(), threads, std::size_t{1} << 14, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) float_boxes_[v] = float_box(vertex_boxes_[v]);
  });
  // The four trees side by side, largest first, each on its share of the threads: one
  // thread per tree builds without handing out the pieces of every loop of the build, and
  // the trees come out the same on any number of threads.
  constexpr std::size_t kTrees = 4;
  const unsigned each = std::max(1u, threads / static_cast<unsigned>(kTrees));
  parallel_chunks(kTrees, threads, 1, [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t k = begin; k < end; ++k) fit_tree(static_cast<int>(k), float_boxes_, each);
    return true;
  });
  built_ = true;
}

void BroadPhaseTrees::fit_tree(int which, const std::vector<FloatBox>& fboxes, unsigned threads) {
  const auto fbox = [&](int v) -> const FloatBox& { return fboxes[static_cast<std::size_t>(v)]; };
  const auto fit_one = [&](BoxTree& tree, std::size_t n, const auto& box_of) {
    if (built_)
      tree.refit(n, box_of, threads);
    else
      tree.build(n, box_of, threads);
  };
  // Pairs sharing a vertex are never candidates: the trees drop them in their leaf tests
  // (set_vertices; isolated points share no vertex with anything: no indices needed).
  switch (which) {
    case 0:
      fit_one(edge_tree_, edges_.size(), [&](std::size_t e) { return hull(fbox(edges_[e][0]), fbox(edges_[e][1])); });
      if (!built_) edge_tree_.set_vertices(2, [&](std::size_t e) { return std::array<int, 3>{edges_[e][0], edges_[e][1], -1}; }, threads);
      break;
    case 1:
      fit_one(triangle_tree_, triangles_.size(), [&](std::size_t t) {
        const Triangle& tri = triangles_[t];
        return hull(hull(fbox(tri[0]), fbox(tri[1])), fbox(tri[2]));
      });
      if (!built_) triangle_tree_.set_vertices(3, [&](std::size_t t) { return triangles_[t]; }, threads);
      break;
    case 2:
      fit_one(vertex_tree_, triangles_.empty() ? 0 : vertices_.size(), [&](std::size_t i) { return fbox(vertices_[i]); });
      if (!built_) vertex_tree_.set_vertices(1, [&](std::size_t i) { return std::array<int, 3>{vertices_[i], -1, -1}; }, threads);
      break;
    default: fit_one(point_tree_, points_.size(), [&](std::size_t i) { return fbox(points_[i]); });
  }
}

std::vector<PairTask> BroadPhaseTrees::pair_tasks(unsigned threads) const {
  std::vector<PairTask> tasks;
  std::vector<BoxTree::NodePair> nodes, scratch;
  pair_tasks(threads, tasks, nodes, scratch);
  return tasks;
}

void BroadPhaseTrees::pair_tasks(unsigned threads, std::vector<PairTask>& tasks, std::vector<BoxTree::NodePair>& nodes,
                                 std::vector<BoxTree::NodePair>& scratch) const {
  if (!built_) throw std::logic_error("BroadPhaseTrees::pair_tasks before fit");
  const std::size_t wanted = threads > 1 ? kTasksPerThread * threads : 1;
  tasks.clear();
  const auto add = [&](CollisionKind kind, const BoxTree& a, const BoxTree& b) {
    a.pair_tasks(b, wanted, nodes, scratch);
    for (const BoxTree::NodePair& pair : nodes) tasks.push_back({kind, pair});
  };
  // The largest kind first: the dynamic hand-out then ends on small pieces.
  add(CollisionKind::edge_edge, edge_tree_, edge_tree_);
  if (!triangles_.empty()) add(CollisionKind::vertex_face, vertex_tree_, triangle_tree_);
  if (!points_.empty()) {
    add(CollisionKind::point_edge, point_tree_, edge_tree_);
    add(CollisionKind::point_point, point_tree_, point_tree_);
  }
}

Candidates BroadPhaseTrees::candidates(unsigned threads) const {
  if (!built_) throw std::logic_error("BroadPhaseTrees::candidates before fit");
  // The trees report the pairs whose float boxes overlap: each kept only when its exact boxes do.
  Candidates c;
  if (!triangles_.empty())
    c.vertex_face = tree_pairs(
        vertex_tree_, triangle_tree_, threads,
        [&](int i, int t) {
          const int v = vertices_[static_cast<std::size_t>(i)];
          const Triangle& tri = triangles_[static_cast<std::size_t>(t)];
          return tri[0] != v && tri[1] != v && tri[2] != v &&
                 overlap(vertex_boxes_[static_cast<std::size_t>(v)], triangle_box(static_cast<std::size_t>(t)));
        },
        [&](int i, int t) { return std::array<int, 2>{vertices_[static_cast<std::size_t>(i)], t}; });
  c.edge_edge = tree_pairs(
      edge_tree_, edge_tree_, threads,
      [&](int i, int j) {
        const Edge& a = edges_[static_cast<std::size_t>(i)];
        const Edge& b = edges_[static_cast<std::size_t>(j)];
        return a[0] != b[0] && a[0] != b[1] && a[1] != b[0] && a[1] != b[1] &&
               overlap(edge_box(static_cast<std::size_t>(i)), edge_box(static_cast<std::size_t>(j)));
      },
      [](int i, int j) { return std::array<int, 2>{i, j}; });  // i < j
  if (!points_.empty()) {
    // Isolated points are on no edge and distinct: no pair shares a vertex. Points ascending,
    // so {points_[i], points_[j]} with i < j is ascending too.
    const auto point_of = [&](int i) { return points_[static_cast<std::size_t>(i)]; };
    c.point_edge = tree_pairs(
        point_tree_, edge_tree_, threads,
        [&](int i, int e) {
          return overlap(point_box(static_cast<std::size_t>(i)), edge_box(static_cast<std::size_t>(e)));
        },
                              [&](int i, int e) { return std::array<int, 2>{point_of(i), e}; });
    c.point_point = tree_pairs(
        point_tree_, point_tree_, threads,
        [&](int i, int j) {
          return overlap(point_box(static_cast<std::size_t>(i)), point_box(static_cast<std::size_t>(j)));
        },
                               [&](int i, int j) { return std::array<int, 2>{point_of(i), point_of(j)}; });
  }
  return c;
}

}  // namespace exactccd::scene
