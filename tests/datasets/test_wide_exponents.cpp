// Wide-exponent queries (coordinates from 2^-1074 to near 2^1024, mixed per axis) whose
// answers and times of impact are known without the library: every degenerate family placed by
// exact per-axis power-of-two scales, translations and shears (families::make_wide; why that
// keeps the construction's answer and TOI: docs/design.md, section 7), and hand-derived cases
// around a query the static volume filter once answered wrongly. Every exact way the API
// answers (each exact Method, the rational overloads, the C API) must give the constructed
// answer and the tightest enclosure of the constructed TOI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "exactccd/exactccd.h"
#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"
#include "generators/families.hpp"
#include "kinds/primitive_kinds.hpp"
#include "generators/fuzz_input.hpp"

namespace exactccd {
namespace {

using families::AnyQuery;
using families::KnownToi;

/// One exact way of answering, and what it said.
struct Answer {
  std::string how;
  bool collides = false;
  std::optional<TimeInterval> toi;
};

/// Every method of the library (both exact; the baselines are the tools', tools::Method).
constexpr Method kEveryMethod[] = {Method::filtered, Method::exact};

template <class Query>
std::array<double, 24> flat(const Query& q) {
  std::array<double, 24> f;
  const auto r = rows(q);
  for (std::size_t i = 0; i < 8; ++i) {
    f[3 * i] = r[i].x;
    f[3 * i + 1] = r[i].y;
    f[3 * i + 2] = r[i].z;
  }
  return f;
}

template <class Query>
auto rational(const Query& q) {
  std::array<RationalVec3, 8> r;
  const auto d = rows(q);
  for (std::size_t i = 0; i < 8; ++i) r[i] = {mpq_class(d[i].x), mpq_class(d[i].y), mpq_class(d[i].z)};
  return from_rows<typename kinds::kind_of<Query>::template Query<mpq_class>>(r);
}

/// The answers of every exact entry point: each exact Method (ccd and toi), the rational
/// overloads and the C API.
template <class Query>
std::vector<Answer> exact_answers(const Query& q, bool with_rational = true) {
  constexpr bool vf = std::is_same_v<Query, VertexFaceQuery>;
  std::vector<Answer> out;
  for (Method m : kEveryMethod) {
    const std::string name = m == Method::filtered ? "filtered" : "exact";
    out.push_back({name + " ccd", ccd(q, m), std::nullopt});
    const auto t = toi(q, m);
    out.push_back({name + " toi", t.has_value(), t});
  }
  if (with_rational) {
    const auto r = rational(q);
    out.push_back({"rational ccd", ccd(r), std::nullopt});
    const auto t = toi(r);
    out.push_back({"rational toi", t.has_value(), t});
  }
  const auto f = flat(q);
  int collides = -1;
  double lo = -1, hi = -1;
  const exactccd_status s = vf ? exactccd_vertex_face_toi(f.data(), &collides, &lo, &hi)
                               : exactccd_edge_edge_toi(f.data(), &collides, &lo, &hi);
  Answer c{"C API toi", collides == 1, std::nullopt};
  if (s != EXACTCCD_OK) c.how += " (failed)";
  if (collides == 1) c.toi = TimeInterval{lo, hi};
  out.push_back(c);
  return out;
}

std::string describe(const AnyQuery& q) {
  return std::visit([](const auto& x) {
    return fuzzing::hex_rows<kinds::kind_of<decltype(x)>>(rows(x));
  }, q);
}

std::string interval(const std::optional<TimeInterval>& t) {
  if (!t) return "none";
  char buf[96];
  std::snprintf(buf, sizeof buf, "[%a, %a]", t->lo, t->hi);
  return buf;
}

/// Checks every exact answer against the expected answer and TOI; returns the failures.
std::vector<std::string> check(const AnyQuery& q, bool expected, const std::optional<KnownToi>& toi,
                               bool with_rational = true) {
  const std::vector<Answer> answers =
      std::visit([&](const auto& x) { return exact_answers(x, with_rational); }, q);
  std::vector<std::string> failures;
  for (const Answer& a : answers) {
    if (a.how.find("(failed)") != std::string::npos) {
      failures.push_back(a.how);
      continue;
    }
    if (a.collides != expected) {
      failures.push_back(a.how + ": " + (a.collides ? "collides" : "no collision") + ", constructed " +
                         (expected ? "collides" : "no collision"));
      continue;
    }
    const bool is_toi = a.how.find("toi") != std::string::npos;
    if (is_toi && expected && toi && !families::is_tightest_enclosure(*toi, *a.toi))
      failures.push_back(a.how + ": " + interval(a.toi) + " is not the tightest enclosure of " +
                         families::to_string(*toi));
  }
  return failures;
}

// --- by hand --------------------------------------------------------------------------------

/// A hand-derived case: the query, the answer and (when it collides) the exact TOI.
struct HandCase {
  const char* name;
  AnyQuery query;
  bool collides;
  mpq_class toi;  ///< meaningful when collides
};

// The static triangle a = (0, 0, 0), b = (2^200, 0, 1), c = (0, 2^-538, 0) has the normal
// n = b x c = (-2^-538, 0, 2^-338): its plane is z = 2^-200 x, and a point (x, y, z) of the
// plane is a + beta (b - a) + gamma (c - a) with beta = 2^-200 x, gamma = 2^538 y,
// alpha = 1 - beta - gamma. p moves in z only, at fixed (x, y), so it crosses the plane once,
// when z = 2^-200 x, and it collides iff that happens for t in [0, 1] with alpha, beta,
// gamma >= 0. The determinant minors are tiny (2^-538 y-extent) next to the huge 2^200.
VertexFaceQuery static_triangle(Vec3 p0, Vec3 p1, int x_shift = 0, int z_shift = 0) {
  const auto s = [&](Vec3 v) { return Vec3{std::ldexp(v.x, x_shift), v.y, std::ldexp(v.z, z_shift)}; };
  const Vec3 a{0, 0, 0}, b = s({0x1p200, 0, 1}), c = s({0, 0x1p-538, 0});
  return {s(p0), a, b, c, s(p1), a, b, c};
}

// Edge-edge analogue: a = [0, (2^200, 0, 1)] static meets the plane x = 2^-360 at
// (2^-360, 0, 2^-560); b is a segment parallel to y at x = 2^-360 and height z(t): they meet
// iff z(t) = 2^-560 and b's y-range holds 0.
EdgeEdgeQuery edge_vs_steep_edge(double y0, double y1, double z1) {
  const Vec3 a0{0, 0, 0}, a1{0x1p200, 0, 1};
  return {a0, a1, {0x1p-360, y0, 0}, {0x1p-360, y1, 0}, a0, a1, {0x1p-360, y0, z1}, {0x1p-360, y1, z1}};
}

std::vector<HandCase> hand_cases() {
  return {
      // The reported query: p = (2^-360, 2^-539, t 2^-559) reaches z = 2^-560 at t = 1/2, where
      // beta = 2^-560, gamma = 1/2, alpha = 1/2 - 2^-560 > 0: inside. The static volume
      // filter once excluded it.
      {"reported", static_triangle({0x1p-360, 0x1p-539, 0}, {0x1p-360, 0x1p-539, 0x1p-559}), true,
       mpq_class(1, 2)},
      // z(t) = 3 t 2^-561 = 2^-560 at t = 2/3, at the same point: inside.
      {"toi_two_thirds", static_triangle({0x1p-360, 0x1p-539, 0}, {0x1p-360, 0x1p-539, 0x1.8p-560}), true,
       mpq_class(2, 3)},
      // z(t) = t 2^-561 < 2^-560 on [0, 1]: p never reaches the plane.
      {"stops_short", static_triangle({0x1p-360, 0x1p-539, 0}, {0x1p-360, 0x1p-539, 0x1p-561}), false, 0},
      // y = 2^-538: gamma = 1, alpha = -2^-560 < 0 at the crossing: just beyond the edge bc.
      {"beside_edge_bc", static_triangle({0x1p-360, 0x1p-538, 0}, {0x1p-360, 0x1p-538, 0x1p-559}), false, 0},
      // x = 2^160 (beta = 2^-40), y = 2^-538 - 2^-578 (gamma = 1 - 2^-40): alpha = 0, on the
      // edge bc, when z(t) = 2^-39 t reaches 2^-40 at t = 1/2.
      {"on_edge_bc",
       static_triangle({0x1p160, 0x1p-538 - 0x1p-578, 0}, {0x1p160, 0x1p-538 - 0x1p-578, 0x1p-39}), true,
       mpq_class(1, 2)},
      // y 2^-590 larger: gamma = 1 - 2^-40 + 2^-52, alpha = -2^-52 < 0: outside.
      {"off_edge_bc",
       static_triangle({0x1p160, 0x1p-538 - 0x1p-578 + 0x1p-590, 0},
                       {0x1p160, 0x1p-538 - 0x1p-578 + 0x1p-590, 0x1p-39}),
       false, 0},
      // The reported query with x scaled by 2^800 (b = (2^1000, 0, 1)) or z by 2^-500 (p ends
      // at z = 2^-1059): per-axis power-of-two scales keep the answer and the TOI.
      {"reported_x_times_2^800",
       static_triangle({0x1p-360, 0x1p-539, 0}, {0x1p-360, 0x1p-539, 0x1p-559}, 800, 0), true,
       mpq_class(1, 2)},
      {"reported_z_times_2^-500",
       static_triangle({0x1p-360, 0x1p-539, 0}, {0x1p-360, 0x1p-539, 0x1p-559}, 0, -500), true,
       mpq_class(1, 2)},
      {"reported_both", static_triangle({0x1p-360, 0x1p-539, 0}, {0x1p-360, 0x1p-539, 0x1p-559}, 823, -515),
       true, mpq_class(1, 2)},
      // Edge-edge: b = [y in +-2^-539] reaches z = 2^-560 at t = 1/2 and holds y = 0: contact.
      {"ee_crossing", edge_vs_steep_edge(-0x1p-539, 0x1p-539, 0x1p-559), true, mpq_class(1, 2)},
      // b = [y in 2^-539..2^-538] never holds y = 0: no contact.
      {"ee_beside", edge_vs_steep_edge(0x1p-539, 0x1p-538, 0x1p-559), false, 0},
      // b stops at z = 2^-561 < 2^-560: no contact.
      {"ee_stops_short", edge_vs_steep_edge(-0x1p-539, 0x1p-539, 0x1p-561), false, 0},
      // b's endpoint y0 = 0 reaches a at t = 1/2: contact through an endpoint.
      {"ee_endpoint", edge_vs_steep_edge(0, 0x1p-539, 0x1p-559), true, mpq_class(1, 2)},
  };
}

TEST(WideExponents, HandDerivedCases) {
  for (const HandCase& c : hand_cases()) {
    std::optional<KnownToi> toi;
    if (c.collides) toi = families::rational_toi(c.toi);
    const std::vector<std::string> failures = check(c.query, c.collides, toi);
    for (const std::string& f : failures) ADD_FAILURE() << c.name << ": " << f << "\n" << describe(c.query);
  }
}

// --- the families, placed wide --------------------------------------------------------------

/// The perturbation exponents swept: unperturbed, every k up to 8, then every fourth to 60.
std::vector<int> swept_k() {
  std::vector<int> ks;
  for (int k = families::kUnperturbed; k <= 60; k += (k < 8 ? 1 : 4)) ks.push_back(k);
  return ks;
}

class WideFamilyTest : public ::testing::TestWithParam<std::string> {};

TEST_P(WideFamilyTest, EveryExactMethodGivesTheConstructedAnswerAndToi) {
  const families::Family* f = families::find_family(GetParam());
  ASSERT_NE(f, nullptr);
  std::uint64_t seed = 1469598103934665603u;  // FNV-1a of the name: the same on every platform
  for (char c : f->name) seed = (seed ^ static_cast<unsigned char>(c)) * 1099511628211u;
  std::mt19937_64 rng(seed);
  int made = 0, checked = 0, collide = 0, discarded = 0, index = 0;
  for (int k : swept_k())
    for (bool toward : {false, true})
      // Four rounds of the styles for the unperturbed configuration (the only colliding one of
      // several families), one otherwise.
      for (int round = 0; round < (k == families::kUnperturbed ? 4 : 1) * families::kWideStyleCount; ++round) {
        const auto style = static_cast<families::WideStyle>(round % families::kWideStyleCount);
        const std::optional<families::Instance> inst = families::make_wide(*f, k, toward, style, rng);
        if (!inst) {
          ++discarded;
          continue;
        }
        ++made;
        ASSERT_EQ(families::kind_name(inst->query), f->kind);
        if (!inst->expected) continue;  // the local perturbation rounded: no constructed answer
        ASSERT_EQ(inst->toi.has_value(), *inst->expected) << "a TOI exactly when it collides";
        ++checked;
        collide += *inst->expected;
        // The rational overloads on every fourth instance: Method::exact converts the doubles to
        // rationals and calls the same function, and wide coplanar instances cost it up to 0.25 s.
        const std::vector<std::string> failures = check(inst->query, *inst->expected, inst->toi, index++ % 4 == 0);
        for (const std::string& what : failures)
          ADD_FAILURE() << f->name << " k=" << k << (toward ? " toward " : " away ")
                        << families::wide_style_name(style) << ": " << what << "\n"
                        << describe(inst->query);
      }
  RecordProperty("instances_made", made);
  RecordProperty("instances_checked", checked);
  RecordProperty("instances_colliding", collide);
  // Enough instances carry a constructed answer, of both kinds.
  EXPECT_GE(checked, 100) << "made " << made << ", discarded " << discarded;
  EXPECT_GE(collide, 20);
  EXPECT_GE(checked - collide, 20);
  EXPECT_LE(discarded, made / 10) << "too many inexact draws";
}

std::vector<std::string> family_names() {
  std::vector<std::string> names;
  for (const families::Family& f : families::all_families()) names.push_back(f.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Families, WideFamilyTest, ::testing::ValuesIn(family_names()),
                         [](const auto& info) { return info.param; });

// --- the placements are wide, and exact ------------------------------------------------------

/// Binary exponents of the smallest and largest nonzero |coordinate|.
std::pair<int, int> exponent_range(const fuzzing::Rows& r) {
  int lo = std::numeric_limits<int>::max(), hi = std::numeric_limits<int>::min();
  for (const Vec3& p : r)
    for (double x : {p.x, p.y, p.z})
      if (x != 0) {
        lo = std::min(lo, std::ilogb(x));
        hi = std::max(hi, std::ilogb(x));
      }
  return {lo, hi};
}

TEST(WideExponents, PlacementsSpanTheWholeExponentRange) {
  std::mt19937_64 rng(3);
  for (int s = 0; s < families::kWideStyleCount; ++s) {
    const auto style = static_cast<families::WideStyle>(s);
    int n = 0, wide = 0, subnormal = 0, huge = 0;
    for (const families::Family& f : families::all_families())
      for (int k : {families::kUnperturbed, 0, 10, 30})
        for (int rep = 0; rep < 5; ++rep) {
          const auto inst = families::make_wide(f, k, rep % 2 == 0, style, rng);
          if (!inst) continue;
          const fuzzing::Rows r = std::visit([](const auto& q) { return rows(q); }, inst->query);
          const auto [lo, hi] = exponent_range(r);
          ++n;
          wide += hi - lo > 1000;
          subnormal += lo < -1022;
          huge += hi > 1000;
        }
    SCOPED_TRACE(families::wide_style_name(style));
    EXPECT_GT(n, 300);
    EXPECT_GT(wide, n / 4) << "exponent spread above 1000 bits";
    if (style == families::WideStyle::extremes) {
      EXPECT_EQ(subnormal, n) << "every extremes placement has a subnormal coordinate";
      EXPECT_GT(huge, n * 9 / 10) << "and one above 2^1000 (not when all but one axis are 0)";
    } else {
      EXPECT_GT(subnormal, 0);
      EXPECT_GT(huge, 0);
    }
  }
}

// axes_only is a permutation, sign flips and one power-of-two scale per axis: every output axis
// is +- 2^e times one local axis, coordinate for coordinate (checked with ldexp, exact here).
TEST(WideExponents, AxesOnlyIsExactlyAScaledSymmetry) {
  std::mt19937_64 rng(4);
  int checked = 0;
  for (const families::Family& f : families::all_families())
    for (int k : {families::kUnperturbed, 0, 7, 33, 52}) {
      const auto inst = families::make_wide(f, k, true, families::WideStyle::axes_only, rng);
      ASSERT_TRUE(inst.has_value()) << f.name << ": scales alone are always exact";
      const fuzzing::Rows out = std::visit([](const auto& q) { return rows(q); }, inst->query);
      const fuzzing::Rows local = std::visit([](const auto& q) { return rows(q); }, f.local(k, true).query);
      const auto get = [](const Vec3& p, int a) { return a == 0 ? p.x : (a == 1 ? p.y : p.z); };
      for (int a = 0; a < 3; ++a) {
        bool found = false;
        for (int b = 0; b < 3 && !found; ++b) {
          // The sign and exponent from the first nonzero coordinate; every coordinate must follow.
          bool ok = true, have = false;
          double sign = 1;
          int e = 0;
          for (std::size_t i = 0; i < 8 && ok; ++i) {
            const double x = get(out[i], a), y = get(local[i], b);
            if ((x == 0) != (y == 0)) ok = false;
            else if (x != 0 && !have) {
              sign = (x < 0) == (y < 0) ? 1 : -1;
              e = std::ilogb(x) - std::ilogb(y);
              have = true;
            }
          }
          for (std::size_t i = 0; i < 8 && ok; ++i) ok = get(out[i], a) == sign * std::ldexp(get(local[i], b), e);
          found = ok;
        }
        EXPECT_TRUE(found) << f.name << " k=" << k << ": output axis " << a << " is not a scaled local axis\n"
                           << describe(inst->query);
      }
      ++checked;
    }
  EXPECT_EQ(checked, static_cast<int>(families::all_families().size()) * 5);
}

}  // namespace
}  // namespace exactccd
