// The contact question's stage 1 on blocks of pairs, ahead of the per-pair question (the batched
// stage of docs/performance.md, "Batched stages"): a worker's vertex-face and edge-edge pairs at
// d = 0 are gathered into blocks (one per kind) and filter::volume_excluded_block decides a
// whole block at once, in vector lanes, at numeric::simd_level(); the pairs it proves never
// coplanar in [0, 1] have no contact (the question, which starts with the same stage 1 on the
// same query, would answer so there) and are dropped; the others go on to the question, in the
// order they came within their kind. Used by the candidate API's loop and the scene's stream.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "filter/volume_block.hpp"
#include "scene/narrow_phase.hpp"

namespace exactccd::scene {

/// One worker's blocks of 3D pairs (Id: what the question is told about a pair).
template <class Id>
class CoplanarBlocks {
 public:
  /// Blocks for the pairs of `tests` (their positions and question).
  explicit CoplanarBlocks(const PairTests<Vec3>& tests) : tests_(tests) {}

  /// Whether the batched stage applies to the question: d = 0 (within d > 0 needs no
  /// coplanarity).
  static bool applies(const CcdParams& params) { return params.contact_only(); }

  /// Adds pair r (identified by id) to its kind's block, or hands it straight to visit(r, id)
  /// when it is of another kind; a full block is decided and its remaining pairs visited.
  /// Returns false as soon as visit does.
  template <class Visit>
  bool add(const PairSides& r, const Id& id, Visit& visit) {
    if (r.kind == CollisionKind::vertex_face) return add_to(vertex_face_, r, id, visit);
    if (r.kind == CollisionKind::edge_edge) return add_to(edge_edge_, r, id, visit);
    return visit(r, id);
  }

  /// Decides both blocks and visits their remaining pairs; false as soon as visit returns false.
  template <class Visit>
  bool flush(Visit& visit) {
    return flush_block(vertex_face_, visit) && flush_block(edge_edge_, visit);
  }

 private:
  /// A kind's block: the queries' rows in lanes, and each lane's pair.
  template <class Query>
  struct Block {
    filter::VolumeBlock lanes;
    std::array<PairSides, filter::kVolumeBlock> pair{};
    std::array<Id, filter::kVolumeBlock> id{};
  };
  using VertexFaceBlock = Block<VertexFaceQuery>;
  using EdgeEdgeBlock = Block<EdgeEdgeQuery>;

  template <class B, class Visit>
  bool add_to(B& block, const PairSides& r, const Id& id, Visit& visit) {
    const std::size_t lane = block.lanes.size;
    block.pair[lane] = r;
    block.id[lane] = id;
    block.lanes.push(tests_.four_point_rows(r));  // the rows of the question's own query
    return block.lanes.full() ? flush_block(block, visit) : true;
  }

  template <class Query, class Visit>
  bool flush_block(Block<Query>& block, Visit& visit) {
    const std::size_t size = block.lanes.size;
    if (size == 0) return true;
    const std::uint32_t excluded = filter::volume_excluded_block<Query>(block.lanes, level_);
    block.lanes.size = 0;
    for (std::size_t i = 0; i < size; ++i)
      if (!(excluded >> i & 1u) && !visit(block.pair[i], block.id[i])) return false;
    return true;
  }

  const PairTests<Vec3>& tests_;
  numeric::SimdLevel level_ = numeric::simd_level();
  VertexFaceBlock vertex_face_;
  EdgeEdgeBlock edge_edge_;
};

}  // namespace exactccd::scene
