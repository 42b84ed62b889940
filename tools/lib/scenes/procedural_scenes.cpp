#include "scenes/procedural_scenes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <utility>

namespace exactccd::scene {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Uniform doubles in [lo, hi) from the top 53 bits of mt19937_64's raw output, so that the
/// scenes do not depend on the standard library's (implementation-defined) distributions.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(engine_() >> 11) * 0x1p-53);
  }

 private:
  std::mt19937_64 engine_;
};

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
  Rng rng(seed);
  const double radius = 0.5, half = 0.8;
  // The drape: the grid point at distance s from the sheet's centre lies on the great circle of
  // azimuth alpha at arc length s from the sphere's top (geodesic polar map, nearly isometric);
  // beyond the contact angle kLeave the sheet leaves the sphere along the tangent there. Every
  // such point is at least radius + clearance from the centre (a tangent line only moves away).
  constexpr double kLeave = 1.0;  // radians
  const auto drape = [&](double gx, double gy, double above) {
    const double s = std::sqrt(gx * gx + gy * gy), alpha = std::atan2(gy, gx);
    const double ca = std::cos(alpha), sa = std::sin(alpha), phi = std::min(s / radius, kLeave);
    const double r = radius + above, beyond = s - radius * phi;
    return Vec3{ca * (r * std::sin(phi) + beyond * std::cos(phi)),
                sa * (r * std::sin(phi) + beyond * std::cos(phi)), r * std::cos(phi) - beyond * std::sin(phi)};
  };
  MovingMesh cloth = grid(resolution, resolution, -half, half, -half, half);
  const std::size_t n = cloth.positions_t0.size();
  std::vector<double> x(n), y(n), clearance(n), settle(n), dx(n), dy(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = cloth.positions_t0[i].x + rng.uniform(-0.002, 0.002);
    y[i] = cloth.positions_t0[i].y + rng.uniform(-0.002, 0.002);
    clearance[i] = rng.uniform(0.001, 0.015);
    // The step: the sheet settles onto the sphere by up to 0.006 and slides a little; where
    // it settles by more than its clearance, it reaches the sphere during the step.
    settle[i] = rng.uniform(0.0, 0.006);
    dx[i] = rng.uniform(-0.001, 0.001);
    dy[i] = rng.uniform(-0.001, 0.001);
  }
  // A flat triangle between points at radius + c sags towards the centre (by about l^2 / (8
  // radius) for a side l): where one would dip into the ball of the sphere at t0, its vertices
  // are lifted until it does not (the ball holds the sphere mesh), so that the sheet is apart
  // from the sphere at t0, as a simulator keeps it. Sampled on a fine barycentric grid.
  for (bool lifted = true; lifted;) {
    lifted = false;
    std::vector<Vec3> p(n);
    for (std::size_t i = 0; i < n; ++i) p[i] = drape(x[i], y[i], clearance[i]);
    for (const Triangle& t : cloth.triangles) {
      constexpr int kSamples = 16;
      double nearest = 1e300;
      for (int a = 0; a <= kSamples; ++a)
        for (int b = 0; a + b <= kSamples; ++b) {
          const double u = double(a) / kSamples, v = double(b) / kSamples, w = 1 - u - v;
          const double qx = u * p[t[0]].x + v * p[t[1]].x + w * p[t[2]].x;
          const double qy = u * p[t[0]].y + v * p[t[1]].y + w * p[t[2]].y;
          const double qz = u * p[t[0]].z + v * p[t[1]].z + w * p[t[2]].z;
          nearest = std::min(nearest, std::sqrt(qx * qx + qy * qy + qz * qz));
        }
      const double needed = radius + 0.0005 - nearest;
      if (needed > 0) {
        for (int k = 0; k < 3; ++k) clearance[t[k]] += needed + 0.0005;
        lifted = true;
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    cloth.positions_t0[i] = drape(x[i], y[i], clearance[i]);
    cloth.positions_t1[i] = drape(x[i] + dx[i], y[i] + dy[i], clearance[i] - settle[i]);
  }
  // A sphere mesh about as fine as the sheet (icosahedron edge 1.05 radius, halved per level).
  const int levels = resolution >= 48 ? 4 : 3;
  MovingMesh scene = icosphere(levels, radius);
  append(scene, cloth);
  return scene;
}

MovingMesh twisting_strip(int resolution, std::uint64_t seed) {
  Rng rng(seed);
  const auto noise = [&] { return rng.uniform(-1.0, 1.0); };
  const int along = std::max(8, resolution * 8), across = 3;
  const double turns = 4.0, radius = 0.5, width = 0.1;
  const double pitch0 = 0.1 + 0.012, pitch1 = 0.1 + 0.004;  // the gap shrinks from 0.012 to 0.004
  MovingMesh m = grid(along, across, 0, 1, 0, 1);
  for (std::size_t i = 0; i < m.positions_t0.size(); ++i) {
    const double u = m.positions_t0[i].x, w = m.positions_t0[i].y;
    const double angle = 2 * kPi * turns * u;
    // Noise on the height moves parts of a turn towards its neighbours; twist tilts the band.
    const double wobble0 = 0.006 * noise(), wobble1 = wobble0 + 0.004 * noise();
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
  Rng rng(seed);
  const auto noise = [&] { return rng.uniform(-1.0, 1.0); };
  MovingMesh m = grid(2 * resolution, resolution, -1, 1, -0.5, 0.5);
  const double theta0 = kPi - 0.08, theta1 = kPi - 0.03;  // the right half closes onto the left
  for (std::size_t i = 0; i < m.positions_t0.size(); ++i) {
    const Vec3 p = m.positions_t0[i];
    const double bump = 0.002 * noise();
    if (p.x <= 0) {  // the left half rests, slightly rumpled
      m.positions_t0[i] = {p.x, p.y, bump};
      m.positions_t1[i] = {p.x + 0.0005 * noise(), p.y, bump + 0.001 * noise()};
    } else {  // the right half rotates about the y axis and sinks a little
      const double sink = 0.011 + 0.005 * noise();
      m.positions_t0[i] = {p.x * std::cos(theta0), p.y, p.x * std::sin(theta0) + bump + 0.01};
      m.positions_t1[i] = {p.x * std::cos(theta1), p.y, p.x * std::sin(theta1) + bump + 0.01 - sink};
    }
  }
  return m;
}

namespace {

/// A 3x3 rotation matrix (rows).
using Mat3 = std::array<std::array<double, 3>, 3>;

Mat3 multiply(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
  return c;
}

/// The rotation by `angle` about the unit axis (x, y, z) (Rodrigues).
Mat3 rotation(double x, double y, double z, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  return {{{t * x * x + c, t * x * y - s * z, t * x * z + s * y},
           {t * x * y + s * z, t * y * y + c, t * y * z - s * x},
           {t * x * z - s * y, t * y * z + s * x, t * z * z + c}}};
}

Vec3 apply(const Mat3& r, const Vec3& v) {
  return {r[0][0] * v.x + r[0][1] * v.y + r[0][2] * v.z, r[1][0] * v.x + r[1][1] * v.y + r[1][2] * v.z,
          r[2][0] * v.x + r[2][1] * v.y + r[2][2] * v.z};
}

/// A body's shape: vertices about its centre, outward-oriented triangles.
struct Shape {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
};

Shape cube(double edge) {
  Shape s;
  const double h = edge / 2;
  for (int i = 0; i < 8; ++i) s.vertices.push_back({i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h});
  s.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return s;
}

Shape tetrahedron(double edge) {
  // Base: an equilateral triangle of circumradius edge / sqrt(3); apex above its centroid at the
  // height edge * sqrt(2/3); centred on the centroid of the solid (a quarter of the height up).
  const double r = edge / std::sqrt(3.0), height = edge * std::sqrt(2.0 / 3.0), z0 = -height / 4;
  Shape s;
  for (int i = 0; i < 3; ++i)
    s.vertices.push_back({r * std::cos(2 * kPi * i / 3), r * std::sin(2 * kPi * i / 3), z0});
  s.vertices.push_back({0, 0, z0 + height});
  s.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  return s;
}

/// A rigid body of the pile over the step: its shape, pose at t0 and t1.
struct Body {
  const Shape* shape;
  Mat3 rotation_t0, rotation_t1;
  Vec3 centre_t0, centre_t1;
  std::vector<Vec3> at_t0() const {
    std::vector<Vec3> out;
    for (const Vec3& v : shape->vertices) {
      const Vec3 w = apply(rotation_t0, v);
      out.push_back({centre_t0.x + w.x, centre_t0.y + w.y, centre_t0.z + w.z});
    }
    return out;
  }
  std::vector<Vec3> at_t1() const {
    std::vector<Vec3> out;
    for (const Vec3& v : shape->vertices) {
      const Vec3 w = apply(rotation_t1, v);
      out.push_back({centre_t1.x + w.x, centre_t1.y + w.y, centre_t1.z + w.z});
    }
    return out;
  }
};

}  // namespace

MovingMesh falling_pile(int resolution, std::uint64_t seed) {
  Rng rng(seed);
  const double cell = 2.0 / resolution;  // bodies on a lattice over [-1, 1]^2
  const Shape shapes[2] = {cube(0.55 * cell), tetrahedron(0.75 * cell)};
  const int layers = 3;
  MovingMesh scene = grid(2 * resolution, 2 * resolution, -1.2, 1.2, -1.2, 1.2);  // the ground
  struct Placed {
    double lo[2], hi[2], top;  // footprint (x, y) and highest point at t0
  };
  std::vector<Placed> below, current;
  for (int layer = 0; layer < layers; ++layer) {
    const double shift = layer % 2 ? cell / 2 : 0;
    current.clear();
    for (int j = 0; j < resolution; ++j)
      for (int i = 0; i < resolution; ++i) {
        Body b;
        b.shape = &shapes[(i + j + layer) % 2];
        // Pose at t0: a random turn about z, a slight tilt; jittered lattice position.
        const double yaw = rng.uniform(0, 2 * kPi), tilt_x = rng.uniform(-0.05, 0.05),
                     tilt_y = rng.uniform(-0.05, 0.05);
        b.rotation_t0 = multiply(rotation(0, 0, 1, yaw),
                                 multiply(rotation(1, 0, 0, tilt_x), rotation(0, 1, 0, tilt_y)));
        b.centre_t0 = {-1 + (i + 0.5) * cell + shift + rng.uniform(-0.06, 0.06) * cell,
                       -1 + (j + 0.5) * cell + shift + rng.uniform(-0.06, 0.06) * cell, 0};
        std::vector<Vec3> p = b.at_t0();
        Placed f{{p[0].x, p[0].y}, {p[0].x, p[0].y}, 0};
        double bottom = p[0].z;
        for (const Vec3& v : p) {
          f.lo[0] = std::min(f.lo[0], v.x), f.hi[0] = std::max(f.hi[0], v.x);
          f.lo[1] = std::min(f.lo[1], v.y), f.hi[1] = std::max(f.hi[1], v.y);
          bottom = std::min(bottom, v.z);
          f.top = std::max(f.top, v.z);
        }
        // Rests a small gap above the highest body of the layer below under its footprint.
        double support = 0;
        for (const Placed& o : below)
          if (o.lo[0] <= f.hi[0] && f.lo[0] <= o.hi[0] && o.lo[1] <= f.hi[1] && f.lo[1] <= o.hi[1])
            support = std::max(support, o.top);
        const double lift = support + rng.uniform(0.001, 0.015) - bottom;
        b.centre_t0.z += lift;
        f.top += lift;
        current.push_back(f);
        // The step: falls by up to 0.008, drifts sideways, turns by up to 0.03 rad.
        double ax, ay, az, norm;
        do {  // a random direction: a point of the unit ball, away from its centre
          ax = rng.uniform(-1, 1), ay = rng.uniform(-1, 1), az = rng.uniform(-1, 1);
          norm = std::sqrt(ax * ax + ay * ay + az * az);
        } while (norm < 0.1 || norm > 1);
        b.rotation_t1 = multiply(rotation(ax / norm, ay / norm, az / norm, rng.uniform(-0.03, 0.03)),
                                 b.rotation_t0);
        b.centre_t1 = {b.centre_t0.x + rng.uniform(-0.002, 0.002), b.centre_t0.y + rng.uniform(-0.002, 0.002),
                       b.centre_t0.z - rng.uniform(0, 0.008)};
        MovingMesh body;
        body.positions_t0 = b.at_t0();
        body.positions_t1 = b.at_t1();
        body.triangles = b.shape->triangles;
        append(scene, body);
      }
    below.swap(current);
  }
  return scene;
}

MovingMesh procedural_scene(const std::string& name, int resolution, std::uint64_t seed) {
  if (resolution < 2) throw std::invalid_argument("scene resolution must be at least 2");
  if (name == "cloth") return cloth_on_sphere(resolution, seed);
  if (name == "strip") return twisting_strip(resolution, seed);
  if (name == "fold") return folding_sheet(resolution, seed);
  if (name == "pile") return falling_pile(resolution, seed);
  throw std::invalid_argument("unknown scene '" + name + "' (expected cloth, strip, fold or pile)");
}

}  // namespace exactccd::scene
