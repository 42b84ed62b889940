#include "scene/procedural_scenes.hpp"

#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <utility>

namespace exactccd::scene {
namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 normalized(const Vec3& v, double radius) {
  const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return {radius * v.x / n, radius * v.y / n, radius * v.z / n};
}

}  // namespace

MovingMesh grid(int nx, int ny, double x0, double x1, double y0, double y1) {
  MovingMesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const Vec3 p{x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny, 0.0};
      m.positions_t0.push_back(p);
    }
  m.positions_t1 = m.positions_t0;
  const auto id = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

MovingMesh icosphere(int levels, double radius) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& p : v) p = normalized(p, radius);
  std::vector<Triangle> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                             {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                             {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                             {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    const auto mid = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      const Vec3 m{(v[a].x + v[b].x) / 2, (v[a].y + v[b].y) / 2, (v[a].z + v[b].z) / 2};
      v.push_back(normalized(m, radius));
      midpoint[key] = static_cast<int>(v.size()) - 1;
      return static_cast<int>(v.size()) - 1;
    };
    std::vector<Triangle> next;
    for (const Triangle& tri : f) {
      const int a = mid(tri[0], tri[1]), b = mid(tri[1], tri[2]), c = mid(tri[2], tri[0]);
      next.push_back({tri[0], a, c});
      next.push_back({tri[1], b, a});
      next.push_back({tri[2], c, b});
      next.push_back({a, b, c});
    }
    f = std::move(next);
  }
  MovingMesh m;
  m.positions_t0 = v;
  m.positions_t1 = v;
  m.triangles = f;
  return m;
}

MovingMesh cloth_on_sphere(int resolution, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> gap(0.004, 0.02), step(0.0, 0.007), jitter(-0.002, 0.002);
  const double radius = 0.5;
  MovingMesh cloth = grid(resolution, resolution, -0.8, 0.8, -0.8, 0.8);
  for (std::size_t i = 0; i < cloth.positions_t0.size(); ++i) {
    Vec3& p0 = cloth.positions_t0[i];
    Vec3& p1 = cloth.positions_t1[i];
    const double r2 = p0.x * p0.x + p0.y * p0.y;
    // Draped shape: the sphere's cap where the sheet rests on it, a falling skirt outside.
    const double r = std::sqrt(r2);
    // On the cap the sheet follows the sphere; beyond the sphere's silhouette it hangs down.
    const double surface = r < radius ? std::sqrt(radius * radius - r2) : -1.5 * (r - radius);
    p0.z = surface + gap(rng);
    p0.x += jitter(rng);
    p0.y += jitter(rng);
    p1 = {p0.x + jitter(rng) * 0.5, p0.y + jitter(rng) * 0.5, p0.z - step(rng)};
  }
  MovingMesh scene = icosphere(resolution >= 24 ? 4 : 3, radius);
  append(scene, cloth);
  return scene;
}

MovingMesh twisting_strip(int resolution, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  const int along = std::max(8, resolution * 8), across = 3;
  const double turns = 4.0, radius = 0.5, width = 0.1;
  const double pitch0 = 0.1 + 0.012, pitch1 = 0.1 + 0.004;  // the gap shrinks from 0.012 to 0.004
  MovingMesh m = grid(along, across, 0, 1, 0, 1);
  for (std::size_t i = 0; i < m.positions_t0.size(); ++i) {
    const double u = m.positions_t0[i].x, w = m.positions_t0[i].y;
    const double angle = 2 * kPi * turns * u;
    // Noise on the height moves parts of a turn towards its neighbours; twist tilts the band.
    const double wobble0 = 0.006 * noise(rng), wobble1 = wobble0 + 0.004 * noise(rng);
    const double twist0 = 0.05 * std::sin(3 * angle), twist1 = twist0 + 0.02;
    const auto place = [&](double pitch, double wobble, double twist) {
      const double r = radius + (w - 0.5) * width * std::sin(twist);
      const double z = pitch * turns * u + (w - 0.5) * width * std::cos(twist) + wobble;
      return Vec3{r * std::cos(angle), r * std::sin(angle), z};
    };
    m.positions_t0[i] = place(pitch0, wobble0, twist0);
    m.positions_t1[i] = place(pitch1, wobble1, twist1);
  }
  return m;
}

MovingMesh folding_sheet(int resolution, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  MovingMesh m = grid(2 * resolution, resolution, -1, 1, -0.5, 0.5);
  const double theta0 = kPi - 0.08, theta1 = kPi - 0.03;  // the right half closes onto the left
  for (std::size_t i = 0; i < m.positions_t0.size(); ++i) {
    const Vec3 p = m.positions_t0[i];
    const double bump = 0.002 * noise(rng);
    if (p.x <= 0) {  // the left half rests, slightly rumpled
      m.positions_t0[i] = {p.x, p.y, bump};
      m.positions_t1[i] = {p.x + 0.0005 * noise(rng), p.y, bump + 0.001 * noise(rng)};
    } else {  // the right half rotates about the y axis and sinks a little
      const double sink = 0.011 + 0.005 * noise(rng);
      m.positions_t0[i] = {p.x * std::cos(theta0), p.y, p.x * std::sin(theta0) + bump + 0.01};
      m.positions_t1[i] = {p.x * std::cos(theta1), p.y, p.x * std::sin(theta1) + bump + 0.01 - sink};
    }
  }
  return m;
}

MovingMesh procedural_scene(const std::string& name, int resolution, std::uint64_t seed) {
  if (resolution < 2) throw std::invalid_argument("scene resolution must be at least 2");
  if (name == "cloth") return cloth_on_sphere(resolution, seed);
  if (name == "strip") return twisting_strip(resolution, seed);
  if (name == "fold") return folding_sheet(resolution, seed);
  throw std::invalid_argument("unknown scene '" + name + "' (expected cloth, strip or fold)");
}

}  // namespace exactccd::scene
