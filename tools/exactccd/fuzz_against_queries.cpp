#include "fuzz_against_queries.hpp"

#include <cmath>
#include <functional>
#include <optional>
#include <set>

namespace exactccd::cli::fuzz {
namespace {

constexpr int kKMin = -1, kKMax = 60;       // k of the family sweep: -1 (unperturbed), 0..60
constexpr int kKCount = kKMax - kKMin + 1;
/// The interleaved sweep visits k = kKMin + (j kKStride mod kKCount), j = 0, 1, ...: every k
/// once per kKCount (the stride is prime to kKCount), the large and the ulp-sized
/// perturbations early in a short run.
constexpr std::size_t kKStride = 29;
static_assert(kKCount == 62 && kKStride % 2 == 1 && kKStride % 31 != 0, "the stride must be prime to kKCount");
static_assert(kKMin == families::kUnperturbed && kKMin == separation_families::kUnperturbed,
              "both kinds of families call the unperturbed instance k = -1");

/// One query of the run and where it came from.
struct Generated {
  Rows rows{};
  std::size_t group = 0;
  bool family = false;  ///< from the family sweep (k, toward, placement_seed set)
  int k = 0;
  bool toward = false;
  std::uint64_t placement_seed = 0;
};

/// The outcome of one query.
struct Outcome {
  int theirs = 0;
  bool truth = false;
  bool error() const { return theirs != 0 && theirs != 1; }
  bool disagrees() const { return !error() && (theirs == 1) != truth; }
  Rows shrunk{};
  std::string note;                      ///< how it was shrunk
  std::optional<double> their_toi;       ///< the plug-in's TOI, for collisions both find
  std::optional<TimeInterval> exact_toi; ///< the exact TOI, likewise
  /// The plug-in's time is after the exact one: a step to it passes through a contact (decided
  /// exactly: t* is in the tight [lo, hi], so T <= t* iff T <= lo).
  bool unsafe() const { return their_toi && exact_toi && !(*their_toi <= exact_toi->lo); }
  /// The plug-in's time T is more than `factor` times early, factor T < t*, decided in exact
  /// rational arithmetic from the tight [lo, hi] around t*: factor T < lo, or factor T == lo
  /// when lo < hi (then lo < t*). Exact whenever factor T is a double (a power-of-two factor):
  /// no double lies strictly between lo and hi; otherwise factor T inside (lo, hi) is not
  /// counted.
  bool early(double factor) const {
    if (!their_toi || !exact_toi || unsafe()) return false;
    if (std::isinf(*their_toi)) return true;  // -inf (+inf is unsafe)
    const mpq_class scaled = mpq_class(*their_toi) * mpq_class(factor), lo(exact_toi->lo);
    return scaled < lo || (scaled == lo && exact_toi->lo < exact_toi->hi);
  }
};

/// The rows of a family instance of the sweep.
Rows family_rows(const Group& g, const CcdParams& params, int k, bool toward, std::uint64_t placement_seed) {
  if (g.separation) return separation_families::make(*g.separation, params, k, toward, placement_seed).rows;
  std::mt19937_64 rng(placement_seed);  // the placement's draws do not depend on k
  const families::Instance inst = g.contact->make(k, toward, rng);
  Rows r;
  std::visit([&r](const auto& q) { r = rows(q); }, inst.query);
  return r;
}

Rows decoded(const FuzzKind& kind, fuzzing::Mode mode, std::mt19937_64& rng) {
  Rows r;
  do {  // an edit may overflow; draw again (the unedited payloads are finite)
    const std::vector<std::uint8_t> bytes = fuzzing::random_input(rng, mode);
    r = kind.decode(bytes.data(), bytes.size());
  } while (!fuzzing::all_finite(r));
  return r;
}

/// Query i of the run: even i sweep the families (every family, k and direction in turn),
/// i = 1 mod 4 are random family instances, i = 3 mod 4 cycle over the plain random groups.
Generated generate(std::size_t i, const FuzzRun& run, const Groups& groups, const FuzzKind& kind) {
  Generated out;
  if (i % 2 == 0) {
    const std::size_t cell = (i / 2) % (groups.sweep_count * kKCount * 2);
    out.family = true;
    if (groups.interleaved) {  // family after family, each k in a scrambled order, both ways
      out.group = cell % groups.sweep_count;
      const std::size_t rest = cell / groups.sweep_count;
      out.k = kKMin + static_cast<int>((rest / 2 * kKStride) % kKCount);
      out.toward = rest % 2 == 0;
    } else {  // each family's k = -1..60 in turn, both ways, then the next family
      out.group = cell / (kKCount * 2);
      out.k = kKMin + static_cast<int>((cell / 2) % kKCount);
      out.toward = cell % 2 == 0;
    }
    out.placement_seed = query_rng(run.seed, i, 0)();
    out.rows = family_rows(groups.list[out.group], run.params, out.k, out.toward, out.placement_seed);
    return out;
  }
  if (i % 4 == 1) {
    std::mt19937_64 rng = query_rng(run.seed, i, 1);
    out.group = groups.random_instance;
    if (groups.list[out.group].source == Source::random_contact_instance) {
      const families::Instance inst = kind.random_contact_instance(rng);
      std::visit([&out](const auto& q) { out.rows = rows(q); }, inst.query);
    } else {
      out.rows = separation_families::random_instance(kind.separation_families, run.params, rng).rows;
    }
    return out;
  }
  out.group = groups.plain[(i / 4) % groups.plain.size()];
  const Group& g = groups.list[out.group];
  if (g.source == Source::decoder) {
    std::mt19937_64 rng = query_rng(run.seed, i, 2);
    out.rows = decoded(kind, g.mode, rng);
  } else {
    std::mt19937_64 rng = query_rng(run.seed, i, 3);
    out.rows = separation_families::random_near(kind.points, kind.dimension, run.params, rng);
  }
  return out;
}

double& coordinate(Rows& r, int c, int dimension) {
  Vec3& p = r[static_cast<std::size_t>(c / dimension)];
  return c % dimension == 0 ? p.x : (c % dimension == 1 ? p.y : p.z);
}

/// x rounded to `bits` significand bits.
double round_to_bits(double x, int bits) {
  int e = 0;
  const double m = std::frexp(x, &e);
  return std::ldexp(std::nearbyint(std::ldexp(m, bits)), e - bits);
}

using Predicate = std::function<bool(const Rows&)>;

/// The most evaluations of `still` per disagreement: queries spanning 2^-1074..2^1023 make
/// each one slow.
constexpr int kShrinkBudget = 120;

/// One pass of simplify_coordinates over coordinate c; returns whether it changed.
bool simplify_one(Rows& r, int c, const FuzzKind& kind, const Predicate& still, const Predicate& keep) {
  const auto attempt = [&](double v) {
    const double x = coordinate(r, c, kind.dimension);
    if (v == x || !std::isfinite(v)) return false;
    Rows s = r;
    coordinate(s, c, kind.dimension) = v;
    if (!still(s) || !keep(s)) return false;
    r = s;
    return true;
  };
  const double x = coordinate(r, c, kind.dimension);
  const int other_time = (c + kind.coordinates() / 2) % kind.coordinates();
  if (x == 0) return false;
  if (attempt(0.0) || attempt(coordinate(r, other_time, kind.dimension)) || attempt(std::nearbyint(x))) return true;
  // The fewest significand bits that keep the disagreement (bisection; verified by attempt).
  int lo = 1, hi = 53;
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    Rows s = r;
    coordinate(s, c, kind.dimension) = round_to_bits(x, mid);
    if (std::isfinite(coordinate(s, c, kind.dimension)) && still(s)) hi = mid;
    else lo = mid + 1;
  }
  return lo < 53 && attempt(round_to_bits(x, lo));
}

/// Simplifies coordinates one at a time (to 0, to its value at the other time, an integer,
/// fewer significand bits) while `still` and `keep` hold (`keep`, the expensive one, is
/// checked only on a change about to be accepted), for at most kShrinkBudget evaluations of
/// `still`; returns how many coordinates changed.
int simplify_coordinates(Rows& r, const FuzzKind& kind, const Predicate& still_unbudgeted, const Predicate& keep) {
  int budget = kShrinkBudget;
  const Predicate still = [&](const Rows& s) { return budget-- > 0 && still_unbudgeted(s); };
  std::set<int> changed;
  for (int pass = 0; pass < 3 && budget > 0; ++pass) {
    bool any = false;
    for (int c = 0; c < kind.coordinates(); ++c)
      if (simplify_one(r, c, kind, still, keep)) {
        changed.insert(c);
        any = true;
      }
    if (!any) break;
  }
  return static_cast<int>(changed.size());
}

void shrink(const Generated& q, Outcome& o, const Plugin& plugin, const FuzzKind& kind, const FuzzRun& run,
            const Groups& groups) {
  const int theirs = o.theirs;
  const Predicate still = [&](const Rows& r) {
    double toi = 0;
    return plugin.answer(r, toi) == theirs && kind.exact_answer(r, run.params) != (theirs == 1);
  };
  if (q.family) {
    std::set<int> failing;
    const Group& g = groups.list[q.group];
    for (int k = kKMin; k <= kKMax; ++k)
      if (k == q.k || still(family_rows(g, run.params, k, q.toward, q.placement_seed))) failing.insert(k);
    const auto least = failing.upper_bound(kKMin);  // the smallest k >= 0, if any
    const int k = least != failing.end() ? *least : kKMin;
    o.shrunk = family_rows(g, run.params, k, q.toward, q.placement_seed);
    o.note = "shrunk to k " + std::to_string(k) + " (this placement disagrees at k = " + k_ranges(failing) + ")";
    return;
  }
  // Keeping the exact degeneracy categories stops the shrinking from sliding into another,
  // simpler failure (e.g. every point at the origin) instead of minimising this one.
  const std::string categories = kind.categories ? kind.categories(q.rows) : "";
  o.shrunk = q.rows;
  const int n = simplify_coordinates(o.shrunk, kind, still, [&](const Rows& r) {
    return !kind.categories || kind.categories(r) == categories;
  });
  o.note = "shrunk: " + std::to_string(n) + " of " + std::to_string(kind.coordinates()) + " coordinates simplified" +
           (kind.categories ? ", categories kept: " + categories : "");
}

/// The plug-in's answer and time against the exact ones on a generated query.
Outcome evaluate(const Generated& q, const Plugin& plugin, const FuzzKind& kind, const FuzzRun& run) {
  Outcome o;
  o.truth = kind.exact_answer(q.rows, run.params);
  double t = 0;
  o.theirs = plugin.answer(q.rows, t);
  if (o.theirs == 1 && o.truth && !std::isnan(t)) {
    o.their_toi = t;
    o.exact_toi = kind.exact_toi(q.rows, run.params);
  }
  return o;
}

/// Adds query j's outcome to the tally.
void tally_one(FuzzTally& t, std::size_t index, const Generated& q, const Outcome& o, double early_factor) {
  Row& row = t.groups[q.group];
  ++row.queries;
  row.collide += o.truth;
  row.errors += o.error();
  row.fp += o.disagrees() && !o.truth;
  row.fn += o.disagrees() && o.truth;
  if (o.disagrees() && q.family) row.ks.insert(q.k);
  if (o.their_toi && o.exact_toi) {
    ++row.shared;
    const FuzzTally::Toi toi{index, q.group, *o.their_toi, *o.exact_toi, q.rows};
    if (o.unsafe()) {
      ++row.unsafe;
      t.unsafe.push_back(toi);
    } else {
      t.gaps.push_back(o.exact_toi->lo - *o.their_toi);
      if (o.early(early_factor)) {
        ++row.early;
        t.early.push_back(toi);
      }
    }
  }
  if (o.disagrees())
    t.disagreements.push_back({index, q.group, o.truth, q.family, q.toward, q.k, o.shrunk, o.note});
}

}  // namespace

std::vector<std::string> Groups::names() const {
  std::vector<std::string> out;
  for (const Group& g : list) out.push_back(g.name);
  return out;
}

Groups make_groups(const FuzzKind& kind, const CcdParams& params) {
  Groups g;
  const bool contact = params.contact_only() && !kind.contact_families.empty();
  if (contact)
    for (const families::Family* f : kind.contact_families) g.list.push_back({f->name, Source::contact_family, f});
  else
    for (const separation_families::Family* f : kind.separation_families)
      g.list.push_back({f->name, Source::separation_family, nullptr, f});
  g.sweep_count = g.list.size();
  g.interleaved = !contact;
  g.random_instance = g.list.size();
  g.list.push_back({"random_instance", contact ? Source::random_contact_instance : Source::random_separation_instance});
  if (kind.decode)
    for (int m = 0; m < fuzzing::kModeCount; ++m) {
      const auto mode = static_cast<fuzzing::Mode>(m);
      g.plain.push_back(g.list.size());
      g.list.push_back({std::string("random_") + fuzzing::mode_name(mode), Source::decoder, nullptr, nullptr, mode});
    }
  if (!contact) {
    g.plain.push_back(g.list.size());
    g.list.push_back({"random_near", Source::random_near});
  }
  return g;
}

FuzzTally fuzz_queries(const FuzzRun& run, const FuzzKind& kind, const Plugin& plugin, const Groups& groups,
                       std::size_t begin, std::size_t end) {
  const std::size_t n = end - begin;
  std::vector<Generated> generated(n);
  std::vector<Outcome> outcomes(n);
  parallel_for(0, n, run.threads, [&](std::size_t j) {
    Generated& q = generated[j];
    q = generate(begin + j, run, groups, kind);
    Outcome& o = outcomes[j];
    o = evaluate(q, plugin, kind, run);
    if (!o.disagrees()) return;
    if (run.shrinking) {
      shrink(q, o, plugin, kind, run, groups);
    } else {
      o.shrunk = q.rows;
      o.note = "not shrunk";
    }
  }, "fuzz-against");
  FuzzTally t;
  t.groups.resize(groups.list.size());
  for (std::size_t j = 0; j < n; ++j) tally_one(t, begin + j, generated[j], outcomes[j], run.early_factor);
  return t;
}

}  // namespace exactccd::cli::fuzz
