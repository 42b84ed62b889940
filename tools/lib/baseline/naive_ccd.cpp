#include "baseline/naive_ccd.hpp"

#include "baseline/mpfr_number.hpp"
#include "baseline/naive_algorithm.hpp"

namespace exactccd::baseline {
namespace {

// The in-primitive test of each kind at one time, in number type T.
template <class T>
bool inside(const VertexFaceQuery&, const std::array<Vec3T<T>, 4>& at, const T& eps) {
  return vertex_face_inside<T>(at, eps);
}
template <class T>
bool inside(const EdgeEdgeQuery&, const std::array<Vec3T<T>, 4>& at, const T& eps) {
  return edge_edge_inside<T>(at, eps);
}

template <class T, class Query>
std::optional<double> textbook(const Query& q, double eps) {
  return naive_toi<T>(q, eps, [&q](const auto& at, const T& e) { return inside<T>(q, at, e); });
}

template <class Query>
std::optional<double> variant_toi(const Query& q, NaiveVariant variant) {
  switch (variant) {
    case NaiveVariant::plain: return textbook<double>(q, 0);
    case NaiveVariant::tolerance: return textbook<double>(q, kNaiveTolerance);
    case NaiveVariant::mpfr24: return textbook<Mpfr<24>>(q, 0);
    case NaiveVariant::mpfr53: return textbook<Mpfr<53>>(q, 0);
    case NaiveVariant::mpfr113: return textbook<Mpfr<113>>(q, 0);
    case NaiveVariant::mpfr256: return textbook<Mpfr<256>>(q, 0);
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> naive_toi(const VertexFaceQuery& q, NaiveVariant variant) { return variant_toi(q, variant); }
std::optional<double> naive_toi(const EdgeEdgeQuery& q, NaiveVariant variant) { return variant_toi(q, variant); }

}  // namespace exactccd::baseline
