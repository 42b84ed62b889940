// One description per primitive kind (docs/design.md, "Adding a primitive kind").
//
// A kind is its query type (the points of the primitives, at t = 0 and t = 1), the names it is
// known by (files, the CLI's --kind, the C API, JSON), its points' names in benchmark row order,
// and where its contact mathematics lives: contact::polynomials(query) and its rule
// (lib/contact), templated on the number type. Every layer derives what it needs from this:
// the filter's stage dispatch (stage functions are overloads on the query type), the public
// entry points, the CLI's readers, printers and --kind values, bench, compare, fuzz-against
// and the test parameterisation (for_each_contact_kind).
#pragma once

#include <array>
#include <string_view>
#include <type_traits>

#include "exactccd/exactccd.h"
#include "exactccd/plugin.h"
#include "exactccd/rigid.hpp"
#include "exactccd/types.hpp"

namespace exactccd::kinds {

/// The pairs of closed features whose distances make up a kind's distance (docs/design.md,
/// "Minimum separation"): dist(A, B) <= d iff one pair's condition holds.
enum class FeaturePair {
  point_point,     ///< points {0, 1}: |x1 - x0| <= d
  point_edge,      ///< point 0 against the open edge (1, 2), projecting into it
  point_triangle,  ///< point 0 against the open triangle (1, 2, 3), projecting into it
  edge_edge,       ///< open edge (0, 1) against open edge (2, 3), closest points interior to both
};

/// One feature pair of a kind: its type and the indices of its points in the kind's point list.
struct Feature {
  FeaturePair pair;
  std::array<int, 4> points;
};

/// Which of a kind's feature pairs (at most 9) take part in a computation: mask[f] for the f-th.
using FeatureMask = std::array<bool, 9>;

/// Every feature pair.
inline constexpr FeatureMask kAllFeatures{true, true, true, true, true, true, true, true, true};

/// Vertex-face: a point p against a triangle (a, b, c).
struct VertexFace {
  template <class T>
  using Query = VertexFaceQueryT<T>;
  /// The query of the rigid motion model (exactccd/rigid.hpp): the same points on two rigid
  /// bodies, the first first_points of them on body A.
  template <class T>
  using RigidQuery = RigidVertexFaceQueryT<T>;
  static constexpr std::string_view name = "vertex-face";  ///< file names, tables, JSON
  static constexpr int c_kind = EXACTCCD_VERTEX_FACE;  ///< the C API's exactccd_kind
  static constexpr std::string_view short_name = "vf";     ///< the CLI's --kind value
  static constexpr std::string_view function = "vertex_face";  ///< C++ and C API stem
  static constexpr std::string_view plugin_symbol = EXACTCCD_PLUGIN_VF_SYMBOL;  ///< plugin.h
  static constexpr std::string_view plugin_toi_symbol = EXACTCCD_PLUGIN_VF_TOI_SYMBOL;  ///< optional
  static constexpr int points = 4;  ///< moving points; a query has 2 * points rows
  static constexpr std::array<std::string_view, points> point_names{"p", "a", "b", "c"};
  /// The volume V = (b - a) . ((c - a) x (p - a)) as rows {base, u, v, w}: V = det[u - base,
  /// v - base, w - base] (stage 1, double-double signs, exact end signs).
  static constexpr std::array<int, 4> volume_rows{1, 2, 3, 0};
  static constexpr int dimension = 3;     ///< coordinates per point
  static constexpr int first_points = 1;  ///< points 0 .. first_points - 1 are primitive A
  /// dist(p, triangle) <= d iff p is within d of a vertex, of an open edge it projects into,
  /// or of the open triangle it projects into.
  static constexpr std::array<Feature, 7> features{{{FeaturePair::point_triangle, {0, 1, 2, 3}},
                                                     {FeaturePair::point_edge, {0, 1, 2, 0}},
                                                     {FeaturePair::point_edge, {0, 2, 3, 0}},
                                                     {FeaturePair::point_edge, {0, 3, 1, 0}},
                                                     {FeaturePair::point_point, {0, 1, 0, 0}},
                                                     {FeaturePair::point_point, {0, 2, 0, 0}},
                                                     {FeaturePair::point_point, {0, 3, 0, 0}}}};
};

/// Edge-edge: edge (a0, a1) against edge (b0, b1).
struct EdgeEdge {
  template <class T>
  using Query = EdgeEdgeQueryT<T>;
  template <class T>
  using RigidQuery = RigidEdgeEdgeQueryT<T>;  ///< the rigid motion model's query
  static constexpr std::string_view name = "edge-edge";
  static constexpr int c_kind = EXACTCCD_EDGE_EDGE;
  static constexpr std::string_view short_name = "ee";
  static constexpr std::string_view function = "edge_edge";
  static constexpr std::string_view plugin_symbol = EXACTCCD_PLUGIN_EE_SYMBOL;
  static constexpr std::string_view plugin_toi_symbol = EXACTCCD_PLUGIN_EE_TOI_SYMBOL;
  static constexpr int points = 4;
  static constexpr std::array<std::string_view, points> point_names{"a0", "a1", "b0", "b1"};
  /// V = (a1 - a0) . ((b0 - a0) x (b1 - a0)).
  static constexpr std::array<int, 4> volume_rows{0, 1, 2, 3};
  static constexpr int dimension = 3;
  static constexpr int first_points = 2;
  /// dist(a, b) <= d iff the open edges' closest points are interior and within d, or an
  /// endpoint is within d of the other edge (its interior or an endpoint).
  static constexpr std::array<Feature, 9> features{{{FeaturePair::edge_edge, {0, 1, 2, 3}},
                                                     {FeaturePair::point_edge, {0, 2, 3, 0}},
                                                     {FeaturePair::point_edge, {1, 2, 3, 0}},
                                                     {FeaturePair::point_edge, {2, 0, 1, 0}},
                                                     {FeaturePair::point_edge, {3, 0, 1, 0}},
                                                     {FeaturePair::point_point, {0, 2, 0, 0}},
                                                     {FeaturePair::point_point, {0, 3, 0, 0}},
                                                     {FeaturePair::point_point, {1, 2, 0, 0}},
                                                     {FeaturePair::point_point, {1, 3, 0, 0}}}};
};

/// Point-edge: a point p against a segment (a, b).
struct PointEdge {
  template <class T>
  using Query = PointEdgeQueryT<T>;
  static constexpr std::string_view name = "point-edge";
  static constexpr int c_kind = EXACTCCD_POINT_EDGE;
  static constexpr std::string_view short_name = "pe";
  static constexpr std::string_view function = "point_edge";
  static constexpr int points = 3;
  static constexpr std::array<std::string_view, points> point_names{"p", "a", "b"};
  static constexpr int dimension = 3;
  static constexpr int first_points = 1;
  static constexpr std::array<Feature, 3> features{{{FeaturePair::point_edge, {0, 1, 2, 0}},
                                                     {FeaturePair::point_point, {0, 1, 0, 0}},
                                                     {FeaturePair::point_point, {0, 2, 0, 0}}}};
  /// The contact question (d = 0) is that of the edge-edge query of this kind's points
  /// {0, 0, 1, 2} (a point is a zero-length edge: (p, p) against (a, b)): it has no contact stages of its own.
  using ContactKind = EdgeEdge;
  static constexpr std::array<int, 4> contact_points{0, 0, 1, 2};
};

/// Point-point: a point p against a point q.
struct PointPoint {
  template <class T>
  using Query = PointPointQueryT<T>;
  static constexpr std::string_view name = "point-point";
  static constexpr int c_kind = EXACTCCD_POINT_POINT;
  static constexpr std::string_view short_name = "pp";
  static constexpr std::string_view function = "point_point";
  static constexpr int points = 2;
  static constexpr std::array<std::string_view, points> point_names{"p", "q"};
  static constexpr int dimension = 3;
  static constexpr int first_points = 1;
  static constexpr std::array<Feature, 1> features{{{FeaturePair::point_point, {0, 1, 0, 0}}}};
  /// The contact question (d = 0) is that of the edge-edge query of this kind's points
  /// {0, 0, 1, 1} ((p, p) against (q, q)): it has no contact stages of its own.
  using ContactKind = EdgeEdge;
  static constexpr std::array<int, 4> contact_points{0, 0, 1, 1};
};

/// Edge-edge in the plane. The features are those of EdgeEdge: with every z = 0 its edge-edge
/// pair is the crossing of the two segments (the lines' distance is 0).
struct EdgeEdge2d {
  template <class T>
  using Query = EdgeEdge2dQueryT<T>;
  static constexpr std::string_view name = "edge-edge-2d";
  static constexpr int c_kind = EXACTCCD_EDGE_EDGE_2D;
  static constexpr std::string_view short_name = "ee2";
  static constexpr std::string_view function = "edge_edge_2d";
  static constexpr int points = 4;
  static constexpr std::array<std::string_view, points> point_names{"a0", "a1", "b0", "b1"};
  static constexpr int dimension = 2;
  static constexpr int first_points = 2;
  static constexpr auto features = EdgeEdge::features;
  /// The contact question (d = 0) is that of the edge-edge query of this kind's points
  /// {0, 1, 2, 3} (the same edges at z = 0): it has no contact stages of its own.
  using ContactKind = EdgeEdge;
  static constexpr std::array<int, 4> contact_points{0, 1, 2, 3};
};

/// Point-edge in the plane.
struct PointEdge2d {
  template <class T>
  using Query = PointEdge2dQueryT<T>;
  static constexpr std::string_view name = "point-edge-2d";
  static constexpr int c_kind = EXACTCCD_POINT_EDGE_2D;
  static constexpr std::string_view short_name = "pe2";
  static constexpr std::string_view function = "point_edge_2d";
  static constexpr int points = 3;
  static constexpr std::array<std::string_view, points> point_names{"p", "a", "b"};
  static constexpr int dimension = 2;
  static constexpr int first_points = 1;
  static constexpr auto features = PointEdge::features;
  /// The contact question (d = 0) is that of the edge-edge query of this kind's points
  /// {0, 0, 1, 2} ((p, p) against (a, b) at z = 0): it has no contact stages of its own.
  using ContactKind = EdgeEdge;
  static constexpr std::array<int, 4> contact_points{0, 0, 1, 2};
};

/// Point-point in the plane.
struct PointPoint2d {
  template <class T>
  using Query = PointPoint2dQueryT<T>;
  static constexpr std::string_view name = "point-point-2d";
  static constexpr int c_kind = EXACTCCD_POINT_POINT_2D;
  static constexpr std::string_view short_name = "pp2";
  static constexpr std::string_view function = "point_point_2d";
  static constexpr int points = 2;
  static constexpr std::array<std::string_view, points> point_names{"p", "q"};
  static constexpr int dimension = 2;
  static constexpr int first_points = 1;
  static constexpr auto features = PointPoint::features;
  /// The contact question (d = 0) is that of the edge-edge query of this kind's points
  /// {0, 0, 1, 1} ((p, p) against (q, q) at z = 0): it has no contact stages of its own.
  using ContactKind = EdgeEdge;
  static constexpr std::array<int, 4> contact_points{0, 0, 1, 1};
};

/// The kind of a query type (double, rational, interval or integer coordinates alike; linear
/// or rigid motion).
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
template <class T>
struct KindOf<PointEdgeQueryT<T>> {
  using type = PointEdge;
};
template <class T>
struct KindOf<PointPointQueryT<T>> {
  using type = PointPoint;
};
template <class T>
struct KindOf<EdgeEdge2dQueryT<T>> {
  using type = EdgeEdge2d;
};
template <class T>
struct KindOf<PointEdge2dQueryT<T>> {
  using type = PointEdge2d;
};
template <class T>
struct KindOf<PointPoint2dQueryT<T>> {
  using type = PointPoint2d;
};
template <class T>
struct KindOf<RigidVertexFaceQueryT<T>> {
  using type = VertexFace;
};
template <class T>
struct KindOf<RigidEdgeEdgeQueryT<T>> {
  using type = EdgeEdge;
};
/// The kind of a query type.
template <class Query>
using kind_of = typename KindOf<std::decay_t<Query>>::type;

/// The one list of kinds: calls f(Kind{}) for every kind, in the order of the CLI's --kind
/// values, the C API's exactccd_kind and every table: vf, ee, pe, pp, ee2, pe2, pp2. Every
/// layer derives its kinds from it (docs/design.md, 7b).
template <class F>
constexpr void for_each_kind(F&& f) {
  f(VertexFace{});
  f(EdgeEdge{});
  f(PointEdge{});
  f(PointPoint{});
  f(EdgeEdge2d{});
  f(PointEdge2d{});
  f(PointPoint2d{});
}

/// True for the kinds with a contact rule and volume filter of their own (lib/contact,
/// lib/filter): those whose description has volume_rows (vertex-face and edge-edge). The
/// others' contact question is the edge-edge one of the same points (questions/methods.hpp).
template <class Kind, class = void>
struct HasContactStages : std::false_type {};
template <class Kind>
struct HasContactStages<Kind, std::void_t<decltype(Kind::volume_rows)>> : std::true_type {};

/// Calls f(Kind{}) for the kinds of the list with contact stages (HasContactStages), in list
/// order: the kinds the textbook baselines and the plug-in ABI's contact-only entry points answer.
template <class F>
constexpr void for_each_contact_kind(F&& f) {
  for_each_kind([&](auto kind) {
    if constexpr (HasContactStages<decltype(kind)>::value) f(kind);
  });
}

/// The number of kinds.
constexpr int kind_count() {
  int n = 0;
  for_each_kind([&](auto) { ++n; });
  return n;
}

/// The C API's exactccd_kind values are the kinds' c_kind, 0 .. kind_count() - 1 in the order
/// of for_each_kind (exactccd.h lists them in that order).
constexpr bool c_kinds_in_list_order() {
  int i = 0;
  bool in_order = true;
  for_each_kind([&](auto kind) { in_order = in_order && decltype(kind)::c_kind == i++; });
  return in_order && kind_count() == EXACTCCD_POINT_POINT_2D + 1;
}
static_assert(c_kinds_in_list_order(), "exactccd.h's exactccd_kind must list the kinds of kinds::for_each_kind in order");

}  // namespace exactccd::kinds
