// The contact question's block stages (pipeline/block.hpp) on the narrow phase's pairs: a
// worker's vertex-face and edge-edge pairs at d = 0 are gathered into blocks (one per kind) and
// questions::contact_block_stages runs the stages with a block form on a whole block at once
// (stage 1 in vector lanes at numeric::simd_level()); the pairs they prove apart have no contact
// (the per-pair question would answer so) and are dropped; the others go on to the question, in
// the order they came within their kind, with what the block stages handed over, so that their
// per-pair stages resume after them (never running a block stage again). Used by the candidate
// API's loop and the scene's stream.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "pipeline/block.hpp"
#include "questions/contact_question.hpp"
#include "scene/narrow_phase.hpp"

namespace exactccd::scene {

/// One worker's blocks of 3D pairs (Id: what the question is told about a pair).
template <class Id>
class CoplanarBlocks {
 public:
  /// Blocks for the pairs of `tests` (their positions and question).
  explicit CoplanarBlocks(const PairTests<Vec3>& tests) : tests_(tests) {}

  /// Whether the block stages apply to the question: d = 0 (within d > 0 needs no coplanarity).
  static bool applies(const CcdParams& params) { return params.contact_only(); }

  /// Adds pair r (identified by id) to its kind's block, or hands it straight to visit(r, id,
  /// nullptr) when it is of another kind; a full block goes through the block stages and its
  /// remaining pairs are visited as visit(r, id, &findings). Returns false as soon as visit does.
  template <class Visit>
  bool add(const PairSides& r, const Id& id, Visit& visit) {
    if (r.kind == CollisionKind::vertex_face) return add_to(vertex_face_, r, id, visit);
    if (r.kind == CollisionKind::edge_edge) return add_to(edge_edge_, r, id, visit);
    return visit(r, id, nullptr);
  }

  /// Runs both blocks and visits their remaining pairs; false as soon as visit returns false.
  template <class Visit>
  bool flush(Visit& visit) {
    return flush_block(vertex_face_, visit) && flush_block(edge_edge_, visit);
  }

 private:
  /// A kind's block: the queries' rows in lanes, and each lane's pair.
  template <class Query>
  struct Block {
    pipeline::QueryLanes<Query> lanes;
    std::array<PairSides, pipeline::kLanes> pair{};
    std::array<Id, pipeline::kLanes> id{};
  };

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
    const pipeline::BlockPrefix<questions::ContactFindings> prefix = questions::contact_block_stages(block.lanes);
    block.lanes.size = 0;
    for (std::size_t i = 0; i < size; ++i)
      if ((prefix.open >> i & 1u) && !visit(block.pair[i], block.id[i], &prefix.findings[i])) return false;
    return true;
  }

  const PairTests<Vec3>& tests_;
  Block<VertexFaceQuery> vertex_face_;
  Block<EdgeEdgeQuery> edge_edge_;
};

}  // namespace exactccd::scene
