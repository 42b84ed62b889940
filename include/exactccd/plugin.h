/**
 * \file exactccd/plugin.h
 * \brief The plug-in ABI of `exactccd fuzz-against`: another CCD code, as a shared library,
 *        tested against the exact answers.
 *
 * A plug-in is a shared library (`.so`) that exports, with C linkage, one or both of
 *
 *     int exactccd_plugin_vf(const double q[24]);   // vertex-face
 *     int exactccd_plugin_ee(const double q[24]);   // edge-edge
 *
 * `q` holds the query's 8 points as 24 doubles in the row order of the public CCD benchmark
 * (the order of exactccd's VertexFaceQuery / EdgeEdgeQuery members and of its CSV files),
 * x y z per point:
 *
 *     vertex-face: p_t0, a_t0, b_t0, c_t0, p_t1, a_t1, b_t1, c_t1
 *     edge-edge:   a0_t0, a1_t0, b0_t0, b1_t0, a0_t1, a1_t1, b0_t1, b1_t1
 *
 * Vertices move linearly, `x(t) = x_t0 + t (x_t1 - x_t0)`, `t` in `[0, 1]`. The function
 * returns 1 when the plug-in's code reports a collision in `[0, 1]` and 0 when it reports
 * none. Any other value is counted as an error (shown in the `errors` column, not as a false
 * positive or negative). Every coordinate passed is finite; the plug-in must not keep `q`.
 *
 * `exactccd fuzz-against` loads the library with `dlopen` and looks the symbol up with
 * `dlsym`; only the symbol of the requested kind (`--kind vf` or `--kind ee`) is required.
 * With `--threads N > 1` the function is called concurrently from N threads, so it must be
 * thread-safe (or run with `--threads 1`, the default). A crash in the plug-in ends the run.
 *
 * **Times of impact (optional).** A plug-in may also export, for a kind,
 *
 *     int exactccd_plugin_vf_toi(const double q[24], double* toi);
 *     int exactccd_plugin_ee_toi(const double q[24], double* toi);
 *
 * returning 1 and its time of impact in `toi[0]` when its code reports a collision, 0 when it
 * reports none. When the symbol of the requested kind is present, `fuzz-against` calls it
 * instead of the answer-only one and also checks, for every collision both find, that the time
 * is safe (`toi <=` the exact TOI: a step to it does not pass through a contact). Plug-ins
 * without it work as before.
 *
 * Including this header is optional; it lets the compiler check the signatures. Build a
 * plug-in with, for example,
 *
 *     c++ -O2 -shared -fPIC -fvisibility=hidden my_plugin.cpp -o my_plugin.so
 *
 * (`-fvisibility=hidden` keeps everything but the two marked functions private). Examples:
 * `fuzz/plugins/naive_plugin.cpp` and `fuzz/plugins/naive_tolerance_plugin.cpp`; the tool and
 * the ABI are described in docs/fuzzing.md.
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

#ifdef __cplusplus
}
#endif

#endif /* EXACTCCD_PLUGIN_H */
