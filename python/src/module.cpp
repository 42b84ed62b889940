// The Python module exactccd._exactccd (python/exactccd/__init__.py re-exports it): NumPy batch
// functions over every primitive kind (one template over lib/kinds, never a copy per kind), the
// scene functions on arrays, and the mesh reader. The GIL is released while the library works;
// batches are spread over threads with the library's oneTBB loops (lib/scene/parallel.hpp);
// the batch narrow phase over the caller's own candidates (exactccd/candidates.hpp).
//
// Errors: the library's std::invalid_argument becomes ValueError (pybind11's own translation),
// with the message unchanged; the bindings' checks of shapes and dtypes raise ValueError too;
// the mesh reader's io::InputError (file:line errors) becomes ValueError, a missing file
// FileNotFoundError.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <type_traits>
#include <stdexcept>
#include <string>
#include <vector>

#include "exactccd/candidates.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/exactccd.h"
#include "exactccd/scene.hpp"
#include "exactccd/types.hpp"
#include "io/input_file.hpp"
#include "io/mesh_file.hpp"
#include "kinds/primitive_kinds.hpp"
#include "scene/parallel.hpp"
#include "arrays.hpp"
#include "batch.hpp"
#include "interruptible.hpp"

namespace py = pybind11;

namespace exactccd::python {

/// The rigid motion model's functions (rigid_module.cpp).
void define_rigid(py::module_& m);

namespace {

/// A C-contiguous int64 array.
using IndexArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

/// An array of type A (an array_t) of the given shape.
template <class A>
A shaped(std::vector<py::ssize_t> shape) {
  return A(py::array::ShapeContainer(std::move(shape)));
}

std::string shape_string(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) {
    if (i > 0) s += ", ";
    s += std::to_string(a.shape(i));
  }
  if (a.ndim() == 1) s += ",";
  return s + ")";
}

std::string dtype_string(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

/// `obj` as a NumPy array (lists and other array-likes are converted by NumPy).
py::array as_array(const py::handle& obj, const std::string& name) {
  if (obj.is_none()) throw py::value_error(name + " must be an array, not None");
  py::array a = py::array::ensure(obj);
  if (!a) {
    PyErr_Clear();
    throw py::value_error(name + " must be an array, not " +
                          py::str(py::type::handle_of(obj).attr("__name__")).cast<std::string>());
  }
  return a;
}

/// The index of the `flat`-th element of `a` (C order) as text, e.g. "[3, 1]".
std::string index_text(const py::array& a, py::ssize_t flat) {
  std::vector<py::ssize_t> index(static_cast<std::size_t>(a.ndim()));
  for (py::ssize_t k = a.ndim() - 1; k >= 0; --k) {
    index[static_cast<std::size_t>(k)] = flat % a.shape(k);
    flat /= a.shape(k);
  }
  std::string s = "[";
  for (std::size_t k = 0; k < index.size(); ++k) s += (k ? ", " : "") + std::to_string(index[k]);
  return s + "]";
}

/// Throws ValueError naming the first element of the integer array `a` (element type T) that
/// is not exactly a double. static_cast<double> rounds v to a double; v is one iff that double
/// converts back to v, tested only inside T's range (a double of magnitude 2^63, or 2^64
/// unsigned, is outside it: converting it back would be undefined; only -2^63 is exact there).
template <class T>
void require_exact_doubles(const py::array& a, const std::string& name) {
  if constexpr (sizeof(T) <= 4) return;  // every 32-bit integer is a double
  const auto c = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(a);
  for (py::ssize_t i = 0; i < c.size(); ++i) {
    const T v = c.data()[i];
    const double d = static_cast<double>(v);
    const bool exact = std::is_signed_v<T> ? (d == -0x1p63 || (d > -0x1p63 && d < 0x1p63 && static_cast<T>(d) == v))
                                           : (d < 0x1p64 && static_cast<T>(d) == v);
    if (!exact)
      throw py::value_error(name + index_text(a, i) + " = " + std::to_string(v) +
                            " is not exactly a double: an integer array is taken only when every value is "
                            "one (convert it yourself, e.g. numpy.asarray(" + name +
                            ", dtype=numpy.float64), to choose the rounding)");
  }
}

/// Throws ValueError unless every value of `a` is exactly a double: floating-point arrays of at
/// most 64 bits (float16, float32 and float64 widen exactly); integer arrays whose every value
/// is a double (any of 32 bits or fewer; 64-bit ones checked value by value).
void require_exact_dtype(const py::array& a, const std::string& name) {
  const char kind = a.dtype().kind();
  if (kind == 'f' && a.itemsize() <= 8) return;
  if (kind == 'i' || kind == 'u') {
    if (a.itemsize() <= 4) return;
    if (kind == 'i') require_exact_doubles<std::int64_t>(a, name);
    else require_exact_doubles<std::uint64_t>(a, name);
    return;
  }
  throw py::value_error(name + " must be an array of float64 (or float32, float16, or integers that are exact "
                        "doubles), not " + dtype_string(a));
}

}  // namespace

/// `obj` as a C-contiguous float64 array of `ndim` dimensions whose trailing dimensions are
/// `tail` (-1: any). Coordinates are taken exactly, never rounded: float64 as it is, float32
/// and float16 widened (exact), integers when each is a double (require_exact_dtype).
DoubleArray float_array(const py::handle& obj, const std::string& name, std::vector<py::ssize_t> shape,
                        const std::string& expected) {
  py::array a = as_array(obj, name);
  bool ok = a.ndim() == static_cast<py::ssize_t>(shape.size());
  for (std::size_t i = 0; ok && i < shape.size(); ++i) ok = shape[i] < 0 || a.shape(i) == shape[i];
  if (!ok) throw py::value_error(name + " must have shape " + expected + ", not " + shape_string(a));
  require_exact_dtype(a, name);
  return DoubleArray::ensure(a);
}

namespace {

/// `obj` as a C-contiguous int64 array of shape (n, width) (width 0: shape (n,)); None and
/// empty arrays of any dtype give an empty array.
IndexArray index_array(const py::handle& obj, const std::string& name, py::ssize_t width) {
  const std::string expected = width > 0 ? "(n, " + std::to_string(width) + ")" : "(n,)";
  if (obj.is_none()) return width > 0 ? shaped<IndexArray>({0, width}) : IndexArray(py::ssize_t{0});
  py::array a = as_array(obj, name);
  if (a.size() == 0 && (a.ndim() == 1 || (width > 0 && a.ndim() == 2 && a.shape(1) == width)))
    return width > 0 ? shaped<IndexArray>({0, width}) : IndexArray(py::ssize_t{0});
  if (a.dtype().kind() != 'i' && a.dtype().kind() != 'u')
    throw py::value_error(name + " must be an integer array, not " + dtype_string(a));
  if (width > 0 ? (a.ndim() != 2 || a.shape(1) != width) : a.ndim() != 1)
    throw py::value_error(name + " must have shape " + expected + ", not " + shape_string(a));
  if (a.dtype().kind() == 'u' && a.itemsize() == 8) {  // values above 2^63 would wrap
    auto u = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    for (py::ssize_t i = 0; i < u.size(); ++i)
      if (u.data()[i] > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
        throw py::value_error(name + ": index " + std::to_string(u.data()[i]) + " is out of range");
  }
  return IndexArray::ensure(a);
}

int to_index(std::int64_t v, const std::string& name) {
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
    throw py::value_error(name + ": index " + std::to_string(v) + " is out of range");
  return static_cast<int>(v);
}

template <std::size_t W>
std::vector<std::array<int, W>> to_tuples(const IndexArray& a, const std::string& name) {
  std::vector<std::array<int, W>> out(static_cast<std::size_t>(a.size()) / W);
  for (std::size_t i = 0; i < out.size(); ++i)
    for (std::size_t k = 0; k < W; ++k) out[i][k] = to_index(a.data()[i * W + k], name);
  return out;
}

std::vector<int> to_ints(const IndexArray& a, const std::string& name) {
  std::vector<int> out(static_cast<std::size_t>(a.size()));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = to_index(a.data()[i], name);
  return out;
}

/// The threads argument, in the library's one range 0..kMaxThreads (SceneOptions::threads; the
/// command line's --threads takes 1..1024): anything else is a ValueError, never capped.
unsigned checked_threads(long long threads) {
  if (threads < 0 || threads > static_cast<long long>(kMaxThreads))
    throw py::value_error("threads must be in 0.." + std::to_string(kMaxThreads) +
                          " (0: every hardware thread), not " + std::to_string(threads));
  return static_cast<unsigned>(threads);
}

}  // namespace

/// The number of worker threads for `threads` (0: every hardware thread).
unsigned to_threads(long long threads) { return scene::resolve_threads(checked_threads(threads)); }

namespace {

/// Keeps the names and docstrings of the generated functions alive for the interpreter's life.
const char* keep(std::string s) {
  static std::deque<std::string> strings;
  strings.push_back(std::move(s));
  return strings.back().c_str();
}

// --- batch functions, one template over the kinds --------------------------------------------

template <class Kind>
struct Batch {
  using Query = typename Kind::template Query<double>;
  static constexpr int rows = 2 * Kind::points;
  static constexpr int dim = Kind::dimension;
  static constexpr int stride = rows * dim;

  static Query query(const double* p) {
    if constexpr (dim == 3) {
      std::array<Vec3, rows> r;
      for (int i = 0; i < rows; ++i) r[i] = Vec3{p[3 * i], p[3 * i + 1], p[3 * i + 2]};
      return from_rows<Query>(r);
    } else {
      std::array<Vec2, rows> r;
      for (int i = 0; i < rows; ++i) r[i] = Vec2{p[2 * i], p[2 * i + 1]};
      return from_rows<Query>(r);
    }
  }

  static std::string expected() {
    return "(N, " + std::to_string(rows) + ", " + std::to_string(dim) + ")";
  }

  /// The checked input and the parameters, validated by the library (its own messages): the
  /// parameters on an all-zero query, so that an empty batch refuses them too; the first row
  /// with a non-finite coordinate, prefixed with its index.
  static DoubleArray prepare(const py::handle& obj, const CcdParams& params, bool want_toi) {
    DoubleArray a = float_array(obj, "q", {-1, rows, dim}, expected());
    const auto check = [&](const Query& q) {
      if (want_toi)
        (void)exactccd::toi(q, params);
      else
        (void)exactccd::ccd(q, params);
    };
    check(Query{});
    const double* data = a.data();
    const std::size_t n = static_cast<std::size_t>(a.shape(0));
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < stride; ++k) {
        if (std::isfinite(data[i * stride + k])) continue;
        try {
          check(query(data + i * stride));
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument("q[" + std::to_string(i) + "]: " + e.what());
        }
        throw std::invalid_argument("q[" + std::to_string(i) + "]: non-finite coordinate");
      }
    }
    return a;
  }

  static py::array_t<bool> ccd(const py::handle& obj, double min_distance, double tmax, long long threads) {
    const CcdParams params{min_distance, tmax};
    const DoubleArray a = prepare(obj, params, false);
    return batch_ccd(a, stride, params, to_threads(threads), query);
  }

  static py::array_t<double> toi(const py::handle& obj, double min_distance, double tmax, long long threads) {
    const CcdParams params{min_distance, tmax};
    const DoubleArray a = prepare(obj, params, true);
    return batch_toi(a, stride, params, to_threads(threads), query);
  }

  static void define(py::module_& m) {
    const std::string stem(Kind::function), name(Kind::name);
    std::string points;
    for (int t = 0; t < 2; ++t)
      for (std::string_view p : Kind::point_names) points += (points.empty() ? "" : ", ") + std::string(p) + "_t" + std::to_string(t);
    const std::string shape = expected();
    const std::string common =
        "q: float64 array of shape " + shape + ", one query per row block, points in file row order (" +
        points + ").\nmin_distance: d, finite and >= 0; a query collides iff some t in [0, tmax] puts its two "
        "closed primitives within distance <= d (0: contact).\ntmax: the time limit, in (0, 1].\nthreads: "
        "worker threads (0: every hardware thread); the answers do not depend on it.\n"
        "The GIL is released during the work. Raises ValueError (the library's message) for a wrong shape "
        "or dtype, a NaN or infinite coordinate (naming the row), or a bad min_distance or tmax.";
    m.def(keep(stem + "_ccd"), &Batch::ccd, py::arg("q"), py::arg("min_distance") = 0.0, py::arg("tmax") = 1.0,
          py::arg("threads") = 0,
          keep("Exact " + name + " CCD of a batch: an (N,) bool array, True where the query collides.\n\n" + common));
    m.def(keep(stem + "_toi"), &Batch::toi, py::arg("q"), py::arg("min_distance") = 0.0, py::arg("tmax") = 1.0,
          py::arg("threads") = 0,
          keep("Exact " + name + " time of impact of a batch: an (N, 2) float64 array of [lo, hi], the tightest "
               "double interval holding the earliest t in [0, tmax] at which the primitives are within "
               "min_distance (lo == hi when that time is a double); NaN rows where there is no collision.\n\n" +
               common));
  }
};

// --- scenes ----------------------------------------------------------------------------------

/// A 3D or 2D scene from arrays.
struct SceneInput {
  bool planar = false;
  Scene s3;
  Scene2d s2;
};

SceneInput make_scene(const py::handle& v0_obj, const py::handle& v1_obj, const py::handle& f_obj,
                      const py::handle& e_obj, const py::handle& p_obj) {
  py::array v0a = as_array(v0_obj, "V0");
  const py::ssize_t d = v0a.ndim() == 2 ? v0a.shape(1) : 3;
  if (d != 2 && d != 3) throw py::value_error("V0 must have shape (n, 3) or (n, 2), not " + shape_string(v0a));
  const std::string expected = d == 3 ? "(n, 3)" : "(n, 2)";
  const DoubleArray v0 = float_array(v0a, "V0", {-1, d}, expected);
  const DoubleArray v1 = float_array(v1_obj, "V1", {-1, d}, expected);
  if (v0.shape(0) != v1.shape(0))
    throw py::value_error("V0 and V1 must have the same shape, not " + shape_string(v0) + " and " + shape_string(v1));
  SceneInput s;
  s.planar = d == 2;
  const std::size_t n = static_cast<std::size_t>(v0.shape(0));
  const IndexArray f = index_array(f_obj, "F", 3), e = index_array(e_obj, "E", 2), p = index_array(p_obj, "P", 0);
  if (s.planar) {
    if (f.size() != 0) throw py::value_error("F: a 2D scene (V0 of shape (n, 2)) has no triangles; pass edges as E");
    s.s2.positions_t0.resize(n);
    s.s2.positions_t1.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      s.s2.positions_t0[i] = Vec2{v0.data()[2 * i], v0.data()[2 * i + 1]};
      s.s2.positions_t1[i] = Vec2{v1.data()[2 * i], v1.data()[2 * i + 1]};
    }
    s.s2.edges = to_tuples<2>(e, "E");
    s.s2.points = to_ints(p, "P");
  } else {
    s.s3.positions_t0.resize(n);
    s.s3.positions_t1.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      s.s3.positions_t0[i] = Vec3{v0.data()[3 * i], v0.data()[3 * i + 1], v0.data()[3 * i + 2]};
      s.s3.positions_t1[i] = Vec3{v1.data()[3 * i], v1.data()[3 * i + 1], v1.data()[3 * i + 2]};
    }
    s.s3.triangles = to_tuples<3>(f, "F");
    s.s3.edges = to_tuples<2>(e, "E");
    s.s3.points = to_ints(p, "P");
  }
  return s;
}

SceneOptions make_options(double min_distance, double tmax, long long threads) {
  SceneOptions o;
  o.threads = to_threads(threads);
  o.min_distance = min_distance;
  o.tmax = tmax;
  return o;
}

py::dict collisions_dict(const std::vector<Collision>& cs) {
  const auto k = static_cast<py::ssize_t>(cs.size());
  py::array_t<std::int8_t> kind(k);
  IndexArray vertex(k), triangle(k), vertex_b(k);
  auto edge_a = shaped<IndexArray>({k, 2}), edge_b = shaped<IndexArray>({k, 2});
  auto toi = shaped<py::array_t<double>>({k, 2});
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const Collision& c = cs[i];
    kind.mutable_data()[i] = static_cast<std::int8_t>(c.kind);
    vertex.mutable_data()[i] = c.vertex;
    triangle.mutable_data()[i] = c.triangle;
    vertex_b.mutable_data()[i] = c.vertex_b;
    for (int j = 0; j < 2; ++j) {
      edge_a.mutable_data()[2 * i + j] = c.edge_a[j];
      edge_b.mutable_data()[2 * i + j] = c.edge_b[j];
    }
    toi.mutable_data()[2 * i] = c.toi.lo;
    toi.mutable_data()[2 * i + 1] = c.toi.hi;
  }
  py::dict d;
  d["kind"] = kind;
  d["vertex"] = vertex;
  d["triangle"] = triangle;
  d["edge_a"] = edge_a;
  d["edge_b"] = edge_b;
  d["vertex_b"] = vertex_b;
  d["toi"] = toi;
  return d;
}

py::dict find_collisions_py(const py::handle& v0, const py::handle& v1, const py::handle& f, const py::handle& e,
                            const py::handle& p, double min_distance, double tmax, long long threads) {
  const SceneInput s = make_scene(v0, v1, f, e, p);
  const SceneOptions o = make_options(min_distance, tmax, threads);
  return collisions_dict(with_cancel(o, [&](const SceneOptions& oc) {
    return s.planar ? find_collisions(s.s2, oc) : find_collisions(s.s3, oc);
  }));
}

std::optional<std::pair<double, double>> earliest_toi_py(const py::handle& v0, const py::handle& v1,
                                                         const py::handle& f, const py::handle& e,
                                                         const py::handle& p, double min_distance, double tmax,
                                                         long long threads) {
  const SceneInput s = make_scene(v0, v1, f, e, p);
  const SceneOptions o = make_options(min_distance, tmax, threads);
  const std::optional<TimeInterval> t = with_cancel(o, [&](const SceneOptions& oc) {
    return s.planar ? earliest_toi(s.s2, oc) : earliest_toi(s.s3, oc);
  });
  if (!t) return std::nullopt;
  return std::make_pair(t->lo, t->hi);
}

bool is_collision_free_py(const py::handle& v0, const py::handle& v1, const py::handle& f, const py::handle& e,
                          const py::handle& p, double min_distance, double tmax, long long threads) {
  const SceneInput s = make_scene(v0, v1, f, e, p);
  const SceneOptions o = make_options(min_distance, tmax, threads);
  return with_cancel(o, [&](const SceneOptions& oc) {
    return s.planar ? is_collision_free(s.s2, oc) : is_collision_free(s.s3, oc);
  });
}

double max_collision_free_step_py(const py::handle& v0, const py::handle& v1, const py::handle& f,
                                  const py::handle& e, const py::handle& p, double min_distance, double tmax,
                                  long long threads) {
  const SceneInput s = make_scene(v0, v1, f, e, p);
  const SceneOptions o = make_options(min_distance, tmax, threads);
  return with_cancel(o, [&](const SceneOptions& oc) {
    return s.planar ? max_collision_free_step(s.s2, oc) : max_collision_free_step(s.s3, oc);
  });
}

bool intersection_free_py(const py::handle& v_obj, const py::handle& f_obj) {
  const DoubleArray v = float_array(v_obj, "V", {-1, 3}, "(n, 3)");
  const IndexArray f = index_array(f_obj, "F", 3);
  std::vector<Vec3> positions(static_cast<std::size_t>(v.shape(0)));
  for (std::size_t i = 0; i < positions.size(); ++i)
    positions[i] = Vec3{v.data()[3 * i], v.data()[3 * i + 1], v.data()[3 * i + 2]};
  const auto triangles = to_tuples<3>(f, "F");
  py::gil_scoped_release release;
  return intersection_free(positions, triangles);
}

py::tuple read_mesh_py(const py::handle& path_obj) {
  const std::string path = py::module_::import("os").attr("fspath")(path_obj).cast<std::string>();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    PyErr_SetObject(PyExc_FileNotFoundError,
                    py::make_tuple(2, "No such file or directory", path).ptr());  // errno ENOENT
    throw py::error_already_set();
  }
  io::TriangleMesh mesh;
  {
    py::gil_scoped_release release;
    mesh = io::read_mesh(path);
  }
  const auto n = static_cast<py::ssize_t>(mesh.vertices.size()), m = static_cast<py::ssize_t>(mesh.triangles.size());
  auto v = shaped<py::array_t<double>>({n, 3});
  auto f = shaped<IndexArray>({m, 3});
  for (py::ssize_t i = 0; i < n; ++i) {
    const Vec3& x = mesh.vertices[static_cast<std::size_t>(i)];
    v.mutable_data()[3 * i] = x.x;
    v.mutable_data()[3 * i + 1] = x.y;
    v.mutable_data()[3 * i + 2] = x.z;
  }
  for (py::ssize_t i = 0; i < m; ++i)
    for (int k = 0; k < 3; ++k) f.mutable_data()[3 * i + k] = mesh.triangles[static_cast<std::size_t>(i)][k];
  return py::make_tuple(v, f);
}

// --- the caller's own candidates (exactccd/candidates.hpp) ------------------------------------

/// Positions and candidates from arrays.
struct CandidateInput {
  std::vector<Vec3> x0, x1;
  CandidateSet set;
};

std::vector<Vec3> to_positions(const DoubleArray& a) {
  std::vector<Vec3> p(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = Vec3{a.data()[3 * i], a.data()[3 * i + 1], a.data()[3 * i + 2]};
  return p;
}

CandidateInput make_candidates(const py::handle& v0_obj, const py::handle& v1_obj, const py::handle& vf_obj,
                               const py::handle& ee_obj, const py::handle& pe_obj, const py::handle& pp_obj,
                               const py::handle& f_obj, const py::handle& e_obj) {
  const DoubleArray v0 = float_array(v0_obj, "V0", {-1, 3}, "(n, 3)");
  const DoubleArray v1 = float_array(v1_obj, "V1", {-1, 3}, "(n, 3)");
  if (v0.shape(0) != v1.shape(0))
    throw py::value_error("V0 and V1 must have the same shape, not " + shape_string(v0) + " and " + shape_string(v1));
  CandidateInput in{to_positions(v0), to_positions(v1), {}};
  const bool by_face = !f_obj.is_none(), by_edge = !e_obj.is_none();
  using Pairs = std::vector<std::array<int, 2>>;
  if (by_face) {
    const auto faces = to_tuples<3>(index_array(f_obj, "F", 3), "F");
    const auto vf = to_tuples<2>(index_array(vf_obj, "vertex_face (with F: rows {vertex, face})", 2), "vertex_face");
    in.set.vertex_face = candidates_from_elements(faces, {}, vf, {}).vertex_face;
  } else {
    in.set.vertex_face = to_tuples<4>(index_array(vf_obj, "vertex_face", 4), "vertex_face");
  }
  if (by_edge) {
    const auto edges = to_tuples<2>(index_array(e_obj, "E", 2), "E");
    const Pairs ee = to_tuples<2>(index_array(ee_obj, "edge_edge (with E: rows {edge, edge})", 2), "edge_edge");
    const Pairs pe = to_tuples<2>(index_array(pe_obj, "point_edge (with E: rows {vertex, edge})", 2), "point_edge");
    CandidateSet expanded = candidates_from_elements({}, edges, {}, ee, pe);
    in.set.edge_edge = std::move(expanded.edge_edge);
    in.set.point_edge = std::move(expanded.point_edge);
  } else {
    in.set.edge_edge = to_tuples<4>(index_array(ee_obj, "edge_edge", 4), "edge_edge");
    in.set.point_edge = to_tuples<3>(index_array(pe_obj, "point_edge", 3), "point_edge");
  }
  in.set.point_point = to_tuples<2>(index_array(pp_obj, "point_point", 2), "point_point");
  return in;
}

py::dict candidates_find_collisions_py(const py::handle& v0, const py::handle& v1, const py::handle& vf,
                                       const py::handle& ee, const py::handle& pe, const py::handle& pp,
                                       const py::handle& f, const py::handle& e, double min_distance, double tmax,
                                       long long threads) {
  const CandidateInput in = make_candidates(v0, v1, vf, ee, pe, pp, f, e);
  const SceneOptions o = make_options(min_distance, tmax, threads);
  const std::vector<CandidateCollision> cs =
      with_cancel(o, [&](const SceneOptions& oc) { return find_collisions(in.x0, in.x1, in.set, oc); });
  const auto k = static_cast<py::ssize_t>(cs.size());
  py::array_t<std::int8_t> kind(k);
  IndexArray index(k);
  auto toi = shaped<py::array_t<double>>({k, 2});
  for (std::size_t i = 0; i < cs.size(); ++i) {
    kind.mutable_data()[i] = static_cast<std::int8_t>(cs[i].kind);
    index.mutable_data()[i] = static_cast<std::int64_t>(cs[i].index);
    toi.mutable_data()[2 * i] = cs[i].toi.lo;
    toi.mutable_data()[2 * i + 1] = cs[i].toi.hi;
  }
  py::dict d;
  d["kind"] = kind;
  d["index"] = index;
  d["toi"] = toi;
  return d;
}

std::optional<std::pair<double, double>> candidates_earliest_toi_py(
    const py::handle& v0, const py::handle& v1, const py::handle& vf, const py::handle& ee, const py::handle& pe,
    const py::handle& pp, const py::handle& f, const py::handle& e, double min_distance, double tmax,
    long long threads) {
  const CandidateInput in = make_candidates(v0, v1, vf, ee, pe, pp, f, e);
  const SceneOptions o = make_options(min_distance, tmax, threads);
  const std::optional<TimeInterval> t =
      with_cancel(o, [&](const SceneOptions& oc) { return earliest_toi(in.x0, in.x1, in.set, oc); });
  if (!t) return std::nullopt;
  return std::make_pair(t->lo, t->hi);
}

bool candidates_is_collision_free_py(const py::handle& v0, const py::handle& v1, const py::handle& vf,
                                     const py::handle& ee, const py::handle& pe, const py::handle& pp,
                                     const py::handle& f, const py::handle& e, double min_distance, double tmax,
                                     long long threads) {
  const CandidateInput in = make_candidates(v0, v1, vf, ee, pe, pp, f, e);
  const SceneOptions o = make_options(min_distance, tmax, threads);
  return with_cancel(o, [&](const SceneOptions& oc) { return is_collision_free(in.x0, in.x1, in.set, oc); });
}

double candidates_max_collision_free_step_py(const py::handle& v0, const py::handle& v1, const py::handle& vf,
                                             const py::handle& ee, const py::handle& pe, const py::handle& pp,
                                             const py::handle& f, const py::handle& e, double min_distance,
                                             double tmax, long long threads) {
  const CandidateInput in = make_candidates(v0, v1, vf, ee, pe, pp, f, e);
  const SceneOptions o = make_options(min_distance, tmax, threads);
  return with_cancel(o, [&](const SceneOptions& oc) { return max_collision_free_step(in.x0, in.x1, in.set, oc); });
}

// --- the scene's broad phase kept across calls (exactccd::SceneBroadPhase) --------------------

/// exactccd.SceneBroadPhase: a thin wrapper over exactccd::SceneBroadPhase (built once, refitted
/// by update()), with the narrow phase over its candidates (exactccd/candidates.hpp), whose
/// answers equal the scene functions' on the current scene. Calls are serialised by a mutex
/// (the GIL is released during the work, and update() must not run concurrently with reads).
class PyBroadPhase {
 public:
  PyBroadPhase(const py::handle& v0, const py::handle& v1, const py::handle& f, const py::handle& e,
               const py::handle& p, double min_distance, double tmax, long long threads)
      : options_(make_options(min_distance, tmax, threads)) {
    const SceneInput s = make_scene(v0, v1, f, e, p);
    if (s.planar) throw py::value_error("SceneBroadPhase takes a 3D scene: V0 of shape (n, 3)");
    broad_ = with_cancel(options_, [&](const SceneOptions& oc) { return std::make_unique<SceneBroadPhase>(s.s3, oc); });
    refresh_candidates();
  }

  void update(const py::handle& v1_obj) {
    const DoubleArray v1 = float_array(v1_obj, "V1", {-1, 3}, "(n, 3)");
    const std::vector<Vec3> positions = to_positions(v1);
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(mutex_);  // without the GIL: see lock()
    broad_->update(positions);  // std::invalid_argument (size, non-finite) leaves it unchanged
    refresh_candidates();
  }

  py::dict candidates() {
    const auto held = lock();
    const SceneCandidates& c = broad_->candidates();
    py::dict d;
    d["vertex_face"] = pairs_array(c.vertex_face);
    d["edge_edge"] = pairs_array(c.edge_edge);
    d["point_edge"] = pairs_array(c.point_edge);
    d["point_point"] = pairs_array(c.point_point);
    return d;
  }

  IndexArray edges() {
    const auto held = lock();
    return pairs_array(broad_->edges());
  }

  py::dict find_collisions_now() {
    const auto held = lock();
    const Scene& s = broad_->scene();
    const std::vector<CandidateCollision> cs = with_cancel(options_, [&](const SceneOptions& oc) {
      return find_collisions(s.positions_t0, s.positions_t1, set_, oc);
    });
    std::vector<Collision> out;
    out.reserve(cs.size());
    for (const CandidateCollision& c : cs) out.push_back(as_scene_collision(c));
    return collisions_dict(out);
  }

  std::optional<std::pair<double, double>> earliest_toi_now() {
    const auto held = lock();
    const Scene& s = broad_->scene();
    const std::optional<TimeInterval> t = with_cancel(options_, [&](const SceneOptions& oc) {
      return earliest_toi(s.positions_t0, s.positions_t1, set_, oc);
    });
    if (!t) return std::nullopt;
    return std::make_pair(t->lo, t->hi);
  }

  bool is_collision_free_now() {
    const auto held = lock();
    const Scene& s = broad_->scene();
    return with_cancel(options_, [&](const SceneOptions& oc) {
      return is_collision_free(s.positions_t0, s.positions_t1, set_, oc);
    });
  }

  double max_collision_free_step_now() {
    const auto held = lock();
    const Scene& s = broad_->scene();
    return with_cancel(options_, [&](const SceneOptions& oc) {
      return max_collision_free_step(s.positions_t0, s.positions_t1, set_, oc);
    });
  }

  double min_distance() const { return options_.min_distance; }
  double tmax() const { return options_.tmax; }

 private:
  /// The object's mutex, taken with the GIL released (then the GIL again): a thread waiting
  /// for the mutex must not hold the GIL, which the holder's signal polling takes.
  std::unique_lock<std::mutex> lock() {
    py::gil_scoped_release release;
    return std::unique_lock<std::mutex>(mutex_);
  }

  template <std::size_t W>
  static IndexArray pairs_array(const std::vector<std::array<int, W>>& rows) {
    auto a = shaped<IndexArray>({static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(W)});
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (std::size_t k = 0; k < W; ++k) a.mutable_data()[W * i + k] = rows[i][k];
    return a;
  }

  /// The candidates by vertex index (CandidateSet), for the narrow phase of candidates.hpp.
  void refresh_candidates() {
    const SceneCandidates& c = broad_->candidates();
    const auto& tri = broad_->scene().triangles;
    const auto& edges = broad_->edges();
    const auto at = [](int i) { return static_cast<std::size_t>(i); };
    set_ = CandidateSet{};
    for (const auto& [v, t] : c.vertex_face)
      set_.vertex_face.push_back({v, tri[at(t)][0], tri[at(t)][1], tri[at(t)][2]});
    for (const auto& [i, j] : c.edge_edge)
      set_.edge_edge.push_back({edges[at(i)][0], edges[at(i)][1], edges[at(j)][0], edges[at(j)][1]});
    for (const auto& [p, e] : c.point_edge) set_.point_edge.push_back({p, edges[at(e)][0], edges[at(e)][1]});
    set_.point_point = c.point_point;
  }

  /// A colliding candidate as the scene functions report it (Collision).
  Collision as_scene_collision(const CandidateCollision& c) const {
    const SceneCandidates& cands = broad_->candidates();
    const auto& edges = broad_->edges();
    const auto at = [](int i) { return static_cast<std::size_t>(i); };
    Collision out;
    out.kind = c.kind;
    out.toi = c.toi;
    switch (c.kind) {
      case CollisionKind::vertex_face:
        out.vertex = cands.vertex_face[c.index][0];
        out.triangle = cands.vertex_face[c.index][1];
        break;
      case CollisionKind::edge_edge:
        out.edge_a = edges[at(cands.edge_edge[c.index][0])];
        out.edge_b = edges[at(cands.edge_edge[c.index][1])];
        break;
      case CollisionKind::point_edge:
        out.vertex = cands.point_edge[c.index][0];
        out.edge_a = edges[at(cands.point_edge[c.index][1])];
        break;
      case CollisionKind::point_point:
        out.vertex = cands.point_point[c.index][0];
        out.vertex_b = cands.point_point[c.index][1];
        break;
    }
    return out;
  }

  SceneOptions options_;
  std::unique_ptr<SceneBroadPhase> broad_;
  CandidateSet set_;
  std::mutex mutex_;
};

constexpr const char* kCandidateArgs =
    "V0, V1: float64 arrays of shape (n, 3), the vertex positions at t = 0 and t = 1.\n"
    "vertex_face: integer array (m, 4) of rows {vertex, a, b, c} (a vertex and a triangle), or, with F, "
    "(m, 2) of rows {vertex, face}.\n"
    "edge_edge: integer array (m, 4) of rows {a0, a1, b0, b1}, or, with E, (m, 2) of rows {edge, edge}.\n"
    "point_edge: integer array (m, 3) of rows {p, a, b}, or, with E, (m, 2) of rows {vertex, edge}.\n"
    "point_point: integer array (m, 2) of rows {p, q}.\n"
    "F: integer array (f, 3) of faces, or None; E: integer array (e, 2) of edges, or None.\n"
    "Every list may be None (empty); each is taken in the caller's order. Every kind is tested for "
    "every min_distance, including 0.\n"
    "min_distance: d, finite and >= 0 (0: contact).\ntmax: the time limit, in (0, 1].\n"
    "threads: worker threads (0: every hardware thread); the result does not depend on it.\n"
    "The GIL is released during the work. Raises ValueError (the library's message, naming the "
    "element) for a wrong shape or dtype, a NaN or infinite coordinate, an index out of range, a "
    "candidate whose two sides share a vertex index (it touches at t = 0 by construction) or whose "
    "triangle or edge repeats one, or bad options.";

constexpr const char* kSceneArgs =
    "V0, V1: float64 arrays of shape (n, 3) (or (n, 2) for a 2D scene), the vertex positions at t = 0 "
    "and t = 1.\nF: integer array (m, 3) of triangles (0-based; None or empty in 2D).\nE: integer array "
    "(k, 2) of extra edges (3D: codimensional edges; 2D: the edges), or None.\nP: integer array (p,) of "
    "points, or None.\nmin_distance: d, finite and >= 0 (0: contact).\ntmax: the time limit, in (0, 1].\n"
    "threads: narrow-phase threads (0: every hardware thread); the result does not depend on it.\n"
    "The GIL is released during the work. Raises ValueError (the library's message) for a malformed "
    "scene (shapes, dtypes, NaN or infinite coordinates, indices out of range or repeated) or bad options.";

/// The library's input errors (io::InputError: file:line messages) as ValueError.
void register_input_errors() {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const io::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
}

/// The batch functions of every kind of the one list, and KINDS: function stem -> (rows per
/// query, coordinates per row), from which the package imports them (exactccd/__init__.py).
void bind_batch_functions(py::module_& m) {
  py::dict batch_kinds;
  kinds::for_each_kind([&](auto kind) {
    using Kind = decltype(kind);
    Batch<Kind>::define(m);
    batch_kinds[py::str(std::string(Kind::function))] = py::make_tuple(2 * Kind::points, Kind::dimension);
  });
  m.attr("KINDS") = batch_kinds;
}

/// The collision kinds' numbers and names, as the scene functions report them.
void bind_collision_kinds(py::module_& m) {
  m.attr("VERTEX_FACE") = static_cast<int>(CollisionKind::vertex_face);
  m.attr("EDGE_EDGE") = static_cast<int>(CollisionKind::edge_edge);
  m.attr("POINT_EDGE") = static_cast<int>(CollisionKind::point_edge);
  m.attr("POINT_POINT") = static_cast<int>(CollisionKind::point_point);
  m.attr("KIND_NAMES") = py::make_tuple("vertex-face", "edge-edge", "point-edge", "point-point");
}

/// The scene functions on arrays: find_collisions, earliest_toi, is_collision_free and
/// max_collision_free_step.
void bind_scene_functions(py::module_& m) {
  const std::string args = kSceneArgs;
  m.def("find_collisions", &find_collisions_py, py::arg("V0"), py::arg("V1"), py::arg("F") = py::none(),
        py::arg("E") = py::none(), py::arg("P") = py::none(), py::arg("min_distance") = 0.0,
        py::arg("tmax") = 1.0, py::arg("threads") = 0,
        keep("Every colliding pair of the scene and its time of impact, as a dict of arrays, one entry per "
             "pair, in the library's order (by kind, then by indices):\n"
             "  kind: int8 (k,), VERTEX_FACE=0, EDGE_EDGE=1, POINT_EDGE=2, POINT_POINT=3 (KIND_NAMES);\n"
             "  vertex: int64 (k,), the vertex (vertex-face) or the (first) point (point-edge, point-point), "
             "else -1;\n"
             "  triangle: int64 (k,), the triangle's index in F (vertex-face), else -1;\n"
             "  edge_a: int64 (k, 2), the first edge (edge-edge) or the edge (point-edge), ascending "
             "vertex indices, else [-1, -1];\n"
             "  edge_b: int64 (k, 2), the second edge (edge-edge), else [-1, -1];\n"
             "  vertex_b: int64 (k,), the second point (point-point), else -1;\n"
             "  toi: float64 (k, 2), [lo, hi], the tightest double interval holding the exact time of "
             "impact.\nIn 3D, point-edge and point-point pairs are reported only for min_distance > 0; in 2D "
             "the kinds are edge-edge, point-edge and point-point.\n\n" +
             args));
  m.def("earliest_toi", &earliest_toi_py, py::arg("V0"), py::arg("V1"), py::arg("F") = py::none(),
        py::arg("E") = py::none(), py::arg("P") = py::none(), py::arg("min_distance") = 0.0,
        py::arg("tmax") = 1.0, py::arg("threads") = 0,
        keep("The scene's earliest time of impact as (lo, hi), the tightest double interval holding the exact "
             "earliest time in [0, tmax] at which some pair is within min_distance, or None.\n\n" +
             args));
  m.def("is_collision_free", &is_collision_free_py, py::arg("V0"), py::arg("V1"), py::arg("F") = py::none(),
        py::arg("E") = py::none(), py::arg("P") = py::none(), py::arg("min_distance") = 0.0,
        py::arg("tmax") = 1.0, py::arg("threads") = 0,
        keep("True iff no pair of the scene comes within min_distance at some t in [0, tmax].\n\n" + args));
  m.def("max_collision_free_step", &max_collision_free_step_py, py::arg("V0"), py::arg("V1"),
        py::arg("F") = py::none(), py::arg("E") = py::none(), py::arg("P") = py::none(),
        py::arg("min_distance") = 0.0, py::arg("tmax") = 1.0, py::arg("threads") = 0,
        keep("The largest step s <= tmax keeping every pair at distance > min_distance: tmax when no pair "
             "collides, else the largest double strictly below the earliest TOI's lo (0 for a collision at "
             "t = 0).\n\n" +
             args));
}

/// The narrow phase over the caller's own candidates (exactccd/candidates.hpp).
void bind_candidate_functions(py::module_& m) {
  const std::string cargs = kCandidateArgs;
  const auto candidate_function = [&](const char* name, auto f, const std::string& doc) {
    m.def(name, f, py::arg("V0"), py::arg("V1"), py::arg("vertex_face") = py::none(),
          py::arg("edge_edge") = py::none(), py::arg("point_edge") = py::none(), py::arg("point_point") = py::none(),
          py::arg("F") = py::none(), py::arg("E") = py::none(), py::arg("min_distance") = 0.0, py::arg("tmax") = 1.0,
          py::arg("threads") = 0, keep(doc + "\n\n" + cargs));
  };
  candidate_function("candidates_find_collisions", &candidates_find_collisions_py,
                     "Every colliding candidate of the caller's own candidate lists (e.g. from a simulator's broad "
                     "phase) and its time of impact, as a dict of arrays, sorted by kind then by row:\n"
                     "  kind: int8 (k,), VERTEX_FACE=0, EDGE_EDGE=1, POINT_EDGE=2, POINT_POINT=3 (which list);\n"
                     "  index: int64 (k,), the row in that list;\n"
                     "  toi: float64 (k, 2), [lo, hi], the tightest double interval holding the exact time of "
                     "impact.");
  candidate_function("candidates_earliest_toi", &candidates_earliest_toi_py,
                     "The earliest time of impact over the candidates as (lo, hi), the tightest double interval "
                     "holding the exact earliest time in [0, tmax] at which some candidate is within "
                     "min_distance, or None (pruned by time and stopped early as earliest_toi).");
  candidate_function("candidates_is_collision_free", &candidates_is_collision_free_py,
                     "True iff no candidate comes within min_distance at some t in [0, tmax].");
  candidate_function("candidates_max_collision_free_step", &candidates_max_collision_free_step_py,
                     "The largest step s <= tmax keeping every candidate at distance > min_distance: tmax when "
                     "none collides, else the largest double strictly below the earliest TOI's lo (0 for a "
                     "collision at t = 0).");
}

/// exactccd.SceneBroadPhase: the scene's broad phase kept across calls.
void bind_broad_phase(py::module_& m) {
  const std::string args = kSceneArgs;
  py::class_<PyBroadPhase>(m, "SceneBroadPhase",
                           "A scene's broad phase kept across calls (the C++ exactccd::SceneBroadPhase): bounding "
                           "volume hierarchies over the triangles, edges and isolated points, built once and refitted "
                           "by update(V1) when only the positions at t = 1 change, as in a line search trying several "
                           "steps from the same V0. The candidates are always those a new SceneBroadPhase of the "
                           "current scene would give; the narrow-phase methods answer exactly as the scene functions "
                           "(find_collisions, earliest_toi, is_collision_free, max_collision_free_step) on the "
                           "current scene with the same min_distance and tmax, without rebuilding anything. 3D "
                           "scenes only. Long calls can be interrupted (Ctrl-C).")
      .def(py::init<const py::handle&, const py::handle&, const py::handle&, const py::handle&, const py::handle&,
                    double, double, long long>(),
           py::arg("V0"), py::arg("V1"), py::arg("F") = py::none(), py::arg("E") = py::none(),
           py::arg("P") = py::none(), py::arg("min_distance") = 0.0, py::arg("tmax") = 1.0, py::arg("threads") = 0,
           keep("Builds the broad phase of the scene for the question (min_distance, tmax).\n\n" + args))
      .def("update", &PyBroadPhase::update, py::arg("V1"),
           "Replaces the positions at t = 1 (V1: float64 array (n, 3), the same n), refits the hierarchies and "
           "recomputes the candidates. Raises ValueError (leaving the object unchanged) for a wrong shape or a "
           "NaN or infinite coordinate.")
      .def_property_readonly("candidates", &PyBroadPhase::candidates,
                             "The current candidates as a dict of int64 arrays of shape (m, 2), each sorted: "
                             "vertex_face {vertex, triangle}, edge_edge {edge i, edge j} (i < j, rows of edges), "
                             "point_edge {point, edge} and point_point {p, q} (only for min_distance > 0).")
      .def_property_readonly("edges", &PyBroadPhase::edges,
                             "The scene's edges, an int64 array (e, 2): the triangles' unique edges and the extra "
                             "edges, each ascending, sorted (what the candidates' edge indices refer to).")
      .def_property_readonly("min_distance", &PyBroadPhase::min_distance, "The question's minimum separation.")
      .def_property_readonly("tmax", &PyBroadPhase::tmax, "The question's time limit.")
      .def("find_collisions", &PyBroadPhase::find_collisions_now,
           "Every colliding pair of the current scene, as exactccd.find_collisions returns them (the same dict).")
      .def("earliest_toi", &PyBroadPhase::earliest_toi_now,
           "The current scene's earliest time of impact (lo, hi), or None, as exactccd.earliest_toi.")
      .def("is_collision_free", &PyBroadPhase::is_collision_free_now,
           "True iff no pair of the current scene collides, as exactccd.is_collision_free.")
      .def("max_collision_free_step", &PyBroadPhase::max_collision_free_step_now,
           "The largest collision-free step of the current scene, as exactccd.max_collision_free_step.");
}

/// The mesh functions: the static self-intersection check and the mesh reader.
void bind_meshes(py::module_& m) {
  m.def("intersection_free", &intersection_free_py, py::arg("V"), py::arg("F"),
        "Exact static self-intersection check of a triangle mesh: True iff triangles sharing no vertex index "
        "are disjoint and triangles sharing one vertex meet only there (see exactccd/scene.hpp).\n\n"
        "V: float64 array (n, 3); F: integer array (m, 3). Raises ValueError for NaN or infinite "
        "coordinates, out-of-range or repeated indices.");
  m.def("read_mesh", &read_mesh_py, py::arg("path"),
        "The triangle mesh in the file at path, as (V, F): V a float64 array (n, 3) of positions (read "
        "exactly), F an int64 array (m, 3) of 0-based triangles (polygons fan-triangulated). The format "
        "comes from the extension and the content, which must agree (the formats the library reads; see "
        "docs/formats.md). Raises FileNotFoundError for a missing file and ValueError with the library's "
        "message (\"<path>:<line>: <reason>\") for an unreadable, unsupported or malformed file.");
}

}  // namespace
}  // namespace exactccd::python

PYBIND11_MODULE(_exactccd, m) {
  using namespace exactccd;
  using namespace exactccd::python;
  m.doc() = "Exact continuous collision detection (the C++ library exactccd): NumPy batch functions per "
            "primitive kind, scene functions on arrays, and the mesh reader.";
  m.attr("__version__") = exactccd_version();  // the library's: one version (CMake's project version)
  register_input_errors();
  bind_batch_functions(m);
  define_rigid(m);
  bind_collision_kinds(m);
  bind_scene_functions(m);
  bind_candidate_functions(m);
  bind_broad_phase(m);
  bind_meshes(m);
}
