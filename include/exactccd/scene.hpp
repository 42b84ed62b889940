// exactccd: scene-level continuous collision detection over one time step.
//
// A scene is a set of vertices moving linearly from their positions at t = 0 to their positions
// at t = 1, with triangles, optional extra (codimensional) edges and optional isolated points
// over them. Its primitives:
// - the vertices of the scene: every vertex referenced by a triangle, an extra edge or a point
//   (vertices referenced by nothing take part in nothing);
// - its edges: the unique undirected edges of the triangles, and the extra edges;
// - its isolated points: the listed points that are an endpoint of no edge;
// - its triangles.
// A vertex-face (VF) pair is a vertex and a triangle, an edge-edge (EE) pair two distinct edges;
// with a minimum separation d > 0 (SceneOptions::min_distance) also point-edge (PE) pairs, an
// isolated point and an edge, and point-point (PP) pairs, two isolated points. Pairs sharing a
// vertex index are never tested (a vertex against its own triangles, edges with a common
// endpoint): they touch by construction. Every other pair is decided exactly, as the primitive
// queries of ccd.hpp decide it with CcdParams{d, tmax}: it collides iff its two closed
// primitives come within distance <= d at some t in [0, tmax]. So the scene answers are exact
// too: a broad phase of swept boxes drops only pairs that cannot come within d (its box test is
// exact at d = 0 and certified when the boxes are inflated by d), and a time of impact is the
// tightest double interval holding the exact time.
//
// Why PE and PP pairs only for d > 0 (in 3D): at d = 0 the VF and EE pairs are the contacts
// the library has always reported (a point meeting an extra edge or another point in space is
// not a VF or EE contact); for d > 0, VF covers a point against a triangle with its edges and
// vertices, EE an edge endpoint against another edge, and PE / PP the isolated points against
// the extra edges and each other (PE also repeats the triangles' edges, which VF covers too).
// In the plane (Scene2d) there are no triangles: EE, PE and PP pairs are tested for every d.
//
// All functions are thread-safe and keep no global state; they throw std::invalid_argument on a
// malformed scene (see validate()) or invalid options (see SceneOptions).
#pragma once

#include <array>
#include <atomic>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "exactccd/types.hpp"

namespace exactccd {

/// Vertices moving linearly over one step, x(t) = positions_t0 + t (positions_t1 -
/// positions_t0) for t in [0, 1], and the primitives over them (indices are 0-based).
struct Scene {
  std::vector<Vec3> positions_t0;              ///< vertex positions at t = 0
  std::vector<Vec3> positions_t1;              ///< vertex positions at t = 1 (same size)
  std::vector<std::array<int, 3>> triangles;   ///< triangles (three distinct vertex indices)
  std::vector<std::array<int, 2>> edges;       ///< extra edges (codimensional), in EE and VF
  std::vector<int> points;                     ///< points: VF vertices; with d > 0, those on no edge also in PE and PP
};

/// A scene in the plane: vertices moving linearly over one step, x(t) = positions_t0 +
/// t (positions_t1 - positions_t0) for t in [0, 1], with edges and points over them (indices
/// are 0-based). Its pairs: two edges sharing no vertex index (EE), an isolated point (a listed
/// point that is an endpoint of no edge) and an edge (PE), two distinct isolated points (PP),
/// for every minimum separation including 0 (in the plane a point on an edge is a contact).
struct Scene2d {
  std::vector<Vec2> positions_t0;              ///< vertex positions at t = 0
  std::vector<Vec2> positions_t1;              ///< vertex positions at t = 1 (same size)
  std::vector<std::array<int, 2>> edges;       ///< edges (two distinct vertex indices each)
  std::vector<int> points;                     ///< points (those on an edge add nothing: EE covers them)
};

/// The most threads a scene function takes (SceneOptions::threads): the same range, 0..1024,
/// in the C API, the Python module and the command line (which takes 1..1024).
constexpr unsigned kMaxThreads = 1024;

/// Options of the scene functions.
struct SceneOptions {
  /// Threads of the broad and the narrow phase, 0..kMaxThreads (1024); 0 means
  /// std::thread::hardware_concurrency() (at most 1024 of them). A larger value is refused
  /// (std::invalid_argument). The loops run on oneTBB: at most this many threads, fewer when
  /// the machine has fewer; called from inside a caller's TBB loop, on the caller's threads
  /// (when its task arena has no more than this many) or in a task arena of this many, never
  /// on threads of its own. The results do not depend on it.
  unsigned threads = 0;
  /// The minimum separation d: a pair collides when its primitives come within distance <= d
  /// (Euclidean, between the closed primitives). Finite and >= 0; 0 asks for contact.
  double min_distance = 0.0;
  /// The time limit: only times t in [0, tmax] count. In (0, 1].
  double tmax = 1.0;
  /// Cancellation (for interactive callers, e.g. Ctrl-C in the Python module): when not null,
  /// the call's parallel loops (broad and narrow phase) check *cancel between pieces of work
  /// of a few hundred queries or boxes, and once another thread sets it to true the workers
  /// stop and the function throws exactccd::Cancelled (no partial result). The flag must
  /// outlive the call; nullptr (the default): never cancelled. SceneBroadPhase honours it in
  /// its constructor only (update() is not cancellable).
  const std::atomic<bool>* cancel = nullptr;
};

/// Thrown by a scene function (scene.hpp, candidates.hpp) whose SceneOptions::cancel flag was
/// set during the call.
class Cancelled : public std::runtime_error {
 public:
  /// The exception with the message "exactccd: cancelled".
  Cancelled() : std::runtime_error("exactccd: cancelled") {}
};

/// Throws std::invalid_argument when options.min_distance is negative, NaN or infinite,
/// options.tmax is not in (0, 1], or options.threads exceeds kMaxThreads. Every scene
/// function taking SceneOptions calls it first.
void validate(const SceneOptions& options);

/// Which kind of pair a Collision is.
enum class CollisionKind {
  vertex_face,  ///< a vertex and a triangle
  edge_edge,    ///< two edges
  point_edge,   ///< an isolated point and an edge (d > 0 in 3D; always in the plane)
  point_point,  ///< two isolated points (d > 0 in 3D; always in the plane)
};

/// A colliding pair of primitives and its certified time of impact. The fields set per kind
/// (the others keep their default -1):
/// - vertex_face: vertex, triangle;
/// - edge_edge: edge_a, edge_b (each ascending, edge_a < edge_b);
/// - point_edge: vertex (the isolated point), edge_a (the edge, ascending);
/// - point_point: vertex and vertex_b (the two isolated points, vertex < vertex_b).
struct Collision {
  CollisionKind kind = CollisionKind::vertex_face;  ///< which kind of pair
  int vertex = -1;               ///< vertex-face: the vertex; point-edge, point-point: the (first) point
  int triangle = -1;             ///< vertex-face: index into Scene::triangles (else -1)
  std::array<int, 2> edge_a{{-1, -1}};  ///< edge-edge: first edge; point-edge: the edge (ascending vertex indices)
  std::array<int, 2> edge_b{{-1, -1}};  ///< edge-edge: second edge, ascending; edge_a < edge_b
  TimeInterval toi;              ///< tightest double enclosure of the earliest time within min_distance
  int vertex_b = -1;             ///< point-point: the second point, vertex < vertex_b (else -1)
};

/// Throws std::invalid_argument, with a message naming the offending element, when the scene
/// is malformed: positions_t0 and positions_t1 differ in size, a coordinate is NaN or infinite,
/// an index (of a triangle, edge or point) is out of range, or a triangle or edge repeats a
/// vertex index. Every other function calls it first.
void validate(const Scene& scene);

/// Every colliding pair of the scene with its time of impact (the earliest t in [0, tmax] at
/// which the pair is within distance <= d, d = options.min_distance, tmax = options.tmax):
/// sorted by kind in CollisionKind order, vertex-face pairs by (vertex, triangle), edge-edge by
/// (edge_a, edge_b), point-edge by (vertex, edge_a), point-point by (vertex, vertex_b); the
/// point kinds only when d > 0. Pairs sharing a vertex index are excluded. The narrow phase runs
/// on options.threads threads; the result is the same for any number of threads. With the
/// default options (d = 0, tmax = 1) the pairs are the VF and EE contacts over the whole step.
std::vector<Collision> find_collisions(const Scene& scene, const SceneOptions& options = {});

/// The earliest time of impact over the scene (the tightest double interval holding the exact
/// earliest time in [0, tmax] at which some pair is within distance <= d), or std::nullopt when
/// no pair collides. Prunes by time: once a collision with upper bound h is known, a pair is
/// skipped when its primitives' boxes over [0, h] (enclosed with interval arithmetic, inflated
/// by d with outward rounding) do not overlap, and evaluation stops at a collision at t = 0.
std::optional<TimeInterval> earliest_toi(const Scene& scene, const SceneOptions& options = {});

/// The earliest of the collisions' times of impact (ordered by lo, then hi), or std::nullopt
/// for an empty list: earliest_toi(find_collisions(s, o)) == earliest_toi(s, o).
std::optional<TimeInterval> earliest_toi(const std::vector<Collision>& collisions);

/// True iff no pair of the scene collides (comes within distance <= d at some t in [0, tmax]);
/// stops at the first collision found.
bool is_collision_free(const Scene& scene, const SceneOptions& options = {});

/// The largest step s <= tmax over which the motion keeps every pair at distance > d,
/// conservatively: tmax when no pair collides in [0, tmax]; otherwise, with [lo, hi] the
/// earliest time of impact, the largest double strictly below lo, so that the motion over
/// [0, s] is collision-free exactly. A collision at t = 0 (lo == 0) allows no step: the result
/// is 0 (and 0 is then not itself collision-free when the contact is exactly at t = 0). With
/// the default options (d = 0, tmax = 1): 1 when collision-free.
double max_collision_free_step(const Scene& scene, const SceneOptions& options = {});

/// max_collision_free_step given the scene's earliest time of impact over [0, tmax]
/// (std::nullopt: none): tmax when none. Throws std::invalid_argument when tmax is not in
/// (0, 1].
double max_collision_free_step(const std::optional<TimeInterval>& earliest, double tmax = 1.0);

/// Throws std::invalid_argument, naming the offending element, when the 2D scene is malformed:
/// positions_t0 and positions_t1 differ in size, a coordinate is NaN or infinite, an index (of
/// an edge or point) is out of range, or an edge repeats a vertex index.
void validate(const Scene2d& scene);

/// Every colliding pair of the 2D scene with its time of impact (see find_collisions(const
/// Scene&, const SceneOptions&)): edge-edge pairs by (edge_a, edge_b), then point-edge by
/// (vertex, edge_a), then point-point by (vertex, vertex_b), for every d including 0. Decided
/// with the 2D primitive queries of ccd.hpp (edge_edge_2d_toi, point_edge_2d_toi,
/// point_point_2d_toi).
std::vector<Collision> find_collisions(const Scene2d& scene, const SceneOptions& options = {});

/// The earliest time of impact over the 2D scene, or std::nullopt; see earliest_toi(const
/// Scene&, const SceneOptions&).
std::optional<TimeInterval> earliest_toi(const Scene2d& scene, const SceneOptions& options = {});

/// True iff no pair of the 2D scene collides; see is_collision_free(const Scene&, const
/// SceneOptions&).
bool is_collision_free(const Scene2d& scene, const SceneOptions& options = {});

/// The largest collision-free step of the 2D scene; see max_collision_free_step(const Scene&,
/// const SceneOptions&).
double max_collision_free_step(const Scene2d& scene, const SceneOptions& options = {});

/// Candidate pairs of a scene's broad phase (SceneBroadPhase::candidates()): every pair of the
/// scene's kinds (see the top of this file) whose boxes over [0, tmax], grown by d with outward
/// rounding, overlap, and which shares no vertex index. A pair that comes within distance d at
/// some t in [0, tmax] is always among them (most candidates do not collide). Every list
/// sorted, without duplicates.
struct SceneCandidates {
  std::vector<std::array<int, 2>> vertex_face;  ///< {vertex, triangle}
  std::vector<std::array<int, 2>> edge_edge;    ///< {edge i, edge j}, i < j, into SceneBroadPhase::edges()
  std::vector<std::array<int, 2>> point_edge;   ///< {isolated point, edge} (edge into edges())
  std::vector<std::array<int, 2>> point_point;  ///< {isolated point p, isolated point q}, p < q
};

/// A scene's broad phase kept across calls: bounding volume hierarchies over the triangles, the
/// edges and the isolated points, built once and refitted (not rebuilt) when only the positions
/// at t = 1 change, as in a line search that tries several steps from the same positions at
/// t = 0 over the same topology. It answers the scene functions for the scene as it is now
/// (find_collisions(), earliest_toi(), is_collision_free(), max_collision_free_step(): exactly
/// the answers of the free functions for scene() and the options given at construction), each
/// streaming the trees' pairs into the narrow phase without storing them; so a line search
/// calling update() and max_collision_free_step() for shrinking steps pays the topology and
/// the trees' build once. The candidates are always exactly those a new SceneBroadPhase of the
/// current scene would give (the hierarchy's shape affects only speed); candidates() lists
/// them on first request after a change. Built and queried on options.threads threads. Not
/// thread-safe for update() concurrently with other calls; const members may be called from
/// several threads.
class SceneBroadPhase {
 public:
  /// Validates the scene and the options (std::invalid_argument, as validate()), keeps a copy
  /// of the scene and computes its candidates for the question of `options` (min_distance d,
  /// tmax).
  explicit SceneBroadPhase(const Scene& scene, const SceneOptions& options = {});
  /// Releases the scene copy and the hierarchies.
  ~SceneBroadPhase();
  /// Takes over another broad phase's state (the moved-from object may only be destroyed or
  /// assigned to).
  SceneBroadPhase(SceneBroadPhase&&) noexcept;
  /// Takes over another broad phase's state (as the move constructor).
  SceneBroadPhase& operator=(SceneBroadPhase&&) noexcept;
  /// Not copyable (the hierarchies are large; build another from scene()).
  SceneBroadPhase(const SceneBroadPhase&) = delete;
  /// Not copyable.
  SceneBroadPhase& operator=(const SceneBroadPhase&) = delete;

  /// Replaces the scene's positions at t = 1 (positions at t = 0 and topology kept) and refits
  /// the hierarchies (the candidates are listed again when next asked for). Throws
  /// std::invalid_argument (leaving the object unchanged) when the size differs from
  /// positions_t0 or a coordinate is not finite.
  void update(const std::vector<Vec3>& positions_t1);

  /// find_collisions(scene(), options) from the kept hierarchies.
  std::vector<Collision> find_collisions() const;

  /// earliest_toi(scene(), options) from the kept hierarchies.
  std::optional<TimeInterval> earliest_toi() const;

  /// is_collision_free(scene(), options) from the kept hierarchies.
  bool is_collision_free() const;

  /// max_collision_free_step(scene(), options) from the kept hierarchies: the step of a line
  /// search after update(positions_t1) with the trial positions.
  double max_collision_free_step() const;

  /// The scene as it is now (the last positions_t1 given).
  const Scene& scene() const;

  /// The scene's edges (the triangles' unique edges and the extra edges, each ascending,
  /// sorted): what SceneCandidates::edge_edge and point_edge index.
  const std::vector<std::array<int, 2>>& edges() const;

  /// The candidates of the scene as it is now (listed on the first call after construction or
  /// update(), then kept until the next update()).
  const SceneCandidates& candidates() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// Exact static self-intersection check of a triangle mesh: true iff
/// - every two triangles with no vertex index in common are disjoint as closed triangles, and
/// - for every two triangles sharing exactly one vertex index v, the edge of each opposite v is
///   disjoint from the other closed triangle. For non-degenerate triangles this holds iff the
///   two meet only at v's position; a degenerate triangle whose vertex v lies on its opposite
///   edge counts as meeting its neighbours there.
/// Triangles sharing two or three vertex indices are not checked (they meet along the shared
/// edge; a coplanar fold-over beyond it is not reported). Degenerate triangles (collinear or
/// coincident positions) are their hulls. Throws std::invalid_argument on non-finite
/// coordinates, out-of-range or repeated indices.
/// Runs on one thread (the overload below takes a thread count).
bool intersection_free(const std::vector<Vec3>& positions,
                       const std::vector<std::array<int, 3>>& triangles);

/// intersection_free(positions, triangles) on `threads` threads (0: every hardware thread, at
/// most 1024); the answer does not depend on them. Stops at the first intersecting pair found.
bool intersection_free(const std::vector<Vec3>& positions, const std::vector<std::array<int, 3>>& triangles,
                       unsigned threads);

}  // namespace exactccd
