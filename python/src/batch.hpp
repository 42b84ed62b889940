// The batch functions' loop, shared by every motion model of the module (module.cpp's Batch for
// the linear kinds, rigid_module.cpp's RigidBatch): the validated rows of a float64 array, one
// query of `stride` numbers each, answered on the worker threads (run_batch: the GIL released,
// Ctrl-C honoured), into a new array, through exactccd::answer_batch (the library's stage lists on
// blocks of queries).
#pragma once

#include <pybind11/numpy.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>

#include "arrays.hpp"
#include "exactccd/ccd.hpp"    // exactccd::ccd and toi of the linear kinds
#include "exactccd/rigid.hpp"  // and of the rigid ones (looked up here, where the calls are)
#include "exactccd/types.hpp"
#include "interruptible.hpp"

namespace exactccd::python {

/// Rows answered together by exactccd::answer_batch (on the worker's stack).
constexpr std::size_t kRowsPerCall = 64;

/// answer(i, toi) for every row i of [begin, end) of `in` (rows of `stride` numbers, query
/// making each a query), in order: exactccd::answer_batch over up to kRowsPerCall rows at a time
/// (the library's stage lists on blocks of queries; the TOI only when want_toi, else [0, 0] for
/// a collision).
template <class MakeQuery, class Answer>
void answer_rows(std::size_t begin, std::size_t end, const double* in, std::size_t stride, const CcdParams& params,
                 bool want_toi, MakeQuery& query, Answer&& answer) {
  using Query = std::decay_t<decltype(query(in))>;
  std::array<Query, kRowsPerCall> queries;
  std::array<std::optional<TimeInterval>, kRowsPerCall> tois;
  for (std::size_t first = begin; first < end; first += kRowsPerCall) {
    const std::size_t count = std::min(end - first, kRowsPerCall);
    for (std::size_t k = 0; k < count; ++k) queries[k] = query(in + (first + k) * stride);
    answer_batch(queries.data(), count, params, Method::filtered, want_toi, tois.data());
    for (std::size_t k = 0; k < count; ++k) answer(first + k, tois[k]);
  }
}

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
    answer_rows(begin, end, in, stride, params, false, query,
                [&](std::size_t i, const std::optional<TimeInterval>& t) { o[i] = t.has_value(); });
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
    answer_rows(begin, end, in, stride, params, true, query, [&](std::size_t i, const std::optional<TimeInterval>& t) {
      o[2 * i] = t ? t->lo : std::numeric_limits<double>::quiet_NaN();
      o[2 * i + 1] = t ? t->hi : std::numeric_limits<double>::quiet_NaN();
    });
  });
  return out;
}

}  // namespace exactccd::python
