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
  EXACTCCD_ERROR_INTERNAL = 3,   /* unexpected failure (e.g. out of memory) */
  EXACTCCD_ERROR_PARAMETER = 4   /* unknown kind, min_distance < 0 or not finite, tmax not in (0, 1] */
} exactccd_status;

/* The primitive kinds (the values of the CLI's --kind in this order: vf ee pe pp ee2 pe2 pp2). */
typedef enum exactccd_kind {
  EXACTCCD_VERTEX_FACE = 0,    /* p, a, b, c: 4 points, 3D */
  EXACTCCD_EDGE_EDGE = 1,      /* a0, a1, b0, b1: 4 points, 3D */
  EXACTCCD_POINT_EDGE = 2,     /* p, a, b: 3 points, 3D */
  EXACTCCD_POINT_POINT = 3,    /* p, q: 2 points, 3D */
  EXACTCCD_EDGE_EDGE_2D = 4,   /* a0, a1, b0, b1: 4 points, x y per point */
  EXACTCCD_POINT_EDGE_2D = 5,  /* p, a, b: 3 points, x y per point */
  EXACTCCD_POINT_POINT_2D = 6  /* p, q: 2 points, x y per point */
} exactccd_kind;

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

/* The number of doubles of a query of `kind` (an exactccd_kind value; an int, so that any value
 * a foreign caller passes is defined): every point at t0, then every point at t1, with 3 (or,
 * for the 2D kinds, 2) coordinates each; 0 for an unknown kind. */
int exactccd_query_size(int kind);

/* Minimum separation and a time limit, any kind: *collides = 1 when the primitives come within
 * distance min_distance (>= 0) of each other at some t in [0, tmax] (tmax in (0, 1]), else 0.
 * min_distance = 0, tmax = 1 is the question of the functions above. */
exactccd_status exactccd_ccd(int kind, const double* query, double min_distance, double tmax, int* collides);

/* As exactccd_ccd, with the earliest such t in [*lo, *hi] when *collides is 1 (the tightest
 * double interval; [0, 0] when the initial distance is <= min_distance). */
exactccd_status exactccd_toi(int kind, const double* query, double min_distance, double tmax, int* collides,
                             double* lo, double* hi);

/* A static description of a status, e.g. for error messages. */
const char* exactccd_status_string(exactccd_status status);

#ifdef __cplusplus
}
#endif

#endif /* EXACTCCD_EXACTCCD_H */
