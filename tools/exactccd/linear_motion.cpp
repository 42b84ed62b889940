// The linear motion model of the command line (linear_motion.hpp): check's truth source and
// method limits, bench's arms and table, generate's query sets.
#include "linear_motion.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <random>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <variant>

#include "generators/catalogue.hpp"
#include "generators/families.hpp"
#include "io/data_dir.hpp"
#include "query_sets.hpp"
#include "scenes/procedural_scenes.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

namespace fs = std::filesystem;

/// The largest extent of a query's bounding box over its first `count` points (t0 and t1).
double box_size(const std::array<Vec3, 8>& rows, int count) {
  double size = 0;
  for (int axis = 0; axis < 3; ++axis) {
    double lo = 0, hi = 0;
    for (int k = 0; k < count; ++k) {
      const double c = axis == 0 ? rows[k].x : axis == 1 ? rows[k].y : rows[k].z;
      lo = k == 0 ? c : std::min(lo, c);
      hi = k == 0 ? c : std::max(hi, c);
    }
    size = std::max(size, hi - lo);
  }
  return size;
}

/// A short dataset name: "unit-tests/vertex-face/data_0_0" or the file's stem for others.
std::string dataset_name(const std::string& path) {
  const fs::path p(path);
  const std::string parent = p.parent_path().filename().string();
  if (parent == "vertex-face" || parent == "edge-edge")
    return p.parent_path().parent_path().filename().string() + "/" + parent + "/" + p.stem().string();
  return p.stem().string();
}

}  // namespace

TruthSource LinearMotion::truth_source(const ParsedOptions& options, std::size_t files, bool answers) {
  TruthSource truth;
  truth.json = options.has("--truth") ? options.text("--truth") : "";
  truth.required = !answers;
  if (!truth.json.empty() && files != 1)
    throw UsageError("check: --truth FILE.json goes with one FILE.csv (" + std::to_string(files) + " given)");
  return truth;
}

void LinearMotion::require_answers(const Dataset& d, tools::Method method, const CcdParams& params) {
  require_method_answers(method, d.kind, params);
  require_double_range(d, method);
}

std::vector<std::string> LinearMotion::bundled_files(const fs::path& data) {
  std::vector<std::string> files;
  if (const std::optional<fs::path> sample_dir = io::shared_sample_dir()) {
    const fs::path sample = *sample_dir / "unit-tests";
    for (const char* f : {"vertex-face/data_0_0.csv", "vertex-face/data_0_1.csv",
                          "edge-edge/data_0_0.csv", "edge-edge/data_0_1.csv"})
      if (fs::exists(sample / f)) files.push_back((sample / f).string());
  }
  const fs::path sim = data / "sim";
  if (fs::is_directory(sim)) {
    std::vector<std::string> sims;
    for (const auto& e : fs::directory_iterator(sim))
      if (e.path().extension() == ".csv") sims.push_back(e.path().string());
    std::sort(sims.begin(), sims.end());
    files.insert(files.end(), sims.begin(), sims.end());
  }
  return files;
}

// ---------------------------------------------------------------------------------------
// bench

LinearMotion::BenchCase::BenchCase(const Dataset& d, const BenchSettings& s)
    : d_(d), s_(s), name_(dataset_name(d.path)) {
  // FP and FN are counted against the file's published truth column; the exact reference
  // (Method::exact) says how far that column can be trusted.
  const std::size_t n = d.queries.size();
  for (std::size_t i = 0; i < n; ++i)
    truth_disagrees_ += run_query(d, i, tools::Method::exact, nullptr, false).has_value() != d.queries.truth[i];
  if (truth_disagrees_ > 0)
    std::fprintf(stderr, "exactccd bench: %s: the truth column disagrees with Method::exact on %zu of %zu "
                         "queries: its FP and FN are against that column\n",
                 d.path.c_str(), truth_disagrees_, n);
}

double LinearMotion::BenchCase::box_size(std::size_t i) const {
  const auto& rows = d_.doubles[i] ? *d_.doubles[i] : io::nearest_double_rows(d_.queries.rows[i]);
  return cli::box_size(rows, d_.queries.layout.rows);
}

std::vector<bool> LinearMotion::BenchCase::reference(const std::vector<CcdParams>& params,
                                                     bool contact_question) const {
  std::vector<bool> reference = d_.queries.truth;
  if (!contact_question)
    for (std::size_t i = 0; i < reference.size(); ++i)
      reference[i] = run_query(d_, i, tools::Method::exact, nullptr, false, params[i]).has_value();
  return reference;
}

std::vector<BenchArm> LinearMotion::BenchCase::arms(const std::vector<CcdParams>& params) const {
  std::vector<BenchArm> arms;
  for (const tools::Method m : s_.methods)
    arms.push_back([this, m, &params](std::vector<bool>& answers, StageCounters& counters) {
      for (std::size_t i = 0; i < answers.size(); ++i)
        answers[i] = run_query(d_, i, m, &counters, false, params[i]).has_value();
    });
  return arms;
}

namespace {

using Row = LinearMotion::BenchTable::Row;

void write_json(std::ostream& out, const std::vector<Row>& rows) {
  out << "[\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    out << "  {\"dataset\": " << json_string(r.dataset) << ", \"kind\": \"" << r.kind << "\", \"method\": \""
        << r.method << "\", \"min_distance\": " << r.min_distance << ", \"relative\": "
        << (r.relative ? "true" : "false") << ", \"tmax\": " << r.tmax << ", \"queries\": " << r.queries << ", \"mean_ns\": " << r.mean_ns
        << ", \"median_ns\": " << r.median_ns << ", \"fp\": " << r.fp << ", \"fn\": " << r.fn
        << ", \"fp_fn_against\": \""
        << (CcdParams{r.min_distance, r.tmax}.contact_over_whole_step() ? "file truth column" : "Method::exact at the same d and tmax")
        << "\", \"truth_disagrees_with_exact\": "
        << r.truth_disagrees_with_exact
        << ", \"exact_fallbacks\": " << r.exact_fallbacks << ", \"stages\": {\"volume_exclusion\": "
        << r.stages.volume_exclusion << ", \"static_predicates\": " << r.stages.static_predicates
        << ", \"separating_direction\": " << r.stages.separating_direction << ", \"interval\": " << r.stages.interval
        << ", \"fixed_integer\": " << r.stages.fixed_integer << ", \"integer\": " << r.stages.integer << ", \"exact\": " << r.stages.exact << "}}"
        << (i + 1 < rows.size() ? "," : "") << "\n";
  }
  out << "]\n";
}

/// The row of one arm (method m) at one d.
Row bench_row(const LinearMotion::BenchCase& c, const BenchSettings& s, tools::Method m, double distance,
              const std::vector<bool>& reference, const ArmRun& run) {
  Row r;
  r.dataset = c.name();
  r.kind = kind_name(c.dataset().kind);
  r.method = method_name(m);
  r.min_distance = distance;
  r.relative = s.relative;
  r.tmax = s.tmax;
  r.queries = reference.size();
  r.truth_disagrees_with_exact = c.truth_disagrees_with_exact();
  for (std::size_t i = 0; i < reference.size(); ++i) {
    r.fp += run.answers[i] && !reference[i];
    r.fn += !run.answers[i] && reference[i];
  }
  r.stages = run.stages;
  r.exact_fallbacks = m == tools::Method::exact ? r.queries : m == tools::Method::filtered ? run.stages.exact : 0;
  r.mean_ns = mean(run.ns_per_query);
  r.median_ns = median(run.ns_per_query);
  return r;
}

/// The table line of a row; the stage shares and gmp_cgal for the filtered method only.
void print_bench_row(FILE* table, const Row& r, bool filtered) {
  const std::size_t n = r.queries;
  std::string stages = "-";
  std::string gmp_cgal = "-";
  if (filtered && n) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%.1f%% / %.1f%% / %.1f%% / %.1f%% / %.2f%% / %.2f%% / %.3f%%",
                  100.0 * r.stages.volume_exclusion / n, 100.0 * r.stages.static_predicates / n,
                  100.0 * r.stages.separating_direction / n, 100.0 * r.stages.interval / n,
                  100.0 * r.stages.fixed_integer / n, 100.0 * r.stages.integer / n, 100.0 * r.stages.exact / n);
    stages = buf;
    gmp_cgal = std::to_string(r.stages.integer + r.stages.exact);
  }
  std::fprintf(table, "%-34s %4s %-9s %9.3g %8zu %10.1f %10.1f %6zu %6zu %12zu %9llu %8s  %s\n", r.dataset.c_str(),
               r.kind.c_str(), r.method.c_str(), r.min_distance, r.queries, r.mean_ns, r.median_ns, r.fp, r.fn,
               r.truth_disagrees_with_exact, static_cast<unsigned long long>(r.exact_fallbacks), gmp_cgal.c_str(),
               stages.c_str());
}

}  // namespace

LinearMotion::BenchTable::BenchTable(const BenchSettings& s) : s_(s), table_(s.json == "-" ? stderr : stdout) {
  if (!s.json.empty() && s.json != "-") json_file_.emplace(s.json);
}

void LinearMotion::BenchTable::header() {
  std::fprintf(table_, "FP and FN: against each file's truth column; truth!=exact: queries whose truth column "
                       "disagrees with Method::exact\n");
  std::fprintf(table_, "%-34s %4s %-9s %9s %8s %10s %10s %6s %6s %12s %9s %8s  %s\n", "dataset", "kind", "method",
               s_.relative ? "d/box" : "d", "queries", "mean_ns", "median_ns", "FP", "FN", "truth!=exact",
               "exact_fb", "gmp_cgal", "stages (vol/static/sep/int/fixed/gmp/exact)");
}

void LinearMotion::BenchTable::add(const BenchCase& c, double distance, const std::vector<bool>& reference,
                                   const std::vector<ArmRun>& runs) {
  for (std::size_t m = 0; m < runs.size(); ++m) {
    rows_.push_back(bench_row(c, s_, s_.methods[m], distance, reference, runs[m]));
    print_bench_row(table_, rows_.back(), s_.methods[m] == tools::Method::filtered);
  }
}

void LinearMotion::BenchTable::finish() {
  if (s_.json.empty()) return;
  if (s_.json == "-") {
    write_json(std::cout, rows_);
  } else {
    write_json(json_file_->stream(), rows_);
    json_file_->commit();
  }
}

// ---------------------------------------------------------------------------------------
// generate

namespace {

/// The benchmark-format set of hand-derived entries (query and answer).
template <class E>
io::BenchmarkQueries to_benchmark(const std::vector<E>& entries) {
  io::BenchmarkQueries q;
  for (const E& e : entries) {
    q.rows.push_back(rows(e.query));
    q.truth.push_back(e.collides);
  }
  return q;
}

/// Writes a benchmark CSV (query_sets.hpp's write_query_file).
void write_benchmark_file(const fs::path& path, const io::BenchmarkQueries& q, const std::string& note = "") {
  write_query_file(path.string(), q.truth, note, [&](std::ostream& out) { io::write_benchmark_csv(out, q); });
}

/// The eight points of a double query as exact rationals (a double is m 2^e: mpq_class holds it
/// as the reduced m 2^max(e,0) / 2^max(-e,0)).
template <class Query>
std::array<RationalVec3, 8> rational_rows(const Query& q) {
  std::array<RationalVec3, 8> r;
  const auto d = rows(q);
  for (std::size_t j = 0; j < 8; ++j) r[j] = {mpq_class(d[j].x), mpq_class(d[j].y), mpq_class(d[j].z)};
  return r;
}

/// The kept candidates of a scene, in the benchmark format, with their truth.
template <class Query>
io::BenchmarkQueries kept_queries(const std::vector<Query>& candidates, const Selection& s) {
  io::BenchmarkQueries out;
  for (const std::size_t i : s.kept) {
    out.rows.push_back(rational_rows(candidates[i]));
    out.truth.push_back(s.truth[i]);
  }
  return out;
}

void write_catalogue(const ParsedOptions& options) {
  const std::string out = options.text("--out");
  io::prepare_output_directory(out);
  write_benchmark_file(fs::path(out) / "catalogue-vertex-face.csv", to_benchmark(catalogue::vertex_face_cases()));
  write_benchmark_file(fs::path(out) / "catalogue-edge-edge.csv", to_benchmark(catalogue::edge_edge_cases()));
}

/// The truth of a family instance: its answer by construction where the family knows it,
/// else the exact reference (Method::exact). A constructed answer or time of impact that
/// Method::exact contradicts is a bug in the construction or in the exact path: thrown as an
/// internal error (exit 1) naming the instance, before anything is written.
bool family_truth(const families::Instance& inst, const std::string& where) {
  const auto [exact, toi] = std::visit(
      [](const auto& q) { return std::pair{ccd(q, Method::exact), exactccd::toi(q, Method::exact)}; }, inst.query);
  if (const std::optional<std::string> why = families::disagreement(inst, exact, toi))
    throw std::runtime_error("generate families: " + where + ": the construction and Method::exact disagree: " + *why);
  return inst.expected.value_or(exact);
}

/// The instances of every family, by the kind's long name, and how many have their truth by
/// construction.
struct FamilySets {
  std::map<std::string_view, io::BenchmarkQueries> by_kind;
  std::size_t constructed = 0, total = 0;

  /// Adds an instance (its truth checked by family_truth).
  void add(const families::Family& f, const families::Instance& inst, const std::string& where) {
    io::BenchmarkQueries& queries = by_kind[f.kind];
    queries.truth.push_back(family_truth(inst, where));
    queries.rows.push_back(std::visit([](const auto& q) { return rational_rows(q); }, inst.query));
    constructed += inst.expected.has_value();
    ++total;
  }
};

/// The instances of family f at k in one direction: plain, or in every wide style.
void add_family_instance(FamilySets& sets, const families::Family& f, int k, bool toward, const std::string& where,
                         bool wide, std::mt19937_64& rng) {
  if (!wide) {
    sets.add(f, f.make(k, toward, rng), where);
    return;
  }
  for (int style = 0; style < families::kWideStyleCount; ++style) {
    const auto w = static_cast<families::WideStyle>(style);
    if (const auto inst = families::make_wide(f, k, toward, w, rng))
      sets.add(f, *inst, where + " wide " + families::wide_style_name(w));
  }
}

void write_families(const ParsedOptions& options) {
  const int instances = static_cast<int>(options.integer("--instances"));
  const int k_step = static_cast<int>(options.integer("--k-step"));
  const bool wide = options.flag("--wide");
  FamilySets sets;
  std::mt19937_64 rng(options.unsigned64("--seed"));
  for (const families::Family& f : families::all_families())
    for (int k = families::kUnperturbed; k <= 60; k = (k < 0 ? 0 : k + k_step))
      for (int i = 0; i < 2 * instances; ++i) {
        const bool toward = i % 2 == 0;
        const std::string where = f.name + " k=" + std::to_string(k) + (toward ? " toward" : " away") +
                                  " instance " + std::to_string(i / 2);
        add_family_instance(sets, f, k, toward, where, wide, rng);
      }
  const std::string out = options.text("--out");
  io::prepare_output_directory(out);
  const std::string note = " (truth: " + std::to_string(sets.constructed) + " of " + std::to_string(sets.total) +
                           " by construction, checked against Method::exact; the others by Method::exact)";
  const std::string prefix = wide ? "families-wide-" : "families-";
  for (QueryKind k : all_kinds()) {  // one file per kind that has families, named by the kind
    const auto it = sets.by_kind.find(kind_long_name(k));
    if (it != sets.by_kind.end())
      write_benchmark_file(fs::path(out) / (prefix + std::string(it->first) + ".csv"), it->second, note);
  }
}

/// The procedural scene of --scene, --resolution and --seed (a UsageError naming `what` for an
/// unknown one).
scene::MovingMesh scene_of(const ParsedOptions& options, const std::string& what) {
  try {
    return scene::procedural_scene(options.text("--scene"), static_cast<int>(options.integer("--resolution")),
                                   options.unsigned64("--seed"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(what + ": " + e.what());
  }
}

void write_sim(const ParsedOptions& options) {
  const std::string out = options.text("--out"), truth_name = options.text("--truth");
  const auto max_queries = static_cast<std::size_t>(options.integer("--max-queries"));
  const unsigned threads = batch_options(options).threads;
  if (!options.has("--scene")) throw UsageError("generate sim: --scene cloth|strip|fold|pile is required");
  io::prepare_output_directory(out);  // an unwritable DIR fails before the work
  const std::string name = options.text("--scene");
  const scene::MovingMesh mesh = scene_of(options, "generate sim");
  const Method truth_method = truth_name == "exact" ? Method::exact : Method::filtered;
  const scene::StepQueries q = scene::step_queries(mesh);
  std::fprintf(stderr, "scene %s: %zu vertices, %zu triangles, %zu VF and %zu EE candidates\n", name.c_str(),
               mesh.positions_t0.size(), mesh.triangles.size(), q.vertex_face.size(), q.edge_edge.size());
  const auto collides = [&](const auto& x) { return ccd(x, truth_method); };
  const Selection vf = answer_and_select(q.vertex_face, max_queries, threads, collides);
  const Selection ee = answer_and_select(q.edge_edge, max_queries, threads, collides);
  const auto note = [&](const Selection& s) {
    return " (truth: " + truth_name + "; the step: " + std::to_string(s.truth.size()) + " candidates, " +
           std::to_string(s.positives) + " collide)";
  };
  write_benchmark_file(fs::path(out) / ("sim-" + name + "-vertex-face.csv"), kept_queries(q.vertex_face, vf), note(vf));
  write_benchmark_file(fs::path(out) / ("sim-" + name + "-edge-edge.csv"), kept_queries(q.edge_edge, ee), note(ee));
}

void write_scene(const ParsedOptions& options) {
  generate_scene(options.has("--scene") ? options.text("--scene") : "",
                 static_cast<int>(options.integer("--resolution")), options.unsigned64("--seed"),
                 options.text("--out"));
}

}  // namespace

const std::vector<GenerateSet>& LinearMotion::generate_sets() {
  static const std::vector<GenerateSet> sets = {
      {"catalogue", write_catalogue}, {"families", write_families}, {"sim", write_sim}, {"scene", write_scene}};
  return sets;
}

}  // namespace exactccd::cli
