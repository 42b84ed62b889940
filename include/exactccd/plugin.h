/**
 * \file exactccd/plugin.h
 * \brief The plug-in ABI of `exactccd fuzz-against`: another CCD code, as a shared library,
 *        tested against the exact answers.
 *
 * A plug-in is a shared library (`.so`) that exports, with C linkage, entry points of one or
 * more kinds. **The entry point for any question** (`--min-distance D --tmax T`, every kind):
 *
 *     int exactccd_plugin_<kind>_query(const double* q, double min_distance, double tmax, double* toi);
 *
 * with `<kind>` the kind's `--kind` value: vf, ee, pe, pp, ee2, pe2, pp2 (declared below, one
 * per kind of exactccd's list of kinds). `q` holds the kind's points at t = 0, then the same
 * points at t = 1, in the row order of exactccd's benchmark files (its query structs' member
 * order), x y z per point (x y for the plane's kinds ee2, pe2, pp2):
 *
 *     vf:  p, a, b, c        (vertex p, triangle a b c)   24 doubles
 *     ee:  a0, a1, b0, b1    (edge a0 a1, edge b0 b1)     24 doubles
 *     pe:  p, a, b           (point p, segment a b)       18 doubles
 *     pp:  p, q                                           12 doubles
 *     ee2: a0, a1, b0, b1    (in the plane)               16 doubles
 *     pe2: p, a, b                                        12 doubles
 *     pp2: p, q                                            8 doubles
 *
 * each at t = 0 then at t = 1 (e.g. vf: p_t0, a_t0, b_t0, c_t0, p_t1, a_t1, b_t1, c_t1).
 * Vertices move linearly, `x(t) = x_t0 + t (x_t1 - x_t0)`. The function returns 1 when the
 * plug-in's code reports the two primitives within distance `min_distance` (Euclidean, >= 0)
 * of each other at some t in `[0, tmax]` (`tmax` in (0, 1]), and then, when `toi` is not
 * null, writes its time of impact to `*toi` (fuzz-against always passes a `toi`, preset to
 * NaN: a plug-in that has no time of impact leaves it untouched and only its answers are
 * graded); 0 when it reports none; any other value is an error (the `errors` column, not a
 * false positive or negative). exactccd's answer to the same question is exact: a collision
 * iff some t in [0, tmax] has distance <= min_distance between the closed primitives, its
 * time of impact the earliest such t.
 *
 * **The contact-only entry points** (d = 0, tmax = 1, vertex-face and edge-edge; plug-ins
 * written for them keep working):
 *
 *     int exactccd_plugin_vf(const double q[24]);   // vertex-face
 *     int exactccd_plugin_ee(const double q[24]);   // edge-edge
 *
 * returning 1 for a collision in `[0, 1]`, 0 for none, and optionally, with a time of impact,
 *
 *     int exactccd_plugin_vf_toi(const double q[24], double* toi);
 *     int exactccd_plugin_ee_toi(const double q[24], double* toi);
 *
 * returning 1 and the time in `toi[0]`, or 0. fuzz-against uses, for the requested kind, the
 * `_query` entry point when the plug-in has it, else (vf and ee at d = 0 and tmax = 1 only)
 * the `_toi` one, else the answer-only one; a plug-in without a usable one is an error naming
 * the symbol it needs.
 *
 * **Times of impact.** For every collision both find, fuzz-against decides exactly whether the
 * reported time T is safe (T <= the exact time t*: a step to T does not pass through a
 * contact) or unsafe, and whether it is more than a stated factor F early (F T < t*).
 *
 * Every coordinate passed is finite; the plug-in must not keep `q`. `exactccd fuzz-against`
 * loads the library with `dlopen` and looks the symbols up with `dlsym`. With `--threads N > 1`
 * the functions are called concurrently from N threads, so they must be thread-safe (or run
 * with `--threads 1`, the default). A crash in the plug-in ends the run.
 *
 * Including this header is optional; it lets the compiler check the signatures. Build a
 * plug-in with, for example,
 *
 *     c++ -O2 -shared -fPIC -fvisibility=hidden my_plugin.cpp -o my_plugin.so
 *
 * (`-fvisibility=hidden` keeps everything but the marked functions private). Examples in
 * fuzz/plugins/: exact_plugin.cpp (exactccd itself, every kind and question),
 * sampled_distance_plugin.cpp (a distance checked at sampled times only: a plausible mistake),
 * naive_plugin.cpp and naive_tolerance_plugin.cpp (contact only); docs/fuzzing.md describes the
 * tool and how to wrap another code's narrow phase.
 */
#ifndef EXACTCCD_PLUGIN_H
#define EXACTCCD_PLUGIN_H

/** Marks a plug-in entry point as exported (default visibility, C linkage is separate). */
#if defined(_WIN32)
#define EXACTCCD_PLUGIN_EXPORT __declspec(dllexport)
#else
#define EXACTCCD_PLUGIN_EXPORT __attribute__((visibility("default")))
#endif

/** The name of the vertex-face entry point, for `dlsym`. */
#define EXACTCCD_PLUGIN_VF_SYMBOL "exactccd_plugin_vf"
/** The name of the edge-edge entry point, for `dlsym`. */
#define EXACTCCD_PLUGIN_EE_SYMBOL "exactccd_plugin_ee"
/** The name of the optional vertex-face entry point with a time of impact. */
#define EXACTCCD_PLUGIN_VF_TOI_SYMBOL "exactccd_plugin_vf_toi"
/** The name of the optional edge-edge entry point with a time of impact. */
#define EXACTCCD_PLUGIN_EE_TOI_SYMBOL "exactccd_plugin_ee_toi"
/** The name prefix and suffix of the entry points for any question: the prefix, the kind's
 *  --kind value (vf, ee, pe, pp, ee2, pe2, pp2), the suffix. */
#define EXACTCCD_PLUGIN_QUERY_PREFIX "exactccd_plugin_"
/** See EXACTCCD_PLUGIN_QUERY_PREFIX. */
#define EXACTCCD_PLUGIN_QUERY_SUFFIX "_query"

#ifdef __cplusplus
extern "C" {
#endif

/** The type of both entry points: 24 doubles in, 1 (collision) or 0 (none) out. */
typedef int (*exactccd_plugin_fn)(const double q[24]);

/** The type of the optional entry points with a time of impact: 1 and toi[0], or 0. */
typedef int (*exactccd_plugin_toi_fn)(const double q[24], double* toi);

/**
 * Vertex-face CCD of the plug-in's code: 1 if the vertex p meets the triangle (a, b, c) for
 * some t in [0, 1], else 0. q = p_t0, a_t0, b_t0, c_t0, p_t1, a_t1, b_t1, c_t1 (x y z each).
 */
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_vf(const double q[24]);

/**
 * Edge-edge CCD of the plug-in's code: 1 if the edges (a0, a1) and (b0, b1) meet for some t
 * in [0, 1], else 0. q = a0_t0, a1_t0, b0_t0, b1_t0, a0_t1, a1_t1, b0_t1, b1_t1 (x y z each).
 */
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_ee(const double q[24]);

/**
 * Optional: vertex-face CCD of the plug-in's code with its time of impact: returns 1 and
 * writes the time to `toi[0]` when it reports a collision, else returns 0.
 * \param q   the query, as for exactccd_plugin_vf (24 doubles)
 * \param toi where the time of impact is written (one double)
 */
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_vf_toi(const double q[24], double* toi);

/**
 * Optional: edge-edge CCD of the plug-in's code with its time of impact; see
 * exactccd_plugin_vf_toi.
 * \param q   the query, as for exactccd_plugin_ee (24 doubles)
 * \param toi where the time of impact is written (one double)
 */
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_ee_toi(const double q[24], double* toi);

/** The type of the entry points for any question (exactccd_plugin_<kind>_query). */
typedef int (*exactccd_plugin_query_fn)(const double* q, double min_distance, double tmax, double* toi);

/**
 * Vertex-face, any question: 1 if the plug-in's code finds the vertex p within min_distance of
 * the triangle (a, b, c) at some t in [0, tmax] (and its time of impact in *toi when toi is not
 * null), 0 if not, anything else an error.
 * \param q            p, a, b, c at t = 0, then at t = 1 (x y z each: 24 doubles)
 * \param min_distance the distance d >= 0 that counts as a collision
 * \param tmax         the end of the time interval, in (0, 1]
 * \param toi          where the time of impact is written, or null
 */
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_vf_query(const double* q, double min_distance, double tmax, double* toi);

/**
 * Edge-edge, any question (see exactccd_plugin_vf_query).
 * \param q            a0, a1, b0, b1 at t = 0, then at t = 1 (x y z each: 24 doubles)
 * \param min_distance the distance d >= 0 that counts as a collision
 * \param tmax         the end of the time interval, in (0, 1]
 * \param toi          where the time of impact is written, or null
 */
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_ee_query(const double* q, double min_distance, double tmax, double* toi);

/**
 * Point-edge, any question (see exactccd_plugin_vf_query).
 * \param q            p, a, b at t = 0, then at t = 1 (x y z each: 18 doubles)
 * \param min_distance the distance d >= 0 that counts as a collision
 * \param tmax         the end of the time interval, in (0, 1]
 * \param toi          where the time of impact is written, or null
 */
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pe_query(const double* q, double min_distance, double tmax, double* toi);

/**
 * Point-point, any question (see exactccd_plugin_vf_query).
 * \param q            p, q at t = 0, then at t = 1 (x y z each: 12 doubles)
 * \param min_distance the distance d >= 0 that counts as a collision
 * \param tmax         the end of the time interval, in (0, 1]
 * \param toi          where the time of impact is written, or null
 */
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pp_query(const double* q, double min_distance, double tmax, double* toi);

/**
 * Edge-edge in the plane, any question (see exactccd_plugin_vf_query).
 * \param q            a0, a1, b0, b1 at t = 0, then at t = 1 (x y each: 16 doubles)
 * \param min_distance the distance d >= 0 that counts as a collision
 * \param tmax         the end of the time interval, in (0, 1]
 * \param toi          where the time of impact is written, or null
 */
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_ee2_query(const double* q, double min_distance, double tmax, double* toi);

/**
 * Point-edge in the plane, any question (see exactccd_plugin_vf_query).
 * \param q            p, a, b at t = 0, then at t = 1 (x y each: 12 doubles)
 * \param min_distance the distance d >= 0 that counts as a collision
 * \param tmax         the end of the time interval, in (0, 1]
 * \param toi          where the time of impact is written, or null
 */
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pe2_query(const double* q, double min_distance, double tmax, double* toi);

/**
 * Point-point in the plane, any question (see exactccd_plugin_vf_query).
 * \param q            p, q at t = 0, then at t = 1 (x y each: 8 doubles)
 * \param min_distance the distance d >= 0 that counts as a collision
 * \param tmax         the end of the time interval, in (0, 1]
 * \param toi          where the time of impact is written, or null
 */
EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_pp2_query(const double* q, double min_distance, double tmax, double* toi);

#ifdef __cplusplus
}
#endif

#endif /* EXACTCCD_PLUGIN_H */
