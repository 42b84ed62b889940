// The batch functions' loop, shared by every motion model of the module (module.cpp's Batch for
// the linear kinds, rigid_module.cpp's RigidBatch): the validated rows of a float64 array, one
// query of `stride` numbers each, answered on the worker threads (run_batch: the GIL released,
// Ctrl-C honoured), into a new array; at d = 0 the library's batched stage 1 first (answer_rows).
#pragma once

#include <pybind11/numpy.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>

#include "arrays.hpp"
#include "exactccd/ccd.hpp"    // exactccd::ccd and toi of the linear kinds
#include "exactccd/rigid.hpp"  // and of the rigid ones (looked up here, where the calls are)
#include "exactccd/types.hpp"
#include "filter/volume_block.hpp"
#include "interruptible.hpp"
#include "numeric/fp_environment.hpp"
#include "numeric/simd_level.hpp"

namespace exactccd::python {

/// answer(i, excluded) for every row i of [begin, end) of `in` (rows of `stride` numbers, query
/// making each a query), in order. At d = 0 for vertex-face and edge-edge queries, `excluded` is
/// the library's batched stage 1 (filter/volume_block.hpp: blocks of queries in vector lanes,
/// the same test as the first stage of every query, under the default floating-point
/// environment): true proves that the query does not collide. Otherwise false.
template <class MakeQuery, class Answer>
void answer_rows(std::size_t begin, std::size_t end, const double* in, std::size_t stride, const CcdParams& params,
                 MakeQuery& query, Answer&& answer) {
  using Query = std::decay_t<decltype(query(in))>;
  if constexpr (std::is_same_v<Query, VertexFaceQuery> || std::is_same_v<Query, EdgeEdgeQuery>) {
    if (params.contact_only()) {
      const numeric::SimdLevel level = numeric::simd_level();
      filter::VolumeBlock block;
      for (std::size_t first = begin; first < end; first += filter::kVolumeBlock) {
        const std::size_t last = std::min(end, first + filter::kVolumeBlock);
        block.size = 0;
        for (std::size_t i = first; i < last; ++i) block.push(rows(query(in + i * stride)));
        std::uint32_t excluded = 0;
        {
          const numeric::DefaultFpEnvironment default_environment;  // the stage's bound assumes it
          excluded = filter::volume_excluded_block<Query>(block, level);
        }
        for (std::size_t i = first; i < last; ++i) answer(i, (excluded >> (i - first) & 1u) != 0);
      }
      return;
    }
  }
  for (std::size_t i = begin; i < end; ++i) answer(i, false);
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
    answer_rows(begin, end, in, stride, params, query,
                [&](std::size_t i, bool excluded) { o[i] = !excluded && exactccd::ccd(query(in + i * stride), params); });
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
    answer_rows(begin, end, in, stride, params, query, [&](std::size_t i, bool excluded) {
      const std::optional<TimeInterval> t =
          excluded ? std::nullopt : exactccd::toi(query(in + i * stride), params);
      o[2 * i] = t ? t->lo : std::numeric_limits<double>::quiet_NaN();
      o[2 * i + 1] = t ? t->hi : std::numeric_limits<double>::quiet_NaN();
    });
  });
  return out;
}

}  // namespace exactccd::python
