#include "baseline/naive_ccd.hpp"

#include "baseline/mpfr_number.hpp"
#include "baseline/naive_algorithm.hpp"

namespace exactccd::baseline {
namespace {

template <class T>
std::optional<double> vf(const VertexFaceQuery& q, double eps) {
  return naive_toi<T>(q, eps, [](const auto& at, const T& e) { return vertex_face_inside<T>(at, e); });
}

template <class T>
std::optional<double> ee(const EdgeEdgeQuery& q, double eps) {
  return naive_toi<T>(q, eps, [](const auto& at, const T& e) { return edge_edge_inside<T>(at, e); });
}

}  // namespace

std::optional<double> naive_vertex_face_toi(const VertexFaceQuery& q, NaiveVariant variant) {
  switch (variant) {
    case NaiveVariant::plain: return vf<double>(q, 0);
    case NaiveVariant::tolerance: return vf<double>(q, kNaiveTolerance);
    case NaiveVariant::mpfr24: return vf<Mpfr<24>>(q, 0);
    case NaiveVariant::mpfr53: return vf<Mpfr<53>>(q, 0);
    case NaiveVariant::mpfr113: return vf<Mpfr<113>>(q, 0);
    case NaiveVariant::mpfr256: return vf<Mpfr<256>>(q, 0);
  }
  return std::nullopt;
}

std::optional<double> naive_edge_edge_toi(const EdgeEdgeQuery& q, NaiveVariant variant) {
  switch (variant) {
    case NaiveVariant::plain: return ee<double>(q, 0);
    case NaiveVariant::tolerance: return ee<double>(q, kNaiveTolerance);
    case NaiveVariant::mpfr24: return ee<Mpfr<24>>(q, 0);
    case NaiveVariant::mpfr53: return ee<Mpfr<53>>(q, 0);
    case NaiveVariant::mpfr113: return ee<Mpfr<113>>(q, 0);
    case NaiveVariant::mpfr256: return ee<Mpfr<256>>(q, 0);
  }
  return std::nullopt;
}

}  // namespace exactccd::baseline
