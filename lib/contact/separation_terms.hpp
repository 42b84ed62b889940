// Minimum separation as a union of feature-pair conditions (docs/design.md, "Minimum
// separation"). For a kind's feature pairs (kinds::Feature), dist(A(t), B(t)) <= d iff one
// term holds at t, a term being "f(t) <= 0 and g(t) > 0 for each of its g":
//   point-point (x, y):      f = |y - x|^2 - d^2;
//   point-edge (p; a, b):    e = b - a, r = p - a: g = r.e, e.e - r.e (p projects into the open
//                            edge; e != 0 follows), f = |r x e|^2 - d^2 |e|^2;
//   point-triangle (p; abc): n = (b - a) x (c - a): g = the three barycentric numerators
//                            n.(e_i x (p - v_i)) (p projects into the open triangle; n != 0
//                            follows), f = (n.(p - a))^2 - d^2 |n|^2;
//   edge-edge (a0a1; b0b1):  w = da x db, r = b0 - a0, s = (r x db).w, u = (r x da).w:
//                            g = s, |w|^2 - s, u, |w|^2 - u (the lines' closest points are
//                            interior to both edges; w != 0 follows), f = (w.r)^2 - d^2 |w|^2.
// Written once, templated on the number type (mpq_class on the exact path).
#pragma once

#include <array>
#include <vector>

#include "contact/polynomial.hpp"
#include "contact/vec3_ops.hpp"
#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd::contact {

/// Every term's polynomials are stored with the largest degree (6).
template <class NT>
using Poly6 = contact::Poly<NT, 6>;

/// One feature pair's condition: distance <= 0 and every positive[i] > 0 (i < positives).
template <class NT>
struct Term {
  Poly6<NT> distance;
  std::array<Poly6<NT>, 4> positive;
  int positives = 0;
};

/// The polynomial p of degree D <= 6 as a Poly6.
template <class NT, int D>
Poly6<NT> widen(const contact::Poly<NT, D>& p) {
  auto r = Poly6<NT>::zero();
  for (int k = 0; k <= D; ++k) r.c[k] = p.c[k];
  return r;
}

/// A query's points in NT, all at t0 then all at t1, in 3D (2D kinds get z = 0: distances and
/// every condition are those of the plane).
template <class NT, class Query>
auto points3(const Query& q) {
  const auto r = rows(q);
  std::array<Vec3T<NT>, r.size()> out;
  for (std::size_t i = 0; i < r.size(); ++i) {
    if constexpr (kinds::kind_of<Query>::dimension == 2)
      out[i] = {NT(r[i].x), NT(r[i].y), NT(0)};
    else
      out[i] = {NT(r[i].x), NT(r[i].y), NT(r[i].z)};
  }
  return out;
}

/// One feature pair's condition from the motions of the vectors between its points:
/// calls out(f, g...) with the term's distance polynomial f and its strict conditions g
/// (docs/design.md, 4b.1). `rel(i, j)` is the vector from point i to point j (a Vec3T of
/// polynomials in t, or of numbers: the values at one time), `dd` is d^2 of the same type.
/// Written once for the polynomials (terms) and for the values at one time (term_at).
template <class Rel, class DD, class Out>
void feature_condition(const kinds::Feature& f, Rel&& rel, const DD& dd, Out&& out) {
  using contact::cross;
  using contact::dot;
  const auto [i, j, k, l] = f.points;
  switch (f.pair) {
    case kinds::FeaturePair::point_point: {
      const auto r = rel(i, j);
      out(dot(r, r) - dd);
      return;
    }
    case kinds::FeaturePair::point_edge: {
      const auto r = rel(j, i), e = rel(j, k);
      const auto re = dot(r, e), ee = dot(e, e);
      const auto c = cross(r, e);
      out(dot(c, c) - dd * ee, re, ee - re);
      return;
    }
    case kinds::FeaturePair::point_triangle: {
      const auto n = cross(rel(j, k), rel(j, l));
      const auto h = dot(n, rel(j, i));
      out(h * h - dd * dot(n, n), dot(n, cross(rel(j, k), rel(j, i))), dot(n, cross(rel(k, l), rel(k, i))),
          dot(n, cross(rel(l, j), rel(l, i))));
      return;
    }
    case kinds::FeaturePair::edge_edge: {
      const auto da = rel(i, j), db = rel(k, l), r = rel(i, k);
      const auto w = cross(da, db);
      const auto ww = dot(w, w);
      const auto h = dot(w, r);  // (another degree: its own declaration, for clang)
      const auto s = dot(cross(r, db), w), u = dot(cross(r, da), w);
      out(h * h - dd * ww, s, ww - s, u, ww - u);
      return;
    }
  }
}

/// Calls out(term) with the term of each of a kind's feature pairs for a query with points `x`
/// (points3) and d^2 = `d2`, in feature order; only for the features f with use[f] when `use`
/// is given.
template <class Kind, class NT, std::size_t N, class Out>
void for_each_term(const std::array<Vec3T<NT>, N>& x, const NT& d2, const bool* use, Out&& out) {
  static_assert(N == 2 * Kind::points);
  // The motion of the vector from point i to point j.
  const auto rel = [&](int i, int j) {
    const Vec3T<NT>&u0 = x[i], &u1 = x[i + Kind::points], &v0 = x[j], &v1 = x[j + Kind::points];
    return Vec3T<contact::Poly<NT, 1>>{contact::linear_motion(NT(v0.x - u0.x), NT(v1.x - u1.x)),
                                       contact::linear_motion(NT(v0.y - u0.y), NT(v1.y - u1.y)),
                                       contact::linear_motion(NT(v0.z - u0.z), NT(v1.z - u1.z))};
  };
  const contact::Poly<NT, 0> dd{{d2}};
  for (std::size_t index = 0; index < Kind::features.size(); ++index) {
    if (use && !use[index]) continue;
    feature_condition(Kind::features[index], rel, dd, [&](const auto& distance, const auto&... positive) {
      Term<NT> t;
      t.distance = widen(distance);
      int k = 0;
      ((t.positive[k++] = widen(positive)), ...);
      t.positives = k;
      out(std::move(t));
    });
  }
}

/// The terms of for_each_term as a vector.
template <class Kind, class NT, std::size_t N>
std::vector<Term<NT>> terms(const std::array<Vec3T<NT>, N>& x, const NT& d2, const bool* use = nullptr) {
  std::vector<Term<NT>> out;
  out.reserve(Kind::features.size());
  for_each_term<Kind>(x, d2, use, [&](Term<NT>&& t) { out.push_back(std::move(t)); });
  return out;
}

/// The value of feature f's distance polynomial at one time, from the points' positions at
/// that time (`at[i]`, the kind's points): evaluating the geometry directly keeps the rounding
/// relative to the primitives' local size, where the power-basis coefficients of f cancel.
template <class NT, std::size_t P>
NT distance_at(const kinds::Feature& f, const std::array<Vec3T<NT>, P>& at, const NT& d2) {
  const auto rel = [&](int i, int j) { return contact::operator-(at[j], at[i]); };
  NT value;
  feature_condition(f, rel, d2, [&](const NT& distance, const auto&...) { value = distance; });
  return value;
}

}  // namespace exactccd::contact
