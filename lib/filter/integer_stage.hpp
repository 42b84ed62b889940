// Stage 3 of the filtered method: exact integer arithmetic (GMP) on the contact polynomials
// of a double query scaled to integers, with a small exact kernel for degree <= 4
// (exact/integer_poly.hpp) instead of CGAL's general algebraic kernel. It decides what the
// interval stage could not: contact exactly at t = 0 or 1, signs that vanish at a root
// (contact through a vertex or an edge), double roots, coplanar-for-all-t motion.
#pragma once

#include "exactccd/types.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::filter {

/// Stage 3 for vertex-face: exact; never undecided unless an internal limit is hit (then the
/// CGAL path decides). With want_toi, a collision carries its tightest TOI.
pipeline::Outcome integer_stage(const VertexFaceQuery& q, bool want_toi);

/// Stage 3 for edge-edge; see integer_stage(const VertexFaceQuery&, bool).
pipeline::Outcome integer_stage(const EdgeEdgeQuery& q, bool want_toi);

// Stage 3a, in front of the GMP stage: the same algorithm and code (integer_stage.cpp is a
// template on the integer type) in exact::FixedInteger, a 1024-bit integer stored inline
// (integer_ops.hpp): no allocation per operation. Every FixedInteger operation is checked: it
// returns the exact result or throws (overflow, or a time too small for its double
// conversion), and then the stage answers `uncertain` and the GMP stage decides. So the stage is
// exact whatever the input; the bound below only says when it cannot throw on its common path,
// and the stage is not even tried beyond it (the spread makes an overflow likely there).
//
// Bit bound. Write every nonzero coordinate as m 2^e, |m| < 2^53 (exponent_spread,
// integer_query.hpp), and S = emax - emin. After scaling by 2^-emin every coordinate is an
// integer below 2^(53 + S); a relative motion d0 + t (d1 - d0) (contact_polynomials.hpp) has
// |d0| < 2^(54 + S) and |d1 - d0| < 2^(55 + S) =: 2^b, so its l1 norm (sum of the absolute
// values of the coefficients) is below 2^(b + 1). Every coefficient, and every partial sum of
// a product or a sum, is at most the l1 norm of the result's terms, and ||p q||_1 <=
// ||p||_1 ||q||_1. Each contact polynomial is a sum of T products of m linear factors (cross and
// dot products); the largest are D - U and the barycentric numerators, m = 4, T <= 24 (w . w and
// (r x db) . w each 3 x 2 x 2 = 12 terms): below 24 * 2^(4 (b + 1)) < 2^(4 b + 9) =
// 2^(4 S + 229) =: 2^B. (V: 6 terms, m = 3; segment tests and
// the branch vectors: m = 2; all smaller.) Then, with cells of width 2^-k:
// - Bernstein coefficients times 12 (integer_poly.cpp): |b_j| <= 12 * 2^4 * 2^B; on a cell of
//   depth k the subdivision keeps them times 2^(d k), d <= 4, and the true coefficients on a
//   subcell are convex combinations of the parent's: below 2^(B + 8 + 4 k); the de Casteljau
//   sums of one step add at most 2^4 before the shift: below 2^(B + 12 + 4 k).
// - sign_at(p, a / 2^k), 0 <= a <= 2^k: Horner's partial sums are 2^(k (deg - i)) times partial
//   sums of p's terms at a point of [0, 1]: below 5 * 2^(B + 4 k) < 2^(B + 3 + 4 k).
// - sign_on_cell at depth k: e_j = sum_i C(i, j) a^(i - j) 2^(k (d - i)) c_i, each term below
//   6 * 2^(k (d - j)) 2^B, the sum below 2^(B + 6 + 4 k); its Bernstein coefficients times 12:
//   below 2^(B + 14 + 4 k).
// So every step of isolation to depth k <= 64 (the first isolation attempt), of the refinement
// to cells of 2^-56 around a long-double guess, and every sign at such a cell or point stays
// below 2^(4 S + 229 + 14 + 256) = 2^(4 S + 499), which fits 1024 bits (|x| < 2^1024, checked)
// when 4 S + 499 <= 1023, i.e. S <= 131. The limit is 128. Not covered, and guarded only by the
// checks: the square-free part and gcds (pseudo-remainders multiply by leading coefficients, up
// to a few times B bits) and bisection past 2^-64 (a root of q within 2^-64 of the candidate,
// or a TOI enclosure below 2^-11 that needs cells narrower than 2^-64);
// their overflow sends the query to the GMP stage. tests/test_fixed_integer_stage checks the
// stage against the GMP stage on random, degenerate and extreme-spread queries.
inline constexpr int kFixedIntegerSpreadLimit = 128;

/// Stage 3a for vertex-face: the integer stage in exact::FixedInteger (see above). Exact when
/// it decides; undecided when the exponent spread exceeds kFixedIntegerSpreadLimit, when an
/// operation would overflow 1024 bits or an internal limit is hit (then the GMP stage decides).
pipeline::Outcome fixed_integer_stage(const VertexFaceQuery& q, bool want_toi);

/// Stage 3a for edge-edge; see fixed_integer_stage(const VertexFaceQuery&, bool).
pipeline::Outcome fixed_integer_stage(const EdgeEdgeQuery& q, bool want_toi);

/// Stage 3a in the contact question's stage list.
struct FixedIntegerStage {
  static constexpr pipeline::Counter counter = &StageCounters::fixed_integer;  ///< counted as
  /// The stage on work.query() (also, after a collision was proved, for its TOI).
  template <class Query, class Findings>
  pipeline::Outcome operator()(const pipeline::Work<Query, Findings>& work) const {
    return fixed_integer_stage(work.query(), work.question.want_toi);
  }
};

/// Stage 3 in the contact question's stage list.
struct IntegerStage {
  static constexpr pipeline::Counter counter = &StageCounters::integer;  ///< counted as
  /// The stage on work.query() (also, after a collision was proved, for its TOI).
  template <class Query, class Findings>
  pipeline::Outcome operator()(const pipeline::Work<Query, Findings>& work) const {
    return integer_stage(work.query(), work.question.want_toi);
  }
};

}  // namespace exactccd::filter
