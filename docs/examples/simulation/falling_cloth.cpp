// The loop of falling_cloth.py in C++, through the public API only (docs/simulation.md): a cloth
// falls under gravity onto a hill, folds onto itself and comes to rest, never closer than d to
// the hill or to itself. Each step: position-based dynamics proposes x1; the line search
// (SceneBroadPhase::max_collision_free_step with min_distance d) gives the safe fraction s; while
// s < 1/2 the pairs find_collisions lists stop their cloth vertices (inelastic, sticking) and
// the broad phase is refitted and asked again; the rounded positions x0 + s (x1 - x0) are
// checked (is_collision_free) and s halved until they are safe.
//
// Usage: falling_cloth [STEPS [RESOLUTION [EVERY PREFIX]]]  (defaults 200, 40): one CSV line per
// step on stdout; with EVERY and PREFIX also the mesh every EVERY steps as PREFIX-STEP.obj.
#include <exactccd/exactccd.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

using exactccd::Vec3;
using Triangles = std::vector<std::array<int, 3>>;

Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
double norm(Vec3 a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }

constexpr Vec3 kGravity{0, 0, -9.81};  // m / s^2
constexpr int kSweeps = 10;            // Gauss-Seidel sweeps over the edges per step
constexpr double kMinFraction = 0.5;   // the contact response runs until s >= kMinFraction

/// Appends a square n x n grid of side `size`, centred at the origin in the plane z = 0, each
/// cell split into two triangles.
void add_grid(int n, double size, std::vector<Vec3>& V, Triangles& F) {
  const int first = static_cast<int>(V.size());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) V.push_back({size * (i / (n - 1.0) - 0.5), size * (j / (n - 1.0) - 0.5), 0.0});
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = first + i * n + j;
      F.push_back({a, a + n, a + n + 1});
      F.push_back({a, a + n + 1, a + 1});
    }
}

/// An edge of the cloth and its rest length.
struct Constraint {
  int i, j;
  double rest;
};

/// One step's record.
struct Record {
  double first_fraction = 1, safe_fraction = 1, ccd_seconds = 0;
  std::size_t contacts = 0, self_contacts = 0;
  int response_rounds = 0, retries = 0;
};

/// The cloth (vertices [0, n_cloth)) and the fixed hill (the others) in one scene.
class FallingCloth {
 public:
  explicit FallingCloth(int resolution) {
    add_grid(resolution, 1.0, x_, faces_);
    const double tilt = 20.0 * std::acos(-1.0) / 180.0;
    for (Vec3& p : x_) p = {p.x, std::sin(tilt) * (p.y + 0.5), 0.35 + std::cos(tilt) * (p.y + 0.5)};
    n_cloth_ = static_cast<int>(x_.size());
    for (const auto& t : faces_)
      for (int k = 0; k < 3; ++k) {
        const int a = std::min(t[k], t[(k + 1) % 3]), b = std::max(t[k], t[(k + 1) % 3]);
        if (std::none_of(edges_.begin(), edges_.end(), [&](const Constraint& c) { return c.i == a && c.j == b; }))
          edges_.push_back({a, b, norm(x_[a] - x_[b])});
      }
    add_grid(25, 1.6, x_, faces_);
    for (std::size_t k = static_cast<std::size_t>(n_cloth_); k < x_.size(); ++k)
      x_[k].z = 0.2 * std::exp(-(x_[k].x * x_[k].x + x_[k].y * x_[k].y) / (2 * 0.25 * 0.25));
    v_.assign(x_.size(), Vec3{0, 0, 0});
    options_.min_distance = 1e-3;
  }

  Record step();
  const std::vector<Vec3>& positions() const { return x_; }
  const Triangles& triangles() const { return faces_; }

 private:
  /// Position-based dynamics: the predicted cloth positions, then Gauss-Seidel sweeps over the
  /// edge-length constraints.
  std::vector<Vec3> propose() const {
    std::vector<Vec3> x1 = x_;
    for (int k = 0; k < n_cloth_; ++k) x1[k] = x_[k] + h_ * v_[k] + (h_ * h_) * kGravity;
    for (int sweep = 0; sweep < kSweeps; ++sweep)
      for (const Constraint& c : edges_) {
        const Vec3 delta = x1[c.i] - x1[c.j];
        const double length = norm(delta);
        const Vec3 correction = (0.5 * (length - c.rest) / length) * delta;
        x1[c.i] = x1[c.i] - correction;
        x1[c.j] = x1[c.j] + correction;
      }
    return x1;
  }

  /// The vertices of a colliding pair (a vertex and a triangle, or two edges: four).
  std::array<int, 4> pair_vertices(const exactccd::Collision& c) const {
    if (c.kind == exactccd::CollisionKind::vertex_face) {
      const auto& t = faces_[static_cast<std::size_t>(c.triangle)];
      return {c.vertex, t[0], t[1], t[2]};
    }
    return {c.edge_a[0], c.edge_a[1], c.edge_b[0], c.edge_b[1]};
  }

  /// Stops the cloth vertices of the pairs (x1 = x0 there); false when they were all stopped.
  bool stop(const std::vector<exactccd::Collision>& hits, const std::vector<Vec3>& x0, std::vector<Vec3>& x1,
            std::vector<char>& stopped) const {
    bool more = false;
    for (const exactccd::Collision& c : hits)
      for (const int v : pair_vertices(c))
        if (v < n_cloth_ && !stopped[static_cast<std::size_t>(v)]) {
          stopped[static_cast<std::size_t>(v)] = 1;
          x1[static_cast<std::size_t>(v)] = x0[static_cast<std::size_t>(v)];
          more = true;
        }
    return more;
  }

  std::vector<Vec3> x_, v_;
  Triangles faces_;
  std::vector<Constraint> edges_;
  int n_cloth_ = 0;
  double h_ = 0.02;
  exactccd::SceneOptions options_;
};

Record FallingCloth::step() {
  Record r;
  const std::vector<Vec3> x0 = x_;
  std::vector<Vec3> x1 = propose();
  const auto start = std::chrono::steady_clock::now();
  exactccd::SceneBroadPhase line_search(exactccd::Scene{x0, x1, faces_, {}, {}}, options_);
  double s = r.first_fraction = line_search.max_collision_free_step();
  std::vector<exactccd::Collision> hits;
  if (s < 1) hits = line_search.find_collisions();
  r.contacts = hits.size();
  for (const exactccd::Collision& c : hits) {
    const auto v = pair_vertices(c);
    r.self_contacts += std::all_of(v.begin(), v.end(), [&](int k) { return k < n_cloth_; });
  }
  std::vector<char> stopped(x0.size(), 0);
  while (s < kMinFraction) {  // the contact response
    if (!stop(hits, x0, x1, stopped)) throw std::runtime_error("fixed vertices within d of each other");
    line_search.update(x1);
    s = line_search.max_collision_free_step();
    ++r.response_rounds;
    if (s < kMinFraction) hits = line_search.find_collisions();
  }
  std::vector<Vec3> x = x1;
  while (s < 1) {  // the rounded positions, checked
    for (std::size_t k = 0; k < x.size(); ++k) x[k] = x0[k] + s * (x1[k] - x0[k]);
    line_search.update(x);
    if (line_search.is_collision_free()) break;
    s /= 2;
    ++r.retries;
  }
  r.ccd_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.safe_fraction = s;
  for (std::size_t k = 0; k < x.size(); ++k) v_[k] = (1 / h_) * (x[k] - x0[k]);
  x_ = x;
  return r;
}

/// The process's resident memory in KiB (Linux: /proc/self/statm), or -1.
long resident_kib() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  return statm >> pages >> resident ? resident * (sysconf(_SC_PAGESIZE) / 1024) : -1;
}

void write_obj(const std::string& path, const std::vector<Vec3>& V, const Triangles& F) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + path);
  for (const Vec3& p : V) std::fprintf(f, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
  for (const auto& t : F) std::fprintf(f, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
  std::fclose(f);
}

}  // namespace

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::stoi(argv[1]) : 200, resolution = argc > 2 ? std::stoi(argv[2]) : 40;
  const int every = argc > 4 ? std::stoi(argv[3]) : 0;
  FallingCloth sim(resolution);
  std::printf("step,first_fraction,safe_fraction,contacts,self_contacts,response_rounds,retries,ccd_seconds,"
              "intersection_free,resident_kib\n");
  for (int k = 1; k <= steps; ++k) {
    const Record r = sim.step();
    const bool free = exactccd::intersection_free(sim.positions(), sim.triangles());
    std::printf("%d,%.17g,%.17g,%zu,%zu,%d,%d,%.6g,%d,%ld\n", k, r.first_fraction, r.safe_fraction, r.contacts,
                r.self_contacts, r.response_rounds, r.retries, r.ccd_seconds, free, resident_kib());
    if (every > 0 && k % every == 0) write_obj(std::string(argv[4]) + "-" + std::to_string(k) + ".obj", sim.positions(),
                                               sim.triangles());
  }
}
