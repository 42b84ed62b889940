// Certified signs at a double time t of the rigid rule's volume V and of a feature pair's
// distance f (docs/design.md, 9.4), for narrowing a time of impact to adjacent doubles: first in
// double-double arithmetic with a running error bound (numeric/double_word.hpp) on the scaled
// positions (positions.hpp), which almost always decides; exactly in GMP rationals only where it
// does not (a root exactly at a double, or values below the error bound).
//
// Double-double. The query is normalized (rigid_unit_scaling.hpp: lengths below 2, quaternion components
// below 2, both ends of a body scaled alike). Every interpolation q0 + t (q1 - q0) and
// (cA - cB)(t) is formed from exact differences (TwoSum, difference_at) and one product by t;
// then the quaternion products, norms and rotations (quaternion.hpp) and the terms
// (contact_polynomials.hpp, separation_terms.hpp) are Approx operations, each with its proven
// error bound. Magnitudes: |q(t)| < 4, |conj(qB) qA| < 16, |M(q) v| <= |q|^2 |v|, so |N| < 16 (4)
// 16 + 256 (2 sqrt 3) < 2^11, |D b| < 2^10 (2 sqrt 3), every position below 2^12; V (degree 3)
// below 2^40, every term f (degree 6, d D(t) counted as a length when d 2^s D < 2^100) below 2^150,
// error bounds of the same order: nothing near 2^1000. A d whose scaled product d D exceeds 2^100
// is not certified (the exact path decides). Underflow costs kAbsolute per operation (counted).
// t must be a double in [0, 1]. Needs round-to-nearest.
#pragma once

#include "exactccd/rigid.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd::rigid {

/// The sign (-1, 0, 1) of V at the double t in [0, 1] for the normalized query, exactly:
/// double-double when that certifies it, else GMP rationals (then `used_gmp` is set).
int volume_sign_at(const RigidVertexFaceQuery& normalized_query, double t, bool& used_gmp);
/// See volume_sign_at(const RigidVertexFaceQuery&, double, bool&).
int volume_sign_at(const RigidEdgeEdgeQuery& normalized_query, double t, bool& used_gmp);

/// The sign of component `axis` of the contact rule's cross for endpoint `endpoint` (0..3: a0,
/// a1, b0, b1) against the other edge (contact_polynomials.hpp, endpoint_on_edge) at the double t,
/// exactly (as volume_sign_at). Degree 2 in the positions: below 2^26, far from overflow.
int orientation_sign_at(const RigidEdgeEdgeQuery& normalized_query, int endpoint, int axis, double t, bool& used_gmp);

/// The sign of feature f's distance polynomial (separation_terms.hpp) with minimum distance d at
/// the double t, exactly (as volume_sign_at). `approximation`, when given, receives an
/// approximation of its value times a positive factor (for root estimates; 0 when GMP decided).
int distance_sign_at(const RigidVertexFaceQuery& normalized_query, const kinds::Feature& f, double d, double t,
                     bool& used_gmp, double* approximation = nullptr);
/// See distance_sign_at(const RigidVertexFaceQuery&, const kinds::Feature&, double, double, bool&, double*).
int distance_sign_at(const RigidEdgeEdgeQuery& normalized_query, const kinds::Feature& f, double d, double t,
                     bool& used_gmp, double* approximation = nullptr);

}  // namespace exactccd::rigid
