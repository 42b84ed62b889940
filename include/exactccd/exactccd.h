/* exactccd: C API, for foreign-function interfaces from other languages.
 *
 * A query is 24 doubles: the 8 points in benchmark row order, x y z per point.
 *   vertex-face: p_t0, a_t0, b_t0, c_t0, p_t1, a_t1, b_t1, c_t1
 *   edge-edge:   a0_t0, a1_t0, b0_t0, b1_t0, a0_t1, a1_t1, b0_t1, b1_t1
 * Answers are exact (see exactccd/ccd.hpp for the contract). Every function is thread-safe and
 * returns an exactccd_status; outputs are written only on EXACTCCD_OK. */
#ifndef EXACTCCD_EXACTCCD_H
#define EXACTCCD_EXACTCCD_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum exactccd_status {
  EXACTCCD_OK = 0,               /* answered */
  EXACTCCD_ERROR_NON_FINITE = 1, /* a coordinate is NaN or infinite */
  EXACTCCD_ERROR_NULL = 2,       /* a required pointer is NULL */
  EXACTCCD_ERROR_INTERNAL = 3,   /* unexpected failure (e.g. out of memory) */
  EXACTCCD_ERROR_PARAMETER = 4,  /* unknown kind, min_distance < 0 or not finite, tmax not in (0, 1], threads > 1024 */
  EXACTCCD_ERROR_INDEX = 5,      /* a candidate's vertex index is out of range or repeated */
  EXACTCCD_ERROR_CAPACITY = 6,   /* the output arrays are too small (*count holds the size needed) */
  EXACTCCD_ERROR_ROTATION = 7    /* a rigid body's quaternion path (1 - t) q0 + t q1 vanishes in [0, 1] */
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

/* Many queries of one kind with one question: `queries` holds `count` queries of
 * exactccd_query_size(kind) doubles each, one after the other. For every i < count, collides[i]
 * is what exactccd_ccd gives query i and, when lo and hi are not NULL, a collision's earliest
 * time lies in [lo[i], hi[i]] as exactccd_toi gives it (lo and hi are both NULL or both not).
 * The filtered method runs its stage lists on blocks of queries (the same answers). Every query
 * is checked first: on an error nothing is written. `queries` may be NULL when count is 0. */
exactccd_status exactccd_toi_batch(int kind, const double* queries, size_t count, double min_distance, double tmax,
                                   int* collides, double* lo, double* hi);

/** Candidate pairs from the caller's own broad phase (exactccd/candidates.hpp): row-major arrays
 * of vertex indices into the positions, `*_count` rows each; a list may be NULL when its count
 * is 0. A candidate whose two sides share a vertex index, or whose triangle or edge repeats one,
 * is refused (EXACTCCD_ERROR_INDEX): it touches at t = 0 by construction. */
typedef struct exactccd_candidates {
  const int* vertex_face;    /**< rows {vertex, a, b, c}: a vertex and the triangle (a, b, c) */
  size_t vertex_face_count;  /**< rows of vertex_face */
  const int* edge_edge;      /**< rows {a0, a1, b0, b1}: the edges (a0, a1) and (b0, b1) */
  size_t edge_edge_count;    /**< rows of edge_edge */
  const int* point_edge;     /**< rows {p, a, b}: a point and the edge (a, b) */
  size_t point_edge_count;   /**< rows of point_edge */
  const int* point_point;    /**< rows {p, q}: two points */
  size_t point_point_count;  /**< rows of point_point */
} exactccd_candidates;

/* The batch narrow phase over candidates. Common arguments: positions_t0 and positions_t1, 3 *
 * vertex_count doubles (x y z per vertex, at t = 0 and t = 1; NULL allowed when vertex_count is
 * 0); the candidates; min_distance (>= 0) and tmax (in (0, 1]) as for exactccd_ccd; threads
 * in 0..1024 (0: every hardware thread; the answers do not depend on it). Statuses:
 * EXACTCCD_ERROR_NULL, EXACTCCD_ERROR_PARAMETER (also for more than INT_MAX vertices or more
 * than 1024 threads), EXACTCCD_ERROR_NON_FINITE,
 * EXACTCCD_ERROR_INDEX, EXACTCCD_ERROR_INTERNAL; outputs are written only on EXACTCCD_OK. */

/* The earliest time of impact over the candidates: *collides = 1 and [*lo, *hi] the tightest
 * double interval holding the earliest t in [0, tmax] at which some candidate is within
 * min_distance (lo and hi may be NULL), else *collides = 0. Prunes and stops early as
 * exactccd::earliest_toi. */
exactccd_status exactccd_candidates_earliest_toi(const double* positions_t0, const double* positions_t1,
                                                 size_t vertex_count, const exactccd_candidates* candidates,
                                                 double min_distance, double tmax, unsigned threads, int* collides,
                                                 double* lo, double* hi);

/* The largest collision-free step: *step = tmax when no candidate collides in [0, tmax], else the
 * largest double strictly below the earliest time of impact's lo (0 for a collision at t = 0). */
exactccd_status exactccd_candidates_max_collision_free_step(const double* positions_t0, const double* positions_t1,
                                                            size_t vertex_count,
                                                            const exactccd_candidates* candidates,
                                                            double min_distance, double tmax, unsigned threads,
                                                            double* step);

/* *collision_free = 1 when no candidate collides in [0, tmax], else 0; stops at the first
 * collision found. */
exactccd_status exactccd_candidates_is_collision_free(const double* positions_t0, const double* positions_t1,
                                                      size_t vertex_count, const exactccd_candidates* candidates,
                                                      double min_distance, double tmax, unsigned threads,
                                                      int* collision_free);

/* Every colliding candidate: *count of them, sorted by kind (vertex-face, edge-edge, point-edge,
 * point-point: the values 0 to 3 of exactccd_kind) then by row; for the i-th, kinds[i] its kind,
 * rows[i] its row in that kind's list, [lo[i], hi[i]] its time of impact (the tightest double
 * interval). The four arrays hold `capacity` entries (they may be NULL when capacity is 0); when
 * more candidates collide, the status is EXACTCCD_ERROR_CAPACITY and only *count is written (the
 * capacity needed). The total number of candidates is always enough. */
exactccd_status exactccd_candidates_find_collisions(const double* positions_t0, const double* positions_t1,
                                                    size_t vertex_count, const exactccd_candidates* candidates,
                                                    double min_distance, double tmax, unsigned threads,
                                                    size_t capacity, size_t* count, int* kinds, size_t* rows,
                                                    double* lo, double* hi);

/* Rigid bodies (exactccd/rigid.hpp): body A's vertex against body B's triangle (kind
 * EXACTCCD_VERTEX_FACE) or A's edge against B's edge (EXACTCCD_EDGE_EDGE), each body moving from
 * one pose to another (translation c, quaternion q = w x y z of any nonzero length; c and q
 * interpolated linearly). A query is EXACTCCD_RIGID_QUERY_SIZE doubles: cA0 (3), qA0 (4), cA1
 * (3), qA1 (4), cB0 (3), qB0 (4), cB1 (3), qB1 (4), then the body points in body coordinates
 * (vertex-face: p, then a, b, c; edge-edge: a0, a1, then b0, b1). *collides = 1 when the
 * primitives come within min_distance (>= 0) of each other at some t in [0, tmax] (tmax in
 * (0, 1]), exactly; the _toi variant also gives the earliest such t in [*lo, *hi], the tightest
 * double interval (lo and hi may be NULL). Statuses: EXACTCCD_ERROR_NULL,
 * EXACTCCD_ERROR_PARAMETER (another kind, min_distance or tmax out of range),
 * EXACTCCD_ERROR_NON_FINITE, EXACTCCD_ERROR_ROTATION (a quaternion path through zero: q0 = 0,
 * q1 = 0 or q1 a negative multiple of q0), EXACTCCD_ERROR_INTERNAL. */
#define EXACTCCD_RIGID_QUERY_SIZE 40
exactccd_status exactccd_rigid_ccd(int kind, const double* query, double min_distance, double tmax, int* collides);
exactccd_status exactccd_rigid_toi(int kind, const double* query, double min_distance, double tmax, int* collides,
                                   double* lo, double* hi);

/* A static description of a status, e.g. for error messages. */
const char* exactccd_status_string(exactccd_status status);

/* The library's version, "MAJOR.MINOR.PATCH" (a static string): the version of the library
 * linked, where EXACTCCD_VERSION_STRING of exactccd/version.h is that of the headers compiled
 * against. */
const char* exactccd_version(void);

#ifdef __cplusplus
}
#endif

#endif /* EXACTCCD_EXACTCCD_H */
