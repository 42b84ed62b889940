// Exact CCD on CGAL's univariate algebraic kernel. The decision procedure (docs/design.md):
//
// The set of contact times S = {t in [0,1] : in_contact(t)} is closed (it is the projection
// of a compact set), and in_contact(t) depends only on the signs at t of finitely many
// polynomials. Between consecutive roots of those polynomials every sign is constant, so
// in_contact is constant there; if it holds on an open cell it holds at the cell's left end
// by closedness. Hence S is empty iff in_contact fails at every "candidate": 0, 1 and every
// root in [0,1] of every polynomial that is not identically zero, and min S is the first
// candidate, in increasing order, where it holds. When the volume V is not identically zero
// contact needs V(t) = 0, so the candidates shrink to the roots of V in [0,1].
#include "exact/exact_ccd.hpp"

#include <algorithm>
#include <vector>

#include "contact/contact_rule.hpp"
#include "exact/algebraic_kernel.hpp"
#include "exact/stack_budget.hpp"

namespace exactccd::exact {
namespace {

using namespace algebraic;
using AlgebraicKernel = Kernel;

/// Appends the real roots of a polynomial that is not identically zero lying in [0, 1].
void append_roots_in_unit_interval(const AlgebraicKernel& kernel, const IntegerPoly& p,
                                   std::vector<Root>& out) {
  append_roots(kernel, p, 0, 1, out);
}

/// Candidate times of docs/design.md, sorted increasingly and without repetition.
template <class Polys>
std::vector<Root> candidate_times(const AlgebraicKernel& kernel, const Polys& P) {
  std::vector<Root> times;
  if (!contact::is_zero(P.volume())) {
    append_roots_in_unit_interval(kernel, integer_poly(P.volume()), times);
    return times;  // solve_1 returns them sorted and distinct
  }
  times.push_back(rational_root(0));
  times.push_back(rational_root(1));
  contact::for_each_in_plane_poly(P, [&](const auto& p) {
    if (!contact::is_zero(p)) append_roots_in_unit_interval(kernel, integer_poly(p), times);
  });
  sort_unique(kernel, times);
  return times;
}

/// The earliest time in [0, 1] at which the contact rule holds, exactly.
template <class Polys>
std::optional<Root> earliest_contact(const Polys& P) {
  const AlgebraicKernel kernel;
  const auto sign_at = kernel.sign_at_1_object();
  for (const Root& t : candidate_times(kernel, P)) {
    const auto sign = [&](const auto& p) -> int {
      if (contact::is_zero(p)) return 0;
      return static_cast<int>(sign_at(integer_poly(p), t));
    };
    if (contact::in_contact(P, sign) == contact::Truth::yes) return t;  // exact: never unknown
  }
  return std::nullopt;
}

template <class Polys>
std::optional<TimeInterval> earliest_toi(const Polys& P) {
  const std::optional<Root> t = earliest_contact(P);
  if (!t) return std::nullopt;
  return enclose(AlgebraicKernel(), *t);
}

/// The most bits of an integer coefficient among the polynomials CGAL may isolate or evaluate
/// for P (the volume and every in-plane polynomial), which bounds its recursion depth.
template <class Polys>
std::size_t coefficient_bits(const Polys& P) {
  std::size_t bits = 0;
  const auto note = [&](const auto& p) {
    if (contact::is_zero(p)) return;
    bits = std::max(bits, algebraic::coefficient_bits(integer_poly(p)));
  };
  note(P.volume());
  contact::for_each_in_plane_poly(P, note);
  return bits;
}

/// Runs `f` on P with the stack its CGAL isolation provably needs (stack_budget.hpp).
template <class Polys, class F>
auto with_stack_for(const Polys& P, F&& f) {
  decltype(f(P)) result{};
  run_with_stack_for_depth(descartes_depth_bound(coefficient_bits(P)), [&] { result = f(P); });
  return result;
}

template <class Query>
bool ccd_of(const Query& q) {
  return with_stack_for(contact::polynomials(q), [](const auto& P) { return earliest_contact(P).has_value(); });
}

template <class Query>
std::optional<TimeInterval> toi_of(const Query& q) {
  return with_stack_for(contact::polynomials(q), [](const auto& P) { return earliest_toi(P); });
}

}  // namespace

bool ccd(const RationalVertexFaceQuery& q) { return ccd_of(q); }
bool ccd(const RationalEdgeEdgeQuery& q) { return ccd_of(q); }
std::optional<TimeInterval> toi(const RationalVertexFaceQuery& q) { return toi_of(q); }
std::optional<TimeInterval> toi(const RationalEdgeEdgeQuery& q) { return toi_of(q); }

}  // namespace exactccd::exact
