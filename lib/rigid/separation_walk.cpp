#include "rigid/separation_walk.hpp"

namespace exactccd::rigid {

// Not yet written: every query passes to the exact path.
StageResult separation_walk(const RigidVertexFaceQuery&, double, double, bool) { return StageResult::undecided(); }
StageResult separation_walk(const RigidEdgeEdgeQuery&, double, double, bool) { return StageResult::undecided(); }

}  // namespace exactccd::rigid
