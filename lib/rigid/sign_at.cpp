#include "rigid/sign_at.hpp"

#include <gmpxx.h>

#include <cmath>

#include "contact/polynomial.hpp"
#include "numeric/double_word.hpp"
#include "rigid/positions.hpp"
#include "contact/separation_terms.hpp"

namespace exactccd::rigid {
namespace {

namespace dw = numeric::double_word;
using dw::Approx;

/// Double-double with error bounds at the double t (sign_at.hpp).
struct ApproxArithmetic {
  double t;
  Approx lerp(double x0, double x1) const { return dw::difference_at(0.0, x0, 0.0, x1, t); }
  Approx difference(double u0, double v0, double u1, double v1) const { return dw::difference_at(u0, v0, u1, v1, t); }
  Approx constant(double x) const { return {{x, 0.0}, 0.0}; }
  Approx negate(const Approx& x) const { return {dw::neg(x.value), x.error}; }
};

/// Exact rationals at the rational t (constant polynomials: their operators evaluate at once,
/// where mpq_class's expression templates would dangle in the templates' `auto` temporaries).
struct RationalArithmetic {
  using Q = contact::Poly<mpq_class, 0>;
  mpq_class t;
  Q lerp(double x0, double x1) const { return Q{{mpq_class(x0) + t * (mpq_class(x1) - mpq_class(x0))}}; }
  Q difference(double u0, double v0, double u1, double v1) const {
    const mpq_class d0 = mpq_class(v0) - mpq_class(u0), d1 = mpq_class(v1) - mpq_class(u1);
    return Q{{d0 + t * (d1 - d0)}};
  }
  Q constant(double x) const { return Q{{mpq_class(x)}}; }
  Q negate(const Q& x) const { return Q{{mpq_class(-x.c[0])}}; }
};

int sign_of(const Approx& v) { return dw::certain_sign(v); }
int sign_of(const RationalArithmetic::Q& v) { return sgn(v.c[0]); }

template <class Query, class A>
int volume_sign(const Query& q, const A& arithmetic) {
  const auto at = positions_at(q, arithmetic);
  return sign_of(value_terms<Query>(at.point).volume());
}

template <class Query, class A>
int orientation_sign(const Query& q, int endpoint, int axis, const A& arithmetic) {
  const auto at = positions_at(q, arithmetic);
  const auto terms = value_terms<Query>(at.point);
  const auto& c = terms.endpoint_on_edge(endpoint).cross;
  return sign_of(axis == 0 ? c.x : axis == 1 ? c.y : c.z);
}

/// Feature f's distance at the positions `at` with d D(t) for d.
template <class R>
R distance_value(const kinds::Feature& f, const PositionsAt<R>& at, const R& d) {
  const ValueMotion<R> motion(at.point);
  const R dD = d * at.D;
  R value = dD;
  contact::feature_condition(f, [&](int i, int j) { return motion.rel(i, j); }, dD * dD,
                                [&](const R& distance, const auto&...) { value = distance; });
  return value;
}

template <class Query>
int volume_sign_of(const Query& q, double t, bool& used_gmp) {
  if (const int s = volume_sign(q, ApproxArithmetic{t}); s != 0) return s;
  used_gmp = true;
  return volume_sign(q, RationalArithmetic{mpq_class(t)});
}

template <class Query>
int orientation_sign_of(const Query& q, int endpoint, int axis, double t, bool& used_gmp) {
  if (const int s = orientation_sign(q, endpoint, axis, ApproxArithmetic{t}); s != 0) return s;
  used_gmp = true;
  return orientation_sign(q, endpoint, axis, RationalArithmetic{mpq_class(t)});
}

template <class Query>
int distance_sign_of(const Query& q, const kinds::Feature& f, double d, double t, bool& used_gmp, double* approximation) {
  if (approximation) *approximation = 0;
  const auto at = positions_at(q, ApproxArithmetic{t});
  const Approx dd{{d, 0.0}, 0.0};
  if (std::fabs(d * at.D.value.hi) < 0x1p100) {  // sign_at.hpp: d D below 2^100
    const Approx value = distance_value(f, at, dd);
    if (approximation) *approximation = value.value.hi;
    if (const int s = dw::certain_sign(value); s != 0) return s;
  }
  used_gmp = true;
  const RationalArithmetic exact{mpq_class(t)};
  return sign_of(distance_value(f, positions_at(q, exact), exact.constant(d)));
}

}  // namespace

int volume_sign_at(const RigidVertexFaceQuery& q, double t, bool& used_gmp) { return volume_sign_of(q, t, used_gmp); }
int volume_sign_at(const RigidEdgeEdgeQuery& q, double t, bool& used_gmp) { return volume_sign_of(q, t, used_gmp); }
int orientation_sign_at(const RigidEdgeEdgeQuery& q, int endpoint, int axis, double t, bool& used_gmp) {
  return orientation_sign_of(q, endpoint, axis, t, used_gmp);
}
int distance_sign_at(const RigidVertexFaceQuery& q, const kinds::Feature& f, double d, double t, bool& used_gmp,
                     double* approximation) {
  return distance_sign_of(q, f, d, t, used_gmp, approximation);
}
int distance_sign_at(const RigidEdgeEdgeQuery& q, const kinds::Feature& f, double d, double t, bool& used_gmp,
                     double* approximation) {
  return distance_sign_of(q, f, d, t, used_gmp, approximation);
}

}  // namespace exactccd::rigid
