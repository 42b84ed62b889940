// Exact CCD on CGAL's univariate algebraic kernel: the contact rule's polynomials in GMP
// rationals, made integers, and the one exact "earliest root where the rule holds"
// (earliest_root.hpp, the proof there; docs/design.md 3 and 4) over [0, 1].
#include "exact/exact_ccd.hpp"

#include <algorithm>

#include "contact/contact_rule.hpp"
#include "exact/algebraic_kernel.hpp"
#include "exact/earliest_root.hpp"
#include "exact/stack_budget.hpp"

namespace exactccd::exact {
namespace {

using namespace algebraic;
using AlgebraicKernel = Kernel;

/// The earliest time in [0, 1] at which the contact rule holds, exactly (earliest_root.hpp).
template <class Polys>
std::optional<Root> contact_time(const Polys& P) {
  const AlgebraicKernel kernel;
  return algebraic::earliest_contact(kernel, P, [](const auto& p) { return integer_poly(p); }, 1);
}

template <class Polys>
std::optional<TimeInterval> earliest_toi(const Polys& P) {
  const std::optional<Root> t = contact_time(P);
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
  return with_stack_for(contact::polynomials(q), [](const auto& P) { return contact_time(P).has_value(); });
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
