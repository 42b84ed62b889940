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

#include <array>

#include "exactccd/types.hpp"
#include "numeric/certified_sign.hpp"

namespace exactccd::filter {

/// V of one query at any number of doubles t: the query scaled once (ScaledRows), the parts of
/// its three edge vectors that do not depend on t formed once, then each t evaluated in
/// double-double.
class VolumeSigns {
 public:
  /// V of a vertex-face query.
  explicit VolumeSigns(const VertexFaceQuery& q);
  /// V of an edge-edge query.
  explicit VolumeSigns(const EdgeEdgeQuery& q);

  /// The certified sign (-1 or +1) of V(t) for a double t in [0, 1], or 0 when double-double
  /// precision cannot certify it (always when V(t) = 0). `approximation`, when given, receives
  /// the double nearest the computed double-double value of V(t) times 2^(3 s) (s the scaling's
  /// exponent, the same for every t of the query: ratios of approximations are meaningful).
  int sign_at(double t, double* approximation = nullptr) const;

 private:
  template <class Query>
  void hoist(const Query& q);

  // V = det[A, B, C], A, B, C the vectors from the kind's volume row `base` to its rows u, v, w
  // (numeric::moving_vector: the parts that do not depend on t formed once).
  using Approx = numeric::double_word::Approx;
  std::array<Vec3T<numeric::double_word::MovingDifference>, 3> vectors_{};
  bool usable_ = false;  // false: the scaled rows are not usable (ScaledRows::usable)
};

/// The certified sign (-1 or +1) of V(t) (V as in contact_polynomials.hpp) for a double t in
/// [0, 1], or 0 when double-double precision cannot certify it (always when V(t) = 0).
int certified_volume_sign(const VertexFaceQuery& q, double t);

/// See certified_volume_sign(const VertexFaceQuery&, double).
int certified_volume_sign(const EdgeEdgeQuery& q, double t);

}  // namespace exactccd::filter
