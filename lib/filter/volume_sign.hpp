// The sign of the contact volume V at a double time t, certified in double-double arithmetic
// (numeric/certified_sign.hpp, the proof there).
//
// Used to narrow a time of impact to adjacent doubles: the interval stage stops a few bits
// short, where V's value drops below its double-precision evaluation error; double-double
// (about 106 bits) with a running error bound settles the sign at the two doubles next to the
// root in almost every case, in well under a microsecond, where exact GMP evaluation takes
// several. When the bound does not separate the value from zero the answer is "not certified"
// and the caller decides exactly.
#pragma once

#include "exactccd/types.hpp"

namespace exactccd::filter {

/// The certified sign (-1 or +1) of V(t) (V as in contact_polynomials.hpp) for a double t in
/// [0, 1], or 0 when double-double precision cannot certify it (always when V(t) = 0).
int certified_volume_sign(const VertexFaceQuery& q, double t);

/// See certified_volume_sign(const VertexFaceQuery&, double).
int certified_volume_sign(const EdgeEdgeQuery& q, double t);

}  // namespace exactccd::filter
