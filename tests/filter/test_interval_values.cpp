// The interval stage's term values over a time interval (filter/interval/values.hpp): every
// term of VertexFaceTerms / EdgeEdgeTerms built on MotionOver (the cell T) must contain the
// exact value of the same term's rational polynomial (VertexFacePolys<mpq_class>, ...) at every
// t in T; checked at T's ends and midpoint on random, nearly coplanar and grid queries, on wide
// and on narrow cells. Also next_up_nonnegative against std::nextafter.
#include <gtest/gtest.h>

#include <CGAL/Interval_nt.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "contact/contact_polynomials.hpp"
#include "exactccd/rational.hpp"
#include "filter/interval/values.hpp"

namespace exactccd {
namespace {

using filter::interval::Interval;
using filter::interval::MotionOver;

/// x lies in the interval (exactly, in rationals).
bool contains(const Interval& i, const mpq_class& x) { return mpq_class(i.inf()) <= x && x <= mpq_class(i.sup()); }

struct Checker {
  mpq_class t;
  std::string where;
  int checked = 0;
  template <int D>
  void operator()(const Interval& value, const contact::Poly<mpq_class, D>& exact, const char* name) {
    ++checked;
    const mpq_class e = exact(t);
    EXPECT_TRUE(contains(value, e)) << where << ": " << name << " = " << e.get_d() << " not in [" << value.inf()
                                    << ", " << value.sup() << "]";
  }
  template <int D>
  void vector(const Vec3T<Interval>& value, const Vec3T<contact::Poly<mpq_class, D>>& exact, const char* name) {
    (*this)(value.x, exact.x, name), (*this)(value.y, exact.y, name), (*this)(value.z, exact.z, name);
  }
  void segment(const contact::PointOnSegment<Vec3T<Interval>, Interval>& value, const contact::PointOnSegmentPolys<mpq_class>& exact,
               const char* name) {
    vector(value.cross, exact.cross, name), (*this)(value.dot, exact.dot, name);
  }
};

template <class Rows>
std::array<Vec3T<mpq_class>, 8> exact_rows(const Rows& r) {
  std::array<Vec3T<mpq_class>, 8> out;
  for (std::size_t i = 0; i < 8; ++i) out[i] = {mpq_class(r[i].x), mpq_class(r[i].y), mpq_class(r[i].z)};
  return out;
}

/// Checks every term of both kinds on the rows over [lo, hi] at lo, hi and the midpoint.
void check_terms(const std::array<Vec3, 8>& r, double lo, double hi, const std::string& where, int& checked) {
  CGAL::Protect_FPU_rounding<true> upwards;
  std::array<Vec3T<Interval>, 8> ir;
  for (std::size_t i = 0; i < 8; ++i) ir[i] = {Interval(r[i].x), Interval(r[i].y), Interval(r[i].z)};
  const Interval cell(lo, hi);
  const auto q = exact_rows(r);
  const contact::VertexFaceTerms<MotionOver> vf(std::in_place, ir, cell);
  const contact::EdgeEdgeTerms<MotionOver> ee(std::in_place, ir, cell);
  const auto vf_exact = contact::polynomials(from_rows<VertexFaceQueryT<mpq_class>>(q));
  const auto ee_exact = contact::polynomials(from_rows<EdgeEdgeQueryT<mpq_class>>(q));
  for (const mpq_class& t : {mpq_class(lo), mpq_class(hi), mpq_class((mpq_class(lo) + mpq_class(hi)) / 2)}) {
    Checker c{t, where + " at t = " + std::to_string(t.get_d())};
    c(vf.volume(), vf_exact.volume(), "vf volume");
    c.vector(vf.normal(), vf_exact.normal(), "vf normal");
    for (int i = 0; i < 3; ++i) {
      c(vf.barycentric(i), vf_exact.barycentric(i), "vf barycentric");
      c.segment(vf.on_edge(i), vf_exact.on_edge(i), "vf on_edge");
    }
    c(ee.volume(), ee_exact.volume(), "ee volume");
    c.vector(ee.direction_cross(), ee_exact.direction_cross(), "ee direction_cross");
    for (int i = 0; i < 4; ++i) {
      c(ee.parameter(i), ee_exact.parameter(i), "ee parameter");
      c.segment(ee.endpoint_on_edge(i), ee_exact.endpoint_on_edge(i), "ee endpoint on edge");
    }
    checked += c.checked;
  }
}

TEST(IntervalValues, TermsOverACellContainTheExactPolynomialValues) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), time(0.0, 1.0);
  std::uniform_int_distribution<int> grid(-4, 4), width_exponent(1, 50);
  int checked = 0;
  for (int n = 0; n < 600; ++n) {
    std::array<Vec3, 8> r;
    for (Vec3& p : r) p = {unit(rng), unit(rng), unit(rng)};
    if (n % 3 == 1)  // grid points: exactly representable, exact zeros and parallel edges
      for (Vec3& p : r) p = {grid(rng) / 4.0, grid(rng) / 4.0, grid(rng) / 8.0};
    if (n % 3 == 2)  // all points near the plane z = 0.25 (a flat sheet): nearly zero volumes
      for (Vec3& p : r) p.z = 0.25 + std::ldexp(unit(rng), -40);
    double lo = time(rng), hi = time(rng);
    if (lo > hi) std::swap(lo, hi);
    if (n % 2 == 0) hi = std::fmin(1.0, lo + std::ldexp(1.0, -width_exponent(rng)));  // narrow cells
    if (n % 10 == 0) lo = 0.0, hi = 1.0;
    if (n % 10 == 5) hi = lo;  // a point cell: the values at one double time
    check_terms(r, lo, hi, "query " + std::to_string(n), checked);
  }
  EXPECT_GT(checked, 600 * 3 * 40);
}

TEST(IntervalValues, NextUpNonnegativeIsTheNextDouble) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double inf = std::numeric_limits<double>::infinity();
  for (double x : {0.0, -0.0, std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(),
                   0x1p-1022 - 0x1p-1074, 0.5, 1.0, std::nextafter(1.0, 0.0), std::numeric_limits<double>::max()})
    EXPECT_EQ(filter::interval::next_up_nonnegative(x), std::nextafter(x, inf)) << x;
  for (int n = 0; n < 10000; ++n) {
    const double x = std::ldexp(unit(rng), -(n % 1100));
    EXPECT_EQ(filter::interval::next_up_nonnegative(x), std::nextafter(x, inf)) << x;
  }
}

}  // namespace
}  // namespace exactccd
