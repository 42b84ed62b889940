// The textbook method in plain doubles, NOT robust: the speed baseline and the example of
// what goes wrong near degeneracies (missed and invented collisions). Never use it where a
// wrong answer matters; the other methods are exact.
//
// Cubic coefficients of V(t) in doubles, its real roots in [0, 1] by the closed-form cubic
// formula, and at each root the least-squares solve z = (M^T M)^-1 M^T r of the inclusion
// (vertex-face: alpha, beta, gamma >= 0; edge-edge: alpha, beta in [0, 1]), no tolerance.
#pragma once

#include <optional>

#include "exactccd/types.hpp"

namespace exactccd::baseline {

/// Naive vertex-face CCD (non-robust). Returns the earliest root found to collide, if any.
std::optional<double> naive_vertex_face_toi(const VertexFaceQuery& q);

/// Naive edge-edge CCD (non-robust). Returns the earliest root found to collide, if any.
std::optional<double> naive_edge_edge_toi(const EdgeEdgeQuery& q);

/// Real roots of a t^3 + b t^2 + c t + d in [0, 1], increasing, computed in doubles by the
/// closed-form (Cardano / trigonometric) formulas; degenerates to the quadratic and linear
/// formulas when leading coefficients are exactly zero. Returns the number of roots written.
int naive_cubic_roots_in_unit_interval(double a, double b, double c, double d, double roots[3]);

}  // namespace exactccd::baseline
