// exactccd bench --motion rigid: the rigid filtered method against the linear filtered method on
// the same bodies' linearised queries (each vertex's world positions at t0 and t1, rounded to
// doubles, as a linear query), in one run, interleaved per repetition.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "exactccd/ccd.hpp"
#include "exactccd/rigid.hpp"
#include "rigid/rigid_layout.hpp"
#include "rigid_cli.hpp"

namespace exactccd::cli {
namespace {

namespace fs = std::filesystem;

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

/// The linearised query's rows: the kind's points at t0, then at t1.
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

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (const double x : v) s += x;
  return s / static_cast<double>(v.size());
}

std::vector<std::string> bundled_rigid_files() {
  std::vector<std::string> files;
  const fs::path dir = fs::path(EXACTCCD_DATA_DIR) / "rigid";
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".csv") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

/// The largest extent of the rows' bounding box.
double box_size(const std::array<Vec3, 8>& rows) {
  double size = 0;
  for (int axis = 0; axis < 3; ++axis) {
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec3& v : rows) {
      const double c = axis == 0 ? v.x : axis == 1 ? v.y : v.z;
      lo = std::min(lo, c), hi = std::max(hi, c);
    }
    size = std::max(size, hi - lo);
  }
  return size;
}

}  // namespace

int run_rigid_bench(const ParsedOptions& options, const std::vector<double>& distances, bool relative, double tmax) {
  const std::optional<QueryKind> kind = kind_of(options);
  const int repetitions = static_cast<int>(options.integer("--repetitions"));
  bool with_exact = false;
  for (const std::string& m : options.list("--methods")) with_exact = with_exact || m == "exact";
  if (options.given("--json")) throw UsageError("bench --motion rigid: --json is not available for rigid queries");
  std::vector<std::string> files = options.positionals();
  if (files.empty()) files = bundled_rigid_files();
  if (files.empty()) throw UsageError("bench --motion rigid: no dataset given and no bundled data/rigid found");
  std::vector<RigidDataset> datasets;
  for (const std::string& f : files) datasets.push_back(load_rigid_dataset(f, kind));

  std::printf("%-34s %4s %9s %7s %10s %10s %10s %10s %7s %4s %4s %8s %s\n", "dataset", "kind", "d", "queries",
              "rigid_ns", "rigid_med", "linear_ns", "linear_med", "ratio", "FP", "FN", "gmp_cgal", "stages");
  for (const RigidDataset& d : datasets) {
    const std::size_t n = d.queries.size();
    const bool vf = d.kind == query_kind<kinds::VertexFace>();
    std::vector<std::array<Vec3, 8>> rows(n);
    for (std::size_t i = 0; i < n; ++i)
      rows[i] = vf ? linearised(rigid::from_numbers<RigidVertexFaceQuery>(d.queries.numbers[i].data()), 1)
                   : linearised(rigid::from_numbers<RigidEdgeEdgeQuery>(d.queries.numbers[i].data()), 2);
    for (const double dist : distances) {
      // The question of each query: d absolute, or relative to its linearised box.
      std::vector<CcdParams> params(n);
      for (std::size_t i = 0; i < n; ++i) params[i] = {relative ? dist * box_size(rows[i]) : dist, tmax};
      std::vector<double> rigid_ns, linear_ns;
      std::vector<bool> rigid_answer(n), reference(n);
      StageCounters stages;
      for (int r = 0; r < repetitions; ++r) {
        StageCounters run;
        double start = now_seconds();
        for (std::size_t i = 0; i < n; ++i)
          rigid_answer[i] = run_rigid_query(d, i, Method::filtered, &run, false, params[i]).has_value();
        rigid_ns.push_back(1e9 * (now_seconds() - start) / static_cast<double>(n));
        if (r == 0) stages = run;
        std::size_t sink = 0;
        start = now_seconds();
        for (std::size_t i = 0; i < n; ++i)
          sink += vf ? vertex_face_ccd(from_rows<VertexFaceQuery>(rows[i]), params[i])
                     : edge_edge_ccd(from_rows<EdgeEdgeQuery>(rows[i]), params[i]);
        linear_ns.push_back(1e9 * (now_seconds() - start) / static_cast<double>(n));
        if (sink > n) std::printf("?");  // keeps the loop
      }
      // FP/FN: against the file's truth at the default question, else against Method::exact.
      const bool default_question = dist == 0 && tmax == 1;
      for (std::size_t i = 0; i < n; ++i)
        reference[i] = default_question && !with_exact
                           ? bool(d.queries.truth[i])
                           : run_rigid_query(d, i, Method::exact, nullptr, false, params[i]).has_value();
      std::size_t fp = 0, fn = 0;
      for (std::size_t i = 0; i < n; ++i) fp += rigid_answer[i] && !reference[i], fn += !rigid_answer[i] && reference[i];
      char stage_text[256];
      std::snprintf(stage_text, sizeof stage_text, "dir %llu, interval %llu, integer %llu, exact %llu",
                    static_cast<unsigned long long>(stages.separating_direction),
                    static_cast<unsigned long long>(stages.interval), static_cast<unsigned long long>(stages.integer),
                    static_cast<unsigned long long>(stages.exact));
      char dtext[32];
      std::snprintf(dtext, sizeof dtext, "%g%s", dist, relative ? "r" : "");
      std::printf("%-34s %4s %9s %7zu %10.0f %10.0f %10.0f %10.0f %7.2f %4zu %4zu %8llu %s\n",
                  fs::path(d.path).stem().string().c_str(), kind_name(d.kind).c_str(), dtext, n, mean(rigid_ns),
                  median(rigid_ns), mean(linear_ns), median(linear_ns), mean(rigid_ns) / mean(linear_ns), fp, fn,
                  static_cast<unsigned long long>(stages.integer + stages.exact), stage_text);
      std::fflush(stdout);
    }
  }
  return kExitOk;
}

}  // namespace exactccd::cli
