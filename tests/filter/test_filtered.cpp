// Agreement tests of the filtered front end (Method::filtered) against the exact CGAL path
// (Method::exact): same collision answer, identical time of impact, on
//   1. the shared unit-test subset of the public CCD benchmark (and its ground truth),
//   2. perturbations of those queries (ulp shifts of one coordinate, power-of-two scalings and
//      translations),
//   3. fixed-seed random degenerate queries on small dyadic grids,
// plus the stage counters, non-finite input and the floating-point rounding mode.
//
// Every disagreement fails the test and prints the query as a C++ initializer with hex-float
// coordinates (%a), e.g. `VertexFaceQuery{{0x1p+0, ...}, ...}`, ready to paste into a replay.
//
// The CSV files are parsed here with GMP rationals (a small local parser) on purpose: this test
// must not depend on the io library.
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cfenv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"
#include "numeric/fp_environment.hpp"
#include "filter/integer_stage.hpp"
#include "filter/interval_stage.hpp"
#include "separation/separating_plane.hpp"
#include "filter/static_stage.hpp"
#include "filter/toi_narrowing.hpp"
#include "filter/volume_exclusion.hpp"
#include "methods/methods.hpp"

// EXACTCCD_SAMPLE_QUERIES_DIR: the CMake cache variable of that name (tests/CMakeLists.txt).

namespace exactccd {
namespace {

namespace fs = std::filesystem;

constexpr double kInf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------------------
// Queries of either kind, as their eight rows.

enum class Kind { vertex_face, edge_edge };
using Rows = std::array<Vec3, 8>;

struct TestQuery {
  Kind kind = Kind::vertex_face;
  Rows rows{};
  int truth = -1;  ///< published ground truth (0 or 1), -1 when unknown
};

const char* kind_name(Kind k) { return k == Kind::vertex_face ? "vertex-face" : "edge-edge"; }

double& coordinate(Rows& r, int i) {
  Vec3& v = r[static_cast<std::size_t>(i / 3)];
  return i % 3 == 0 ? v.x : (i % 3 == 1 ? v.y : v.z);
}

std::string hex(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

/// The query as a C++ initializer with all 24 coordinates in %a hex-float form.
std::string describe(const TestQuery& q) {
  std::string s = q.kind == Kind::vertex_face ? "VertexFaceQuery{" : "EdgeEdgeQuery{";
  for (std::size_t i = 0; i < q.rows.size(); ++i) {
    const Vec3& v = q.rows[i];
    s += "{" + hex(v.x) + ", " + hex(v.y) + ", " + hex(v.z) + "}";
    if (i + 1 < q.rows.size()) s += ", ";
  }
  return s + "}";
}

std::string describe(const std::optional<TimeInterval>& t) {
  if (!t) return "none";
  return "[" + hex(t->lo) + ", " + hex(t->hi) + "]";
}

std::string describe(const StageCounters& c) {
  return "stages: volume_exclusion " + std::to_string(c.volume_exclusion) + ", static_predicates " +
         std::to_string(c.static_predicates) + ", separating_direction " + std::to_string(c.separating_direction) +
         ", interval " +
         std::to_string(c.interval) + ", fixed_integer " + std::to_string(c.fixed_integer) + ", integer " +
         std::to_string(c.integer) + ", exact " +
         std::to_string(c.exact) + ", toi_refined " + std::to_string(c.toi_refined);
}

bool same_toi(const std::optional<TimeInterval>& a, const std::optional<TimeInterval>& b) {
  if (a.has_value() != b.has_value()) return false;
  return !a || (a->lo == b->lo && a->hi == b->hi);
}

bool tight(const TimeInterval& t) {
  return t.lo == t.hi || std::nextafter(t.lo, kInf) == t.hi;
}

// ---------------------------------------------------------------------------------------------
// Calling the library.

struct Answers {
  bool ccd = false;
  std::optional<TimeInterval> toi;
};

/// f(query) for the test query as its kind's double query (the ccd()/toi() overloads take
/// either kind).
template <class F>
auto with_query(const TestQuery& q, F&& f) {
  if (q.kind == Kind::vertex_face) return f(from_rows<VertexFaceQuery>(q.rows));
  return f(from_rows<EdgeEdgeQuery>(q.rows));
}

/// M: exactccd::Method (the public entry points) or tools::Method (also the baselines); ccd()
/// and toi() are the overloads of M's namespace.
template <class M>
bool call_ccd(const TestQuery& q, M m, StageCounters* counters) {
  return with_query(q, [&](const auto& query) { return counters ? ccd(query, m, *counters) : ccd(query, m); });
}

template <class M>
std::optional<TimeInterval> call_toi(const TestQuery& q, M m, StageCounters* counters) {
  return with_query(q, [&](const auto& query) { return counters ? toi(query, m, *counters) : toi(query, m); });
}

/// Checks that the rounding mode is round-to-nearest; restores it (so one failure does not
/// poison every later computation) and records a problem otherwise.
void check_rounding(const char* after, std::vector<std::string>& problems) {
  if (std::fegetround() == FE_TONEAREST) return;
  problems.push_back(std::string("rounding mode is not FE_TONEAREST after ") + after);
  std::fesetround(FE_TONEAREST);
}

/// Result of one agreement check.
struct Checked {
  bool ok = true;
  Answers exact;  ///< the exact path's answers (valid when ok)
};

/// The core check: filtered and exact agree on the collision and on the TOI; each method's
/// ccd and toi agree with each other; the exact TOI is a tight enclosure in [0, 1]; the ground
/// truth, when known, matches; the rounding mode is restored. On any problem the test fails
/// with the hex-float query. counters, when given, receive the filtered calls.
Checked check_agreement(const TestQuery& q, const std::string& label,
                        StageCounters* counters = nullptr) {
  Checked result;
  std::vector<std::string> problems;
  Answers f, e;
  try {
    f.ccd = call_ccd(q, Method::filtered, counters);
    check_rounding("filtered ccd", problems);
    f.toi = call_toi(q, Method::filtered, counters);
    check_rounding("filtered toi", problems);
    e.ccd = call_ccd(q, Method::exact, nullptr);
    check_rounding("exact ccd", problems);
    e.toi = call_toi(q, Method::exact, nullptr);
    check_rounding("exact toi", problems);
  } catch (const std::exception& ex) {
    std::fesetround(FE_TONEAREST);
    ADD_FAILURE() << label << ": unexpected exception: " << ex.what() << "\n  query: "
                  << describe(q);
    result.ok = false;
    return result;
  }
  if (f.ccd != e.ccd)
    problems.push_back(std::string("ccd disagrees: filtered ") + (f.ccd ? "collides" : "misses") +
                       ", exact " + (e.ccd ? "collides" : "misses"));
  if (!same_toi(f.toi, e.toi))
    problems.push_back("toi disagrees: filtered " + describe(f.toi) + ", exact " +
                       describe(e.toi));
  if (f.ccd != f.toi.has_value())
    problems.push_back("filtered ccd (" + std::to_string(f.ccd) + ") and toi (" +
                       describe(f.toi) + ") disagree");
  if (e.ccd != e.toi.has_value())
    problems.push_back("exact ccd (" + std::to_string(e.ccd) + ") and toi (" + describe(e.toi) +
                       ") disagree");
  if (e.toi) {
    const TimeInterval t = *e.toi;
    if (!(t.lo <= t.hi)) problems.push_back("exact toi " + describe(e.toi) + " has lo > hi");
    if (!tight(t)) problems.push_back("exact toi " + describe(e.toi) + " is not tight");
    if (!(0.0 <= t.lo) || !(t.hi <= 1.0))
      problems.push_back("exact toi " + describe(e.toi) + " is not in [0, 1]");
  }
  if (q.truth >= 0 && (f.ccd != (q.truth == 1) || e.ccd != (q.truth == 1)))
    problems.push_back("ground truth is " + std::to_string(q.truth) + ", filtered " +
                       std::to_string(f.ccd) + ", exact " + std::to_string(e.ccd));
  if (!problems.empty()) {
    std::string msg;
    for (const std::string& p : problems) msg += "\n  " + p;
    ADD_FAILURE() << label << " (" << kind_name(q.kind) << "):" << msg << "\n  query: "
                  << describe(q);
    result.ok = false;
  }
  result.exact = e;
  return result;
}

// ---------------------------------------------------------------------------------------------
// The shared sample queries: a small CSV parser over GMP rationals.

using RationalRows = std::array<RationalVec3, 8>;

struct ParsedQuery {
  RationalRows rows;
  int truth = 0;
};

bool parse_integer(std::string s, mpz_class& out) {
  const auto not_space = [](unsigned char c) { return !std::isspace(c); };
  s.erase(s.begin(), std::find_if(s.begin(), s.end(), not_space));
  s.erase(std::find_if(s.rbegin(), s.rend(), not_space).base(), s.end());
  if (s.empty()) return false;
  const std::size_t first = (s[0] == '-' || s[0] == '+') ? 1 : 0;
  if (first == s.size()) return false;
  for (std::size_t i = first; i < s.size(); ++i)
    if (s[i] < '0' || s[i] > '9') return false;
  if (s[0] == '+') s.erase(0, 1);
  return out.set_str(s, 10) == 0;
}

/// Parses one benchmark CSV (8 rows per query, x_num,x_den,y_num,y_den,z_num,z_den,truth).
/// Returns an error message, empty on success.
std::string parse_csv(const fs::path& path, std::vector<ParsedQuery>& out) {
  std::ifstream in(path);
  if (!in) return "cannot open " + path.string();
  std::string line;
  std::size_t line_number = 0;
  ParsedQuery current;
  int row = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    const std::string where = path.string() + ":" + std::to_string(line_number) + ": ";
    std::vector<std::string> fields;
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = line.find(',', start);
      fields.push_back(line.substr(start, comma == std::string::npos ? comma : comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (fields.size() != 7) return where + "expected 7 fields, got " + std::to_string(fields.size());
    std::array<mpz_class, 7> v;
    for (std::size_t i = 0; i < 7; ++i)
      if (!parse_integer(fields[i], v[i])) return where + "field " + std::to_string(i + 1) + " is not an integer";
    for (std::size_t i = 1; i < 6; i += 2)
      if (v[i] == 0) return where + "zero denominator";
    if (v[6] != 0 && v[6] != 1) return where + "truth must be 0 or 1";
    const int truth = static_cast<int>(v[6].get_si());
    if (row == 0) current.truth = truth;
    if (truth != current.truth) return where + "truth differs within a query";
    RationalVec3& p = current.rows[static_cast<std::size_t>(row)];
    p.x = mpq_class(v[0], v[1]);
    p.y = mpq_class(v[2], v[3]);
    p.z = mpq_class(v[4], v[5]);
    p.x.canonicalize();
    p.y.canonicalize();
    p.z.canonicalize();
    if (++row == 8) {
      out.push_back(current);
      row = 0;
    }
  }
  if (row != 0) return path.string() + ": the number of rows is not a multiple of 8";
  return {};
}

/// x as a double when it is exactly one.
std::optional<double> exact_double(const mpq_class& x) {
  const double d = x.get_d();
  if (!std::isfinite(d) || mpq_class(d) != x) return std::nullopt;
  return d;
}

struct SharedQuery {
  TestQuery query;
  std::string label;  ///< file:index
};

struct SharedData {
  bool available = false;  ///< the data folder exists
  std::string error;       ///< a parse or conversion error (fails the tests that need the data)
  std::vector<SharedQuery> queries;
};

// Query counts of the known files (from the data's README), to catch a parser that drops rows.
const std::map<std::string, std::size_t> kKnownCounts = {
    {"vertex-face/data_0_0.csv", 125},
    {"vertex-face/data_0_1.csv", 125},
    {"edge-edge/data_0_0.csv", 54},
    {"edge-edge/data_0_1.csv", 20},
};

SharedData load_shared_data() {
  SharedData data;
  const fs::path root = fs::path(EXACTCCD_SAMPLE_QUERIES_DIR) / "unit-tests";
  if (!fs::is_directory(root)) return data;
  data.available = true;
  for (const auto& [folder, kind] :
       {std::pair{"vertex-face", Kind::vertex_face}, std::pair{"edge-edge", Kind::edge_edge}}) {
    std::vector<fs::path> files;
    if (fs::is_directory(root / folder))
      for (const auto& entry : fs::directory_iterator(root / folder))
        if (entry.path().extension() == ".csv") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    if (files.empty()) {
      data.error = "no CSV file in " + (root / folder).string();
      return data;
    }
    for (const fs::path& file : files) {
      std::vector<ParsedQuery> parsed;
      data.error = parse_csv(file, parsed);
      if (!data.error.empty()) return data;
      const std::string name = std::string(folder) + "/" + file.filename().string();
      if (const auto known = kKnownCounts.find(name);
          known != kKnownCounts.end() && known->second != parsed.size()) {
        data.error = name + ": " + std::to_string(parsed.size()) + " queries, the README says " +
                     std::to_string(known->second);
        return data;
      }
      for (std::size_t i = 0; i < parsed.size(); ++i) {
        SharedQuery s;
        s.query.kind = kind;
        s.query.truth = parsed[i].truth;
        s.label = name + " query " + std::to_string(i);
        for (std::size_t r = 0; r < 8; ++r) {
          const RationalVec3& p = parsed[i].rows[r];
          const auto x = exact_double(p.x), y = exact_double(p.y), z = exact_double(p.z);
          if (!x || !y || !z) {
            data.error = s.label + ", row " + std::to_string(r) + ": " + p.x.get_str() + " " +
                         p.y.get_str() + " " + p.z.get_str() + " is not exactly a double";
            return data;
          }
          s.query.rows[r] = {*x, *y, *z};
        }
        data.queries.push_back(std::move(s));
      }
    }
  }
  return data;
}

const SharedData& shared_data() {
  static const SharedData data = load_shared_data();
  return data;
}

#define REQUIRE_SHARED_DATA()                                                                  \
  do {                                                                                         \
    if (!shared_data().available)                                                              \
      GTEST_SKIP() << "shared sample queries not found: " << EXACTCCD_SAMPLE_QUERIES_DIR       \
                   << "/unit-tests is absent (configure with -DEXACTCCD_SAMPLE_QUERIES_DIR=...)"; \
    ASSERT_TRUE(shared_data().error.empty()) << shared_data().error;                           \
    ASSERT_FALSE(shared_data().queries.empty());                                               \
  } while (0)

// ---------------------------------------------------------------------------------------------
// 1. The shared unit-test queries.

TEST(FilteredAgreement, SharedQueriesMatchExactAndGroundTruth) {
  REQUIRE_SHARED_DATA();
  std::size_t disagreements = 0, collisions = 0;
  for (const SharedQuery& s : shared_data().queries) {
    const Checked c = check_agreement(s.query, s.label);
    disagreements += !c.ok;
    collisions += c.ok && c.exact.ccd;
  }
  EXPECT_EQ(disagreements, 0u);
  EXPECT_GT(collisions, 0u);
}

// ---------------------------------------------------------------------------------------------
// 2. Perturbations of the shared queries.
//
// Runtime budget (~60 s for the whole file in a Release build on 2 cores; every check makes
// two filtered and two exact calls): the ulp family is a deterministic subset. It shifts
// kUlpCoordinatesPerQuery = 6 coordinates per query, one at a time, cycling through all 24
// coordinate slots across consecutive queries (query i shifts slots (6 i + j) mod 24, j < 6,
// so every 4 consecutive queries cover all 24 slots), by k ulps for every k in -4..4, k != 0:
// 324 x 6 x 8 = 15552 queries, ~6 s in Release (measured). EXACTCCD_STRESS=4 or more shifts
// all 24 slots of every query. The scale and translation families use every query. A shifted
// zero becomes a subnormal (k * 2^-1074), deliberately.

constexpr int kUlpCoordinatesPerQuery = 6;

// Sanitizer builds run about 10 times slower: they check a sixth of the subsets below (the
// Release and -march=native passes of tools/test.sh check all of them).
#if defined(__SANITIZE_ADDRESS__)
constexpr int kSanitizerDivisor = 6;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr int kSanitizerDivisor = 6;
#else
constexpr int kSanitizerDivisor = 1;
#endif
#else
constexpr int kSanitizerDivisor = 1;
#endif

/// The size of a deterministic subset: base times the stress factor from the environment
/// (EXACTCCD_STRESS=n multiplies every subset by n; the default 1 keeps the suite within its
/// time budget), divided by kSanitizerDivisor.
int workload(int base) {
  const char* s = std::getenv("EXACTCCD_STRESS");
  const int stress = std::max(s ? std::atoi(s) : 1, 1);
  return std::max(base * stress / kSanitizerDivisor, 1);
}

double shift_ulps(double x, int k) {
  for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, k > 0 ? kInf : -kInf);
  return x;
}

TEST(FilteredAgreement, UlpShiftsOfOneCoordinate) {
  REQUIRE_SHARED_DATA();
  const auto& queries = shared_data().queries;
  std::size_t checked = 0, disagreements = 0;
  StageCounters stages;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const int per_query = std::min(24, workload(kUlpCoordinatesPerQuery));
    for (int j = 0; j < per_query; ++j) {
      const int slot = static_cast<int>((i * per_query + j) % 24);
      for (int k = -4; k <= 4; ++k) {
        if (k == 0) continue;
        TestQuery q = queries[i].query;
        q.truth = -1;
        double& x = coordinate(q.rows, slot);
        x = shift_ulps(x, k);
        const Checked c = check_agreement(
            q, queries[i].label + ", coordinate " + std::to_string(slot) + " shifted by " +
                   std::to_string(k) + " ulps",
            &stages);
        ++checked;
        disagreements += !c.ok;
      }
    }
  }
  EXPECT_EQ(disagreements, 0u) << "of " << checked << " perturbed queries";
  std::cout << "[ ulps     ] " << checked << " perturbed queries, " << describe(stages) << "\n";
}

TEST(FilteredAgreement, PowerOfTwoScalings) {
  REQUIRE_SHARED_DATA();
  std::size_t disagreements = 0, invariance_checked = 0;
  for (const SharedQuery& s : shared_data().queries) {
    const Checked original = check_agreement(s.query, s.label);
    for (int e : {-600, -30, 30, 600}) {
      TestQuery q = s.query;
      q.truth = -1;
      bool exact_scaling = true;
      for (int i = 0; i < 24; ++i) {
        double& x = coordinate(q.rows, i);
        const double scaled = std::ldexp(x, e);
        exact_scaling = exact_scaling && std::ldexp(scaled, -e) == x;
        x = scaled;
      }
      const Checked c = check_agreement(q, s.label + ", scaled by 2^" + std::to_string(e));
      disagreements += !c.ok;
      // An exact scaling changes neither the collision nor the time of impact.
      if (exact_scaling && original.ok && c.ok) {
        ++invariance_checked;
        EXPECT_EQ(c.exact.ccd, original.exact.ccd) << s.label << " scaled by 2^" << e;
        EXPECT_TRUE(same_toi(c.exact.toi, original.exact.toi))
            << s.label << " scaled by 2^" << e << ": " << describe(c.exact.toi) << " vs "
            << describe(original.exact.toi) << "\n  query: " << describe(q);
      }
    }
  }
  EXPECT_EQ(disagreements, 0u);
  EXPECT_GT(invariance_checked, 0u);
}

TEST(FilteredAgreement, PowerOfTwoTranslations) {
  REQUIRE_SHARED_DATA();
  const auto& queries = shared_data().queries;
  std::size_t disagreements = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    for (int e : {20, 40}) {
      // The offset's signs per axis cycle through the 8 patterns across queries. Adding the
      // offset rounds the coordinates: a different query, still one filtered and exact must
      // agree on.
      const double o = std::ldexp(1.0, e);
      const Vec3 offset{i & 1 ? -o : o, i & 2 ? -o : o, i & 4 ? -o : o};
      TestQuery q = queries[i].query;
      q.truth = -1;
      for (Vec3& v : q.rows) v = {v.x + offset.x, v.y + offset.y, v.z + offset.z};
      const Checked c = check_agreement(q, queries[i].label + ", translated by (" +
                                               hex(offset.x) + ", " + hex(offset.y) + ", " +
                                               hex(offset.z) + ")");
      disagreements += !c.ok;
    }
  }
  EXPECT_EQ(disagreements, 0u);
}

// ---------------------------------------------------------------------------------------------
// 3. Random degenerate queries on small dyadic grids (fixed seed).
//
// 18 families, 250 queries of each kind per family (fewer for the two slow families): 8250
// queries, ~8 s in Release (measured). EXACTCCD_STRESS=n multiplies the counts.

class Generator {
 public:
  explicit Generator(std::uint64_t seed) : rng_(seed) {}

  int integer(int lo, int hi) {  // uniform in [lo, hi]
    return lo + static_cast<int>(rng_() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  bool coin(int percent) { return integer(0, 99) < percent; }
  /// {-2..2} * 2^-3.
  double grid() { return integer(-2, 2) * 0.125; }
  Vec3 grid_point() { return {grid(), grid(), grid()}; }
  Vec3 small_vector() {  // integer vector in {-2..2}^3
    return {double(integer(-2, 2)), double(integer(-2, 2)), double(integer(-2, 2))};
  }

  /// All 24 coordinates on the grid.
  Rows uniform() {
    Rows r;
    for (Vec3& v : r) v = grid_point();
    return r;
  }

  /// Grid query where some rows repeat others (shared vertices, static vertices).
  Rows repeated_vertices() {
    Rows r = uniform();
    const int copies = integer(1, 3);
    for (int i = 0; i < copies; ++i) r[static_cast<std::size_t>(integer(0, 7))] = r[static_cast<std::size_t>(integer(0, 7))];
    for (std::size_t v = 0; v < 4; ++v)
      if (coin(20)) r[v + 4] = r[v];  // a vertex that does not move
    return r;
  }

  /// Nothing moves (t1 rows = t0 rows): points of a plane grid i u + j v + k w (small
  /// integers i, j; k = 0 except with `off_plane`) scaled by a non-dyadic step s (0.1, 0.3 or
  /// 0.7, rounded in doubles, as a mesh on a regular grid has): parallel, collinear and touching
  /// segments, points on edges, degenerate triangles, exactly or only up to rounding.
  Rows static_grid(bool off_plane) {
    static constexpr double kSteps[] = {0.1, 0.3, 0.7};
    const double s = kSteps[integer(0, 2)];
    const Vec3 u = small_vector(), v = small_vector(), w = small_vector();
    Rows r;
    for (std::size_t k = 0; k < 4; ++k) {
      const double i = integer(-2, 2), j = integer(-2, 2), h = off_plane && coin(30) ? integer(-1, 1) : 0;
      r[k] = {(i * u.x + j * v.x + h * w.x) * s, (i * u.y + j * v.y + h * w.y) * s,
              (i * u.z + j * v.z + h * w.z) * s};
    }
    if (coin(30)) r[static_cast<std::size_t>(integer(0, 3))] = r[static_cast<std::size_t>(integer(0, 3))];
    for (std::size_t k = 0; k < 4; ++k) r[k + 4] = r[k];
    return r;
  }

  /// Three of the four points share one coordinate at both times (on a grid line of a flat or
  /// folding sheet): p, a, b (vertex-face) or a1, b0, b1 (edge-edge); the others are random
  /// doubles with full significands. Then V = (linear factor) x (the cross product component
  /// of "p on edge ab" / "a1 on edge b"), and p / a1 crosses the line of the segment at an
  /// irrational time, where it is exactly on that line; about half of those are contacts.
  Rows shared_coordinate(Kind kind) {
    const auto coordinate = [this] { return std::ldexp(static_cast<double>(rng_() >> 11), -53) * 2 - 1; };
    Rows r;
    for (Vec3& v : r) v = {coordinate(), coordinate(), coordinate()};
    const int axis = integer(0, 2);
    const double shared = coordinate();
    const std::array<std::size_t, 3> on_plane =
        kind == Kind::vertex_face ? std::array<std::size_t, 3>{0, 1, 2} : std::array<std::size_t, 3>{1, 2, 3};
    for (std::size_t i : on_plane)
      for (std::size_t t : {i, i + 4}) (axis == 0 ? r[t].x : axis == 1 ? r[t].y : r[t].z) = shared;
    return r;
  }

  /// At t = 0 or t = 1 (random), three of the four points lie on one axis-parallel line (two
  /// shared coordinates): p, b, c (vertex-face) or a1, b0, b1 (edge-edge), so V is exactly zero
  /// at that end, but not computed exactly (full-significand doubles). The point is between the
  /// other two along the line (contact at that end) about a third of the time.
  Rows collinear_at_an_end(Kind kind) {
    const auto coordinate = [this] { return std::ldexp(static_cast<double>(rng_() >> 11), -53) * 2 - 1; };
    Rows r;
    for (Vec3& v : r) v = {coordinate(), coordinate(), coordinate()};
    const std::size_t offset = coin(50) ? 0 : 4;
    const int free_axis = integer(0, 2);
    const double s = coordinate(), t = coordinate();
    const std::array<std::size_t, 3> on_line =
        kind == Kind::vertex_face ? std::array<std::size_t, 3>{0, 2, 3} : std::array<std::size_t, 3>{1, 2, 3};
    for (std::size_t i : on_line) {
      Vec3& v = r[i + offset];
      if (free_axis == 0) v.y = s, v.z = t;
      if (free_axis == 1) v.x = s, v.z = t;
      if (free_axis == 2) v.x = s, v.y = t;
    }
    return r;
  }

  /// All eight points at one height: coplanar for every t.
  Rows same_z() {
    Rows r = uniform();
    const double z = grid();
    for (Vec3& v : r) v.z = z;
    return r;
  }

  /// Points o + (i u + j v) / 8 with small integers: all in one plane (or on a line, when u
  /// and v are parallel). With `two_planes` the t = 1 points use a second plane, so the four
  /// points are coplanar at t = 0 and t = 1 but usually not in between.
  Rows in_plane(bool two_planes) {
    Rows r;
    Vec3 o = grid_point(), u = small_vector(), v = small_vector();
    for (std::size_t k = 0; k < 8; ++k) {
      if (two_planes && k == 4) o = grid_point(), u = small_vector(), v = small_vector();
      const double i = integer(-2, 2), j = integer(-2, 2);
      r[k] = {o.x + (i * u.x + j * v.x) / 8, o.y + (i * u.y + j * v.y) / 8,
              o.z + (i * u.z + j * v.z) / 8};
    }
    return r;
  }

  /// Parallel or collinear edges (edge-edge), or a collinear triangle and a point on or off its
  /// line (vertex-face), at t = 0 and t = 1 independently. Rows 0-3 at t0, 4-7 at t1.
  Rows parallel_or_collinear(Kind kind) {
    Rows r;
    for (std::size_t base : {std::size_t{0}, std::size_t{4}}) {
      const Vec3 a = grid_point(), d = small_vector();
      const auto along = [&](double s) {
        return Vec3{a.x + s * d.x / 8, a.y + s * d.y / 8, a.z + s * d.z / 8};
      };
      const auto param = [&] { return integer(-4, 4) * 0.5; };
      if (kind == Kind::edge_edge) {
        r[base] = a;
        r[base + 1] = along(param());
        if (coin(50)) {  // collinear
          r[base + 2] = along(param());
          r[base + 3] = along(param());
        } else {  // parallel: b1 - b0 a multiple of a1 - a0
          const Vec3 b = grid_point();
          const double s = param();
          r[base + 2] = b;
          r[base + 3] = {b.x + s * d.x / 8, b.y + s * d.y / 8, b.z + s * d.z / 8};
        }
      } else {
        // p, a, b, c: a, b, c on one line; p on it or anywhere.
        r[base] = coin(50) ? along(param()) : grid_point();
        r[base + 1] = along(param());
        r[base + 2] = along(param());
        r[base + 3] = along(param());
      }
    }
    return r;
  }

  /// A random double in (0, 1]: a random 53-bit significand and a random binary exponent
  /// (down to the subnormals).
  double random_time() {
    const double m = static_cast<double>((rng_() >> 11) | 1);  // odd, below 2^53
    return std::ldexp(m, integer(-1074, -53));
  }

  /// A collision time set to order: a static triangle in the plane z = 0 (vertex-face) or a
  /// static edge in it (edge-edge), and a point (an edge) moving from z = -u to z = w, so that
  /// the volume is linear with its root at u / (u + w). u is a random double, possibly tiny;
  /// w = 1 - u (exact root u when the subtraction is exact), or a random double, or u itself
  /// (root 1/2). The in-plane position is on a small grid, inside, on the boundary or outside.
  Rows crossing(Kind kind) {
    const double u = random_time();
    const int choice = integer(0, 2);
    const double w = choice == 0 ? 1 - u : (choice == 1 ? 2 * random_time() : u);
    const double s = integer(-1, 5) * 0.25, r = integer(-1, 5) * 0.25;
    Rows rows;
    if (kind == Kind::vertex_face) {
      rows = {Vec3{s, r, -u}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
              Vec3{s, r, w},  {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    } else {
      rows = {Vec3{-1, s - 1, -u}, {1, s - 1, -u}, {r - 1, -1, 0}, {r - 1, 1, 0},
              Vec3{-1, s - 1, w},  {1, s - 1, w},  {r - 1, -1, 0}, {r - 1, 1, 0}};
    }
    if (coin(50)) std::swap(rows[0].z, rows[4].z);  // cross the other way
    return rows;
  }

  /// A random double in [-1, 1] with a full 53-bit significand.
  double unit() { return std::ldexp(static_cast<double>(rng_() >> 11), -52) - 1; }

  /// All eight points rounded onto one random plane z = alpha x + beta y + gamma (full-precision
  /// doubles): the rounding leaves the volume tiny, of any sign, and its roots anywhere, the
  /// classic stress test of a floating-point orientation filter. Vertex-face: p is a random
  /// convex combination of the triangle's vertices (inside, or slightly outside) at each time;
  /// edge-edge: the edges cross in the plane at each time.
  Rows nearly_coplanar(Kind kind) {
    const double alpha = unit(), beta = unit(), gamma = unit();
    const auto on_plane = [&](double x, double y) { return Vec3{x, y, alpha * x + beta * y + gamma}; };
    Rows r;
    for (std::size_t base : {std::size_t{0}, std::size_t{4}}) {
      const Vec3 a = on_plane(unit(), unit()), b = on_plane(unit(), unit()),
                 c = on_plane(unit(), unit());
      double l1 = std::fabs(unit()), l2 = std::fabs(unit());
      if (coin(70) && l1 + l2 > 1) l1 = 1 - l1, l2 = 1 - l2;  // inside, mostly
      const auto mix = [&](const Vec3& u, const Vec3& v, const Vec3& w) {
        return on_plane(u.x + l1 * (v.x - u.x) + l2 * (w.x - u.x),
                        u.y + l1 * (v.y - u.y) + l2 * (w.y - u.y));
      };
      if (kind == Kind::vertex_face) {
        r[base] = mix(a, b, c);
        r[base + 1] = a, r[base + 2] = b, r[base + 3] = c;
      } else {
        // Edge (a, b) and an edge through a point of (a, b) towards c and beyond.
        const Vec3 m = on_plane(a.x + l1 * (b.x - a.x), a.y + l1 * (b.y - a.y));
        r[base] = a, r[base + 1] = b, r[base + 2] = c;
        r[base + 3] = on_plane(2 * m.x - c.x, 2 * m.y - c.y);
      }
    }
    return r;
  }

  /// Coordinates drawn from a set of extreme magnitudes (subnormal, smallest normal, huge,
  /// DBL_MAX): differences and products overflow or underflow in every double stage.
  Rows extreme() {
    static const double values[] = {0.0,
                                    std::numeric_limits<double>::denorm_min(),
                                    std::numeric_limits<double>::min(),
                                    0x1p-537,
                                    1.0,
                                    0x1p+511,
                                    0x1p+1023,
                                    std::numeric_limits<double>::max()};
    Rows r;
    const int n = integer(2, 8);  // a few distinct values: repeats make degeneracies likely
    for (int i = 0; i < 24; ++i) {
      const double v = values[integer(0, n - 1)];
      coordinate(r, i) = coin(50) ? v : -v;
    }
    return r;
  }

  /// One of the families above, then 1 to 3 coordinates nudged by a few ulps.
  Rows nudged(Kind kind) {
    Rows r = base_family(kind, integer(0, kBaseFamilies - 1));
    const int n = integer(1, 3);
    for (int i = 0; i < n; ++i) {
      double& x = coordinate(r, integer(0, 23));
      const int k = integer(-4, 4);
      for (int s = 0; s < std::abs(k); ++s) x = std::nextafter(x, k > 0 ? kInf : -kInf);
    }
    return r;
  }

  /// Coplanar for every t (all z equal) with 1 to 4 x or y coordinates nudged by a few ulps:
  /// the volume stays identically zero while the in-plane polynomials get nearly double or
  /// nearly coincident roots.
  Rows coplanar_nudged(Kind kind) {
    Rows r = coin(50) ? same_z() : parallel_or_collinear(kind);
    if (r[0].z != r[1].z) {  // parallel_or_collinear is not flat: flatten it
      const double z = grid();
      for (Vec3& v : r) v.z = z;
    }
    const int n = integer(1, 4);
    for (int i = 0; i < n; ++i) {
      Vec3& v = r[static_cast<std::size_t>(integer(0, 7))];
      double& x = coin(50) ? v.x : v.y;
      const int k = integer(-4, 4);
      for (int s = 0; s < std::abs(k); ++s) x = std::nextafter(x, k > 0 ? kInf : -kInf);
    }
    return r;
  }

  /// One of the families above scaled by 2^e, e in [-1071, 1021]: the values stay finite (the
  /// smallest may round to subnormals or zero), differences and products underflow or overflow.
  Rows scaled(Kind kind) {
    Rows r = base_family(kind, integer(0, kBaseFamilies - 1));
    const int e = integer(-1071, 1021);
    for (int i = 0; i < 24; ++i) coordinate(r, i) = std::ldexp(coordinate(r, i), e);
    return r;
  }

  /// One of the families above translated by a random power of two per axis (2^0..2^60, either
  /// sign): the sum rounds, so the motion is no longer on the grid.
  Rows translated(Kind kind) {
    Rows r = base_family(kind, integer(0, kBaseFamilies - 1));
    double offset[3];
    for (double& o : offset) o = std::ldexp(coin(50) ? 1.0 : -1.0, integer(0, 60));
    for (int i = 0; i < 24; ++i) coordinate(r, i) += offset[i % 3];
    return r;
  }

  Rows base_family(Kind kind, int family) {
    switch (family) {
      case 0: return uniform();
      case 1: return repeated_vertices();
      case 2: return same_z();
      case 3: return in_plane(false);
      case 4: return in_plane(true);
      case 5: return parallel_or_collinear(kind);
      case 6: return crossing(kind);
      default: return nearly_coplanar(kind);
    }
  }

  static constexpr int kBaseFamilies = 8;

 private:
  std::mt19937_64 rng_;
};

struct Family {
  const char* name;
  std::function<Rows(Generator&, Kind)> make;
  int per_kind = 250;  ///< queries of each kind (times the stress factor)
};

TEST(FilteredAgreement, RandomDegenerateGridQueries) {
  const std::vector<Family> families = {
      {"uniform grid", [](Generator& g, Kind) { return g.uniform(); }},
      {"repeated vertices", [](Generator& g, Kind) { return g.repeated_vertices(); }},
      {"all z equal", [](Generator& g, Kind) { return g.same_z(); }},
      {"static, one plane, non-dyadic grid step", [](Generator& g, Kind) { return g.static_grid(false); }},
      {"static, non-dyadic grid step", [](Generator& g, Kind) { return g.static_grid(true); }},
      {"three points sharing one coordinate", [](Generator& g, Kind k) { return g.shared_coordinate(k); }},
      {"three points on an axis-parallel line at t0 or t1",
       [](Generator& g, Kind k) { return g.collinear_at_an_end(k); }},
      {"one plane", [](Generator& g, Kind) { return g.in_plane(false); }},
      {"plane at t0, plane at t1", [](Generator& g, Kind) { return g.in_plane(true); }},
      {"parallel or collinear", [](Generator& g, Kind k) { return g.parallel_or_collinear(k); }},
      {"crossing at a random time", [](Generator& g, Kind k) { return g.crossing(k); }},
      {"nearly coplanar", [](Generator& g, Kind k) { return g.nearly_coplanar(k); }},
      {"nearly coplanar, scaled by 2^[-400, 300]",
       [](Generator& g, Kind k) {
         Rows r = g.nearly_coplanar(k);
         const int e = g.integer(-400, 300);
         for (int i = 0; i < 24; ++i) coordinate(r, i) = std::ldexp(coordinate(r, i), e);
         return r;
       }},
      // Huge exponent ranges make integers of thousands of bits: ~10-50 ms per query on the
      // exact path, hence fewer of them.
      {"extreme magnitudes", [](Generator& g, Kind) { return g.extreme(); }, 25},
      {"nudged by ulps", [](Generator& g, Kind k) { return g.nudged(k); }},
      // Subnormal nudges of zeros make ~1100-bit integers: ~2-3 ms per query, hence fewer.
      {"all z equal, x or y nudged by ulps",
       [](Generator& g, Kind k) { return g.coplanar_nudged(k); }, 100},
      {"scaled by 2^e", [](Generator& g, Kind k) { return g.scaled(k); }},
      {"translated by 2^e", [](Generator& g, Kind k) { return g.translated(k); }},
  };
  Generator gen(0x5eed'ccd0'2024'0001ULL);
  std::size_t checked = 0, disagreements = 0, collisions = 0, naive_wrong = 0;
  for (const Family& family : families) {
    const int per_kind = workload(family.per_kind);
    std::size_t family_collisions = 0, family_naive_wrong = 0;
    StageCounters stages;
    const auto start = std::chrono::steady_clock::now();
    for (Kind kind : {Kind::vertex_face, Kind::edge_edge}) {
      for (int i = 0; i < per_kind; ++i) {
        TestQuery q;
        q.kind = kind;
        q.rows = family.make(gen, kind);
        const Checked c = check_agreement(
            q, std::string("random ") + family.name + " #" + std::to_string(i), &stages);
        ++checked;
        disagreements += !c.ok;
        if (!c.ok) continue;
        family_collisions += c.exact.ccd;
        bool naive = false;
        try {
          naive = call_ccd(q, tools::Method::naive, nullptr);
        } catch (const std::exception& ex) {
          ADD_FAILURE() << "naive threw " << ex.what() << " on " << describe(q);
        }
        family_naive_wrong += naive != c.exact.ccd;
      }
    }
    std::cout << "[ random   ] " << family.name << ": " << family_collisions << " of "
              << 2 * per_kind << " collide, naive wrong on " << family_naive_wrong << "; "
              << describe(stages) << " ("
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
              << " s)\n";
    collisions += family_collisions;
    naive_wrong += family_naive_wrong;
  }
  EXPECT_EQ(disagreements, 0u) << "of " << checked << " random queries";
  // The families must exercise both answers.
  EXPECT_GT(collisions, checked / 20);
  EXPECT_LT(collisions, checked - checked / 20);
  // Why the filters exist: the textbook double-precision method fails on these inputs. The
  // count depends on the seed (fixed) and on libm; it is documentation, not a specification.
  std::cout << "[ random   ] naive (non-robust) method wrong on " << naive_wrong << " of "
            << checked << " random queries\n";
  RecordProperty("naive_wrong", static_cast<int>(naive_wrong));
  EXPECT_GT(naive_wrong, 0u);
}

// ---------------------------------------------------------------------------------------------
// 4. Stage counters.

TEST(FilteredStageCounters, EveryFilteredCallIsCountedOnce) {
  REQUIRE_SHARED_DATA();
  StageCounters ccd_counters, toi_counters;
  std::size_t ccd_calls = 0, toi_calls = 0;
  for (const SharedQuery& s : shared_data().queries) {
    const StageCounters before_ccd = ccd_counters;
    call_ccd(s.query, Method::filtered, &ccd_counters);
    ++ccd_calls;
    EXPECT_EQ(ccd_counters.total(), before_ccd.total() + 1) << s.label;
    EXPECT_EQ(ccd_counters.toi_refined, 0u) << s.label << ": a ccd call has no TOI to refine";

    const StageCounters before_toi = toi_counters;
    call_toi(s.query, Method::filtered, &toi_counters);
    ++toi_calls;
    EXPECT_EQ(toi_counters.total(), before_toi.total() + 1) << s.label;
    if (toi_counters.toi_refined != before_toi.toi_refined) {
      EXPECT_EQ(toi_counters.toi_refined, before_toi.toi_refined + 1) << s.label;
      EXPECT_EQ(toi_counters.interval, before_toi.interval + 1)
          << s.label << ": toi_refined counts answers of the interval stage";
    }
  }
  EXPECT_EQ(ccd_counters.total(), ccd_calls);
  EXPECT_EQ(toi_counters.total(), toi_calls);
  EXPECT_GT(ccd_counters.volume_exclusion, 0u);
  EXPECT_GT(toi_counters.volume_exclusion, 0u);

  // Counters are additive: one counter over both kinds of call.
  StageCounters sum = ccd_counters;
  sum += toi_counters;
  EXPECT_EQ(sum.total(), ccd_calls + toi_calls);

  std::cout << "[ stages   ] shared data, ccd calls, " << describe(ccd_counters) << "\n"
            << "[ stages   ] shared data, toi calls, " << describe(toi_counters) << "\n";
}

TEST(FilteredStageCounters, StaticQueriesAreDecidedByTheStaticPredicates) {
  // Every static query that passes the volume filter is decided by the static stage, with the
  // exact answer and the TOI [0, 0] for a contact (it holds at every t).
  Generator gen(0x5eed'ccd0'2026'1130ULL);
  std::size_t collisions = 0, static_decided = 0;
  for (Kind kind : {Kind::vertex_face, Kind::edge_edge}) {
    for (int i = 0; i < 400; ++i) {
      TestQuery q;
      q.kind = kind;
      q.rows = gen.static_grid(i % 2 == 1);
      StageCounters c;
      const std::optional<TimeInterval> toi = call_toi(q, Method::filtered, &c);
      const std::optional<TimeInterval> exact = call_toi(q, Method::exact, nullptr);
      EXPECT_TRUE(same_toi(toi, exact)) << describe(q) << "\nfiltered " << describe(toi) << ", exact "
                                        << describe(exact) << ", " << describe(c);
      EXPECT_EQ(c.total(), 1u);
      EXPECT_EQ(c.static_predicates + c.volume_exclusion, 1u) << describe(q) << ": " << describe(c);
      if (toi) {
        EXPECT_TRUE(toi->lo == 0 && toi->hi == 0) << describe(q);
      }
      collisions += toi.has_value();
      static_decided += c.static_predicates;
    }
  }
  EXPECT_GT(collisions, 80u);    // both answers occur often (measured: see the output)
  EXPECT_LT(collisions, 720u);
  EXPECT_GT(static_decided, 400u);
  std::cout << "[ static   ] " << collisions << " of 800 static queries collide, " << static_decided
            << " decided by the static stage\n";
}

// ---------------------------------------------------------------------------------------------
// 5. Non-finite input and the rounding mode.

TestQuery simple_query(Kind kind) {
  // A collision at t = 1/2: the point (or the edge) crosses the plane z = 0 at that time.
  TestQuery q;
  q.kind = kind;
  if (kind == Kind::vertex_face)
    q.rows = {Vec3{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
              Vec3{0.25, 0.25, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  else
    q.rows = {Vec3{-1, 0, 1}, {1, 0, 1}, {0, -1, 0}, {0, 1, 0},
              Vec3{-1, 0, -1}, {1, 0, -1}, {0, -1, 0}, {0, 1, 0}};
  return q;
}

TEST(FilteredInput, SimpleQueriesCollideAtOneHalf) {
  for (Kind kind : {Kind::vertex_face, Kind::edge_edge}) {
    const TestQuery q = simple_query(kind);
    const Checked c = check_agreement(q, std::string("simple ") + kind_name(kind));
    ASSERT_TRUE(c.ok);
    EXPECT_TRUE(c.exact.ccd);
    EXPECT_TRUE(same_toi(c.exact.toi, TimeInterval{0.5, 0.5})) << describe(c.exact.toi);
  }
}

/// A vertex-face query: the triangle (0,0,0), (1,0,0), (0,1,0) at rest and the point (1/4, 1/4)
/// moving from height z0 to height z1.
TestQuery crossing_at(double z0, double z1) {
  TestQuery q = simple_query(Kind::vertex_face);
  q.rows[0].z = z0;
  q.rows[4].z = z1;
  return q;
}

TEST(FilteredInput, KnownTimesOfImpactAreTightEnclosures) {
  constexpr double kThird = 1.0 / 3;  // rounds down: 1/3 = 0x1.5555...p-2
  const struct {
    const char* name;
    TestQuery query;
    std::optional<TimeInterval> toi;
  } cases[] = {
      {"crossing at 1/3 (not a double)", crossing_at(1, -2),
       TimeInterval{kThird, std::nextafter(kThird, kInf)}},
      {"touching at t = 0", crossing_at(0, 1), TimeInterval{0, 0}},
      {"touching at t = 1", crossing_at(1, 0), TimeInterval{1, 1}},
      {"never reaching the plane", crossing_at(1, 0x1p-1074), std::nullopt},
      // Root 2^-1074 / (1 + 2^-1074): just below the smallest subnormal.
      {"crossing before 2^-1074", crossing_at(-0x1p-1074, 1), TimeInterval{0, 0x1p-1074}},
      // Root 1 / (1 + 2^-60): between the last double below 1 and 1.
      {"crossing just before 1", crossing_at(-1, 0x1p-60),
       TimeInterval{std::nextafter(1.0, 0.0), 1}},
      // Every point at the origin: a degenerate triangle (a point) holding p from t = 0.
      {"all points equal", TestQuery{Kind::vertex_face, Rows{}, -1}, TimeInterval{0, 0}},
      {"all endpoints equal", TestQuery{Kind::edge_edge, Rows{}, -1}, TimeInterval{0, 0}},
  };
  for (const auto& c : cases) {
    const Checked checked = check_agreement(c.query, c.name);
    if (!checked.ok) continue;
    EXPECT_TRUE(same_toi(checked.exact.toi, c.toi))
        << c.name << ": exact toi " << describe(checked.exact.toi) << ", expected "
        << describe(c.toi) << "\n  query: " << describe(c.query);
  }
}

TEST(FilteredInput, NonFiniteCoordinatesThrowInvalidArgumentForEveryMethod) {
  const double bad_values[] = {std::numeric_limits<double>::quiet_NaN(), kInf, -kInf};
  std::size_t calls = 0;
  for (Kind kind : {Kind::vertex_face, Kind::edge_edge}) {
    for (int slot = 0; slot < 24; ++slot) {
      for (double bad : bad_values) {
        TestQuery q = simple_query(kind);
        coordinate(q.rows, slot) = bad;
        for (tools::Method m : {tools::Method::filtered, tools::Method::exact, tools::Method::naive}) {
          const std::string what = std::string(kind_name(kind)) + ", method " +
                                   std::to_string(static_cast<int>(m)) + ", coordinate " +
                                   std::to_string(slot) + " = " + hex(bad);
          StageCounters counters;
          EXPECT_THROW(call_ccd(q, m, nullptr), std::invalid_argument) << "ccd, " << what;
          EXPECT_THROW(call_ccd(q, m, &counters), std::invalid_argument) << "ccd, " << what;
          EXPECT_THROW(call_toi(q, m, nullptr), std::invalid_argument) << "toi, " << what;
          EXPECT_THROW(call_toi(q, m, &counters), std::invalid_argument) << "toi, " << what;
          calls += 4;
          EXPECT_EQ(counters.total(), 0u) << "a rejected query was counted: " << what;
          EXPECT_EQ(counters.toi_refined, 0u) << what;
          ASSERT_EQ(std::fegetround(), FE_TONEAREST) << "after the throwing calls, " << what;
        }
      }
    }
  }
  EXPECT_EQ(calls, 2u * 24 * 3 * 3 * 4);
}

/// The shared queries when they are available (these tests also run without them).
std::vector<TestQuery> shared_or_no_queries() {
  std::vector<TestQuery> queries;
  if (shared_data().available && shared_data().error.empty())
    for (const SharedQuery& s : shared_data().queries) queries.push_back(s.query);
  return queries;
}

TEST(FilteredInput, ConcurrentCallsGiveTheSequentialAnswers) {
  // The API promises thread safety (no shared mutable state) and a per-thread rounding mode:
  // two threads answer the same queries with both exact methods, against a sequential run.
  std::vector<TestQuery> queries = shared_or_no_queries();
  Generator gen(7);
  for (int i = 0; i < 200; ++i) {
    const Kind kind = i % 2 ? Kind::edge_edge : Kind::vertex_face;
    queries.push_back(TestQuery{kind, gen.base_family(kind, i % Generator::kBaseFamilies), -1});
  }
  const Method methods[] = {Method::filtered, Method::exact};
  std::vector<std::array<std::optional<TimeInterval>, 2>> expected(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i)
    for (std::size_t m = 0; m < 2; ++m) expected[i][m] = call_toi(queries[i], methods[m], nullptr);

  std::array<std::size_t, 2> mismatches{}, rounding_errors{};
  std::array<std::string, 2> first_mismatch;
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < 2; ++t) {
    threads.emplace_back([&, t] {
      for (std::size_t k = 0; k < queries.size(); ++k) {
        const std::size_t i = t == 0 ? k : queries.size() - 1 - k;  // opposite orders
        for (std::size_t m = 0; m < 2; ++m) {
          if (!same_toi(call_toi(queries[i], methods[m], nullptr), expected[i][m]) &&
              mismatches[t]++ == 0)
            first_mismatch[t] = "method " + std::to_string(m) + ": " + describe(queries[i]);
          if (std::fegetround() != FE_TONEAREST) ++rounding_errors[t];
        }
      }
    });
  }
  for (std::thread& th : threads) th.join();
  for (std::size_t t = 0; t < 2; ++t) {
    EXPECT_EQ(mismatches[t], 0u) << "thread " << t << ", first: " << first_mismatch[t];
    EXPECT_EQ(rounding_errors[t], 0u) << "thread " << t;
  }
}

/// Runs every stage of the filtered method on q directly (each one that applies), checking after
/// each that the thread's whole floating-point control state (rounding mode of SSE and x87,
/// FTZ/DAZ, exception masks) is the default again. Returns how many stage calls it made.
int run_each_stage_checking_environment(const TestQuery& q) {
  int calls = 0;
  const auto check = [&](const char* stage) {
    ++calls;
    EXPECT_TRUE(numeric::is_default_fp_environment()) << stage << " changed the environment: " << describe(q);
  };
  const auto stages = [&](const auto& query) {
    (void)filter::volume_excluded(from_rows<VertexFaceQuery>(q.rows));
    (void)filter::volume_excluded(from_rows<EdgeEdgeQuery>(q.rows));
    check("volume exclusion");
    (void)filter::contact_at_end(query, 0);
    (void)filter::volume_sign_at_end(query, 1);
    check("static predicates");
    (void)separation::separated_by_plane(query);
    check("separating plane");
    filter::RootCells findings;
    if (q.kind == Kind::vertex_face)
      (void)filter::interval_stage(from_rows<VertexFaceQuery>(q.rows), true, findings);
    else
      (void)filter::interval_stage(from_rows<EdgeEdgeQuery>(q.rows), true, findings);
    check("interval stage");
    if (findings.toi_cell) {
      (void)filter::toi_in_cell(query, *findings.toi_cell);
      check("toi_in_cell (double-double and GMP signs)");
    }
    if (q.kind == Kind::vertex_face)
      (void)filter::fixed_integer_stage(from_rows<VertexFaceQuery>(q.rows), true);
    else
      (void)filter::fixed_integer_stage(from_rows<EdgeEdgeQuery>(q.rows), true);
    check("fixed-width integer stage");
    if (q.kind == Kind::vertex_face)
      (void)filter::integer_stage(from_rows<VertexFaceQuery>(q.rows), true);
    else
      (void)filter::integer_stage(from_rows<EdgeEdgeQuery>(q.rows), true);
    check("integer stage");
  };
  if (q.kind == Kind::vertex_face)
    stages(from_rows<VertexFaceQuery>(q.rows));
  else
    stages(from_rows<EdgeEdgeQuery>(q.rows));
  return calls;
}

TEST(FilteredInput, RoundingModeIsRoundToNearestAfterEveryStage) {
  // Every stage switches the rounding mode (interval arithmetic rounds upwards; CGAL's static
  // predicates need to-nearest inside that) and must restore the whole control state, on every
  // path. The queries are chosen so that, together, they reach every stage of the filtered
  // method through the public API (asserted with the counters below, every counter), and each
  // stage is also run directly on each of them, with the state checked after each stage.
  ASSERT_TRUE(numeric::is_default_fp_environment());
  StageCounters counters;
  std::vector<TestQuery> queries = shared_or_no_queries();
  for (Kind kind : {Kind::vertex_face, Kind::edge_edge}) queries.push_back(simple_query(kind));
  Generator gen(11);
  for (int i = 0; i < 100; ++i) {
    const Kind kind = i % 2 ? Kind::edge_edge : Kind::vertex_face;
    queries.push_back(TestQuery{kind, gen.base_family(kind, i % Generator::kBaseFamilies), -1});
  }
  // An edge-edge candidate of the folding-sheet scene (data/sim): its endpoint meets the other
  // edge at an irrational time, where a parameter polynomial vanishes exactly (the edges lie on
  // the grid's boundary row y = -1/2): only the integer stage can certify that zero.
  queries.push_back(TestQuery{
      Kind::edge_edge,
      {Vec3{-0x1.5555555555558p-4, -0x1p-1, 0x1.bc758523fa9acp-10},
       Vec3{-0x1.555555555555p-5, -0x1p-1, 0x1.055095fc95602p-10},
       Vec3{-0x1.543ddcb6e394fp-4, -0x1p-1, 0x1.13a69d7d82f45p-6},
       Vec3{-0x1.fe5ccb12555fep-4, -0x1.d555555555555p-2, 0x1.2da1a486ff0a7p-6},
       Vec3{-0x1.57480aaeb4277p-4, -0x1p-1, 0x1.23ad17bed7afep-9},
       Vec3{-0x1.532c9d7804aap-5, -0x1p-1, 0x1.024b53e622b6cp-9},
       Vec3{-0x1.552e03c239349p-4, -0x1p-1, 0x1.6bca68bce12dp-11},
       Vec3{-0x1.ffc505a355cf6p-4, -0x1.d555555555555p-2, -0x1.ce8767762e64p-11}},
      1});
  // A static pair (nothing moves: CGAL's static predicates decide).
  queries.push_back(TestQuery{Kind::vertex_face,
                              {Vec3{0.25, 0.25, 0}, Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0},
                               Vec3{0.25, 0.25, 0}, Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}},
                              1});
  // A degenerate grid query scaled per axis by 2^383, 2^-697 and 1 (an exact affine map): its
  // roots are separated by less than 2^-192, past the integer stage's refinement limit, so the
  // CGAL path decides it.
  queries.push_back(TestQuery{Kind::vertex_face,
                              {Vec3{-0x1p+383, -0x1p-697, 0}, Vec3{0x1p+383, -0x1p-697, 0}, Vec3{0x1p+384, 0x1p-697, 0},
                               Vec3{-0x1p+384, 0, 0}, Vec3{0x1p+384, 0x1p-697, 0}, Vec3{0, 0x1p-696, 0},
                               Vec3{-0x1p+383, 0x1p-696, 0}, Vec3{-0x1p+384, 0x1p-696, 0}},
                              -1});
  // An edge pair of the helical strip (data/sim/sim-strip-edge-edge.csv, query 171: left open
  // by the interval stage, and no plane separates it at both ends) with its x axis scaled by
  // 2^-200 (exact; a per-axis power-of-two scale keeps the answer): exponent spread beyond the
  // fixed-width integer stage's limit (integer_stage.hpp), so the GMP integer stage decides it.
  // (Query 195, used before, is now decided by the separating-plane stage.)
  queries.push_back(TestQuery{
      Kind::edge_edge,
      {Vec3{0x1.1c2cabad55f30p-202, 0x1.a94c1465084bep-2, 0x1.31ef61aa134cbp-2},
       Vec3{0x1.889e1abf495f9p-203, 0x1.d9ee6dbf18a58p-2, 0x1.3545f4ab98681p-2},
       Vec3{0x1.879e2fa420548p-203, 0x1.d8b98204838e7p-2, 0x1.115fef04d5e64p-2},
       Vec3{0x1.871e3a168bcf2p-203, 0x1.d81f0c273902ep-2, 0x1.30eb15ebe7ddbp-2},
       Vec3{0x1.1b9b0fe2bef6cp-202, 0x1.a872293b01761p-2, 0x1.19c7d93080007p-2},
       Vec3{0x1.87d57ad8557aap-203, 0x1.d8fc40dc3c226p-2, 0x1.1793b1cfe7779p-2},
       Vec3{0x1.87e10f9bc6f62p-203, 0x1.d90a3ba577ba1p-2, 0x1.02a5161065b01p-2},
       Vec3{0x1.87e6d9fd7fb40p-203, 0x1.d911390a1585fp-2, 0x1.1ccb163171187p-2}},
      0});
  // A generic hit whose TOI the interval stage hands over as a cell (toi_refined).
  queries.push_back(TestQuery{Kind::vertex_face,
                              {Vec3{0.3, 0.2, 1.0}, Vec3{0.0, 0.0, 0.0}, Vec3{1.0, 0.1, 0.0}, Vec3{0.1, 1.0, 0.05},
                               Vec3{0.31, 0.21, -0.7}, Vec3{0.0, 0.0, 0.1}, Vec3{1.0, 0.1, 0.1}, Vec3{0.1, 1.0, 0.1}},
                              1});
  int stage_calls = 0;
  for (const TestQuery& q : queries) {
    call_ccd(q, Method::filtered, &counters);
    ASSERT_TRUE(numeric::is_default_fp_environment()) << describe(q);
    call_toi(q, Method::filtered, &counters);
    ASSERT_TRUE(numeric::is_default_fp_environment()) << describe(q);
    for (tools::Method m : {tools::Method::exact, tools::Method::naive}) {
      call_ccd(q, m, nullptr);
      ASSERT_TRUE(numeric::is_default_fp_environment()) << describe(q);
      call_toi(q, m, nullptr);
      ASSERT_TRUE(numeric::is_default_fp_environment()) << describe(q);
    }
    stage_calls += run_each_stage_checking_environment(q);
  }
  std::cout << "[ stages   ] reached " << describe(counters) << "; " << stage_calls << " direct stage calls\n";
  EXPECT_GT(counters.volume_exclusion, 0u);
  EXPECT_GT(counters.static_predicates, 0u);
  EXPECT_GT(counters.separating_direction, 0u);
  EXPECT_GT(counters.interval, 0u);
  EXPECT_GT(counters.fixed_integer, 0u);
  EXPECT_GT(counters.integer, 0u);
  EXPECT_GT(counters.exact, 0u);
  EXPECT_GT(counters.toi_refined, 0u);
}

}  // namespace
}  // namespace exactccd
