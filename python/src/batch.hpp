// The batch functions' loop, shared by every motion model of the module (module.cpp's Batch for
// the linear kinds, rigid_module.cpp's RigidBatch): the validated rows of a float64 array, one
// query of `stride` numbers each, answered on the worker threads (run_batch: the GIL released,
// Ctrl-C honoured), into a new array.
#pragma once

#include <pybind11/numpy.h>

#include <cstddef>
#include <limits>
#include <optional>

#include "arrays.hpp"
#include "exactccd/ccd.hpp"    // exactccd::ccd and toi of the linear kinds
#include "exactccd/rigid.hpp"  // and of the rigid ones (looked up here, where the calls are)
#include "exactccd/types.hpp"
#include "interruptible.hpp"

namespace exactccd::python {

/// Whether each query collides: exactccd::ccd(query(row), params) for every row of `a` (its
/// numbers validated by the caller), `query` making a query of its `stride` numbers.
template <class MakeQuery>
pybind11::array_t<bool> batch_ccd(const DoubleArray& a, std::size_t stride, const CcdParams& params, unsigned workers,
                                  MakeQuery&& query) {
  const std::size_t n = static_cast<std::size_t>(a.shape(0));
  pybind11::array_t<bool> out(static_cast<pybind11::ssize_t>(n));
  bool* o = out.mutable_data();
  const double* in = a.data();
  run_batch(n, workers, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) o[i] = exactccd::ccd(query(in + i * stride), params);
  });
  return out;
}

/// Each query's TOI as a row [lo, hi] of an (N, 2) array, NaN for no collision: exactccd::toi
/// over the rows of `a` as in batch_ccd.
template <class MakeQuery>
pybind11::array_t<double> batch_toi(const DoubleArray& a, std::size_t stride, const CcdParams& params, unsigned workers,
                                    MakeQuery&& query) {
  const std::size_t n = static_cast<std::size_t>(a.shape(0));
  pybind11::array_t<double> out(pybind11::array::ShapeContainer({static_cast<pybind11::ssize_t>(n), pybind11::ssize_t{2}}));
  double* o = out.mutable_data();
  const double* in = a.data();
  run_batch(n, workers, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const std::optional<TimeInterval> t = exactccd::toi(query(in + i * stride), params);
      o[2 * i] = t ? t->lo : std::numeric_limits<double>::quiet_NaN();
      o[2 * i + 1] = t ? t->hi : std::numeric_limits<double>::quiet_NaN();
    }
  });
  return out;
}

}  // namespace exactccd::python
