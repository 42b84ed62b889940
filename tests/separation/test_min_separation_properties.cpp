// Minimum-separation CCD (CcdParams: min_distance d, tmax), checked independently of the
// implementation:
// 1. Against exact distances from CGAL (Simple_cartesian<mpq_class>: squared distances between
//    Point_3 / Segment_3 / Triangle_3 at exact rational positions x0 + t (x1 - x0), t a double):
//    the TOI [lo, hi] must be consistent with dist(t) at lo, hi, at sampled times before lo, and
//    a non-colliding query must stay farther than d at 0, tmax and sampled times. Point-point
//    kinds are checked against their closed-form exact TOI; constructed contacts (linear gaps,
//    isolated tangencies at an exact distance d) against their TOI known by construction.
// 2. Properties on the shared sample queries and the bundled data (data/sim, data/families):
//    CcdParams{} is today's TOI, monotone in d, tmax restricts exactly.
// 3. Exact invariances: vertex/edge/primitive permutations, 2D == 3D with z = 0, translations,
//    axis permutations and reflections, power-of-two scaling (with d), a common velocity added
//    to every vertex, and degenerate primitives equal to their hull's kind.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"
#include "io/benchmark_csv.hpp"
#include "kinds/primitive_kinds.hpp"
#include "tests/exact_distance.hpp"
#include "tests/test_support.hpp"

namespace exactccd {
namespace {

using testing::P3;
using testing::sq_point_segment;
using testing::sq_point_triangle;
using testing::sq_segment_segment;

constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- the kinds, generically ---------------------------------------------------------------

/// nv vertices per time; the first na belong to primitive A, the rest to B; dim 2 or 3 (from
/// the kind's description: the oracle below computes the distances itself).
template <class Q>
struct Kind {
  using Description = kinds::kind_of<Q>;
  static constexpr int nv = Description::points, na = Description::first_points, dim = Description::dimension;
  static constexpr const char* name = Description::name.data();
};

template <class Q>
struct Tag {
  using type = Q;
};

/// f(Tag<Query>{}) for the double query type of every kind (kinds::for_each_kind).
template <class F>
void for_each_query_type(F&& f) {
  kinds::for_each_kind([&](auto kind) { f(Tag<typename decltype(kind)::template Query<double>>{}); });
}

using Row = std::array<double, 3>;  // a point; z = 0 for the 2D kinds
template <class Q>
using Rows = std::array<Row, 2 * Kind<Q>::nv>;  // file row order: every vertex at t0, then at t1

inline Row get3(const Vec3& p) { return {p.x, p.y, p.z}; }
[[maybe_unused]] inline Row get3(const Vec2& p) { return {p.x, p.y, 0.0}; }

template <class Q>
Rows<Q> rows_of(const Q& q) {
  const auto r = rows(q);
  Rows<Q> out;
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = get3(r[i]);
  return out;
}

template <class Q>
Q make(const Rows<Q>& r) {
  constexpr std::size_t n = 2 * Kind<Q>::nv;
  if constexpr (Kind<Q>::dim == 3) {
    std::array<Vec3, n> a;
    for (std::size_t i = 0; i < n; ++i) a[i] = {r[i][0], r[i][1], r[i][2]};
    return from_rows<Q>(a);
  } else {
    std::array<Vec2, n> a;
    for (std::size_t i = 0; i < n; ++i) a[i] = {r[i][0], r[i][1]};
    return from_rows<Q>(a);
  }
}

template <class Q>
double bbox_size(const Rows<Q>& r) {
  double s = 0;
  for (int k = 0; k < 3; ++k) {
    double lo = kInf, hi = -kInf;
    for (const Row& p : r) lo = std::min(lo, p[k]), hi = std::max(hi, p[k]);
    s = std::max(s, hi - lo);
  }
  return s;
}

std::string fmt(double x) {
  std::ostringstream s;
  s << std::setprecision(17) << x << " (" << std::hexfloat << x << ")";
  return s.str();
}

template <class Q>
std::string describe(const Rows<Q>& r) {
  std::ostringstream s;
  s << Kind<Q>::name << " rows (x y z; hexfloat):\n";
  for (const Row& p : r) {
    s << "   " << std::hexfloat << p[0] << " " << p[1] << " " << p[2] << std::defaultfloat << "   |  "
      << std::setprecision(17) << p[0] << " " << p[1] << " " << p[2] << "\n";
  }
  return s.str();
}

std::string fmt(const std::optional<TimeInterval>& t) {
  if (!t) return "no collision";
  std::ostringstream s;
  s << "[" << fmt(t->lo) << ", " << fmt(t->hi) << "]";
  return s.str();
}

// ---- failures: counted, the first few reported in full ---------------------------------------

struct Report {
  std::size_t failures = 0;
  std::string first;
  void fail(const std::string& what) {
    if (failures++ < 8) first += "\n--- " + what;
  }
  void expect_clean(const char* context) const {
    EXPECT_EQ(failures, 0u) << context << ": " << failures << " failures; the first:" << first;
  }
};

template <class Q>
std::string context(const Rows<Q>& r, const CcdParams& p, const std::string& origin) {
  return origin + ": " + describe<Q>(r) + "   d = " + fmt(p.min_distance) + ", tmax = " + fmt(p.tmax) + "\n";
}

// ---- the independent exact distance (CGAL: tests/exact_distance.hpp) -------------------------

P3 position(const Row& x0, const Row& x1, const mpq_class& t) {
  auto c = [&](int k) {
    const mpq_class a(x0[k]), b(x1[k]);
    return mpq_class(a + t * (b - a));
  };
  return P3(c(0), c(1), c(2));
}

/// The squared distance between the two closed primitives at time t, exactly.
template <class Q>
mpq_class sqdist(const Rows<Q>& r, const mpq_class& t) {
  constexpr int nv = Kind<Q>::nv;
  std::array<P3, nv> p;
  for (int i = 0; i < nv; ++i) p[i] = position(r[i], r[i + nv], t);
  if constexpr (nv == 2) {
    return CGAL::squared_distance(p[0], p[1]);
  } else if constexpr (nv == 3) {
    return sq_point_segment(p[0], p[1], p[2]);
  } else if constexpr (Kind<Q>::na == 1) {
    return sq_point_triangle(p[0], p[1], p[2], p[3]);
  } else {
    return sq_segment_segment(p[0], p[1], p[2], p[3]);
  }
}

template <class Q>
mpq_class sqdist(const Rows<Q>& r, double t) {
  return sqdist<Q>(r, mpq_class(t));
}

/// Is the TOI the tightest double enclosure of the exact time `t`?
bool tightly_encloses(const TimeInterval& got, const mpq_class& t) {
  if (mpq_class(got.lo) == t) return got.hi == got.lo;
  return mpq_class(got.lo) < t && t < mpq_class(got.hi) && got.hi == std::nextafter(got.lo, kInf);
}

/// Point-point kinds: the exact earliest t in [0, tmax] with |p(t) - q(t)|^2 <= d^2, in closed
/// form (a convex quadratic), checked against the TOI by exact signs only.
template <class Q>
std::optional<std::string> point_point_truth(const Rows<Q>& r, const CcdParams& prm,
                                             const std::optional<TimeInterval>& got) {
  mpq_class A = 0, B = 0, C = 0;
  for (int k = 0; k < 3; ++k) {
    const mpq_class d0 = mpq_class(r[0][k]) - mpq_class(r[1][k]);
    const mpq_class d1 = mpq_class(r[2][k]) - mpq_class(r[3][k]);
    const mpq_class v = d1 - d0;
    A += v * v;
    B += 2 * d0 * v;
    C += d0 * d0;
  }
  const mpq_class dd(prm.min_distance);
  C -= dd * dd;
  const mpq_class T(prm.tmax);
  auto f = [&](const mpq_class& t) { return mpq_class(A * t * t + B * t + C); };
  if (C <= 0) {  // in contact at t = 0
    if (!got || got->lo != 0 || got->hi != 0) return std::string("closed form: TOI [0, 0]");
    return std::nullopt;
  }
  bool collides = false;
  mpq_class tv;
  if (A > 0) {
    tv = -B / (2 * A);
    collides = tv > 0 && f(tv) <= 0 && (T >= tv || f(T) <= 0);
  }
  if (!collides) {
    if (got) return std::string("closed form: no collision in [0, tmax]");
    return std::nullopt;
  }
  if (!got) return std::string("closed form: collides (the first root of |p-q|^2 - d^2 is <= tmax)");
  // The first root r1 lies in (0, tv]; f > 0 before it, f <= 0 on [r1, r2].
  const mpq_class lo(got->lo), hi(got->hi);
  const bool lo_is_root = lo <= tv && f(lo) == 0;
  if (got->lo == got->hi) {
    if (!lo_is_root) return std::string("closed form: lo == hi but lo is not the first root");
    return std::nullopt;
  }
  const bool lo_before = lo < tv && f(lo) > 0;
  const bool hi_after = hi > tv || f(hi) < 0;
  if (!lo_before || !hi_after || got->hi != std::nextafter(got->lo, kInf))
    return std::string("closed form: [lo, hi] is not the tightest enclosure of the first root");
  return std::nullopt;
}

// ---- the check of one query against the distances ------------------------------------------

struct Tally {
  std::size_t queries = 0, none = 0, at_zero = 0, exact_time = 0, interval = 0, exact_method = 0;
  void count(const std::optional<TimeInterval>& t) {
    ++queries;
    if (!t) ++none;
    else if (t->hi == 0) ++at_zero;
    else if (t->lo == t->hi) ++exact_time;
    else ++interval;
  }
  std::string str() const {
    std::ostringstream s;
    s << queries << " checks: " << none << " no collision, " << at_zero << " at t = 0, " << exact_time
      << " at a double t > 0, " << interval << " at a non-double t; " << exact_method << " also by Method::exact";
    return s.str();
  }
};

struct CheckOptions {
  /// The query is generic (random real inputs, d > 0 not constructed to be a tangency): where
  /// the TOI is not a double, dist(hi) <= d too (with d > 0 a contact at an isolated time is a
  /// tangency, non-generic).
  bool generic = false;
  /// Also Method::exact, bit for bit.
  bool exact_method = false;
  /// The TOI known by construction (nullopt: unknown), as "collides at exactly this time".
  std::optional<std::optional<mpq_class>> expected;
  int samples = 32;
};

double sample_below(std::mt19937_64& rng, double limit) {
  double t = std::uniform_real_distribution<double>(0.0, limit)(rng);
  if (t >= limit) t = std::nextafter(limit, 0.0);
  return std::max(t, 0.0);
}

template <class Q>
std::optional<TimeInterval> check_query(const Rows<Q>& r, const CcdParams& prm, const std::string& origin,
                                        std::mt19937_64& rng, Report& rep, Tally& tally,
                                        const CheckOptions& opt = {}) {
  const Q q = make<Q>(r);
  std::optional<TimeInterval> got;
  bool answer = false;
  try {
    got = toi(q, prm);
    answer = ccd(q, prm);
  } catch (const std::exception& e) {
    rep.fail(context<Q>(r, prm, origin) + "   threw: " + e.what());
    return std::nullopt;
  }
  tally.count(got);
  auto fail = [&](const std::string& what) {
    rep.fail(context<Q>(r, prm, origin) + "   filtered TOI " + fmt(got) + ", ccd " + (answer ? "true" : "false") +
             "\n   " + what);
  };
  if (answer != got.has_value()) fail("ccd() and toi() disagree");
  if (opt.exact_method) {
    ++tally.exact_method;
    try {
      const auto e = toi(q, prm, Method::exact);
      const bool ea = ccd(q, prm, Method::exact);
      if (e.has_value() != got.has_value() || (e && !(*e == *got)) || ea != answer)
        fail("Method::exact differs: TOI " + fmt(e) + ", ccd " + (ea ? "true" : "false"));
    } catch (const std::exception& ex) {
      fail(std::string("Method::exact threw: ") + ex.what());
    }
  }
  const mpq_class dq(prm.min_distance);
  const mpq_class d2 = dq * dq;
  if constexpr (Kind<Q>::nv == 2) {
    if (const auto w = point_point_truth<Q>(r, prm, got)) fail(*w);
  }
  if (opt.expected) {
    const auto& e = *opt.expected;
    if (e.has_value() != got.has_value() || (e && !tightly_encloses(*got, *e)))
      fail("constructed TOI: " + (e ? e->get_str() + " (" + fmt(e->get_d()) + ")" : std::string("no collision")));
  }
  if (got) {
    const double lo = got->lo, hi = got->hi;
    if (!(lo >= 0 && lo <= hi && hi <= prm.tmax) || (hi != lo && hi != std::nextafter(lo, kInf))) {
      fail("not a tightest enclosure in [0, tmax]");
      return got;
    }
    if (hi == 0) {
      if (!(sqdist<Q>(r, 0.0) <= d2)) fail("TOI [0, 0] but dist(0) > d");
    } else if (lo == hi) {
      if (sqdist<Q>(r, lo) != d2) fail("TOI is the double lo > 0, but dist(lo)^2 != d^2");
      if (!(sqdist<Q>(r, std::nextafter(lo, 0.0)) > d2)) fail("dist(prev(lo)) <= d: not the earliest");
    } else {
      if (!(sqdist<Q>(r, lo) > d2)) fail("TOI is not a double, but dist(lo) <= d: lo is a contact time");
      if (opt.generic && !(sqdist<Q>(r, hi) <= d2))
        fail("generic query: dist(hi) > d (a contact only at an isolated non-double time?)");
    }
    if (lo > 0) {
      if (!(sqdist<Q>(r, 0.0) > d2)) fail("TOI > 0 but dist(0) <= d");
      for (int i = 0; i < opt.samples / 2; ++i) {
        const double t = sample_below(rng, lo);
        if (!(sqdist<Q>(r, t) > d2)) {
          fail("dist(" + fmt(t) + ") <= d before the TOI");
          break;
        }
      }
    }
  } else {
    std::vector<double> ts{0.0, prm.tmax};
    for (int i = 0; i < opt.samples - 2; ++i) ts.push_back(sample_below(rng, prm.tmax));
    for (double t : ts)
      if (!(sqdist<Q>(r, t) > d2)) {
        fail("no collision reported, but dist(" + fmt(t) + ") <= d");
        break;
      }
  }
  return got;
}

// ---- query generators -----------------------------------------------------------------------

template <class Q>
Rows<Q> random_rows(std::mt19937_64& rng, double box = 1.0) {
  std::uniform_real_distribution<double> u(-box, box);
  Rows<Q> r;
  for (Row& p : r) p = {u(rng), u(rng), Kind<Q>::dim == 3 ? u(rng) : 0.0};
  return r;
}

/// tests/test_support.hpp's grid rows (multiples of 1/8 in [-1/4, 1/4], repeated points,
/// coplanar motion, static primitives), cut to the kind's vertices.
template <class Q>
Rows<Q> grid_rows(std::mt19937_64& rng) {
  const std::array<Vec3, 8> g = testing::degenerate_rows(rng);
  constexpr int nv = Kind<Q>::nv;
  Rows<Q> r;
  for (int i = 0; i < nv; ++i) {
    r[i] = get3(g[i]);
    r[i + nv] = get3(g[i + 4]);
  }
  // More coincidences across the primitives (a vertex of B on one of A, at t0 or at t1).
  std::uniform_int_distribution<int> c(0, 5);
  const int k = c(rng);
  if (k == 0) r[nv - 1] = r[0];
  if (k == 1) r[2 * nv - 1] = r[nv];
  if constexpr (Kind<Q>::dim == 2)
    for (Row& p : r) p[2] = 0;
  return r;
}

/// Random rows, then B translated so that a random point of B meets a random point of A at a
/// random time tc, up to a small random offset: the primitives come near each other.
template <class Q>
Rows<Q> near_rows(std::mt19937_64& rng) {
  constexpr int nv = Kind<Q>::nv, na = Kind<Q>::na;
  Rows<Q> r = random_rows<Q>(rng);
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
  const double tc = u(rng);
  auto at = [&](int i, int k) { return r[i][k] + tc * (r[i + nv][k] - r[i][k]); };
  auto point_on = [&](int first, int count) {
    std::array<double, 4> w{};
    double sum = 0;
    for (int i = 0; i < count; ++i) sum += (w[i] = -std::log(u(rng) + 1e-300));
    Row p{0, 0, 0};
    for (int i = 0; i < count; ++i)
      for (int k = 0; k < 3; ++k) p[k] += w[i] / sum * at(first + i, k);
    return p;
  };
  const Row pa = point_on(0, na), pb = point_on(na, nv - na);
  const double noise = std::pow(10.0, -6.0 * u(rng)) * (u(rng) < 0.2 ? 0.0 : 1.0);
  for (int k = 0; k < Kind<Q>::dim; ++k) {
    const double off = pa[k] - pb[k] + noise * s(rng);
    for (int i = na; i < nv; ++i) r[i][k] += off, r[i + nv][k] += off;
  }
  return r;
}

/// sqrt of a nonnegative rational, to about double precision (for near-tangent d).
double approx_sqrt(const mpq_class& x) { return std::sqrt(x.get_d()); }

// ---- 1. the independent distance check --------------------------------------------------------

template <class Q>
void random_group(std::mt19937_64& rng, int n, Report& rep, Tally& tally) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    const Rows<Q> r = random_rows<Q>(rng);
    const double s = bbox_size<Q>(r);
    for (double d : {0.0, s * 0.3 * u(rng), s * 0.05 * u(rng)}) {
      const double tmax = u(rng) < 0.7 ? 1.0 : std::max(u(rng), 0x1p-20);
      CheckOptions o;
      o.generic = d > 0;  // d = 0: a crossing is an isolated contact time
      o.exact_method = i % 12 == 0;
      check_query<Q>(r, {d, tmax}, "random", rng, rep, tally, o);
    }
  }
}

TEST(MinSeparationCgal, RandomQueries) {
  // 7 kinds x 200 queries x 3 d (0, and two random fractions of the bounding box), tmax = 1
  // or random; every 12th query also by Method::exact.
  std::mt19937_64 rng(101);
  Report rep;
  Tally tally;
  for_each_query_type([&](auto tag) { random_group<typename decltype(tag)::type>(rng, 200, rep, tally); });
  rep.expect_clean("random queries");
  EXPECT_GT(tally.exact_time + tally.interval, 300u) << tally.str();
  std::cout << "[ info ] " << tally.str() << "\n";
}

template <class Q>
void grid_group(std::mt19937_64& rng, int n, Report& rep, Tally& tally) {
  // Grid distances are square roots of multiples of 1/64: d on the grid gives exact contacts.
  const double ds[] = {0.0, 0.0625, 0.125, 0.25, 0.125 * std::sqrt(2.0), 0.3, 0.5};
  std::uniform_int_distribution<int> pick(0, 6), tm(0, 4);
  const double tmaxes[] = {1.0, 1.0, 0.5, 0.75, 1.0 / 3};
  for (int i = 0; i < n; ++i) {
    const Rows<Q> r = grid_rows<Q>(rng);
    for (int j = 0; j < 2; ++j) {
      CheckOptions o;
      o.exact_method = i % 6 == 0;
      check_query<Q>(r, {ds[j == 0 ? 0 : pick(rng)], tmaxes[tm(rng)]}, "grid", rng, rep, tally, o);
    }
  }
}

TEST(MinSeparationCgal, DegenerateGridQueries) {
  // 7 kinds x 300 grid queries (repeated points, coplanar motion, static primitives) x 2 d
  // (0 and a grid distance or a near one); every 6th also by Method::exact.
  std::mt19937_64 rng(202);
  Report rep;
  Tally tally;
  for_each_query_type([&](auto tag) { grid_group<typename decltype(tag)::type>(rng, 300, rep, tally); });
  rep.expect_clean("grid queries");
  EXPECT_GT(tally.exact_time, 100u) << tally.str();
  std::cout << "[ info ] " << tally.str() << "\n";
}

template <class Q>
void near_group(std::mt19937_64& rng, int n, Report& rep, Tally& tally) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    const Rows<Q> r = near_rows<Q>(rng);
    const double s = bbox_size<Q>(r);
    // d = the distance at a random double time ts (to double precision) and its neighbours: the
    // primitives come within about d at ts, a near-tangency when ts is near the closest approach.
    const double ts = u(rng);
    const double dts = approx_sqrt(sqdist<Q>(r, ts));
    const double ds[] = {0.0, s * 1e-3 * u(rng), dts, std::nextafter(dts, 0.0), std::nextafter(dts, kInf)};
    for (int j = 0; j < 5; ++j) {
      if (j >= 3 && i % 2) continue;
      CheckOptions o;
      o.generic = ds[j] > 0;  // d = 0: a crossing is an isolated contact time
      o.exact_method = i % 12 == 0;
      const double tmax = j == 2 && i % 3 == 0 ? ts : 1.0;
      if (tmax <= 0) continue;
      check_query<Q>(r, {ds[j], tmax}, "near", rng, rep, tally, o);
    }
  }
}

TEST(MinSeparationCgal, NearQueries) {
  // 7 kinds x 140 queries whose primitives meet (up to a noise of 0 or 10^-6..1) at a random
  // time; d = 0, a random fraction 1e-3 of the bounding box, and the distance at a random double
  // time and its two neighbouring doubles; every 12th also by Method::exact.
  std::mt19937_64 rng(303);
  Report rep;
  Tally tally;
  for_each_query_type([&](auto tag) { near_group<typename decltype(tag)::type>(rng, 140, rep, tally); });
  rep.expect_clean("near queries");
  EXPECT_GT(tally.exact_time + tally.interval, 1000u) << tally.str();
  std::cout << "[ info ] " << tally.str() << "\n";
}

// -- constructed contacts with a known TOI --------------------------------------------------------

/// The earliest t in [0, T] with |g0 + t (g1 - g0)| <= d.
std::optional<mpq_class> linear_gap_toi(const mpq_class& g0, const mpq_class& g1, const mpq_class& d,
                                        const mpq_class& T) {
  std::optional<mpq_class> t;
  if (abs(g0) <= d) t = mpq_class(0);
  else if (g0 > d && g1 <= d) t = mpq_class((g0 - d) / (g0 - g1));
  else if (g0 < -d && g1 >= -d) t = mpq_class((-d - g0) / (g1 - g0));
  if (t && *t > T) t.reset();
  return t;
}

/// The crossing time of s0 + t (s1 - s0) through 0, when in [0, T].
std::optional<mpq_class> crossing(const mpq_class& s0, const mpq_class& s1, const mpq_class& T) {
  if (s0 == s1) return s0 == 0 ? std::optional<mpq_class>(mpq_class(0)) : std::nullopt;
  const mpq_class t = -s0 / (s1 - s0);
  if (t < 0 || t > T) return std::nullopt;
  return t;
}

struct Constructed {
  std::vector<Row> rows;  // 2 nv rows
  double d;
  std::optional<mpq_class> toi;  // for tmax = 1
  std::string what;
};

/// Exact-contact configurations per kind: a linear gap |g(t)| against d (the TOI is rational,
/// often dyadic: lo == hi and dist(lo) == d exactly), and an isolated tangency: the closest
/// features pass at exactly d = 5/8 (a 3-4-5 triangle) at the crossing time of a coordinate,
/// often 1/3 (not a double), where d - ulp never collides.
template <class Q>
std::vector<Constructed> constructed(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> e(-16, 16), dpos(0, 8);
  const double g0 = e(rng) / 8.0, g1 = e(rng) / 8.0, d = dpos(rng) / 8.0;
  const double s0 = -(1 + dpos(rng)) / 8.0, s1 = (1 + std::abs(e(rng))) / 8.0;  // crosses 0
  const double five8 = 0.625;
  std::vector<Constructed> out;
  auto lin = [&](std::vector<Row> rows, const char* what) {
    out.push_back({std::move(rows), d, linear_gap_toi(g0, g1, d, 1), what});
  };
  auto tangent = [&](std::vector<Row> rows, const char* what) {
    out.push_back({rows, five8, crossing(s0, s1, 1), what});
    out.push_back({rows, std::nextafter(five8, 0.0), std::nullopt, std::string(what) + ", d - ulp"});
  };
  const char* name = Kind<Q>::name;
  const std::string k(name);
  if (k == "vertex-face") {
    // the point above the triangle's interior, the gap along z
    lin({{0, 0, g0}, {-1, -1, 0}, {2, -1, 0}, {-1, 2, 0}, {0, 0, g1}, {-1, -1, 0}, {2, -1, 0}, {-1, 2, 0}},
        "vf point over the interior");
    // the same with the triangle moving instead, and the z gap split between both
    lin({{0, 0, 0}, {-1, -1, -g0}, {2, -1, -g0}, {-1, 2, -g0}, {0, 0, g1 / 2}, {-1, -1, -g1 / 2}, {2, -1, -g1 / 2},
         {-1, 2, -g1 / 2}},
        "vf triangle moving onto the point");
    // the point in vertex a's Voronoi region at (-3/8, -1/2), passing z = 0: closest 5/8
    tangent({{-0.375, -0.5, s0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-0.375, -0.5, s1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
            "vf isolated tangency at a vertex");
  } else if (k == "edge-edge") {
    lin({{-1, 0, 0}, {1, 0, 0}, {0, -1, g0}, {0, 1, g0}, {-1, 0, 0}, {1, 0, 0}, {0, -1, g1}, {0, 1, g1}},
        "ee crossing edges, gap along z");
    lin({{-1, 0, 0}, {1, 0, 0}, {-0.5, g0, 0}, {1.5, g0, 0}, {-1, 0, 0}, {1, 0, 0}, {-0.5, g1, 0}, {1.5, g1, 0}},
        "ee parallel overlapping edges");
    tangent({{-1, 0, 0}, {0, 0, 0}, {0.375, 0.5, s0}, {1.375, 0.5, s0}, {-1, 0, 0}, {0, 0, 0}, {0.375, 0.5, s1},
             {1.375, 0.5, s1}},
            "ee isolated tangency of two endpoints");
  } else if (k == "point-edge") {
    lin({{0, g0, 0}, {-1, 0, 0}, {1, 0, 0}, {0, g1, 0}, {-1, 0, 0}, {1, 0, 0}}, "pe point over the interior");
    tangent({{0.375, 0.5, s0}, {-1, 0, 0}, {0, 0, 0}, {0.375, 0.5, s1}, {-1, 0, 0}, {0, 0, 0}},
            "pe isolated tangency at an endpoint");
  } else if (k == "point-point") {
    lin({{g0, 0, 0}, {0, 0, 0}, {g1, 0, 0}, {0, 0, 0}}, "pp along x");
    tangent({{0.375, 0.5, s0}, {0, 0, 0}, {0.375, 0.5, s1}, {0, 0, 0}}, "pp isolated tangency");
  } else if (k == "edge-edge-2d") {
    // b points away from a (upwards from its end at height g): distance max(g, 0) while g >= -1
    if (g0 > 0 && g1 >= -1)
      lin({{-1, 0, 0}, {1, 0, 0}, {0, g0, 0}, {0, g0 + 1, 0}, {-1, 0, 0}, {1, 0, 0}, {0, g1, 0}, {0, g1 + 1, 0}},
          "ee2d endpoint onto an edge");
    lin({{-1, 0, 0}, {1, 0, 0}, {-0.5, g0, 0}, {1.5, g0, 0}, {-1, 0, 0}, {1, 0, 0}, {-0.5, g1, 0}, {1.5, g1, 0}},
        "ee2d parallel overlapping edges");
    tangent({{-1, 0, 0}, {0, 0, 0}, {five8, s0, 0}, {five8 + 1, s0, 0}, {-1, 0, 0}, {0, 0, 0}, {five8, s1, 0},
             {five8 + 1, s1, 0}},
            "ee2d isolated tangency of two endpoints");
  } else if (k == "point-edge-2d") {
    lin({{0, g0, 0}, {-1, 0, 0}, {1, 0, 0}, {0, g1, 0}, {-1, 0, 0}, {1, 0, 0}}, "pe2d point over the interior");
    tangent({{five8, s0, 0}, {-1, 0, 0}, {0, 0, 0}, {five8, s1, 0}, {-1, 0, 0}, {0, 0, 0}},
            "pe2d isolated tangency at an endpoint");
  } else {
    lin({{g0, 0, 0}, {0, 0, 0}, {g1, 0, 0}, {0, 0, 0}}, "pp2d along x");
    tangent({{s0, five8, 0}, {0, 0, 0}, {s1, five8, 0}, {0, 0, 0}}, "pp2d isolated tangency");
  }
  return out;
}

/// An exact symmetry of a query of kind Q applied to its rows (all exact on small dyadic
/// coordinates): axis permutation, reflections, integer translation, a common velocity.
template <class Q>
Rows<Q> random_isometry(const Rows<Q>& r, std::mt19937_64& rng) {
  constexpr int nv = Kind<Q>::nv, dim = Kind<Q>::dim;
  std::array<int, 3> axes{0, 1, 2};
  std::shuffle(axes.begin(), axes.begin() + dim, rng);
  std::uniform_int_distribution<int> sg(0, 1), tr(-8, 8);
  Row sign, shift, vel;
  for (int k = 0; k < 3; ++k) {
    sign[k] = sg(rng) ? 1.0 : -1.0;
    shift[k] = k < dim ? tr(rng) : 0.0;
    vel[k] = k < dim ? tr(rng) / 4.0 : 0.0;
  }
  Rows<Q> out;
  for (int i = 0; i < 2 * nv; ++i)
    for (int k = 0; k < 3; ++k)
      out[i][k] = k < dim ? sign[k] * r[i][axes[k]] + shift[k] + (i >= nv ? vel[k] : 0.0) : 0.0;
  return out;
}

template <class Q>
void constructed_group(std::mt19937_64& rng, int n, Report& rep, Tally& tally) {
  constexpr int nv = Kind<Q>::nv;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    for (const Constructed& c : constructed<Q>(rng)) {
      Rows<Q> r;
      std::copy(c.rows.begin(), c.rows.end(), r.begin());
      if (i % 2) r = random_isometry<Q>(r, rng);
      // tmax: 1, or a dyadic cut that may fall before or after the contact, or the TOI itself
      double tmax = 1.0;
      if (i % 3 == 1) tmax = std::ceil(u(rng) * 8) / 8;
      if (i % 3 == 2 && c.toi && *c.toi > 0) tmax = std::nextafter(c.toi->get_d(), kInf);
      if (tmax > 1) tmax = 1;
      CheckOptions o;
      o.exact_method = i % 4 == 0;
      std::optional<mpq_class> e = c.toi;
      if (e && *e > mpq_class(tmax)) e.reset();
      o.expected = e;
      check_query<Q>(r, {c.d, tmax}, c.what, rng, rep, tally, o);
      static_assert(nv >= 2);
    }
  }
}

TEST(MinSeparationCgal, ConstructedExactContacts) {
  // 7 kinds x 60 rounds of 3-6 configurations with a TOI known by construction (linear gaps
  // in multiples of 1/8, isolated tangencies at d = 5/8 and d = 5/8 - ulp), every other one
  // moved by a random exact isometry and common velocity; tmax = 1, a multiple of 1/8, or just
  // past the contact; every 4th round also by Method::exact.
  std::mt19937_64 rng(404);
  Report rep;
  Tally tally;
  for_each_query_type([&](auto tag) { constructed_group<typename decltype(tag)::type>(rng, 60, rep, tally); });
  rep.expect_clean("constructed contacts");
  EXPECT_GT(tally.exact_time, 50u) << tally.str();
  EXPECT_GT(tally.interval, 200u) << tally.str();
  std::cout << "[ info ] " << tally.str() << "\n";
}

TEST(MinSeparationCgal, OracleSelfCheck) {
  // The distance oracle itself on hand-computed cases (degenerate primitives included).
  auto P = [](double x, double y, double z) { return P3(x, y, z); };
  EXPECT_EQ(sq_point_triangle(P(0, 0, 2), P(-1, -1, 0), P(2, -1, 0), P(-1, 2, 0)), 4);
  EXPECT_EQ(sq_point_triangle(P(-0.375, -0.5, 0), P(0, 0, 0), P(1, 0, 0), P(0, 1, 0)), mpq_class(25, 64));
  EXPECT_EQ(sq_point_triangle(P(0, 1, 0), P(0, 0, 0), P(1, 0, 0), P(2, 0, 0)), 1);  // collinear
  EXPECT_EQ(sq_point_triangle(P(0, 1, 0), P(3, 0, 0), P(3, 0, 0), P(3, 0, 0)), 10);  // a point
  EXPECT_EQ(sq_segment_segment(P(-1, 0, 0), P(1, 0, 0), P(0, -1, 3), P(0, 1, 3)), 9);
  EXPECT_EQ(sq_segment_segment(P(-1, 0, 0), P(1, 0, 0), P(-0.5, 2, 0), P(1.5, 2, 0)), 4);  // parallel
  EXPECT_EQ(sq_segment_segment(P(0, 0, 0), P(1, 0, 0), P(3, 0, 0), P(5, 0, 0)), 4);      // collinear
  EXPECT_EQ(sq_segment_segment(P(1, 1, 1), P(1, 1, 1), P(0, 0, 0), P(2, 0, 0)), 2);      // zero-length
  EXPECT_EQ(sq_point_segment(P(0, 0, 0), P(1, 1, 0), P(1, 1, 0)), 2);
  EXPECT_EQ(sq_point_segment(P(0, 0, 0), P(-1, 1, 0), P(1, 1, 0)), 1);
}

// ---- 2. properties on the shared and bundled data ---------------------------------------------

struct DataSet {
  std::string name;
  bool vertex_face;
  io::BenchmarkQueries queries;
};

std::optional<DataSet> load_file(const std::filesystem::path& path, bool vf) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  return DataSet{path.filename().string(), vf, io::read_benchmark_csv(in, path.string())};
}

template <class Q>
Rows<Q> rows_from(const std::array<Vec3, 8>& d) {
  Rows<Q> r;
  for (int i = 0; i < 8; ++i) r[i] = get3(d[i]);
  return r;
}

bool collides_by(const std::optional<TimeInterval>& t, double T) {
  return t && (t->lo == t->hi ? t->lo <= T : t->hi <= T);
}

template <class Q>
void data_properties(const Rows<Q>& r, const std::string& origin, std::mt19937_64& rng, Report& rep,
                     Tally& tally, bool cgal_check) {
  const Q q = make<Q>(r);
  const double s = bbox_size<Q>(r);
  auto fail = [&](const CcdParams& p, const std::string& what) { rep.fail(context<Q>(r, p, origin) + "   " + what); };
  // (a) CcdParams{} is today's answer and TOI, bit for bit
  const auto old_toi = toi(q, Method::filtered);
  const auto base = toi(q, CcdParams{});
  if (old_toi.has_value() != base.has_value() || (base && !(*base == *old_toi)))
    fail({}, "CcdParams{} TOI " + fmt(base) + " != toi(q, Method::filtered) " + fmt(old_toi));
  if (ccd(q, CcdParams{}) != ccd(q, Method::filtered)) fail({}, "CcdParams{} answer != ccd(q)");
  // (b) monotone in d
  const double ds[] = {0.0, 1e-4 * s, 1e-3 * s, 1e-2 * s};
  std::array<std::optional<TimeInterval>, 4> at;
  at[0] = base;
  for (int j = 1; j < 4; ++j) at[j] = toi(q, CcdParams{ds[j], 1.0});
  for (int j = 1; j < 4; ++j) {
    if (at[j - 1] && !at[j]) fail({ds[j], 1}, "not monotone: collides at d = " + fmt(ds[j - 1]) + " but not at d");
    if (at[j - 1] && at[j] && at[j]->lo > at[j - 1]->lo)
      fail({ds[j], 1}, "not monotone: TOI " + fmt(at[j]) + " later than " + fmt(at[j - 1]) + " at d = " + fmt(ds[j - 1]));
  }
  tally.count(at[2]);
  // (c) tmax restricts exactly, at d = 0 and d = 1e-3 s
  for (int j : {0, 2}) {
    const auto& full = at[j];
    std::vector<double> Ts{0.5, std::max(std::uniform_real_distribution<double>(0, 1)(rng), 0x1p-30)};
    if (full) {
      Ts.push_back(full->hi);
      if (full->lo > 0) Ts.push_back(full->lo);
      if (full->lo > 0) Ts.push_back(std::nextafter(full->lo, 0.0));
    }
    for (double T : Ts) {
      if (!(T > 0 && T <= 1)) continue;
      const CcdParams p{ds[j], T};
      const auto got = toi(q, p);
      const bool want = collides_by(full, T);
      if (got.has_value() != want || (got && !(*got == *full)))
        fail(p, "tmax: TOI " + fmt(got) + " but with tmax = 1 " + fmt(full));
      if (ccd(q, p) != want) fail(p, "tmax: ccd() != the tmax = 1 TOI restricted");
    }
  }
  if (cgal_check) {
    CheckOptions o;
    o.samples = 16;
    check_query<Q>(r, {ds[2], 1.0}, origin + " (d = 1e-3 bbox)", rng, rep, tally, o);
  }
}

void run_data(const std::vector<DataSet>& sets, std::size_t stride, const char* what) {
  std::mt19937_64 rng(505);
  Report rep;
  Tally tally;
  std::size_t checked = 0, not_doubles = 0;
  for (const DataSet& set : sets) {
    for (std::size_t i = 0; i < set.queries.size(); i += stride) {
      const auto d = io::exact_double_rows(set.queries.rows[i]);
      if (!d) {
        ++not_doubles;
        continue;
      }
      const std::string origin = set.name + " query " + std::to_string(i);
      const bool cgal = (i / stride) % 4 == 0;
      if (set.vertex_face)
        data_properties<VertexFaceQuery>(rows_from<VertexFaceQuery>(*d), origin, rng, rep, tally, cgal);
      else
        data_properties<EdgeEdgeQuery>(rows_from<EdgeEdgeQuery>(*d), origin, rng, rep, tally, cgal);
      ++checked;
    }
  }
  rep.expect_clean(what);
  EXPECT_GT(checked, 0u);
  std::cout << "[ info ] " << what << ": " << checked << " queries (" << not_doubles
            << " skipped: not doubles); at d = 1e-3 bbox: " << tally.str() << "\n";
}

TEST(MinSeparationData, SharedSampleQueries) {
  // Every query of the shared unit-test sample (324).
  std::vector<DataSet> sets;
  for (const auto& [path, vf] : {std::pair<const char*, bool>{"unit-tests/vertex-face/data_0_0.csv", true},
                                 {"unit-tests/vertex-face/data_0_1.csv", true},
                                 {"unit-tests/edge-edge/data_0_0.csv", false},
                                 {"unit-tests/edge-edge/data_0_1.csv", false}}) {
    const auto q = testing::load_sample(path);
    if (!q) continue;
    sets.push_back({path, vf, *q});
  }
  if (sets.empty())
    GTEST_SKIP() << "shared sample queries not found under " << EXACTCCD_SAMPLE_QUERIES_DIR
                 << " (set -DEXACTCCD_SAMPLE_QUERIES_DIR)";
  run_data(sets, 1, "shared sample queries");
}

TEST(MinSeparationData, BundledFamilies) {
  // Every query of data/families (646).
  const auto dir = std::filesystem::path(EXACTCCD_SOURCE_DIR) / "data" / "families";
  std::vector<DataSet> sets;
  for (const auto& [name, vf] : {std::pair<const char*, bool>{"families-vertex-face.csv", true},
                                 {"families-edge-edge.csv", false}}) {
    auto s = load_file(dir / name, vf);
    ASSERT_TRUE(s) << dir / name;
    sets.push_back(std::move(*s));
  }
  run_data(sets, 1, "data/families");
}

TEST(MinSeparationData, BundledSim) {
  // Every query of data/sim (2785).
  const auto dir = std::filesystem::path(EXACTCCD_SOURCE_DIR) / "data" / "sim";
  std::vector<DataSet> sets;
  for (const char* scene : {"cloth", "strip", "fold", "pile"})
    for (const auto& [kind, vf] : {std::pair<const char*, bool>{"vertex-face", true}, {"edge-edge", false}}) {
      const auto path = dir / ("sim-" + std::string(scene) + "-" + kind + ".csv");
      auto s = load_file(path, vf);
      ASSERT_TRUE(s) << path;
      sets.push_back(std::move(*s));
    }
  run_data(sets, 1, "data/sim");
}

// ---- 3. exact invariances -----------------------------------------------------------------------

/// Vertex permutations that leave the primitives (as sets) unchanged, and the swap of two
/// primitives of the same kind (ee, pp): each as a map of the nv vertices.
template <class Q>
std::vector<std::vector<int>> vertex_permutations() {
  const std::string k = Kind<Q>::name;
  if (Kind<Q>::nv == 4 && Kind<Q>::na == 1)  // (a, b, c): every permutation but the identity
    return {{0, 2, 3, 1}, {0, 3, 1, 2}, {0, 2, 1, 3}, {0, 1, 3, 2}, {0, 3, 2, 1}};
  if (Kind<Q>::nv == 4)  // a0 <-> a1, b0 <-> b1, a <-> b, all at once
    return {{1, 0, 2, 3}, {0, 1, 3, 2}, {2, 3, 0, 1}, {3, 2, 1, 0}};
  if (Kind<Q>::nv == 3) return {{0, 2, 1}};
  return {{1, 0}};
}

template <class Q>
Rows<Q> permuted(const Rows<Q>& r, const std::vector<int>& perm) {
  constexpr int nv = Kind<Q>::nv;
  Rows<Q> out;
  for (int i = 0; i < nv; ++i) {
    out[i] = r[perm[i]];
    out[i + nv] = r[perm[i] + nv];
  }
  return out;
}

template <class Q>
void expect_same(const Rows<Q>& base, const Rows<Q>& other, const CcdParams& p, const std::string& what,
                 Report& rep, std::size_t& compared) {
  ++compared;
  try {
    const auto a = toi(make<Q>(base), p), b = toi(make<Q>(other), p);
    const bool ca = ccd(make<Q>(base), p), cb = ccd(make<Q>(other), p);
    if (a.has_value() != b.has_value() || (a && !(*a == *b)) || ca != cb)
      rep.fail(context<Q>(base, p, what) + "   TOI " + fmt(a) + " but transformed: TOI " + fmt(b) + "\n   " +
               describe<Q>(other));
  } catch (const std::exception& e) {
    rep.fail(context<Q>(base, p, what) + "   threw: " + e.what());
  }
}

template <class Q>
std::vector<std::pair<Rows<Q>, std::string>> invariance_sources(std::mt19937_64& rng, int n) {
  std::vector<std::pair<Rows<Q>, std::string>> out;
  for (int i = 0; i < n; ++i) {
    out.emplace_back(grid_rows<Q>(rng), "grid");
    out.emplace_back(near_rows<Q>(rng), "near");
  }
  return out;
}

TEST(MinSeparationInvariance, VertexAndPrimitivePermutations) {
  // 7 kinds x 200 (grid + near) queries x every primitive-preserving permutation, at d = 0 and a
  // positive d (a grid distance or 1e-3 of the bounding box), tmax 1 or 0.5.
  std::mt19937_64 rng(606);
  Report rep;
  std::size_t compared = 0;
  for_each_query_type([&](auto tag) {
    using Q = typename decltype(tag)::type;
    int i = 0;
    for (const auto& [r, origin] : invariance_sources<Q>(rng, 100)) {
      const double d = origin == std::string("grid") ? 0.125 : 1e-3 * bbox_size<Q>(r);
      const CcdParams p{++i % 2 ? d : 0.0, i % 3 ? 1.0 : 0.5};
      for (const auto& perm : vertex_permutations<Q>())
        expect_same<Q>(r, permuted<Q>(r, perm), p, origin + std::string(" permuted"), rep, compared);
    }
  });
  rep.expect_clean("permutations");
  std::cout << "[ info ] " << compared << " comparisons\n";
}

template <class Q2, class Q3>
void two_vs_three(std::mt19937_64& rng, Report& rep, std::size_t& compared, int n) {
  for (const auto& [r, origin] : invariance_sources<Q2>(rng, n)) {
    for (const CcdParams& p : {CcdParams{}, CcdParams{1e-2 * bbox_size<Q2>(r), 1.0}, CcdParams{0.125, 0.75}}) {
      ++compared;
      Rows<Q3> r3;
      std::copy(r.begin(), r.end(), r3.begin());  // z = 0 already
      const auto a = toi(make<Q2>(r), p), b = toi(make<Q3>(r3), p);
      const bool ca = ccd(make<Q2>(r), p), cb = ccd(make<Q3>(r3), p);
      if (a.has_value() != b.has_value() || (a && !(*a == *b)) || ca != cb)
        rep.fail(context<Q2>(r, p, origin) + "   2D TOI " + fmt(a) + " but 3D with z = 0: " + fmt(b));
    }
  }
}

TEST(MinSeparationInvariance, TwoDimensionalEqualsThreeDimensionalWithZeroZ) {
  // 3 kinds x 200 (grid + near) queries x 3 (d, tmax).
  std::mt19937_64 rng(707);
  Report rep;
  std::size_t compared = 0;
  two_vs_three<EdgeEdge2dQuery, EdgeEdgeQuery>(rng, rep, compared, 100);
  two_vs_three<PointEdge2dQuery, PointEdgeQuery>(rng, rep, compared, 100);
  two_vs_three<PointPoint2dQuery, PointPointQuery>(rng, rep, compared, 100);
  rep.expect_clean("2D vs 3D");
  std::cout << "[ info ] " << compared << " comparisons\n";
}

TEST(MinSeparationInvariance, TranslationsIsometriesCommonVelocityAndScaling) {
  // Exact transformations of grid queries (multiples of 1/8, |x| <= 1/4) and constructed
  // contacts: integer translation, axis permutation with reflections and a common velocity
  // (random_isometry), and scaling by 2^k with d scaled too; also scaling of random queries.
  // 7 kinds x 150 queries x 3 transformations x 2 d.
  std::mt19937_64 rng(808);
  Report rep;
  std::size_t compared = 0;
  for_each_query_type([&](auto tag) {
    using Q = typename decltype(tag)::type;
    std::uniform_int_distribution<int> ex(-40, 40), tr(-1000, 1000);
    for (int i = 0; i < 150; ++i) {
      const Rows<Q> r = i % 3 == 2 ? random_rows<Q>(rng) : grid_rows<Q>(rng);
      const bool grid = i % 3 != 2;
      for (double d : {0.0, grid ? 0.125 : 0.01}) {
        const CcdParams p{d, i % 4 ? 1.0 : 0.625};
        if (grid) {
          Rows<Q> t = r;  // a pure integer translation
          Row shift{double(tr(rng)), double(tr(rng)), Kind<Q>::dim == 3 ? double(tr(rng)) : 0.0};
          for (Row& x : t)
            for (int k = 0; k < 3; ++k) x[k] += shift[k];
          expect_same<Q>(r, t, p, "grid translated", rep, compared);
          expect_same<Q>(r, random_isometry<Q>(r, rng), p, "grid isometry + common velocity", rep, compared);
        }
        const double scale = std::ldexp(1.0, ex(rng));
        Rows<Q> sc = r;
        for (Row& x : sc)
          for (double& c : x) c *= scale;
        const CcdParams ps{d * scale, p.tmax};
        ++compared;
        const auto a = toi(make<Q>(r), p), b = toi(make<Q>(sc), ps);
        if (a.has_value() != b.has_value() || (a && !(*a == *b)))
          rep.fail(context<Q>(r, p, grid ? "grid scaled" : "random scaled") + "   TOI " + fmt(a) + " but scaled by " +
                   fmt(scale) + " (d too): " + fmt(b));
      }
    }
  });
  rep.expect_clean("translations, isometries, scaling");
  std::cout << "[ info ] " << compared << " comparisons\n";
}

TEST(MinSeparationInvariance, DegeneratePrimitivesEqualTheirHullsKind) {
  // A degenerate triangle or zero-length edge is its hull: vf with c = b is pe, vf with
  // a = b = c is pp, ee with a0 = a1 is pe, ee with both edges of zero length is pp, pe with
  // a = b is pp (bit-identical TOIs). 300 (grid + near) queries x 3 (d, tmax).
  std::mt19937_64 rng(909);
  Report rep;
  std::size_t compared = 0;
  auto compare = [&](const auto& big, const auto& small, const CcdParams& p, const std::string& what) {
    ++compared;
    const auto a = toi(big, p), b = toi(small, p);
    if (a.has_value() != b.has_value() || (a && !(*a == *b)))
      rep.fail(what + ": d = " + fmt(p.min_distance) + ", tmax = " + fmt(p.tmax) + "\n   " +
               describe<std::decay_t<decltype(big)>>(rows_of(big)) + "   TOI " + fmt(a) + ", reduced kind " +
               fmt(b));
  };
  for (int i = 0; i < 150; ++i) {
    for (const auto& base : {grid_rows<VertexFaceQuery>(rng), near_rows<VertexFaceQuery>(rng)}) {
      const double s = bbox_size<VertexFaceQuery>(base);
      for (const CcdParams& p : {CcdParams{}, CcdParams{1e-2 * s, 1.0}, CcdParams{0.125, 0.5}}) {
        auto r = base;
        r[3] = r[2], r[7] = r[6];  // vf, c = b  ->  pe (p; a, b)
        compare(make<VertexFaceQuery>(r),
                make<PointEdgeQuery>({r[0], r[1], r[2], r[4], r[5], r[6]}), p, "vf with c = b vs pe");
        r[2] = r[1], r[3] = r[1], r[6] = r[5], r[7] = r[5];  // a = b = c  ->  pp
        compare(make<VertexFaceQuery>(r), make<PointPointQuery>({r[0], r[1], r[4], r[5]}), p, "vf with a = b = c vs pp");
        auto e = base;
        e[1] = e[0], e[5] = e[4];  // ee, a0 = a1  ->  pe (a0; b0, b1)
        compare(make<EdgeEdgeQuery>(e), make<PointEdgeQuery>({e[0], e[2], e[3], e[4], e[6], e[7]}), p,
                "ee with a0 = a1 vs pe");
        e[3] = e[2], e[7] = e[6];  // and b0 = b1  ->  pp
        compare(make<EdgeEdgeQuery>(e), make<PointPointQuery>({e[0], e[2], e[4], e[6]}), p,
                "ee with zero-length edges vs pp");
        auto pe = make<PointEdgeQuery>({base[0], base[1], base[1], base[4], base[5], base[5]});
        compare(pe, make<PointPointQuery>({base[0], base[1], base[4], base[5]}), p, "pe with a = b vs pp");
      }
    }
  }
  rep.expect_clean("degenerate primitives");
  std::cout << "[ info ] " << compared << " comparisons\n";
}

// ---- the API's preconditions and the rational overloads ----------------------------------------

TEST(MinSeparationApi, RejectsInvalidParamsAndMethods) {
  const VertexFaceQuery q{{0, 0, 1}, {-1, -1, 0}, {2, -1, 0}, {-1, 2, 0}, {0, 0, -1}, {-1, -1, 0}, {2, -1, 0}, {-1, 2, 0}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const CcdParams& p : {CcdParams{-1e-300, 1}, CcdParams{nan, 1}, CcdParams{kInf, 1}, CcdParams{0, 0},
                             CcdParams{0, -0.0}, CcdParams{0, std::nextafter(1.0, 2.0)}, CcdParams{0, nan}}) {
    EXPECT_THROW(toi(q, p), std::invalid_argument) << p.min_distance << " " << p.tmax;
    EXPECT_THROW(ccd(q, p), std::invalid_argument) << p.min_distance << " " << p.tmax;
  }
  EXPECT_THROW(toi(q, CcdParams{}, static_cast<Method>(7)), std::invalid_argument);  // no such method
  EXPECT_THROW(point_point_toi(PointPointQuery{{0, 0, 0}, {1, 0, 0}, {0, 0, nan}, {1, 0, 0}}), std::invalid_argument);
  // the smallest tmax and a huge d are valid
  EXPECT_EQ(toi(q, CcdParams{0, std::numeric_limits<double>::denorm_min()}), std::nullopt);
  EXPECT_EQ(toi(q, CcdParams{1e300, 1}), std::optional<TimeInterval>(TimeInterval{0, 0}));
  EXPECT_EQ(toi(q, CcdParams{1, 1}), std::optional<TimeInterval>(TimeInterval{0, 0}));  // dist(0) == 1
  EXPECT_EQ(toi(q, CcdParams{0.5, 1}), std::optional<TimeInterval>(TimeInterval{0.25, 0.25}));
}

template <class Q>
using RationalOf = typename kinds::kind_of<Q>::template Query<mpq_class>;

template <class Q>
RationalOf<Q> rational_query(const Rows<Q>& r) {
  constexpr std::size_t n = 2 * Kind<Q>::nv;
  if constexpr (Kind<Q>::dim == 3) {
    std::array<RationalVec3, n> a;
    for (std::size_t i = 0; i < n; ++i) a[i] = {mpq_class(r[i][0]), mpq_class(r[i][1]), mpq_class(r[i][2])};
    return from_rows<RationalOf<Q>>(a);
  } else {
    std::array<Vec2T<mpq_class>, n> a;
    for (std::size_t i = 0; i < n; ++i) a[i] = {mpq_class(r[i][0]), mpq_class(r[i][1])};
    return from_rows<RationalOf<Q>>(a);
  }
}

TEST(MinSeparationApi, RationalOverloadsAgreeWithDoubles) {
  // 7 kinds x 40 (grid + near) queries x 2 (d, tmax): the rational overloads on the same
  // (double-valued) inputs give the same answers and TOIs.
  std::mt19937_64 rng(1001);
  Report rep;
  std::size_t compared = 0;
  for_each_query_type([&](auto tag) {
    using Q = typename decltype(tag)::type;
    for (const auto& [r, origin] : invariance_sources<Q>(rng, 20)) {
      for (const CcdParams& p : {CcdParams{1e-2 * bbox_size<Q>(r), 1.0}, CcdParams{0.125, 0.375}}) {
        ++compared;
        const RationalCcdParams rp{mpq_class(p.min_distance), mpq_class(p.tmax)};
        const auto a = toi(make<Q>(r), p);
        const auto b = toi(rational_query<Q>(r), rp);
        const bool ca = ccd(make<Q>(r), p), cb = ccd(rational_query<Q>(r), rp);
        if (a.has_value() != b.has_value() || (a && !(*a == *b)) || ca != cb)
          rep.fail(context<Q>(r, p, origin) + "   double API TOI " + fmt(a) + ", rational API " + fmt(b));
      }
    }
  });
  rep.expect_clean("rational overloads");
  std::cout << "[ info ] " << compared << " comparisons\n";
}

}  // namespace
}  // namespace exactccd
