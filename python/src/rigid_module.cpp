// The rigid motion model in the Python module (docs/design.md 9): batch functions over arrays of
// rigid queries (40 numbers each, the order of the CLI's lines and the C API) and the scene
// functions over rigid bodies, with the module's input rules (arrays.hpp). Called from module.cpp's PYBIND11_MODULE (define_rigid).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <limits>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "batch.hpp"
#include "interruptible.hpp"
#include "exactccd/rigid.hpp"
#include "rigid/rigid_layout.hpp"
#include "rigid/validation.hpp"
#include "scene/parallel.hpp"

namespace py = pybind11;

namespace exactccd::python {
namespace {

using IndexArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

template <class Query>
struct RigidBatch {
  static constexpr int stride = static_cast<int>(rigid::kQueryNumbers);

  /// Validates every query (the library's message, prefixed with the row) and the parameters.
  static DoubleArray prepare(const py::handle& obj, const CcdParams& params) {
    DoubleArray a = float_array(obj, "q", {-1, stride}, "(N, 40)");
    Query valid{};  // all zero but the quaternions: the parameters checked, also for an empty batch
    for (RigidPose* p : {&valid.a_t0, &valid.a_t1, &valid.b_t0, &valid.b_t1}) p->q = {1, 0, 0, 0};
    (void)exactccd::ccd(valid, params, Method::filtered);
    const std::size_t n = static_cast<std::size_t>(a.shape(0));
    for (std::size_t i = 0; i < n; ++i) {
      const Query q = rigid::from_numbers<Query>(a.data() + i * stride);
      bool finite = true;
      for (int k = 0; k < stride; ++k) finite = finite && std::isfinite(a.data()[i * stride + k]);
      // (the exact test only on finite numbers: GMP traps on NaN)
      const bool vanishes = finite && (rigid::quaternion_path_vanishes(q.a_t0.q, q.a_t1.q) ||
                                        rigid::quaternion_path_vanishes(q.b_t0.q, q.b_t1.q));
      if (finite && !vanishes) continue;
      try {
        (void)exactccd::ccd(q, params);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("q[" + std::to_string(i) + "]: " + e.what());
      }
    }
    return a;
  }

  static Query query(const double* numbers) { return rigid::from_numbers<Query>(numbers); }

  static py::array_t<bool> ccd(const py::handle& obj, double min_distance, double tmax, long long threads) {
    const CcdParams params{min_distance, tmax};
    const DoubleArray a = prepare(obj, params);
    return batch_ccd(a, stride, params, to_threads(threads), query);
  }

  static py::array_t<double> toi(const py::handle& obj, double min_distance, double tmax, long long threads) {
    const CcdParams params{min_distance, tmax};
    const DoubleArray a = prepare(obj, params);
    return batch_toi(a, stride, params, to_threads(threads), query);
  }
};

/// A body from a tuple (V, F, c0, q0, c1, q1).
RigidBody body_of(const py::handle& item, std::size_t index) {
  const std::string name = "bodies[" + std::to_string(index) + "]";
  const py::tuple t = py::reinterpret_borrow<py::object>(item).cast<py::tuple>();
  if (t.size() != 6) throw py::value_error(name + " must be a tuple (V, F, c0, q0, c1, q1)");
  const DoubleArray V = float_array(t[0], name + " V", {-1, 3}, "(n, 3)");
  py::array f = py::array::ensure(t[1]);
  if (!f || f.dtype().kind() != 'i' || f.ndim() != 2 || f.shape(1) != 3)
    throw py::value_error(name + " F must be an integer array of shape (m, 3)");
  const IndexArray F = IndexArray::ensure(f);
  RigidBody b;
  for (py::ssize_t i = 0; i < V.shape(0); ++i) b.vertices.push_back({V.data()[3 * i], V.data()[3 * i + 1], V.data()[3 * i + 2]});
  for (py::ssize_t i = 0; i < F.shape(0); ++i) {
    std::array<int, 3> tri;
    for (int k = 0; k < 3; ++k) {
      const std::int64_t v = F.data()[3 * i + k];
      if (v < 0 || v > std::numeric_limits<int>::max()) throw py::value_error(name + " F: index out of range");
      tri[k] = static_cast<int>(v);
    }
    b.triangles.push_back(tri);
  }
  const auto vec = [&](const py::handle& o, const char* what) {
    const DoubleArray a = float_array(o, name + " " + what, {3}, "(3,)");
    return Vec3{a.data()[0], a.data()[1], a.data()[2]};
  };
  const auto quat = [&](const py::handle& o, const char* what) {
    const DoubleArray a = float_array(o, name + " " + what, {4}, "(4,)");
    return Quaternion{a.data()[0], a.data()[1], a.data()[2], a.data()[3]};
  };
  b.t0 = {vec(t[2], "c0"), quat(t[3], "q0")};
  b.t1 = {vec(t[4], "c1"), quat(t[5], "q1")};
  return b;
}

std::vector<RigidBody> bodies_of(const py::sequence& bodies) {
  std::vector<RigidBody> out;
  for (std::size_t i = 0; i < bodies.size(); ++i) out.push_back(body_of(bodies[i], i));
  return out;
}

SceneOptions options_of(double min_distance, double tmax, long long threads) {
  return SceneOptions{to_threads(threads), min_distance, tmax};
}

py::dict find_collisions(const py::sequence& bodies, double min_distance, double tmax, long long threads) {
  const std::vector<RigidBody> b = bodies_of(bodies);
  const SceneOptions options = options_of(min_distance, tmax, threads);
  const std::vector<RigidCollision> hits =
      with_cancel(options, [&](const SceneOptions& oc) { return rigid_find_collisions(b, oc); });
  const auto n = static_cast<py::ssize_t>(hits.size());
  py::array_t<std::int64_t> kind(n), body_a(n), body_b(n), vertex(n), triangle(n);
  py::array_t<std::int64_t> edge_a(py::array::ShapeContainer({n, py::ssize_t{2}})), edge_b(py::array::ShapeContainer({n, py::ssize_t{2}}));
  py::array_t<double> toi(py::array::ShapeContainer({n, py::ssize_t{2}}));
  for (py::ssize_t i = 0; i < n; ++i) {
    const RigidCollision& c = hits[static_cast<std::size_t>(i)];
    kind.mutable_data()[i] = static_cast<int>(c.kind);
    body_a.mutable_data()[i] = c.body_a, body_b.mutable_data()[i] = c.body_b;
    vertex.mutable_data()[i] = c.vertex, triangle.mutable_data()[i] = c.triangle;
    for (int k = 0; k < 2; ++k) edge_a.mutable_data()[2 * i + k] = c.edge_a[k], edge_b.mutable_data()[2 * i + k] = c.edge_b[k];
    toi.mutable_data()[2 * i] = c.toi.lo, toi.mutable_data()[2 * i + 1] = c.toi.hi;
  }
  py::dict d;
  d["kind"] = kind, d["body_a"] = body_a, d["body_b"] = body_b, d["vertex"] = vertex, d["triangle"] = triangle;
  d["edge_a"] = edge_a, d["edge_b"] = edge_b, d["toi"] = toi;
  return d;
}

py::object earliest_toi(const py::sequence& bodies, double min_distance, double tmax, long long threads) {
  const std::vector<RigidBody> b = bodies_of(bodies);
  const SceneOptions options = options_of(min_distance, tmax, threads);
  const std::optional<TimeInterval> t =
      with_cancel(options, [&](const SceneOptions& oc) { return rigid_earliest_toi(b, oc); });
  if (!t) return py::none();
  return py::make_tuple(t->lo, t->hi);
}

double max_step(const py::sequence& bodies, double min_distance, double tmax, long long threads) {
  const std::vector<RigidBody> b = bodies_of(bodies);
  const SceneOptions options = options_of(min_distance, tmax, threads);
  return with_cancel(options, [&](const SceneOptions& oc) { return rigid_max_collision_free_step(b, oc); });
}

/// Keeps a docstring alive for the interpreter's life.
const char* keep(std::string s) {
  static std::vector<std::unique_ptr<std::string>> strings;
  strings.push_back(std::make_unique<std::string>(std::move(s)));
  return strings.back()->c_str();
}

}  // namespace

void define_rigid(py::module_& m) {
  const std::string common =
      "q: array of shape (N, 40) (float64, or float32, float16 or integers, taken exactly), one rigid query per row: cA0 (3), qA0 (4: w x y z), cA1 (3), qA1 (4), cB0 "
      "(3), qB0 (4), cB1 (3), qB1 (4), then the body points (vertex-face: p of A, a b c of B; edge-edge: a0 a1 of A, "
      "b0 b1 of B). Each body moves from pose (c0, q0) to (c1, q1), c and q interpolated linearly, a point p at "
      "c + R(q) p with R(q) = M(q) / |q|^2.\nmin_distance: d >= 0; tmax in (0, 1]; threads: worker threads in 0..1024 (0: "
      "every hardware thread).\nRaises ValueError for a wrong shape or dtype, a non-finite number or a quaternion path through zero "
      "(naming the row), or bad parameters.";
  m.def("rigid_vertex_face_ccd", &RigidBatch<RigidVertexFaceQuery>::ccd, py::arg("q"), py::arg("min_distance") = 0.0,
        py::arg("tmax") = 1.0, py::arg("threads") = 0,
        keep(std::string("Exact rigid vertex-face CCD of a batch: an (N,) bool array.\n\n") + common));
  m.def("rigid_vertex_face_toi", &RigidBatch<RigidVertexFaceQuery>::toi, py::arg("q"), py::arg("min_distance") = 0.0,
        py::arg("tmax") = 1.0, py::arg("threads") = 0,
        keep(std::string("Exact rigid vertex-face time of impact of a batch: an (N, 2) array of [lo, hi], the tightest "
                     "double interval of the earliest t in [0, tmax] within min_distance; NaN rows without a "
                     "collision.\n\n") + common));
  m.def("rigid_edge_edge_ccd", &RigidBatch<RigidEdgeEdgeQuery>::ccd, py::arg("q"), py::arg("min_distance") = 0.0,
        py::arg("tmax") = 1.0, py::arg("threads") = 0,
        keep(std::string("Exact rigid edge-edge CCD of a batch: an (N,) bool array.\n\n") + common));
  m.def("rigid_edge_edge_toi", &RigidBatch<RigidEdgeEdgeQuery>::toi, py::arg("q"), py::arg("min_distance") = 0.0,
        py::arg("tmax") = 1.0, py::arg("threads") = 0,
        keep(std::string("Exact rigid edge-edge time of impact of a batch: (N, 2) [lo, hi], NaN rows without a "
                     "collision.\n\n") + common));
  const std::string bodies_doc =
      "bodies: a sequence of tuples (V, F, c0, q0, c1, q1): V (n, 3) body coordinates (taken exactly, as q above), F integer (m, 3) "
      "triangles, c0, c1 (3,) translations and q0, q1 (4,) quaternions (w x y z) at t = 0 and 1. Pairs between "
      "different bodies: vertex-face both ways, edge-edge.";
  m.def("rigid_find_collisions", &find_collisions, py::arg("bodies"), py::arg("min_distance") = 0.0,
        py::arg("tmax") = 1.0, py::arg("threads") = 0,
        keep(std::string("Every colliding pair of rigid bodies: a dict of arrays kind (0 vertex-face, 1 edge-edge), "
                     "body_a, body_b, vertex, triangle, edge_a (k, 2), edge_b (k, 2), toi (k, 2).\n\n") + bodies_doc));
  m.def("rigid_earliest_toi", &earliest_toi, py::arg("bodies"), py::arg("min_distance") = 0.0, py::arg("tmax") = 1.0,
        py::arg("threads") = 0,
        keep(std::string("The earliest time of impact of rigid bodies: (lo, hi) or None.\n\n") + bodies_doc));
  m.def("rigid_max_collision_free_step", &max_step, py::arg("bodies"), py::arg("min_distance") = 0.0,
        py::arg("tmax") = 1.0, py::arg("threads") = 0,
        keep(std::string("The largest collision-free step of rigid bodies (tmax without a collision).\n\n") + bodies_doc));
}

}  // namespace exactccd::python
