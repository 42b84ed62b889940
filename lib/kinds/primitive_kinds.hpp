// One description per primitive kind (docs/design.md, "Adding a primitive kind").
//
// A kind is its query type (the points of the primitives, at t = 0 and t = 1), the names it is
// known by (files, the CLI's --kind, the C API, JSON), its points' names in benchmark row order,
// and where its contact mathematics lives: contact::polynomials(query) and its rule
// (lib/contact), templated on the number type. Every layer derives what it needs from this:
// the filter's stage dispatch (stage functions are overloads on the query type), the public
// entry points, the CLI's readers, printers and --kind values, bench, compare, fuzz-against
// and the test parameterisation (for_each_kind).
#pragma once

#include <array>
#include <string_view>
#include <type_traits>

#include "exactccd/plugin.h"
#include "exactccd/types.hpp"

namespace exactccd::kinds {

/// Vertex-face: a point p against a triangle (a, b, c).
struct VertexFace {
  template <class T>
  using Query = VertexFaceQueryT<T>;
  static constexpr std::string_view name = "vertex-face";  ///< file names, tables, JSON
  static constexpr std::string_view short_name = "vf";     ///< the CLI's --kind value
  static constexpr std::string_view function = "vertex_face";  ///< C++ and C API stem
  static constexpr std::string_view plugin_symbol = EXACTCCD_PLUGIN_VF_SYMBOL;  ///< plugin.h
  static constexpr int points = 4;  ///< moving points; a query has 2 * points rows
  static constexpr std::array<std::string_view, points> point_names{"p", "a", "b", "c"};
  /// The volume V = (b - a) . ((c - a) x (p - a)) as rows {base, u, v, w}: V = det[u - base,
  /// v - base, w - base] (stage 1, double-double signs, exact end signs).
  static constexpr std::array<int, 4> volume_rows{1, 2, 3, 0};
};

/// Edge-edge: edge (a0, a1) against edge (b0, b1).
struct EdgeEdge {
  template <class T>
  using Query = EdgeEdgeQueryT<T>;
  static constexpr std::string_view name = "edge-edge";
  static constexpr std::string_view short_name = "ee";
  static constexpr std::string_view function = "edge_edge";
  static constexpr std::string_view plugin_symbol = EXACTCCD_PLUGIN_EE_SYMBOL;
  static constexpr int points = 4;
  static constexpr std::array<std::string_view, points> point_names{"a0", "a1", "b0", "b1"};
  /// V = (a1 - a0) . ((b0 - a0) x (b1 - a0)).
  static constexpr std::array<int, 4> volume_rows{0, 1, 2, 3};
};

/// The kind of a query type (double, rational, interval or integer coordinates alike).
template <class Query>
struct KindOf;
template <class T>
struct KindOf<VertexFaceQueryT<T>> {
  using type = VertexFace;
};
template <class T>
struct KindOf<EdgeEdgeQueryT<T>> {
  using type = EdgeEdge;
};
/// The kind of a query type.
template <class Query>
using kind_of = typename KindOf<std::decay_t<Query>>::type;

/// Calls f(Kind{}) for every kind, in a fixed order (the order of --kind values and tables).
template <class F>
constexpr void for_each_kind(F&& f) {
  f(VertexFace{});
  f(EdgeEdge{});
}

}  // namespace exactccd::kinds
