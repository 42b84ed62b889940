// exactccd fuzz-against: another CCD code, loaded as a plug-in (include/exactccd/plugin.h),
// against the exact answers on the degenerate families and on random degenerate queries.
// Every disagreement is shrunk and written as a benchmark CSV that `exactccd check` replays.
#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "degeneracy/degeneracy.hpp"
#include "exactccd/plugin.h"
#include "fuzz/families.hpp"
#include "fuzz/fuzz_input.hpp"
#include "output_file.hpp"
#include "partial.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

namespace fs = std::filesystem;
using fuzzing::Rows;

constexpr const char* kDescription = R"(Tests another CCD code against the exact answers. PLUGIN.so is a shared library exporting
  int exactccd_plugin_vf(const double q[24])   (for --kind vf)
  int exactccd_plugin_ee(const double q[24])   (for --kind ee)
(include/exactccd/plugin.h: the 8 points in benchmark row order, x y z each; 1 = collision,
0 = none, anything else counts as an error). Query i of the run is
  i even:      the degenerate families (fuzz/families.hpp) of the kind, cycling over every
               family, k = -1 (unperturbed), 0..60 and both directions (toward/away from
               contact), each instance randomly placed;
  i = 1 mod 4: families::random_instance (a random family, k, direction and placement);
  i = 3 mod 4: plain random queries biased to degeneracies (the fuzzers' decoder on random
               bytes), cycling over its modes: integer grids at power-of-two scales, random
               doubles, family instances and catalogue cases, each with random edits (shared
               vertices, coplanar and collinear points, ulp nudges, subnormal and huge values).
The truth is the exact answer of the reference path (Method::exact: rational arithmetic and
CGAL's algebraic kernel, not the filtered front end). Prints a table of false positives and false
negatives per group (for the families, the k at which the plug-in disagreed).

Every disagreement is shrunk, then written to DIR:
  NNNNNN-GROUP-FP|FN-vertex-face.csv (or -edge-edge.csv): the shrunk query (query index NNNNNN
      of the run), benchmark format, truth = the exact answer, coordinates exact rationals;
  disagreements-vertex-face.csv: all of them, in run order; disagreements-vertex-face.txt: one
      line per disagreement (file, group, k and direction, how it was shrunk) and the shrunk
      query in hex floats.
Replay: exactccd check --kind vf DIR/disagreements-vertex-face.csv (0 FP, 0 FN: the truth
column is exact). Files of the same kind from an earlier run in DIR are replaced.
Shrinking: a family instance is replaced by the least degenerate instance of the same family,
direction and placement that still disagrees the same way (the smallest k >= 0, else the
unperturbed one); the .txt lists every k at which that placement disagrees. Other queries:
each coordinate is simplified (0, its value at the other time, an integer, fewer significand
bits) while the same disagreement persists.

)";

/// A loaded plug-in; unloaded on destruction.
class Plugin {
 public:
  Plugin(const std::string& path, QueryKind kind)
      : symbol_(visit_kind(kind, [](auto k) -> const char* {
          if constexpr (is_contact_kind<decltype(k)>)
            return decltype(k)::plugin_symbol.data();
          else
            throw UsageError("fuzz-against: the plug-in ABI (exactccd/plugin.h) has vf and ee queries, not " +
                             std::string(decltype(k)::short_name));
        })) {
    // dlopen searches the library path for a bare name: "x.so" means the file ./x.so here.
    const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
    handle_ = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) {
      const char* why = dlerror();
      throw UsageError("fuzz-against: cannot load plug-in '" + path + "': " + (why ? why : "unknown error"));
    }
    dlerror();
    void* f = dlsym(handle_, symbol_);
    if (!f) {
      dlclose(handle_);
      throw UsageError("fuzz-against: plug-in '" + path + "' does not export the symbol " + symbol_ +
                       ", needed for --kind " + kind_name(kind) +
                       " (see include/exactccd/plugin.h: int " + symbol_ + "(const double q[24]))");
    }
    static_assert(sizeof(void*) == sizeof(exactccd_plugin_fn), "dlsym returns functions as void*");
    std::memcpy(&fn_, &f, sizeof fn_);  // POSIX: a dlsym'd function pointer is stored as void*
    // The optional entry point with a time of impact (plugin.h).
    const char* toi_symbol = visit_kind(kind, [](auto k) -> const char* {
      if constexpr (is_contact_kind<decltype(k)>) return decltype(k)::plugin_toi_symbol.data();
      return nullptr;
    });
    dlerror();
    if (void* g = toi_symbol ? dlsym(handle_, toi_symbol) : nullptr) {
      static_assert(sizeof(void*) == sizeof(exactccd_plugin_toi_fn), "dlsym returns functions as void*");
      std::memcpy(&toi_fn_, &g, sizeof toi_fn_);
    }
  }
  ~Plugin() { dlclose(handle_); }
  Plugin(const Plugin&) = delete;
  Plugin& operator=(const Plugin&) = delete;

  /// The plug-in's raw answer on a query.
  int operator()(const Rows& r) const {
    double q[24];
    flatten(r, q);
    return fn_(q);
  }

  /// True when the plug-in reports times of impact (the optional entry point).
  bool reports_toi() const { return toi_fn_ != nullptr; }

  /// The plug-in's raw answer and, when it is 1, its time of impact (reports_toi() only).
  int answer_with_toi(const Rows& r, double& toi) const {
    double q[24];
    flatten(r, q);
    return toi_fn_(q, &toi);
  }

  /// The symbol used.
  const char* symbol() const { return symbol_; }

 private:
  static void flatten(const Rows& r, double* q) {
    for (std::size_t i = 0; i < 8; ++i) {
      q[3 * i] = r[i].x;
      q[3 * i + 1] = r[i].y;
      q[3 * i + 2] = r[i].z;
    }
  }
  const char* symbol_;
  void* handle_ = nullptr;
  exactccd_plugin_fn fn_ = nullptr;
  exactccd_plugin_toi_fn toi_fn_ = nullptr;
};

constexpr int kKMin = families::kUnperturbed, kKMax = 60;
constexpr int kKCount = kKMax - kKMin + 1;  // -1 (unperturbed), 0..60

/// One query of the run and where it came from.
struct Generated {
  Rows rows{};
  std::size_t group = 0;
  const families::Family* family = nullptr;  ///< family sweep only
  int k = 0;
  bool toward = false;
  std::uint64_t placement_seed = 0;
};

/// The groups of the table: the kind's families (sweep), then the random groups.
struct Groups {
  std::vector<const families::Family*> families;
  std::vector<std::string> names;
  std::size_t random_instance = 0, random_first = 0;  ///< random_first + mode: fuzz decoder modes
};

/// The groups of kind Kind (a description of lib/kinds).
template <class Kind>
Groups make_groups() {
  Groups g;
  g.families = families::families_of_kind<Kind>();
  for (const families::Family* f : g.families) g.names.push_back(f->name);
  g.random_instance = g.names.size();
  g.names.push_back("random_instance");
  g.random_first = g.names.size();
  for (int m = 0; m < fuzzing::kModeCount; ++m)
    g.names.push_back(std::string("random_") + fuzzing::mode_name(static_cast<fuzzing::Mode>(m)));
  return g;
}

std::mt19937_64 query_rng(std::uint64_t seed, std::size_t i, std::uint32_t tag) {
  std::seed_seq s{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                  static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(std::uint64_t{i} >> 32), tag};
  return std::mt19937_64(s);
}

Rows family_rows(const families::Family& f, int k, bool toward, std::uint64_t placement_seed) {
  std::mt19937_64 rng(placement_seed);  // the placement's draws do not depend on k
  const families::Instance inst = f.make(k, toward, rng);
  Rows r;
  std::visit([&r](const auto& q) { r = rows(q); }, inst.query);
  return r;
}

template <class Kind>
Generated generate(std::size_t i, std::uint64_t seed, const Groups& g) {
  Generated out;
  if (i % 2 == 0) {
    const std::size_t cells = g.families.size() * kKCount * 2;
    const std::size_t cell = (i / 2) % cells;
    out.group = cell / (kKCount * 2);
    out.family = g.families[out.group];
    out.k = kKMin + static_cast<int>((cell / 2) % kKCount);
    out.toward = cell % 2 == 0;
    out.placement_seed = query_rng(seed, i, 0)();
    out.rows = family_rows(*out.family, out.k, out.toward, out.placement_seed);
  } else if (i % 4 == 1) {
    std::mt19937_64 rng = query_rng(seed, i, 1);
    const families::Instance inst = families::random_instance<Kind>(rng);
    std::visit([&out](const auto& q) { out.rows = rows(q); }, inst.query);
    out.group = g.random_instance;
  } else {
    std::mt19937_64 rng = query_rng(seed, i, 2);
    const auto mode = static_cast<fuzzing::Mode>((i / 4) % fuzzing::kModeCount);
    do {  // an edit may overflow; draw again (the unedited payloads are finite)
      const std::vector<std::uint8_t> bytes = fuzzing::random_input(rng, mode);
      out.rows = fuzzing::decode<Kind>(bytes.data(), bytes.size());
    } while (!fuzzing::all_finite(out.rows));
    out.group = g.random_first + static_cast<std::size_t>(mode);
  }
  return out;
}

/// The truth: the exact reference path (Method::exact), independent of the filtered front end
/// that the libFuzzer targets check against it.
template <class Kind>
bool exact_answer(const Rows& r) {
  return ccd(from_rows<typename Kind::template Query<double>>(r), Method::exact);
}

/// The exact degeneracy categories of a query, joined by '+' (as `exactccd compare` prints).
template <class Kind>
std::string degeneracy_labels(const Rows& r) {
  std::array<RationalVec3, 8> q;
  for (std::size_t i = 0; i < 8; ++i) q[i] = {mpq_class(r[i].x), mpq_class(r[i].y), mpq_class(r[i].z)};
  return exact::join_categories(exact::degeneracy_categories(from_rows<typename Kind::template Query<mpq_class>>(q)));
}

/// The outcome of one query.
struct Outcome {
  int theirs = 0;
  bool truth = false;
  bool error() const { return theirs != 0 && theirs != 1; }
  bool disagrees() const { return !error() && (theirs == 1) != truth; }
  Rows shrunk{};
  std::string note;  ///< how it was shrunk
  std::optional<double> their_toi;         ///< the plug-in's TOI, when it reports one
  std::optional<TimeInterval> exact_toi;   ///< the exact TOI, for collisions both find
  /// Both find the collision and the plug-in's time is after the exact one: a step to it
  /// passes through a contact (decided exactly: t* is in the tight [lo, hi], so T <= t* iff
  /// T <= lo).
  bool unsafe() const { return their_toi && exact_toi && *their_toi > exact_toi->lo; }
};

/// "-1, 23..60" from a sorted set of k.
std::string k_ranges(const std::set<int>& ks) {
  std::string out;
  for (auto it = ks.begin(); it != ks.end();) {
    const int first = *it;
    int last = first;
    while (++it != ks.end() && *it == last + 1) ++last;
    if (!out.empty()) out += ", ";
    out += std::to_string(first);
    if (last > first) out += (last == first + 1 ? ", " : "..") + std::to_string(last);
  }
  return out;
}

double& coordinate(Rows& r, int c) {
  Vec3& p = r[static_cast<std::size_t>(c / 3)];
  return c % 3 == 0 ? p.x : (c % 3 == 1 ? p.y : p.z);
}

/// x rounded to `bits` significand bits.
double round_to_bits(double x, int bits) {
  int e = 0;
  const double m = std::frexp(x, &e);
  return std::ldexp(std::nearbyint(std::ldexp(m, bits)), e - bits);
}

/// Simplifies coordinates one at a time while `still` and `keep` hold (`keep`, the expensive
/// one, is checked only on a change about to be accepted), for at most kShrinkBudget
/// evaluations of `still` (queries spanning 2^-1074..2^1023 make each one slow); returns how
/// many coordinates changed.
constexpr int kShrinkBudget = 120;
int simplify_coordinates(Rows& r, const std::function<bool(const Rows&)>& still_unbudgeted,
                         const std::function<bool(const Rows&)>& keep) {
  int budget = kShrinkBudget;
  const auto still = [&](const Rows& s) { return budget-- > 0 && still_unbudgeted(s); };
  std::set<int> changed;
  for (int pass = 0; pass < 3 && budget > 0; ++pass) {
    bool any = false;
    for (int c = 0; c < 24; ++c) {
      const auto attempt = [&](double v) {
        const double x = coordinate(r, c);
        if (v == x || !std::isfinite(v)) return false;
        Rows s = r;
        coordinate(s, c) = v;
        if (!still(s) || !keep(s)) return false;
        r = s;
        changed.insert(c);
        any = true;
        return true;
      };
      const double x = coordinate(r, c);
      if (x == 0 || attempt(0.0)) continue;
      if (attempt(coordinate(r, (c + 12) % 24))) continue;  // the same value at the other time
      if (attempt(std::nearbyint(x))) continue;
      // The fewest significand bits that keep the disagreement (bisection; verified by attempt).
      int lo = 1, hi = 53;
      while (lo < hi) {
        const int mid = (lo + hi) / 2;
        Rows s = r;
        coordinate(s, c) = round_to_bits(x, mid);
        if (std::isfinite(coordinate(s, c)) && still(s)) hi = mid; else lo = mid + 1;
      }
      if (lo < 53) attempt(round_to_bits(x, lo));
    }
    if (!any) break;
  }
  return static_cast<int>(changed.size());
}

template <class Kind>
void shrink(const Generated& q, Outcome& o, const Plugin& plugin) {
  const int theirs = o.theirs;
  const auto still = [&](const Rows& r) { return plugin(r) == theirs && exact_answer<Kind>(r) != (theirs == 1); };
  if (q.family) {
    std::set<int> failing;
    for (int k = kKMin; k <= kKMax; ++k)
      if (k == q.k || still(family_rows(*q.family, k, q.toward, q.placement_seed))) failing.insert(k);
    const auto least = failing.upper_bound(kKMin);  // the smallest k >= 0, if any
    const int k = least != failing.end() ? *least : kKMin;
    o.shrunk = family_rows(*q.family, k, q.toward, q.placement_seed);
    o.note = "shrunk to k " + std::to_string(k) + " (this placement disagrees at k = " + k_ranges(failing) + ")";
  } else {
    // Keeping the exact degeneracy categories stops the shrinking from sliding into another,
    // simpler failure (e.g. every point at the origin) instead of minimising this one.
    const std::string categories = degeneracy_labels<Kind>(q.rows);
    o.shrunk = q.rows;
    const int n = simplify_coordinates(o.shrunk, still, [&](const Rows& r) {
      return degeneracy_labels<Kind>(r) == categories;
    });
    o.note = "shrunk: " + std::to_string(n) + " of 24 coordinates simplified, categories kept: " + categories;
  }
}

/// Writes text to path through a temporary file and a rename: nothing is left half-written.
void write_atomically(const fs::path& path, const std::string& text) { write_file_atomically(path.string(), text); }

/// An earlier run's output of this kind: NNNNNN-*-<kind>.csv and disagreements-<kind>.*.
bool is_output_of_kind(const std::string& name, const std::string& kind_suffix) {
  if (name == "disagreements-" + kind_suffix + ".csv" || name == "disagreements-" + kind_suffix + ".txt" ||
      name == "unsafe-toi-" + kind_suffix + ".csv" || name == "unsafe-toi-" + kind_suffix + ".txt")
    return true;
  const std::string tail = "-" + kind_suffix + ".csv";
  if (name.size() < 7 + tail.size() || name.compare(name.size() - tail.size(), tail.size(), tail) != 0)
    return false;
  return std::all_of(name.begin(), name.begin() + 6, [](char ch) { return ch >= '0' && ch <= '9'; }) &&
         name[6] == '-';
}

/// The most queries of a run: each holds about half a kilobyte until the end (5 GB at the limit).
constexpr long long kMaxFuzzQueries = 10000000;

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "fuzz-against";
    c.usage = "usage: exactccd fuzz-against PLUGIN.so --kind vf|ee (--out DIR | --partial OUT [--shard I/N]) [options]";
    c.description = kDescription;
    c.options = {
        required(kind_option("query kind")),
        integer_option("--queries", "N", 1, kMaxFuzzQueries, "10000", "number of queries"),
        unsigned64_option("--seed", "S", "1", "seed; a run is reproducible and independent of --threads"),
        text_option("--out", "DIR", "", "where to write the disagreements (created if missing)"),
        threads_option("1", "query on N threads (the plug-in must then be thread-safe)"),
        flag_option("--no-shrink", "write the disagreements as found"),
        shard_option("--shard", kMaxShards,
                     "only the I-th of N contiguous blocks of the queries 0..Q-1 (a cluster job);\n"
                     "needs --partial"),
        text_option("--partial", "OUT", "",
                    "write this run's or shard's partial results to OUT instead of the report and\n"
                    "DIR (then no --out): `exactccd merge --out DIR` of the N shards' files prints\n"
                    "the report and writes DIR, byte-identical to one run"),
    };
    c.epilogue =
        "exit codes: 0 ran (whatever it found), 2 bad usage, an unwritable DIR, or a plug-in that cannot\n"
        "be loaded or lacks the kind's symbol, 1 internal error.\n";
    return c;
  }();
  return spec;
}

/// The settings of a run.
struct Run {
  std::string plugin_path;
  std::size_t queries = 0;
  std::uint64_t seed = 0;
  std::string out_dir;
  unsigned threads = 1;
  bool shrinking = true;
  std::size_t shard_index = 0, shard_count = 1;
  std::string partial_path;  ///< write the partial results here instead of the report
};

/// One row of the table.
struct Row {
  std::size_t queries = 0, collide = 0, fp = 0, fn = 0, errors = 0;
  std::set<int> ks;  // family sweep: k at which some instance disagreed
};

/// What the report of a run is made of, for a range of its queries (the whole run, or one
/// shard): the table's rows per group, the TOI comparison and the disagreements in query order.
struct FuzzTally {
  std::vector<Row> groups;
  std::size_t shared = 0;  ///< collisions both find, with the plug-in's TOI
  std::vector<double> gaps;
  struct Unsafe {
    std::size_t index = 0, group = 0;
    double their_toi = 0;
    TimeInterval exact{};
    Rows rows{};
  };
  std::vector<Unsafe> unsafe;
  struct Disagreement {
    std::size_t index = 0, group = 0;
    bool truth = false, family = false, toward = false;
    int k = 0;
    Rows shrunk{};
    std::string note;
  };
  std::vector<Disagreement> disagreements;
};

/// Runs queries [begin, end) of the run against the plug-in.
template <class Kind>
FuzzTally fuzz_queries(const Run& run, const Plugin& plugin, const Groups& groups, std::size_t begin,
                       std::size_t end) {
  const std::size_t n = end - begin;
  std::vector<Generated> generated(n);
  std::vector<Outcome> outcomes(n);
  parallel_for(0, n, run.threads, [&](std::size_t j) {
    const std::size_t i = begin + j;
    Generated& q = generated[j];
    q = generate<Kind>(i, run.seed, groups);
    Outcome& o = outcomes[j];
    o.truth = exact_answer<Kind>(q.rows);
    if (plugin.reports_toi()) {
      double t = 0;
      o.theirs = plugin.answer_with_toi(q.rows, t);
      if (o.theirs == 1 && o.truth) {
        o.their_toi = t;
        o.exact_toi = toi(from_rows<typename Kind::template Query<double>>(q.rows), Method::exact);
      }
    } else {
      o.theirs = plugin(q.rows);
    }
    if (!o.disagrees()) return;
    if (run.shrinking) {
      shrink<Kind>(q, o, plugin);
    } else {
      o.shrunk = q.rows;
      o.note = "not shrunk";
    }
  }, "fuzz-against");

  FuzzTally t;
  t.groups.resize(groups.names.size());
  for (std::size_t j = 0; j < n; ++j) {
    const Outcome& o = outcomes[j];
    const Generated& q = generated[j];
    Row& row = t.groups[q.group];
    ++row.queries;
    row.collide += o.truth;
    row.errors += o.error();
    row.fp += o.disagrees() && !o.truth;
    row.fn += o.disagrees() && o.truth;
    if (o.disagrees() && q.family) row.ks.insert(q.k);
    if (o.their_toi && o.exact_toi) {
      ++t.shared;
      if (o.unsafe())
        t.unsafe.push_back({begin + j, q.group, *o.their_toi, *o.exact_toi, q.rows});
      else
        t.gaps.push_back(o.exact_toi->lo - *o.their_toi);
    }
    if (o.disagrees())
      t.disagreements.push_back({begin + j, q.group, o.truth, q.family != nullptr, q.toward, q.k, o.shrunk, o.note});
  }
  return t;
}

/// The run's settings as partial-file settings (every shard of one run has the same).
std::vector<std::pair<std::string, std::string>> partial_settings(const Run& run, const std::string& kind_short,
                                                                  bool reports_toi) {
  return {{"plugin", run.plugin_path},
          {"kind", kind_short},
          {"queries", std::to_string(run.queries)},
          {"seed", std::to_string(run.seed)},
          {"shrink", run.shrinking ? "1" : "0"},
          {"toi", reports_toi ? "1" : "0"}};
}

std::string hex_rows(const Rows& r) {
  std::string out;
  for (const Vec3& p : r)
    for (const double x : {p.x, p.y, p.z}) out += " " + hex_double(x);
  return out;
}

/// Reads 24 coordinates from words[first..first+24).
Rows rows_from_words(const std::vector<std::string>& w, std::size_t first, const PartialRecord& r) {
  if (w.size() < first + 24) throw io::ParseError(r.source, r.line, "a query needs 24 coordinates");
  Rows rows{};
  for (std::size_t i = 0; i < 8; ++i)
    rows[i] = {parse_double(w[first + 3 * i], r.source, r.line), parse_double(w[first + 3 * i + 1], r.source, r.line),
               parse_double(w[first + 3 * i + 2], r.source, r.line)};
  return rows;
}

/// The tally as partial records: the group rows, then the TOI records and the disagreements.
void add_records(const FuzzTally& t, Partial& p) {
  for (std::size_t g = 0; g < t.groups.size(); ++g) {
    const Row& r = t.groups[g];
    std::string ks;
    for (const int k : r.ks) ks += (ks.empty() ? "" : ",") + std::to_string(k);
    p.add("group " + std::to_string(g) + " " + std::to_string(r.queries) + " " + std::to_string(r.collide) + " " +
          std::to_string(r.fp) + " " + std::to_string(r.fn) + " " + std::to_string(r.errors) + " " +
          (ks.empty() ? "-" : ks));
  }
  p.add("shared " + std::to_string(t.shared));
  for (const double g : t.gaps) p.add("gap " + hex_double(g));
  for (const FuzzTally::Unsafe& u : t.unsafe)
    p.add("unsafe " + std::to_string(u.index) + " " + std::to_string(u.group) + " " + hex_double(u.their_toi) + " " +
          hex_double(u.exact.lo) + " " + hex_double(u.exact.hi) + hex_rows(u.rows));
  for (const FuzzTally::Disagreement& d : t.disagreements)
    p.add("disagreement " + std::to_string(d.index) + " " + std::to_string(d.group) + " " + (d.truth ? "1" : "0") +
          " " + (d.family ? "1" : "0") + " " + std::to_string(d.k) + " " + (d.toward ? "1" : "0") + hex_rows(d.shrunk) +
          " " + d.note);
}

/// The tally of merged records (shards in order: rows add up, the rest concatenates).
FuzzTally tally_from_records(const Partial& p, std::size_t group_count) {
  FuzzTally t;
  t.groups.resize(group_count);
  for (const PartialRecord& r : p.records) {
    const std::vector<std::string> w = split_words(r.text);
    const auto count = [&](std::size_t i) { return parse_count(w.at(i), r.source, r.line); };
    const auto group = [&](std::size_t i) {
      const std::size_t g = count(i);
      if (g >= group_count) throw io::ParseError(r.source, r.line, "group " + w[i] + " out of range");
      return g;
    };
    const auto flag = [&](std::size_t i) {
      if (w.at(i) != "0" && w.at(i) != "1") throw io::ParseError(r.source, r.line, "expected 0 or 1, found '" + w[i] + "'");
      return w[i] == "1";
    };
    if (w.empty()) throw io::ParseError(r.source, r.line, "empty record");
    if (w[0] == "group" && w.size() == 8) {
      Row& row = t.groups[group(1)];
      row.queries += count(2);
      row.collide += count(3);
      row.fp += count(4);
      row.fn += count(5);
      row.errors += count(6);
      if (w[7] != "-") {
        std::istringstream ks(w[7]);
        for (std::string k; std::getline(ks, k, ',');) row.ks.insert(parse_int(k, r.source, r.line));
      }
    } else if (w[0] == "shared" && w.size() == 2) {
      t.shared += count(1);
    } else if (w[0] == "gap" && w.size() == 2) {
      t.gaps.push_back(parse_double(w[1], r.source, r.line));
    } else if (w[0] == "unsafe" && w.size() == 6 + 24) {
      t.unsafe.push_back({count(1), group(2), parse_double(w[3], r.source, r.line),
                          {parse_double(w[4], r.source, r.line), parse_double(w[5], r.source, r.line)},
                          rows_from_words(w, 6, r)});
    } else if (w[0] == "disagreement" && w.size() >= 7 + 24) {
      FuzzTally::Disagreement d;
      d.index = count(1);
      d.group = group(2);
      d.truth = flag(3);
      d.family = flag(4);
      d.k = parse_int(w[5], r.source, r.line);
      d.toward = flag(6);
      d.shrunk = rows_from_words(w, 7, r);
      // The note is the rest of the line after the 31st word (it has spaces of its own).
      std::size_t pos = 0;
      for (int skip = 0; skip < 31; ++skip) {
        pos = r.text.find_first_not_of(' ', pos);
        pos = r.text.find(' ', pos);
      }
      d.note = pos == std::string::npos ? "" : r.text.substr(pos + 1);
      t.disagreements.push_back(std::move(d));
    } else {
      throw io::ParseError(r.source, r.line, "not a fuzz-against record: '" + w[0] + "' with " +
                                                 std::to_string(w.size()) + " fields");
    }
  }
  return t;
}

/// Prints the report of a whole run and writes its files to run.out_dir (the help describes both).
template <class Kind>
void report_fuzz(const Run& run, const FuzzTally& t, const Groups& groups, bool reports_toi) {
  const std::string kind_suffix(Kind::name);
  const std::string kind_short(Kind::short_name);
  prepare_output_directory(run.out_dir);
  Row total;
  for (const Row& r : t.groups) {
    total.queries += r.queries;
    total.collide += r.collide;
    total.fp += r.fp;
    total.fn += r.fn;
    total.errors += r.errors;
  }
  std::printf("fuzz-against %s (%s): %zu %s queries, seed %llu, truth = the exact answer (Method::exact)\n\n",
              run.plugin_path.c_str(), Kind::plugin_symbol.data(), run.queries, kind_suffix.c_str(),
              static_cast<unsigned long long>(run.seed));
  std::printf("%-28s %8s %8s %7s %7s %7s  %s\n", "group", "queries", "collide", "FP", "FN", "errors",
              "disagrees at k (families; -1 = unperturbed)");
  const auto print_row = [](const std::string& name, const Row& r) {
    std::printf("%-28s %8zu %8zu %7zu %7zu %7zu  %s\n", name.c_str(), r.queries, r.collide, r.fp, r.fn,
                r.errors, k_ranges(r.ks).c_str());
  };
  for (std::size_t g = 0; g < t.groups.size(); ++g) print_row(groups.names[g], t.groups[g]);
  print_row("total", total);

  // Times of impact, when the plug-in reports them.
  std::string unsafe_index;
  io::BenchmarkQueries unsafe_queries;
  const auto rational_rows = [](const Rows& r) {
    std::array<RationalVec3, 8> q;
    for (std::size_t p = 0; p < 8; ++p) q[p] = {mpq_class(r[p].x), mpq_class(r[p].y), mpq_class(r[p].z)};
    return q;
  };
  if (reports_toi) {
    for (const FuzzTally::Unsafe& u : t.unsafe) {
      char line[200];
      std::snprintf(line, sizeof line, "%06zu  %s  T %.17g  exact [%.17g, %.17g]\n", u.index,
                    groups.names[u.group].c_str(), u.their_toi, u.exact.lo, u.exact.hi);
      unsafe_index += line;
      unsafe_queries.rows.push_back(rational_rows(u.rows));
      unsafe_queries.truth.push_back(true);
    }
    std::vector<double> gaps = t.gaps;
    std::sort(gaps.begin(), gaps.end());
    const auto at = [&](double q) { return gaps[static_cast<std::size_t>(std::llround(q * (gaps.size() - 1)))]; };
    std::printf("\ntimes of impact (%s): %zu collisions both find, %zu safe (T <= exact), %zu unsafe (T after the "
                "exact time)\n", Kind::plugin_symbol.data(), t.shared, gaps.size(), unsafe_queries.size());
    if (!gaps.empty())
      std::printf("gap lo - T of the safe ones: min %.3g, median %.3g, max %.3g\n", at(0), at(0.5), at(1));
  }

  // The disagreements: replace this kind's files of an earlier run, then write.
  for (const auto& entry : fs::directory_iterator(run.out_dir))
    if (entry.is_regular_file() && is_output_of_kind(entry.path().filename().string(), kind_suffix))
      fs::remove(entry.path());
  io::BenchmarkQueries all;
  std::string index;
  for (const FuzzTally::Disagreement& d : t.disagreements) {
    const char* type = d.truth ? "FN" : "FP";
    char prefix[32];
    std::snprintf(prefix, sizeof prefix, "%06zu", d.index);
    const std::string name = std::string(prefix) + "-" + groups.names[d.group] + "-" + type + "-" + kind_suffix + ".csv";
    write_atomically(fs::path(run.out_dir) / name, fuzzing::benchmark_csv(d.shrunk, d.truth));
    all.rows.push_back(rational_rows(d.shrunk));
    all.truth.push_back(d.truth);
    index += name + "  " + type + "  " + groups.names[d.group];
    if (d.family) index += " k " + std::to_string(d.k) + (d.toward ? " toward" : " away");
    index += "  " + d.note + "\n" + fuzzing::hex_rows<Kind>(d.shrunk);
  }
  std::ostringstream csv;
  io::write_benchmark_csv(csv, all);
  write_atomically(fs::path(run.out_dir) / ("disagreements-" + kind_suffix + ".csv"), csv.str());
  write_atomically(fs::path(run.out_dir) / ("disagreements-" + kind_suffix + ".txt"),
                   "# exactccd fuzz-against " + run.plugin_path + " --kind " + kind_short + " --queries " +
                       std::to_string(run.queries) + " --seed " + std::to_string(run.seed) +
                       ": one line per disagreement (file, FP/FN, group, shrinking), then the shrunk query "
                       "in hex floats; the rows of disagreements-" + kind_suffix + ".csv in order\n" + index);
  if (reports_toi) {
    std::ostringstream unsafe_csv;
    io::write_benchmark_csv(unsafe_csv, unsafe_queries);
    write_atomically(fs::path(run.out_dir) / ("unsafe-toi-" + kind_suffix + ".csv"), unsafe_csv.str());
    write_atomically(fs::path(run.out_dir) / ("unsafe-toi-" + kind_suffix + ".txt"),
                     "# exactccd fuzz-against " + run.plugin_path + " --kind " + kind_short +
                         ": one line per collision whose reported time of impact T is after the exact "
                         "one (index, group, T, exact TOI); the rows of unsafe-toi-" + kind_suffix +
                         ".csv in order\n" + unsafe_index);
  }
  std::printf("\n%zu disagreements (FP %zu, FN %zu)%s, written to %s: one CSV each, all in "
              "disagreements-%s.csv, described in disagreements-%s.txt\n"
              "replay: exactccd check --kind %s %s/disagreements-%s.csv\n",
              t.disagreements.size(), total.fp, total.fn, run.shrinking ? ", shrunk" : "", run.out_dir.c_str(),
              kind_suffix.c_str(), kind_suffix.c_str(), kind_short.c_str(), run.out_dir.c_str(), kind_suffix.c_str());
}

/// A run (or one shard of it) on queries of the kind Kind (a description of lib/kinds the fuzz
/// decoder writes): the report, or with run.partial_path the partial results.
template <class Kind>
int fuzz_kind(const Run& run) {
  const Plugin plugin(run.plugin_path, query_kind<Kind>());
  if (run.partial_path.empty()) prepare_output_directory(run.out_dir);  // fail before the work
  const Groups groups = make_groups<Kind>();
  const std::size_t begin = run.queries * run.shard_index / run.shard_count;
  const std::size_t end = run.queries * (run.shard_index + 1) / run.shard_count;
  const double start = now_seconds();
  const FuzzTally tally = fuzz_queries<Kind>(run, plugin, groups, begin, end);
  // The time goes to stderr: stdout is the report, the same for a run, its shards merged, and
  // any --threads.
  std::fprintf(stderr, "fuzz-against: %zu queries in %.1f s\n", end - begin, now_seconds() - start);
  if (run.partial_path.empty()) {
    report_fuzz<Kind>(run, tally, groups, plugin.reports_toi());
    return kExitOk;
  }
  Partial p;
  p.command = "fuzz-against";
  p.settings = partial_settings(run, std::string(Kind::short_name), plugin.reports_toi());
  p.shard_index = run.shard_index;
  p.shard_count = run.shard_count;
  p.begin = begin;
  p.end = end;
  p.total = run.queries;
  add_records(tally, p);
  write_partial(run.partial_path, p);
  return kExitOk;
}

}  // namespace

int run_fuzz_against(int argc, char** argv) {
  const ParsedOptions options = parse_options(command(), argc, argv);
  if (options.help()) {
    std::cout << help_text(command());
    return kExitOk;
  }
  const std::optional<QueryKind> kind = kind_of(options);
  const auto queries = static_cast<std::size_t>(options.integer("--queries"));
  const std::uint64_t seed = options.unsigned64("--seed");
  const std::string out_dir = options.has("--out") ? options.text("--out") : "";
  const std::string partial_path = options.has("--partial") ? options.text("--partial") : "";
  const auto [shard_index, shard_count] = options.shard("--shard");
  if (options.has("--shard") && partial_path.empty())
    throw UsageError("fuzz-against: --shard needs --partial FILE (the shards are merged by exactccd merge --out DIR)");
  if (partial_path.empty() == out_dir.empty())
    throw UsageError("fuzz-against: give exactly one of --out DIR and --partial FILE");
  const auto threads = scene::resolve_threads(static_cast<unsigned>(options.integer("--threads")));
  const bool shrinking = !options.flag("--no-shrink");
  if (options.positionals().empty()) throw UsageError("fuzz-against: no plug-in (see exactccd fuzz-against --help)");
  if (options.positionals().size() > 1)
    throw UsageError("fuzz-against: one plug-in at a time ('" + options.positionals()[0] + "' and '" +
                     options.positionals()[1] + "')");
  const Run run{options.positionals()[0], queries, seed, out_dir, threads, shrinking, shard_index, shard_count,
                partial_path};
  return visit_kind(*kind, [&](auto k) {
    using Kind = decltype(k);
    if constexpr (fuzzing::is_decodable_v<Kind>) {
      return fuzz_kind<Kind>(run);
    } else {
      throw UsageError("fuzz-against: --kind " + std::string(Kind::short_name) +
                       " is not supported (the fuzz decoder writes vertex-face and edge-edge queries)");
      return static_cast<int>(kExitUsage);
    }
  });
}

int merge_fuzz_against(const Partial& merged, const std::string& source, const std::string& out_dir) {
  if (out_dir.empty()) throw UsageError("merge: fuzz-against partials need --out DIR (where the run writes its files)");
  Run run;
  run.plugin_path = merged.setting("plugin", source);
  run.queries = parse_count(merged.setting("queries", source), source, 1);
  run.seed = parse_count(merged.setting("seed", source), source, 1);
  run.shrinking = merged.setting("shrink", source) == "1";
  run.out_dir = out_dir;
  const bool reports_toi = merged.setting("toi", source) == "1";
  if (run.queries != merged.total)
    throw io::ParseError(source, 1, "the run has " + std::to_string(run.queries) + " queries but the shards cover " +
                                        std::to_string(merged.total));
  const std::string& kind_text = merged.setting("kind", source);
  return visit_kind(parse_kind(kind_text), [&](auto k) {
    using Kind = decltype(k);
    if constexpr (fuzzing::is_decodable_v<Kind>) {
      const Groups groups = make_groups<Kind>();
      report_fuzz<Kind>(run, tally_from_records(merged, groups.names.size()), groups, reports_toi);
      return static_cast<int>(kExitOk);
    } else {
      throw io::ParseError(source, 1, "fuzz-against has no kind '" + kind_text + "'");
      return static_cast<int>(kExitUsage);
    }
  });
}

}  // namespace exactccd::cli
