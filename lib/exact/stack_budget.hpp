// Running CGAL's root isolation with the stack it provably needs.
//
// CGAL's Descartes method (Algebraic_kernel_d_1, the exact path) recurses once per halving of
// [0, 1], so its depth is the number of bits that separate two roots: about 2100 levels (192
// bytes each in a release build, measured with gdb) for a query mixing 2^-1074 and 2^1000,
// which overflows a 256 KB stack, and more for rational input. exactccd's own kernel is
// iterative (integer_poly.cpp); CGAL's cannot be changed, so the depth is bounded instead and
// a deep isolation runs on a helper thread whose stack is sized from that bound.
//
// The bound (docs/design.md, 8). Descartes is run on the square-free factors f of a polynomial
// p of degree d <= 4 whose integer coefficients have at most tau bits; by Mignotte's bound a
// factor's coefficients have at most tau + d + 2 bits, and by Mahler's root separation bound
//     sep(f) >= sqrt(3) d^-((d + 2) / 2) ||f||_2^(1 - d),
// so -log2 sep(f) <= (d - 1)(tau + d + 2 + log2 sqrt(d + 1)) + ((d + 2) / 2) log2 d <= 3 tau + 31.
// CGAL's Solve_1 isolates all real roots and then keeps those in [0, 1]: its initial interval
// holds every real root, |root| <= 1 + max |a_i / a_d| <= 2^(tau + 1) (Cauchy), so it is at
// most 2^(tau + 2) wide, and the subdivision stops once a cell is narrower than sep / 4
// (two-circle theorem). Its depth is at most (tau + 2) + (-log2 sep + 2) <= 4 tau + 35;
// descartes_depth_bound adds a margin of 64.
#pragma once

#include <cstddef>
#include <functional>

namespace exactccd::exact {

/// Upper bound on the recursion depth of CGAL's Descartes isolation on [0, 1] for a polynomial
/// of degree <= 4 whose integer coefficients have at most `coefficient_bits` bits.
std::size_t descartes_depth_bound(std::size_t coefficient_bits);

/// The same bound for a polynomial of degree <= `degree` (>= 1): with n = degree and
/// tau = coefficient_bits, a square-free factor f has coefficients of at most
/// beta = tau + n + log2 sqrt(n + 1) bits (Mignotte), Mahler's bound gives
/// -log2 sep(f) <= (n - 1)(beta + log2 sqrt(n + 1)) + ((n + 2) / 2) log2 n, and the depth is at
/// most (tau + 2) + (-log2 sep(f) + 2) <= n tau + (n - 1)(n + 2 + 2 log2 sqrt(n + 1)) +
/// ((n + 2) / 2) log2 n + 4, which (n - 1)(n + 6) + ((n + 2) / 2) ceil(log2 n) + 4 bounds for
/// n <= 15 (2 log2 sqrt(n + 1) = log2(n + 1) <= 4); plus the margin of 64. For n <= 4 it is the bound above.
/// Used by the rigid motion model (degree <= 10, docs/design.md 9). Throws std::logic_error
/// for a degree above 15.
std::size_t descartes_depth_bound(std::size_t coefficient_bits, int degree);

/// Runs `work` on the calling thread when `depth` recursion levels of CGAL's isolation fit what
/// is left of its stack (measured where the platform tells, with a reserve; 64 KB where it does
/// not), otherwise on a new thread whose stack holds `depth` levels (and waits for it; an
/// exception thrown by `work` is rethrown here). Throws std::runtime_error when that thread
/// cannot start.
void run_with_stack_for_depth(std::size_t depth, const std::function<void()>& work);

}  // namespace exactccd::exact
