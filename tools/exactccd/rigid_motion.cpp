// The rigid motion model of the command line (rigid_motion.hpp): check's reader and answer, bench's
// arms and table, generate's query sets.
#include "rigid_motion.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <variant>

#include "exactccd/ccd.hpp"
#include "exactccd/rigid.hpp"
#include "generators/rigid_families.hpp"
#include "io/input_file.hpp"
#include "io/output_file.hpp"
#include "query_sets.hpp"
#include "scenes/rigid_sim.hpp"

namespace exactccd::cli {
namespace {

namespace fs = std::filesystem;

/// The kind of a rigid file: --kind (vf or ee only), else vertex-face / edge-edge in the path.
QueryKind rigid_kind(const std::optional<QueryKind>& given, const std::string& path) {
  const QueryKind vf = query_kind<kinds::VertexFace>(), ee = query_kind<kinds::EdgeEdge>();
  const std::optional<QueryKind> kind = given ? given : kind_from_path(path);
  if (!kind)
    throw UsageError("cannot infer the query kind of '" + path +
                     "' (no 'vertex-face' or 'edge-edge' in the path): pass --kind vf|ee");
  if (*kind != vf && *kind != ee)
    throw UsageError("--motion rigid answers the kinds vf and ee, not " + kind_name(*kind));
  return *kind;
}

bool is_vertex_face(const RigidDataset& d) { return d.kind == query_kind<kinds::VertexFace>(); }

}  // namespace

RigidDataset RigidMotion::load(const std::string& path, const std::optional<QueryKind>& kind, const TruthSource&) {
  RigidDataset d;
  d.path = path;
  d.kind = rigid_kind(kind, path);
  io::InputFile file(path);
  d.queries = io::read_rigid_csv(file.stream(), path);
  file.check_read();
  if (d.queries.size() == 0) throw io::InputError(path, "no queries (an empty rigid query file)");
  return d;
}

void RigidMotion::check_method(tools::Method m) {
  if (!tools::is_exact_method(m))
    throw UsageError("--motion rigid: --method " + method_name(m) +
                     " is a baseline for linear queries; rigid queries take filtered or exact");
}

TruthSource RigidMotion::truth_source(const ParsedOptions& options, std::size_t, bool) {
  if (options.given("--truth"))
    throw UsageError("check: --truth is for linear query files (rigid files have their truth column)");
  return {};
}

std::optional<TimeInterval> RigidMotion::answer(const Dataset& d, std::size_t i, tools::Method method,
                                                StageCounters* counters, bool want_toi, const CcdParams& params) {
  const double* x = d.queries.numbers[i].data();
  check_method(method);
  const Method m = tools::library_method(method);
  if (is_vertex_face(d))
    return answer_query(rigid::from_numbers<RigidVertexFaceQuery>(x), params, m, want_toi, counters);
  return answer_query(rigid::from_numbers<RigidEdgeEdgeQuery>(x), params, m, want_toi, counters);
}

StageCounts RigidMotion::stage_counts(const StageCounters& s) {
  return {{"separating_direction", s.separating_direction},
          {"interval", s.interval},
          {"integer", s.integer},
          {"exact", s.exact}};
}

std::vector<std::string> RigidMotion::bundled_files(const fs::path& data) {
  std::vector<std::string> files;
  const fs::path dir = data / "rigid";
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".csv") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// ---------------------------------------------------------------------------------------
// bench

namespace {

/// The world position c + R(q) p in doubles (R = M(q) / |q|^2): for the linearised queries only.
Vec3 world(const RigidPose& pose, const Vec3& p) {
  const Quaternion& q = pose.q;
  const double n2 = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
  const double m[3][3] = {{q.w * q.w + q.x * q.x - q.y * q.y - q.z * q.z, 2 * (q.x * q.y - q.w * q.z), 2 * (q.x * q.z + q.w * q.y)},
                          {2 * (q.x * q.y + q.w * q.z), q.w * q.w - q.x * q.x + q.y * q.y - q.z * q.z, 2 * (q.y * q.z - q.w * q.x)},
                          {2 * (q.x * q.z - q.w * q.y), 2 * (q.y * q.z + q.w * q.x), q.w * q.w - q.x * q.x - q.y * q.y + q.z * q.z}};
  const double v[3] = {p.x, p.y, p.z};
  double r[3];
  for (int i = 0; i < 3; ++i) r[i] = (m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2]) / n2;
  return {pose.c.x + r[0], pose.c.y + r[1], pose.c.z + r[2]};
}

/// The linearised query's rows: the kind's points at t0, then at t1 (the first `first` points
/// are body A's).
template <class Query>
std::array<Vec3, 8> linearised(const Query& q, int first) {
  const auto points = body_points(q);
  std::array<Vec3, 8> rows;
  for (int i = 0; i < 4; ++i) {
    rows[i] = world(i < first ? q.a_t0 : q.b_t0, points[i]);
    rows[i + 4] = world(i < first ? q.a_t1 : q.b_t1, points[i]);
  }
  return rows;
}

}  // namespace

RigidMotion::BenchCase::BenchCase(const Dataset& d, const BenchSettings& s)
    : d_(d), s_(s), linearised_(d.queries.size()) {
  for (std::size_t i = 0; i < linearised_.size(); ++i) {
    const double* x = d.queries.numbers[i].data();
    linearised_[i] = is_vertex_face(d) ? linearised(rigid::from_numbers<RigidVertexFaceQuery>(x), 1)
                                       : linearised(rigid::from_numbers<RigidEdgeEdgeQuery>(x), 2);
  }
}

double RigidMotion::BenchCase::box_size(std::size_t i) const {
  double size = 0;
  for (int axis = 0; axis < 3; ++axis) {
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec3& v : linearised_[i]) {
      const double c = axis == 0 ? v.x : axis == 1 ? v.y : v.z;
      lo = std::min(lo, c), hi = std::max(hi, c);
    }
    size = std::max(size, hi - lo);
  }
  return size;
}

std::vector<bool> RigidMotion::BenchCase::reference(const std::vector<CcdParams>& params,
                                                    bool contact_question) const {
  const bool with_exact =
      std::find(s_.methods.begin(), s_.methods.end(), tools::Method::exact) != s_.methods.end();
  std::vector<bool> reference(params.size());
  for (std::size_t i = 0; i < reference.size(); ++i)
    reference[i] = contact_question && !with_exact
                       ? bool(d_.queries.truth[i])
                       : answer(d_, i, tools::Method::exact, nullptr, false, params[i]).has_value();
  return reference;
}

std::vector<BenchArm> RigidMotion::BenchCase::arms(const std::vector<CcdParams>& params) const {
  const BenchArm rigid = [this, &params](std::vector<bool>& answers, StageCounters& counters) {
    for (std::size_t i = 0; i < answers.size(); ++i)
      answers[i] = answer(d_, i, tools::Method::filtered, &counters, false, params[i]).has_value();
  };
  const BenchArm linear = [this, &params](std::vector<bool>& answers, StageCounters&) {
    const bool vf = is_vertex_face(d_);
    for (std::size_t i = 0; i < answers.size(); ++i)
      answers[i] = vf ? vertex_face_ccd(from_rows<VertexFaceQuery>(linearised_[i]), params[i])
                      : edge_edge_ccd(from_rows<EdgeEdgeQuery>(linearised_[i]), params[i]);
  };
  return {rigid, linear};
}

RigidMotion::BenchTable::BenchTable(const BenchSettings& s) : s_(s) {
  if (!s.json.empty()) throw UsageError("bench --motion rigid: --json is not available for rigid queries");
}

void RigidMotion::BenchTable::header() {
  std::printf("%-34s %4s %9s %7s %10s %10s %10s %10s %7s %4s %4s %8s %s\n", "dataset", "kind", "d", "queries",
              "rigid_ns", "rigid_med", "linear_ns", "linear_med", "ratio", "FP", "FN", "gmp_cgal", "stages");
}

void RigidMotion::BenchTable::add(const BenchCase& c, double distance, const std::vector<bool>& reference,
                                  const std::vector<ArmRun>& runs) {
  const ArmRun& rigid = runs[0];
  const ArmRun& linear = runs[1];
  const StageCounters& stages = rigid.stages;
  std::size_t fp = 0, fn = 0;
  for (std::size_t i = 0; i < reference.size(); ++i)
    fp += rigid.answers[i] && !reference[i], fn += !rigid.answers[i] && reference[i];
  char stage_text[256];
  std::snprintf(stage_text, sizeof stage_text, "dir %llu, interval %llu, integer %llu, exact %llu",
                static_cast<unsigned long long>(stages.separating_direction),
                static_cast<unsigned long long>(stages.interval), static_cast<unsigned long long>(stages.integer),
                static_cast<unsigned long long>(stages.exact));
  char dtext[32];
  std::snprintf(dtext, sizeof dtext, "%g%s", distance, s_.relative ? "r" : "");
  const double rigid_mean = mean(rigid.ns_per_query), linear_mean = mean(linear.ns_per_query);
  std::printf("%-34s %4s %9s %7zu %10.0f %10.0f %10.0f %10.0f %7.2f %4zu %4zu %8llu %s\n",
              fs::path(c.dataset().path).stem().string().c_str(), kind_name(c.dataset().kind).c_str(), dtext,
              reference.size(), rigid_mean, median(rigid.ns_per_query), linear_mean, median(linear.ns_per_query),
              rigid_mean / linear_mean, fp, fn, static_cast<unsigned long long>(stages.integer + stages.exact),
              stage_text);
  std::fflush(stdout);
}

// ---------------------------------------------------------------------------------------
// generate

namespace {

/// Writes a rigid query file with `comments` first (query_sets.hpp's write_query_file).
void write_rigid_file(const fs::path& path, const io::RigidQueries& q, const std::vector<std::string>& comments) {
  write_query_file(path.string(), q.truth, "", [&](std::ostream& out) { io::write_rigid_csv(out, q, comments); });
}

/// Appends a query with its truth.
template <class Query>
void append(io::RigidQueries& q, const Query& query, bool truth) {
  q.numbers.push_back(rigid::to_numbers(query));
  q.truth.push_back(truth);
  q.lines.push_back(0);
}

/// The degenerate families at d = 0 (the file format has no d): truth by construction, checked
/// against Method::exact (a disagreement is an internal error, exit 1, before anything is written).
void write_families(const ParsedOptions& options) {
  const std::uint64_t seed = options.unsigned64("--seed");
  const std::string out = options.text("--out");
  io::prepare_output_directory(out);
  io::RigidQueries families_of[2];  // vertex-face, edge-edge
  std::mt19937_64 rng(seed);
  for (const rigid_families::Family& f : rigid_families::all_families())
    for (int k = -1; k <= 52; k = k < 0 ? 0 : k + 4)
      for (const bool toward : {true, false}) {
        if (k < 0 && !toward) continue;
        const rigid_families::Instance inst = rigid_families::make(f, k, toward, rng);
        if (!CcdParams{inst.min_distance, 1.0}.contact_only()) continue;  // contact families only
        const bool exact = std::visit([](const auto& q) { return ccd(q, CcdParams{}, Method::exact); }, inst.query);
        if (inst.expected && *inst.expected != exact)
          throw std::runtime_error("generate families --motion rigid: " + f.name + " k=" + std::to_string(k) +
                                   ": the construction and Method::exact disagree");
        std::visit([&](const auto& q) { append(families_of[f.vertex_face ? 0 : 1], q, exact); }, inst.query);
      }
  const std::vector<std::string> note{
      "Degenerate rigid families (tools/lib/generators/rigid_families.hpp) at k = unperturbed, 0, 4, ..., 52, both directions,",
      "placed by exact common changes of frame; truth by construction, checked against Method::exact.",
      "Regenerate: exactccd generate families --motion rigid --seed " + std::to_string(seed) + " --out DIR"};
  write_rigid_file(fs::path(out) / "rigid-families-vertex-face.csv", families_of[0], note);
  write_rigid_file(fs::path(out) / "rigid-families-edge-edge.csv", families_of[1], note);
}

/// Every candidate of every step of a scene.
rigid_sim::StepQueries scene_candidates(const rigid_sim::Scene& scene) {
  rigid_sim::StepQueries all;
  for (std::size_t step = 0; step + 1 < scene.poses.size(); ++step) {
    const rigid_sim::StepQueries s = rigid_sim::step_queries(scene, step);
    all.vertex_face.insert(all.vertex_face.end(), s.vertex_face.begin(), s.vertex_face.end());
    all.edge_edge.insert(all.edge_edge.end(), s.edge_edge.begin(), s.edge_edge.end());
  }
  std::fprintf(stderr, "scene %s: %zu VF and %zu EE candidates over %zu steps\n", scene.name.c_str(),
               all.vertex_face.size(), all.edge_edge.size(), scene.poses.size() - 1);
  return all;
}

/// The kept candidates (truth: Method::exact) and the file comments saying where they come from.
template <class Query>
void write_scene_file(const fs::path& path, const rigid_sim::Scene& scene, const std::vector<Query>& candidates,
                      std::size_t max_queries, unsigned threads) {
  const Selection s = answer_and_select(candidates, max_queries, threads,
                                        [](const Query& q) { return ccd(q, CcdParams{}, Method::exact); });
  io::RigidQueries q;
  for (const std::size_t i : s.kept) append(q, candidates[i], s.truth[i]);
  const std::vector<std::string> note{
      "Tumbling rigid bodies (tools/lib/scenes/rigid_sim.hpp, scene '" + scene.name + "'): candidates of " +
          std::to_string(scene.poses.size() - 1) + " steps from certified swept boxes: " +
          std::to_string(candidates.size()) + " candidates, " + std::to_string(s.positives) +
          " collide (truth: Method::exact);",
      "kept: every colliding one, then evenly spaced others, at most " + std::to_string(max_queries) + ".",
      "Regenerate: exactccd generate sim --motion rigid --max-queries " + std::to_string(max_queries) + " --out DIR"};
  write_rigid_file(path, q, note);
}

/// The candidates of the tumbling-body scenes (every scene, or --scene's), answered by Method::exact.
void write_sim(const ParsedOptions& options) {
  const std::string out = options.text("--out");
  const auto max_queries = static_cast<std::size_t>(options.integer("--max-queries"));
  const unsigned threads = batch_options(options).threads;
  std::vector<rigid_sim::Scene> scenes = rigid_sim::all_scenes();
  if (options.has("--scene")) {
    const std::string name = options.text("--scene");
    std::string names;
    for (const rigid_sim::Scene& s : scenes) names += (names.empty() ? "" : ", ") + s.name;
    scenes.erase(std::remove_if(scenes.begin(), scenes.end(), [&](const auto& s) { return s.name != name; }),
                 scenes.end());
    if (scenes.empty())
      throw UsageError("generate sim --motion rigid: no rigid scene '" + name + "' (the scenes: " + names + ")");
  }
  io::prepare_output_directory(out);
  for (const rigid_sim::Scene& scene : scenes) {
    const rigid_sim::StepQueries q = scene_candidates(scene);
    const std::string prefix = "rigid-sim-" + scene.name + "-";
    write_scene_file(fs::path(out) / (prefix + "vertex-face.csv"), scene, q.vertex_face, max_queries, threads);
    write_scene_file(fs::path(out) / (prefix + "edge-edge.csv"), scene, q.edge_edge, max_queries, threads);
  }
}

}  // namespace

const std::vector<GenerateSet>& RigidMotion::generate_sets() {
  static const std::vector<GenerateSet> sets = {{"families", write_families}, {"sim", write_sim}};
  return sets;
}

}  // namespace exactccd::cli
