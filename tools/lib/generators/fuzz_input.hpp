// Fuzzer bytes -> CCD queries biased to degeneracies. Shared by the libFuzzer targets
// (fuzz_vertex_face.cpp, fuzz_edge_edge.cpp), their seed-corpus generator
// (make_seed_corpus.cpp) and `exactccd fuzz-against` (which feeds it random bytes). A library:
// no I/O, no mutable global state. The format is documented in docs/fuzzing.md.
//
// Byte 0 selects a mode (byte % 4), a fixed-size payload follows, then any number of 3-byte
// edits (op, a, b) applied in order. Bytes past the end read as 0, so every input decodes.
//   grid       1 byte scale exponent (a table: 0, -1, ..., -1070 subnormal, 996 ~ 1e300, ...),
//              24 bytes: each coordinate an integer in [-8, 8] times 2^scale.
//   raw        24 doubles, 8 bytes each (little-endian bit patterns; non-finite ones read as 0).
//   family     1 byte family (of the requested kind, tools/lib/generators/families.hpp), 1 byte k (-1..62, or
//              62..1070 in steps of 16: subnormal perturbations), 1 byte direction and
//              placement (bit 0: toward; (byte >> 1) % 5: 0 the family's own placement, 1..4
//              families::make_wide with WideStyle 0..3: per-axis scales over the whole double
//              range), 8 bytes placement seed.
//   catalogue  2 bytes: an entry of tools/lib/generators/catalogue.hpp of the requested kind (with the 2^996,
//              2^-1060, 2^20 and 2^40 copies).
// Edits (op % 15): copy a point onto another (shared and repeated vertices), make a vertex
// static, flatten an axis (coplanar), nudge a coordinate by a few ulps, midpoint and
// reflection of two points (collinear), power-of-two scale, power-of-two translation, a
// special value (0, -0, subnormals, 1e300, ...), swap points, mirror an axis, copy a
// coordinate, permute axes, move a point onto a triangle vertex's or edge's line, and scale
// one axis by a power of two from 2^-1152 to 2^1151 (wide exponents across axes).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "exactccd/types.hpp"
#include "generators/catalogue.hpp"
#include "generators/families.hpp"

namespace exactccd::fuzzing {

/// The eight points of a query in benchmark row order.
using Rows = std::array<Vec3, 8>;

/// What byte 0 selects (byte 0 % kModeCount).
enum class Mode : std::uint8_t { grid = 0, raw = 1, family = 2, catalogue = 3 };

/// Number of modes.
constexpr int kModeCount = 4;

/// A short name of a mode: "grid", "raw", "family", "catalogue".
const char* mode_name(Mode m);

/// True for the kinds the decoder writes (kinds::VertexFace, kinds::EdgeEdge): a kind of lib/kinds
/// whose queries are 8 points in 3D and which has a degenerate catalogue (catalogue::cases).
template <class Kind, class = void>
struct is_decodable : std::false_type {};
template <class Kind>
struct is_decodable<Kind, std::void_t<decltype(catalogue::cases(Kind{}))>>
    : std::is_same<decltype(rows(std::declval<typename Kind::template Query<double>>())), Rows> {};
/// See is_decodable.
template <class Kind>
constexpr bool is_decodable_v = is_decodable<Kind>::value;

/// What decode() draws a kind's queries from: its families (family mode) and its catalogue
/// entries as doubles (catalogue mode; every catalogue coordinate is a double).
struct KindSources {
  std::vector<const families::Family*> families;
  std::vector<Rows> catalogue;
};

/// The sources of a kind (a description of lib/kinds with 8 rows per query:
/// kinds::VertexFace, kinds::EdgeEdge), built once.
template <class Kind>
const KindSources& kind_sources() {
  static_assert(is_decodable_v<Kind>, "the fuzz decoder writes 8-point 3D queries of kinds with a catalogue");
  static const KindSources sources = [] {
    KindSources s{families::families_of_kind<Kind>(), {}};
    for (const auto& e : catalogue::cases(Kind{})) {
      Rows r;
      const auto q = rows(e.query);
      for (std::size_t i = 0; i < 8; ++i) r[i] = {q[i].x.get_d(), q[i].y.get_d(), q[i].z.get_d()};
      s.catalogue.push_back(r);
    }
    return s;
  }();
  return sources;
}

/// Decodes fuzzer bytes into a query drawing from a kind's sources. Every byte string decodes;
/// the result may hold non-finite coordinates (an edit overflowed): callers skip those
/// (all_finite).
Rows decode(const std::uint8_t* data, std::size_t size, const KindSources& sources);

/// Decodes fuzzer bytes into a query of the kind Kind (kinds::VertexFace, kinds::EdgeEdge).
template <class Kind>
Rows decode(const std::uint8_t* data, std::size_t size) {
  return decode(data, size, kind_sources<Kind>());
}

/// The mode byte 0 selects (grid for an empty input).
Mode mode_of(const std::uint8_t* data, std::size_t size);

/// True when all 24 coordinates are finite.
bool all_finite(const Rows& r);

/// The largest difference of binary exponents between two nonzero coordinates (0 when fewer
/// than two are nonzero; at most 2097, 2^-1074 next to 2^1023). The exact paths' cost grows with
/// it: the fuzzers skip queries above a limit unless run in the full-range configuration
/// (fuzz_check.hpp, max_exponent_spread).
int exponent_spread(const Rows& r);

/// The raw-mode encoding of a query (decodes to exactly r; non-finite coordinates become 0).
std::vector<std::uint8_t> encode_raw(const Rows& r);

/// The family-mode encoding: the family_index-th family of the kind, k (as close as the k byte
/// can say: -1..62 exactly), the direction, the placement seed, and a wide placement style
/// (nullopt: the family's own placement).
std::vector<std::uint8_t> encode_family(std::size_t family_index, int k, bool toward,
                                        std::uint64_t seed,
                                        std::optional<families::WideStyle> wide = std::nullopt);

/// The catalogue-mode encoding of the index-th catalogue entry of the kind.
std::vector<std::uint8_t> encode_catalogue(std::size_t index);

/// Appends the edit (op, a, b) to an encoding.
void append_edit(std::vector<std::uint8_t>& bytes, std::uint8_t op, std::uint8_t a, std::uint8_t b);

/// A random structured input for `mode`: its payload drawn from rng and 0..4 random edits
/// (fuzz-against's plain random queries, decoded with decode()).
std::vector<std::uint8_t> random_input(std::mt19937_64& rng, Mode mode);

/// The query as 8 lines "x y z" of C99 hex floats (%a), exact and unambiguous, each named by
/// `row_names`.
std::string hex_rows(const Rows& r, const std::array<std::string, 8>& row_names);

/// The query as hex floats with the row names of the kind Kind (its point names at t0, then
/// at t1: p_t0 ... or a0_t0 ...).
template <class Kind>
std::string hex_rows(const Rows& r) {
  static_assert(2 * Kind::points == 8, "8-point queries");
  std::array<std::string, 8> names;
  for (std::size_t i = 0; i < 8; ++i)
    names[i] = std::string(Kind::point_names[i % Kind::points]) + (i < Kind::points ? "_t0" : "_t1");
  return hex_rows(r, names);
}

/// The query as a benchmark CSV (8 rows, each double as an exact rational) with that truth.
std::string benchmark_csv(const Rows& r, bool truth);

}  // namespace exactccd::fuzzing
