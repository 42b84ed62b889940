/* exactccd: C API, for foreign-function interfaces from other languages.
 *
 * A query is 24 doubles: the 8 points in benchmark row order, x y z per point.
 *   vertex-face: p_t0, a_t0, b_t0, c_t0, p_t1, a_t1, b_t1, c_t1
 *   edge-edge:   a0_t0, a1_t0, b0_t0, b1_t0, a0_t1, a1_t1, b0_t1, b1_t1
 * Answers are exact (see exactccd/ccd.hpp for the contract). Every function is thread-safe and
 * returns an exactccd_status; outputs are written only on EXACTCCD_OK. */
#ifndef EXACTCCD_EXACTCCD_H
#define EXACTCCD_EXACTCCD_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum exactccd_status {
  EXACTCCD_OK = 0,               /* answered */
  EXACTCCD_ERROR_NON_FINITE = 1, /* a coordinate is NaN or infinite */
  EXACTCCD_ERROR_NULL = 2,       /* a required pointer is NULL */
  EXACTCCD_ERROR_INTERNAL = 3    /* unexpected failure (e.g. out of memory) */
} exactccd_status;

/* *collides = 1 when the vertex meets the closed triangle for some t in [0, 1], else 0. */
exactccd_status exactccd_vertex_face_ccd(const double query[24], int* collides);

/* *collides = 1 when the closed edges meet for some t in [0, 1], else 0. */
exactccd_status exactccd_edge_edge_ccd(const double query[24], int* collides);

/* Earliest time of impact: *collides as above; when 1, [*lo, *hi] is the tightest double
 * interval holding the exact time (lo == hi when it is a double). */
exactccd_status exactccd_vertex_face_toi(const double query[24], int* collides, double* lo,
                                         double* hi);

/* Earliest time of impact of an edge-edge query; see exactccd_vertex_face_toi. */
exactccd_status exactccd_edge_edge_toi(const double query[24], int* collides, double* lo,
                                       double* hi);

/* A static description of a status, e.g. for error messages. */
const char* exactccd_status_string(exactccd_status status);

#ifdef __cplusplus
}
#endif

#endif /* EXACTCCD_EXACTCCD_H */
