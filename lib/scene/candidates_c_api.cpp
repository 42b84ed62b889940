// The C API of the batch narrow phase over the caller's candidates (exactccd/exactccd.h) over
// exactccd/candidates.hpp. No exception crosses the boundary; outputs are written only on
// EXACTCCD_OK (and *count on EXACTCCD_ERROR_CAPACITY).
#include <climits>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <vector>

#include "exactccd/candidates.hpp"
#include "exactccd/exactccd.h"
#include "scene/parallel.hpp"

namespace {

using namespace exactccd;

/// `count` rows of N ints from `data` (NULL only when count is 0).
template <std::size_t N>
std::vector<std::array<int, N>> read_rows(const int* data, std::size_t count) {
  std::vector<std::array<int, N>> rows(count);
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t k = 0; k < N; ++k) rows[i][k] = data[N * i + k];
  return rows;
}

/// `n` positions from 3n doubles.
std::vector<Vec3> read_positions(const double* x, std::size_t n) {
  std::vector<Vec3> p(n);
  for (std::size_t i = 0; i < n; ++i) p[i] = Vec3{x[3 * i], x[3 * i + 1], x[3 * i + 2]};
  return p;
}

/// Checks the common arguments, reads them, and returns f(positions_t0, positions_t1,
/// candidates, options) (a status; f writes the outputs): the checks in the order of the
/// statuses the header lists, every C++ exception mapped to a status.
template <class F>
exactccd_status with_candidates(const double* x0, const double* x1, std::size_t n, const exactccd_candidates* c,
                                double d, double tmax, unsigned threads, F&& f) {
  if (!c || (n > 0 && (!x0 || !x1))) return EXACTCCD_ERROR_NULL;
  if ((c->vertex_face_count > 0 && !c->vertex_face) || (c->edge_edge_count > 0 && !c->edge_edge) ||
      (c->point_edge_count > 0 && !c->point_edge) || (c->point_point_count > 0 && !c->point_point))
    return EXACTCCD_ERROR_NULL;
  const scene::SceneCall call;  // the FP environment (not cancellable)
  if (!(std::isfinite(d) && d >= 0 && tmax > 0 && tmax <= 1)) return EXACTCCD_ERROR_PARAMETER;
  if (n > static_cast<std::size_t>(INT_MAX)) return EXACTCCD_ERROR_PARAMETER;
  if (threads > kMaxThreads) return EXACTCCD_ERROR_PARAMETER;  // the range of SceneOptions::threads
  for (std::size_t i = 0; i < 3 * n; ++i)
    if (!std::isfinite(x0[i]) || !std::isfinite(x1[i])) return EXACTCCD_ERROR_NON_FINITE;
  try {
    const std::vector<Vec3> p0 = read_positions(x0, n), p1 = read_positions(x1, n);
    CandidateSet set;
    set.vertex_face = read_rows<4>(c->vertex_face, c->vertex_face_count);
    set.edge_edge = read_rows<4>(c->edge_edge, c->edge_edge_count);
    set.point_edge = read_rows<3>(c->point_edge, c->point_edge_count);
    set.point_point = read_rows<2>(c->point_point, c->point_point_count);
    try {
      validate(p0, p1, set);  // sizes and coordinates are checked above: what fails is an index
    } catch (const std::invalid_argument&) {
      return EXACTCCD_ERROR_INDEX;
    }
    SceneOptions options;
    options.threads = threads;
    options.min_distance = d;
    options.tmax = tmax;
    return f(p0, p1, set, options);
  } catch (const std::exception&) {
    return EXACTCCD_ERROR_INTERNAL;
  }
}

}  // namespace

extern "C" {

exactccd_status exactccd_candidates_earliest_toi(const double* positions_t0, const double* positions_t1,
                                                 size_t vertex_count, const exactccd_candidates* candidates,
                                                 double min_distance, double tmax, unsigned threads, int* collides,
                                                 double* lo, double* hi) {
  if (!collides) return EXACTCCD_ERROR_NULL;
  return with_candidates(positions_t0, positions_t1, vertex_count, candidates, min_distance, tmax, threads,
                         [&](const auto& p0, const auto& p1, const auto& set, const auto& options) {
                           const std::optional<TimeInterval> t = earliest_toi(p0, p1, set, options);
                           *collides = t ? 1 : 0;
                           if (t && lo) *lo = t->lo;
                           if (t && hi) *hi = t->hi;
                           return EXACTCCD_OK;
                         });
}

exactccd_status exactccd_candidates_max_collision_free_step(const double* positions_t0, const double* positions_t1,
                                                            size_t vertex_count,
                                                            const exactccd_candidates* candidates,
                                                            double min_distance, double tmax, unsigned threads,
                                                            double* step) {
  if (!step) return EXACTCCD_ERROR_NULL;
  return with_candidates(positions_t0, positions_t1, vertex_count, candidates, min_distance, tmax, threads,
                         [&](const auto& p0, const auto& p1, const auto& set, const auto& options) {
                           *step = max_collision_free_step(p0, p1, set, options);
                           return EXACTCCD_OK;
                         });
}

exactccd_status exactccd_candidates_is_collision_free(const double* positions_t0, const double* positions_t1,
                                                      size_t vertex_count, const exactccd_candidates* candidates,
                                                      double min_distance, double tmax, unsigned threads,
                                                      int* collision_free) {
  if (!collision_free) return EXACTCCD_ERROR_NULL;
  return with_candidates(positions_t0, positions_t1, vertex_count, candidates, min_distance, tmax, threads,
                         [&](const auto& p0, const auto& p1, const auto& set, const auto& options) {
                           *collision_free = is_collision_free(p0, p1, set, options) ? 1 : 0;
                           return EXACTCCD_OK;
                         });
}

exactccd_status exactccd_candidates_find_collisions(const double* positions_t0, const double* positions_t1,
                                                    size_t vertex_count, const exactccd_candidates* candidates,
                                                    double min_distance, double tmax, unsigned threads,
                                                    size_t capacity, size_t* count, int* kinds, size_t* rows,
                                                    double* lo, double* hi) {
  if (!count || (capacity > 0 && (!kinds || !rows || !lo || !hi))) return EXACTCCD_ERROR_NULL;
  return with_candidates(positions_t0, positions_t1, vertex_count, candidates, min_distance, tmax, threads,
                         [&](const auto& p0, const auto& p1, const auto& set, const auto& options) {
                           const std::vector<CandidateCollision> found = find_collisions(p0, p1, set, options);
                           *count = found.size();
                           if (found.size() > capacity) return EXACTCCD_ERROR_CAPACITY;
                           for (std::size_t i = 0; i < found.size(); ++i) {
                             kinds[i] = static_cast<int>(found[i].kind);
                             rows[i] = found[i].index;
                             lo[i] = found[i].toi.lo;
                             hi[i] = found[i].toi.hi;
                           }
                           return EXACTCCD_OK;
                         });
}

}  // extern "C"
