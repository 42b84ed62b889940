// exactccd: umbrella header. Include this to get the whole public API.
#pragma once

#include "exactccd/candidates.hpp"  // IWYU pragma: export
#include "exactccd/ccd.hpp"    // IWYU pragma: export
#include "exactccd/scene.hpp"  // IWYU pragma: export
#include "exactccd/stats.hpp"  // IWYU pragma: export
#include "exactccd/types.hpp"  // IWYU pragma: export
