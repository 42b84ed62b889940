// The filtered method for callers that checked the question themselves (the scene and batch
// narrow phases, lib/scene/narrow_phase.hpp): they validate the coordinates and the options
// once per call and establish the default floating-point environment on every worker
// (scene::SceneCall, parallel_chunks), so answering each of millions of pairs through the public
// entry point (api/entry_point.cpp: the environment saved and checked, 24 coordinates and the
// question checked again) only repeated that work.
#pragma once

#include <optional>

#include "exactccd/ccd.hpp"

namespace exactccd {

/// What answer_query(q, params, Method::filtered, want_toi, nullptr) returns, for a query whose
/// coordinates are finite and params valid (min_distance finite and >= 0, tmax in (0, 1]), on a
/// thread whose floating-point environment is the default one (round to nearest, no
/// flush-to-zero, exceptions masked, x87 in extended precision): the caller's responsibility.
template <class Query>
std::optional<TimeInterval> answer_checked_query(const Query& q, const CcdParams& params, bool want_toi);

}  // namespace exactccd
