#include "degeneracy/degeneracy.hpp"

#include "contact/contact_polynomials.hpp"
#include "exact/integer_poly.hpp"

namespace exactccd::exact {
namespace {

using contact::Poly;

template <int D>
IntegerPoly integer_poly(const Poly<mpq_class, D>& p) {
  mpz_class common = 1;
  for (const mpq_class& x : p.c) mpz_lcm(common.get_mpz_t(), common.get_mpz_t(), x.get_den_mpz_t());
  IntegerPoly r;
  for (int i = 0; i <= D; ++i) r.c[i] = p.c[i].get_num() * (common / p.c[i].get_den());
  r.normalize();
  return r;
}

template <int D>
mpq_class value_at(const Poly<mpq_class, D>& p, int t) {  // t in {0, 1}
  if (t == 0) return p.c[0];
  mpq_class s = 0;
  for (const mpq_class& x : p.c) s += x;
  return s;
}

bool vector_zero_at(const contact::PolyVec3<mpq_class, 2>& v, int t) {
  return value_at(v.x, t) == 0 && value_at(v.y, t) == 0 && value_at(v.z, t) == 0;
}

template <class Query, class Polys>
std::vector<std::string> volume_labels(const Query& q, const Polys& P) {
  std::vector<std::string> labels;
  const IntegerPoly v = integer_poly(P.volume());
  if (v.is_zero()) {
    labels.push_back("coplanar_for_all_t");
  } else {
    if (sgn(v.c[0]) == 0) labels.push_back("root_at_t0");
    mpz_class at_1 = 0;
    for (int i = 0; i <= v.deg; ++i) at_1 += v.c[i];
    if (sgn(at_1) == 0) labels.push_back("root_at_t1");
    if (v.deg >= 2) {
      const IntegerPoly g = gcd(v, derivative(v));
      if (g.deg >= 1) {
        const auto roots = roots_in_unit_interval(g, 1u << 12);
        if (!roots || !roots->empty()) labels.push_back("multiple_root");
      }
    }
  }
  const auto r = rows(q);
  bool moves = false;
  for (int i = 0; i < 4; ++i)
    moves = moves || r[i].x != r[i + 4].x || r[i].y != r[i + 4].y || r[i].z != r[i + 4].z;
  if (!moves) labels.push_back("static");
  return labels;
}

}  // namespace

std::vector<std::string> degeneracy_categories(const RationalVertexFaceQuery& q) {
  const auto P = contact::polynomials(q);
  std::vector<std::string> labels = volume_labels(q, P);
  if (vector_zero_at(P.normal(), 0) || vector_zero_at(P.normal(), 1)) labels.push_back("degenerate_triangle");
  if (labels.empty()) labels.push_back("generic");
  return labels;
}

std::vector<std::string> degeneracy_categories(const RationalEdgeEdgeQuery& q) {
  const auto P = contact::polynomials(q);
  std::vector<std::string> labels = volume_labels(q, P);
  const auto zero_length = [](const RationalVec3& a, const RationalVec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  };
  if (zero_length(q.a0_t0, q.a1_t0) || zero_length(q.b0_t0, q.b1_t0) || zero_length(q.a0_t1, q.a1_t1) ||
      zero_length(q.b0_t1, q.b1_t1))
    labels.push_back("zero_length_edge");
  else if (vector_zero_at(P.direction_cross(), 0) || vector_zero_at(P.direction_cross(), 1))
    labels.push_back("parallel_edges");
  if (labels.empty()) labels.push_back("generic");
  return labels;
}

std::string join_categories(const std::vector<std::string>& labels) {
  std::string s;
  for (const std::string& l : labels) s += (s.empty() ? "" : "+") + l;
  return s;
}

}  // namespace exactccd::exact
