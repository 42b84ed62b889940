// The hand-derived degenerate catalogue (tools/lib/generators/catalogue.cpp): every method that claims
// exactness, through the rational and the double API, gives the derived answer and TOI.
#include "generators/catalogue.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"
#include "io/benchmark_csv.hpp"

namespace exactccd::catalogue {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

// Short test descriptions (gtest prints parameters in test lists; the coordinates are
// printed on failure by describe()).
template <class Query>
void PrintTo(const Entry<Query>& e, std::ostream* os) {
  *os << e.name;
}

template <class Query>
std::string describe(const Entry<Query>& e) {
  std::string s = e.name + " (" + e.category + "):";
  for (const auto& p : rows(e.query)) s += " [" + p.x.get_str() + " " + p.y.get_str() + " " + p.z.get_str() + "]";
  return s;
}

namespace {

template <class Query>
auto to_doubles(const Query& q) {
  const auto rows_d = io::exact_double_rows(rows(q));
  EXPECT_TRUE(rows_d.has_value()) << "a coordinate is not exactly a double";
  using DoubleQuery = std::conditional_t<std::is_same_v<Query, RationalVertexFaceQuery>,
                                         VertexFaceQuery, EdgeEdgeQuery>;
  return from_rows<DoubleQuery>(rows_d.value_or(std::array<Vec3, 8>{}));
}

/// Every zero coordinate replaced by -0.0: the same geometry, so the same answers.
template <class Query>
Query with_negative_zeros(Query q) {
  std::array<Vec3, 8> r = rows(q);
  for (Vec3& p : r)
    for (double* x : {&p.x, &p.y, &p.z})
      if (*x == 0) *x = -0.0;
  return from_rows<Query>(r);
}

mpq_class evaluate(const std::vector<mpq_class>& c, double t) {
  mpq_class v = 0, x(t), power = 1;
  for (const mpq_class& k : c) {
    v += k * power;
    power *= x;
  }
  return v;
}

template <class E>
void check_toi(const E& e, const std::optional<TimeInterval>& toi, const char* how) {
  SCOPED_TRACE(how);
  ASSERT_EQ(toi.has_value(), e.collides);
  if (!toi) return;
  ASSERT_LE(toi->lo, toi->hi);
  const bool point = toi->lo == toi->hi;
  if (!point) {
    EXPECT_EQ(std::nextafter(toi->lo, kInf), toi->hi) << "not the tightest interval";
  }
  if (e.toi) {
    const mpq_class& t = *e.toi;
    EXPECT_LE(mpq_class(toi->lo), t);
    EXPECT_GE(mpq_class(toi->hi), t);
    const bool t_is_double = io::exact_double(t).has_value();
    EXPECT_EQ(point, t_is_double) << "[" << toi->lo << ", " << toi->hi << "] for " << t.get_str();
  }
  if (!e.toi_polynomial.empty()) {  // irrational: the polynomial changes sign on (lo, hi)
    EXPECT_FALSE(point);
    const int s_lo = sgn(evaluate(e.toi_polynomial, toi->lo));
    const int s_hi = sgn(evaluate(e.toi_polynomial, toi->hi));
    EXPECT_NE(s_lo, 0);
    EXPECT_EQ(s_lo, -s_hi) << "the TOI root is not inside [" << toi->lo << ", " << toi->hi << "]";
  }
}

class VertexFaceCatalogue : public ::testing::TestWithParam<VertexFaceEntry> {};
class EdgeEdgeCatalogue : public ::testing::TestWithParam<EdgeEdgeEntry> {};

TEST_P(VertexFaceCatalogue, EveryExactMethodGivesTheDerivedAnswer) {
  const VertexFaceEntry& e = GetParam();
  SCOPED_TRACE(describe(e));
  EXPECT_EQ(vertex_face_ccd(e.query), e.collides) << "rational API";
  check_toi(e, vertex_face_toi(e.query), "rational toi");
  const VertexFaceQuery q = to_doubles(e.query);
  for (const VertexFaceQuery& v : {q, with_negative_zeros(q)})
    for (Method m : {Method::filtered, Method::exact}) {
      EXPECT_EQ(vertex_face_ccd(v, m), e.collides) << "method " << static_cast<int>(m);
      check_toi(e, vertex_face_toi(v, m), m == Method::filtered ? "filtered toi" : "exact toi");
    }
}

TEST_P(EdgeEdgeCatalogue, EveryExactMethodGivesTheDerivedAnswer) {
  const EdgeEdgeEntry& e = GetParam();
  SCOPED_TRACE(describe(e));
  EXPECT_EQ(edge_edge_ccd(e.query), e.collides) << "rational API";
  check_toi(e, edge_edge_toi(e.query), "rational toi");
  const EdgeEdgeQuery q = to_doubles(e.query);
  for (const EdgeEdgeQuery& v : {q, with_negative_zeros(q)})
    for (Method m : {Method::filtered, Method::exact}) {
      EXPECT_EQ(edge_edge_ccd(v, m), e.collides) << "method " << static_cast<int>(m);
      check_toi(e, edge_edge_toi(v, m), m == Method::filtered ? "filtered toi" : "exact toi");
    }
}

template <class E>
std::string entry_name(const ::testing::TestParamInfo<E>& info) {
  std::string n = info.param.name;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Catalogue, VertexFaceCatalogue, ::testing::ValuesIn(vertex_face_cases()),
                         entry_name<VertexFaceEntry>);
INSTANTIATE_TEST_SUITE_P(Catalogue, EdgeEdgeCatalogue, ::testing::ValuesIn(edge_edge_cases()),
                         entry_name<EdgeEdgeEntry>);

TEST(CatalogueContents, HasFortyHandMadeCasesWithUniqueNamesCoveringEveryCategory) {
  const auto vf = vertex_face_base_cases();
  const auto ee = edge_edge_base_cases();
  EXPECT_GE(vf.size() + ee.size(), 40u);
  std::set<std::string> names, categories;
  for (const auto& e : vertex_face_cases()) {
    EXPECT_TRUE(names.insert(e.name).second) << "duplicate " << e.name;
    categories.insert("vf:" + e.category);
  }
  for (const auto& e : edge_edge_cases()) {
    EXPECT_TRUE(names.insert(e.name).second) << "duplicate " << e.name;
    categories.insert("ee:" + e.category);
  }
  for (const char* c :
       {"vf:vertex_through_vertex", "vf:vertex_through_edge", "vf:vertex_through_interior",
        "vf:grazing", "vf:coplanar_sliding", "vf:degenerate_triangle", "vf:contact_at_t0",
        "vf:contact_at_t1", "vf:static", "vf:subnormal", "vf:huge_coordinates", "vf:large_offset",
        "vf:irrational_root", "ee:crossing", "ee:parallel", "ee:collinear", "ee:zero_length_edge",
        "ee:grazing", "ee:coplanar_sliding", "ee:contact_at_t0", "ee:contact_at_t1", "ee:static",
        "ee:edge_through_endpoint", "ee:subnormal", "ee:huge_coordinates", "ee:large_offset",
        "ee:irrational_root"})
    EXPECT_TRUE(categories.count(c)) << "no case of category " << c;
  std::size_t positives = 0, negatives = 0;
  for (const auto& e : vf) (e.collides ? positives : negatives)++;
  for (const auto& e : ee) (e.collides ? positives : negatives)++;
  EXPECT_GE(positives, 10u);
  EXPECT_GE(negatives, 10u);
}

/// The entry named `name` in `entries`, or nullptr.
template <class E>
const E* find(const std::vector<E>& entries, const std::string& name) {
  for (const E& e : entries)
    if (e.name == name) return &e;
  return nullptr;
}

// The required coverage, situation by situation: each needs the named case with that answer
// (hits and misses side by side). Negative zero coordinates are covered by the parameterized
// tests above, which run every case again with each zero replaced by -0.0 in the double API.
TEST(CatalogueContents, CoversEveryRequiredSituationWithHitsAndMisses) {
  const auto vf = vertex_face_cases();
  const auto ee = edge_edge_cases();
  struct Required {
    const char* situation;
    const char* name;
    bool collides;
  };
  const Required required[] = {
      {"vertex through a triangle vertex", "vf_through_vertex_a", true},
      {"vertex through a triangle vertex", "vf_just_outside_vertex_a", false},
      {"vertex through a triangle edge", "vf_through_edge_ab", true},
      {"vertex through a triangle edge", "vf_through_edge_bc", true},
      {"vertex through a triangle edge", "vf_just_outside_edge_bc", false},
      {"vertex through the interior", "vf_interior_fall", true},
      {"grazing double root inside", "vf_grazing_inside", true},
      {"grazing double root outside", "vf_grazing_outside", false},
      {"grazing double root inside", "ee_grazing_inside", true},
      {"grazing double root outside", "ee_grazing_outside", false},
      {"coplanar sliding into contact mid-step", "vf_coplanar_slide_into", true},
      {"coplanar sliding beside", "vf_coplanar_slide_beside", false},
      {"coplanar sliding, the triangle moves", "vf_coplanar_triangle_sweeps_over_point", true},
      {"coplanar sliding into contact mid-step", "ee_coplanar_slide_into", true},
      {"coplanar sliding beside", "ee_coplanar_slide_beside", false},
      {"collinear triangle", "vf_collinear_triangle_hit", true},
      {"collinear triangle", "vf_collinear_triangle_miss", false},
      {"two coincident triangle vertices", "vf_coincident_vertices_hit", true},
      {"two coincident triangle vertices", "vf_coincident_vertices_miss", false},
      {"three coincident triangle vertices", "vf_point_triangle_hit", true},
      {"three coincident triangle vertices", "vf_point_triangle_miss", false},
      {"parallel edges, disjoint", "ee_parallel_static_apart", false},
      {"parallel edges, disjoint", "ee_parallel_skew_static", false},
      {"parallel edges touching when collinear", "ee_parallel_becoming_collinear_overlap", true},
      {"parallel edges collinear but disjoint", "ee_parallel_becoming_collinear_disjoint", false},
      {"collinear overlapping", "ee_collinear_overlap_static", true},
      {"collinear disjoint", "ee_collinear_disjoint_static", false},
      {"crossing edges", "ee_crossing", true},
      {"crossing edges", "ee_pass_beside", false},
      {"endpoint to endpoint", "ee_endpoint_to_endpoint", true},
      {"endpoint to endpoint", "ee_endpoint_misses_endpoint", false},
      {"T-junction", "ee_t_junction", true},
      {"zero-length edge against an edge", "ee_point_hits_edge", true},
      {"zero-length edge against an edge", "ee_point_misses_edge", false},
      {"both edges zero length", "ee_points_meet", true},
      {"both edges zero length", "ee_points_miss", false},
      {"contact exactly at t = 0", "vf_contact_at_t0", true},
      {"contact exactly at t = 0", "ee_contact_at_t0", true},
      {"contact exactly at t = 1", "vf_contact_at_t1", true},
      {"contact exactly at t = 1", "ee_contact_at_t1", true},
      {"just missing at t = 1", "vf_just_misses_at_t1", false},
      {"just missing at t = 1", "ee_just_misses_at_t1", false},
      {"nothing moves, touching", "vf_static_touching", true},
      {"nothing moves, apart", "vf_static_apart", false},
      {"nothing moves, touching", "ee_static_crossing", true},
      {"nothing moves, apart", "ee_static_skew", false},
      {"subnormal coordinates", "vf_subnormal_crossing", true},
      {"subnormal gap of 2^-1074, no contact", "vf_subnormal_gap_at_t1", false},
      {"subnormal coordinates", "ee_subnormal_crossing", true},
      {"subnormal gap of 2^-1074, no contact", "ee_subnormal_gap_at_t1", false},
      {"subnormal copy", "vf_interior_fall_x2^-1060", true},
      {"subnormal copy", "ee_crossing_x2^-1060", true},
      {"1e300-scale coordinates", "vf_grazing_inside_x2^996", true},
      {"1e300-scale coordinates", "vf_grazing_outside_x2^996", false},
      {"1e300-scale coordinates", "ee_collinear_overlap_static_x2^996", true},
      {"1e300-scale coordinates", "ee_endpoint_misses_endpoint_x2^996", false},
      {"irrational TOI (irreducible cubic)", "vf_irrational_toi", true},
      {"irrational TOI (irreducible cubic)", "ee_irrational_toi", true},
  };
  for (const Required& r : required) {
    SCOPED_TRACE(std::string(r.situation) + ": " + r.name);
    const std::string name = r.name;
    std::optional<bool> collides;
    if (const auto* e = find(vf, name)) collides = e->collides;
    if (const auto* e = find(ee, name)) collides = e->collides;
    ASSERT_TRUE(collides.has_value()) << "missing";
    EXPECT_EQ(*collides, r.collides);
  }
  // Mid-step contact in coplanar sliding: the TOI is strictly inside (0, 1).
  for (const char* name : {"vf_coplanar_slide_into", "vf_coplanar_triangle_sweeps_over_point"}) {
    const auto* e = find(vf, name);
    ASSERT_NE(e, nullptr) << name;
    ASSERT_TRUE(e->toi.has_value()) << name;
    EXPECT_TRUE(*e->toi > 0 && *e->toi < 1) << name;
  }
  const auto* e = find(ee, "ee_coplanar_slide_into");
  ASSERT_NE(e, nullptr);
  ASSERT_TRUE(e->toi.has_value());
  EXPECT_TRUE(*e->toi > 0 && *e->toi < 1);
  // The irrational cases collide (checked above) with no rational TOI.
  const auto* vf_irrational = find(vf, "vf_irrational_toi");
  const auto* ee_irrational = find(ee, "ee_irrational_toi");
  ASSERT_NE(vf_irrational, nullptr);
  ASSERT_NE(ee_irrational, nullptr);
  EXPECT_FALSE(vf_irrational->toi.has_value());
  EXPECT_FALSE(ee_irrational->toi.has_value());
}

/// Each entry's fields agree with one another: coordinates exactly doubles, a TOI (rational in
/// [0, 1], or a polynomial for an irrational root) exactly when it collides.
template <class E>
void expect_consistent(const E& e) {
  SCOPED_TRACE(e.name);
  EXPECT_FALSE(e.name.empty());
  EXPECT_FALSE(e.category.empty());
  for (char ch : e.name)
    EXPECT_TRUE(std::islower(static_cast<unsigned char>(ch)) ||
                std::isdigit(static_cast<unsigned char>(ch)) || ch == '_' || ch == '^' || ch == '-')
        << "not a snake_case id";
  for (const auto& p : rows(e.query))
    for (const mpq_class* x : {&p.x, &p.y, &p.z}) {
      const auto d = io::exact_double(*x);
      ASSERT_TRUE(d.has_value()) << x->get_str() << " is not exactly a double";
      EXPECT_TRUE(std::isfinite(*d));
    }
  if (!e.collides) {
    EXPECT_FALSE(e.toi.has_value()) << "a TOI on a miss";
    EXPECT_TRUE(e.toi_polynomial.empty());
    return;
  }
  EXPECT_NE(e.toi.has_value(), !e.toi_polynomial.empty())
      << "a hit needs exactly one of a rational TOI and an irrational root's polynomial";
  if (e.toi) {
    EXPECT_GE(*e.toi, 0);
    EXPECT_LE(*e.toi, 1);
  }
  if (!e.toi_polynomial.empty()) {
    EXPECT_EQ(e.toi_polynomial.size(), 4u) << "a cubic";
    EXPECT_NE(e.toi_polynomial.back(), 0);
  }
}

TEST(CatalogueContents, EntriesAreConsistent) {
  for (const auto& e : vertex_face_cases()) expect_consistent(e);
  for (const auto& e : edge_edge_cases()) expect_consistent(e);
}

/// Every hand-made case (but the subnormal ones) has its exact 2^996 copy, with the same
/// answer and TOI: coordinates up to a few times 1e300 stay exact doubles.
template <class E>
void expect_huge_copies(const std::vector<E>& base, const std::vector<E>& all) {
  for (const E& b : base) {
    if (b.category == "subnormal") continue;
    const E* copy = find(all, b.name + "_x2^996");
    ASSERT_NE(copy, nullptr) << b.name << " has no 2^996 copy";
    EXPECT_EQ(copy->collides, b.collides) << b.name;
    EXPECT_EQ(copy->toi, b.toi) << b.name;
    const auto rb = rows(b.query);
    const auto rc = rows(copy->query);
    for (std::size_t i = 0; i < 8; ++i) {
      mpq_class scale(1);
      mpq_mul_2exp(scale.get_mpq_t(), scale.get_mpq_t(), 996);
      EXPECT_EQ(rc[i].x, rb[i].x * scale);
      EXPECT_EQ(rc[i].y, rb[i].y * scale);
      EXPECT_EQ(rc[i].z, rb[i].z * scale);
    }
  }
}

TEST(CatalogueContents, EveryCaseHasAnExactHugeCopy) {
  expect_huge_copies(vertex_face_base_cases(), vertex_face_cases());
  expect_huge_copies(edge_edge_base_cases(), edge_edge_cases());
}

}  // namespace
}  // namespace exactccd::catalogue
