// The minimum-separation families (tools/lib/generators/separation_families.hpp) produce what they claim, checked
// independently of the library's separation code: for every family, several questions (d, tmax)
// and perturbations, the exact squared distance of the placed query (CGAL's rational distances,
// tests/exact_distance.hpp) at the claimed contact time and at sampled times, and the reference
// path (Method::exact) at d and at the double just below d.
#include "generators/separation_families.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "exactccd/exactccd.hpp"
#include "io/benchmark_csv.hpp"
#include "tests/exact_distance.hpp"

namespace exactccd::separation_families {
namespace {

using testing::P3;

/// The exact squared distance of the family's primitives at time t (2D kinds at z = 0).
mpq_class squared_distance(const Family& f, const Rows& r, const mpq_class& t) {
  std::vector<P3> p;
  for (int i = 0; i < f.points; ++i) {
    const Vec3& a = r[static_cast<std::size_t>(i)];
    const Vec3& b = r[static_cast<std::size_t>(f.points + i)];
    const auto at = [&](double x0, double x1) { return mpq_class(mpq_class(x0) + t * (mpq_class(x1) - mpq_class(x0))); };
    p.emplace_back(at(a.x, b.x), at(a.y, b.y), at(a.z, b.z));
  }
  if (f.points == 2) return CGAL::squared_distance(p[0], p[1]);
  if (f.points == 3) return testing::sq_point_segment(p[0], p[1], p[2]);
  if (f.first_points == 1) return testing::sq_point_triangle(p[0], p[1], p[2], p[3]);
  return testing::sq_segment_segment(p[0], p[1], p[2], p[3]);
}

/// The reference path's answer on the family's query for a question.
bool exact_answer(const Family& f, const Rows& r, const CcdParams& p) {
  bool out = false;
  kinds::for_each_kind([&](auto kind) {
    using Kind = decltype(kind);
    if (Kind::name == f.kind) out = ccd(io::query_from_rows<typename Kind::template Query<double>>(r), p, Method::exact);
  });
  return out;
}

std::string describe(const Family& f, const CcdParams& p, int k, bool toward, const Rows& r) {
  std::ostringstream s;
  s << f.name << " d = " << std::hexfloat << p.min_distance << " tmax = " << p.tmax << " k = " << std::dec << k
    << (toward ? " toward" : " away") << "\n";
  for (int i = 0; i < 2 * f.points; ++i) s << std::hexfloat << "  " << r[i].x << " " << r[i].y << " " << r[i].z << "\n";
  return s.str();
}

/// The claimed distance profile, at the contact and at sampled times in [0, 1].
void expect_profile(const Family& f, const Instance& inst, const std::string& where) {
  const Claim& c = inst.claim;
  std::vector<mpq_class> times = {mpq_class(0), mpq_class(1, 3), mpq_class(1, 2), mpq_class(1)};
  if (c.contact && *c.contact <= 1) {
    times.push_back(*c.contact);
    times.push_back(*c.contact / 2);
    times.push_back(*c.contact * mpq_class(1023, 1024));
  }
  for (const mpq_class& t : times) {
    const mpq_class d2 = squared_distance(f, inst.rows, t);
    if (c.motion != Motion::pass) {
      const mpq_class h = c.h0 + (c.h1 - c.h0) * t;
      EXPECT_EQ(d2, h * h) << where << "the distance is not the linear gap at t = " << t;
      continue;
    }
    const mpq_class g2 = c.h0 * c.h0;
    if (c.contact && t == *c.contact) {
      EXPECT_EQ(d2, g2) << where << "not at the gap at the contact " << t;
    } else if (c.contact && t < *c.contact) {
      EXPECT_GT(d2, g2) << where << "at the gap before the contact, t = " << t;
    } else {
      EXPECT_GE(d2, g2) << where << "closer than the gap at t = " << t;
    }
  }
}

struct Tally {
  int instances = 0, decided = 0, minimum_d = 0, unperturbed = 0, perturbed = 0;
};

void check_instance(const Family& f, const CcdParams& p, int k, bool toward, std::uint64_t seed, Tally& tally) {
  const Instance inst = make(f, p, k, toward, seed);
  const std::string where = describe(f, p, k, toward, inst.rows);
  for (int i = 0; i < 8; ++i) {
    const Vec3& x = inst.rows[static_cast<std::size_t>(i)];
    ASSERT_TRUE(std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z)) << where;
    if (i >= 2 * f.points || f.dimension == 2) {
      EXPECT_EQ(x.z, 0.0) << where;
    }
  }
  expect_profile(f, inst, where);
  ++tally.instances;
  const Claim& c = inst.claim;
  if (c.expected) {
    ++tally.decided;
    EXPECT_EQ(exact_answer(f, inst.rows, p), *c.expected) << where;
    // Perturbations of 2^-40 and more move the answer the way asked; smaller ones may be
    // undone by the rounding of the motion (the claim says what they became).
    if (k != kUnperturbed && k <= 40) {
      ++tally.perturbed;
      EXPECT_EQ(*c.expected, toward) << where << "h0 " << c.h0 << " h1 " << c.h1 << " contact "
                                     << (c.contact ? c.contact->get_str() : "none");
    }
  }
  if (k == kUnperturbed) ++tally.unperturbed;
  if (c.minimum_is_d) {
    ++tally.minimum_d;
    EXPECT_TRUE(*c.expected) << where;
    if (p.min_distance > 0) {
      EXPECT_FALSE(exact_answer(f, inst.rows, {std::nextafter(p.min_distance, 0.0), p.tmax}))
          << where << "collides below d: its minimum distance is not d";
    }
  }
}

class SeparationFamilyTest : public ::testing::TestWithParam<std::string> {};

TEST_P(SeparationFamilyTest, ProducesWhatItClaims) {
  const Family* f = find_family(GetParam());
  ASSERT_NE(f, nullptr);
  const std::vector<CcdParams> questions = {{1e-3, 1.0}, {1e-3, 0.75}, {0.25, 0.3}, {0x1p-30, 1.0}, {1e-6, 0.5},
                                            {0.0, 1.0}};
  Tally tally;
  std::uint64_t seed = std::hash<std::string>{}(f->name);
  for (const CcdParams& p : questions)
    for (const int k : {kUnperturbed, 0, 3, 21, 40, 60})
      for (const bool toward : {false, true}) check_instance(*f, p, k, toward, ++seed, tally);
  // Most unperturbed instances are at d exactly (the others have their contact placed at tmax
  // and rounded past it, or d = 0 where "just below d" does not exist: still claimed).
  EXPECT_GE(2 * tally.minimum_d, tally.unperturbed) << f->name;
  EXPECT_GE(4 * tally.decided, 3 * tally.instances) << f->name << ": most instances have a known answer";
  EXPECT_GE(2 * tally.perturbed, tally.decided - tally.unperturbed) << f->name << ": most perturbations are decided";
}

std::vector<std::string> family_names() {
  std::vector<std::string> out;
  for (const Family& f : all_families()) out.push_back(f.name);
  return out;
}

INSTANTIATE_TEST_SUITE_P(Families, SeparationFamilyTest, ::testing::ValuesIn(family_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(SeparationFamilies, EveryKindHasFamiliesOfEveryMotionItsPrimitivesAllow) {
  kinds::for_each_kind([](auto kind) {
    using Kind = decltype(kind);
    const std::vector<const Family*> list = families_of_kind<Kind>();
    ASSERT_FALSE(list.empty()) << Kind::name;
    std::set<Motion> motions;
    for (const Family* f : list) {
      EXPECT_EQ(f->points, Kind::points);
      EXPECT_EQ(f->dimension, Kind::dimension);
      motions.insert(f->construction->motion);
    }
    EXPECT_EQ(motions.size(), 4u) << Kind::name << ": pass, approach, leave and slide";
  });
}

TEST(SeparationFamilies, RandomNearStaysOnTheScaleOfD) {
  std::mt19937_64 rng(5);
  for (const double d : {1e-3, 0x1p-1074, 1e300, 0.0}) {
    const int e = d > 0 ? std::ilogb(d) : 0;
    for (int n = 0; n < 50; ++n) {
      const Rows r = random_near(3, 2, {d, 1.0}, rng);
      for (int i = 0; i < 6; ++i) {
        for (const double x : {r[i].x, r[i].y}) {
          ASSERT_TRUE(std::isfinite(x));
          if (x != 0) {
            EXPECT_LE(std::abs(std::ilogb(x) - e), 5) << x;
          }
        }
        EXPECT_EQ(r[i].z, 0.0);
      }
    }
  }
}

}  // namespace
}  // namespace exactccd::separation_families
