// Degenerate query families: exactly degenerate configurations (contact through a vertex, an
// endpoint, grazing, coplanar sliding, ...) perturbed by delta = 2^-k times the scene scale,
// towards or away from contact. Used by the stability sweep, the fuzzers, fuzz-against and
// the tests. A library (no I/O), usable outside fuzzing.
//
// Each instance carries the answer and, where it collides, the time of impact known by
// construction. make() places the configuration by a mild exact placement (scales 2^-4..2^4);
// make_wide() by per-axis power-of-two scales over the whole double range (subnormals next to
// near-overflow magnitudes), translations and shears, all exact affine maps, which keep the
// construction's answer and time of impact (docs/design.md, section 7).
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "exactccd/rational.hpp"
#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd::families {

/// A query of either kind.
using AnyQuery = std::variant<VertexFaceQuery, EdgeEdgeQuery>;

/// The name of a query's kind (its description's, lib/kinds/primitive_kinds.hpp:
/// "vertex-face", "edge-edge").
inline std::string_view kind_name(const AnyQuery& q) {
  return std::visit([](const auto& x) { return kinds::kind_of<decltype(x)>::name; }, q);
}

/// The earliest contact time of a colliding instance, known by construction: the only root in
/// [from, to] of `polynomial` (coefficients c0, c1, ..., lowest degree first). A rational time
/// r is the polynomial t - r with from == to == r; an irrational one is a simple root with
/// nonzero values of opposite signs at from and to.
struct KnownToi {
  std::vector<mpq_class> polynomial;  ///< c0 + c1 t + ... vanishes at the time
  mpq_class from;                     ///< the time is in [from, to]
  mpq_class to;                       ///< (from == to: the time is exactly from)
};

/// The known time r, a rational.
KnownToi rational_toi(const mpq_class& r);

/// True iff `toi` is the tightest double enclosure of the known time t: lo == hi == t when t
/// is a double, else hi == nextafter(lo, +inf) and lo < t < hi. Decided with exact rational
/// arithmetic (independently of the library's TOI code).
bool is_tightest_enclosure(const KnownToi& known, const TimeInterval& toi);

/// The known time as text: "5/12", or "root of [c0, c1, c2] in [0, 1/2]".
std::string to_string(const KnownToi& known);

/// One generated instance.
struct Instance {
  AnyQuery query;
  /// The answer known by construction (derivation in families.cpp), when the perturbation is
  /// represented exactly; nullopt when only the exact path can tell (e.g. it was rounded away).
  std::optional<bool> expected;
  /// The time of impact known by construction: set whenever expected is true.
  std::optional<KnownToi> toi;
};

/// Why the instance's constructed answer or TOI contradicts an answer and TOI of the library
/// (e.g. Method::exact's): a description, or nullopt when they agree or the instance has no
/// constructed answer.
std::optional<std::string> disagreement(const Instance& instance, bool collides,
                                        const std::optional<TimeInterval>& toi);

/// A family: a name, a kind and a generator of instances for a perturbation exponent k
/// (delta = 2^-k times the scale; k = kUnperturbed gives the exact degeneracy itself).
struct Family {
  std::string name;
  /// Its kind: the name of the kind's description (kinds::VertexFace::name, ...); every
  /// instance's query is of that kind.
  std::string_view kind;
  /// toward: perturb towards contact (true) or away from it (false).
  Instance (*make)(int k, bool toward, std::mt19937_64& rng);
  /// The same configuration unplaced, in its local frame (small exact coordinates): what make()
  /// and make_wide() transform.
  Instance (*local)(int k, bool toward);
};

/// k meaning "no perturbation": the exact degenerate configuration, always in contact.
constexpr int kUnperturbed = -1;

/// Every family, vertex-face first.
const std::vector<Family>& all_families();

/// The families of a kind (a description of lib/kinds, e.g. kinds::VertexFace), in
/// all_families() order.
template <class Kind>
std::vector<const Family*> families_of_kind() {
  std::vector<const Family*> out;
  for (const Family& f : all_families())
    if (f.kind == Kind::name) out.push_back(&f);
  return out;
}

/// The family of that name, or nullptr.
const Family* find_family(const std::string& name);

/// How make_wide() places a configuration. Every style first applies a random exact symmetry
/// (axis permutation, sign flips); every scale and translation is a power of two (times a small
/// integer), drawn over the whole range where the coordinates stay exact doubles.
enum class WideStyle : std::uint8_t {
  /// A power-of-two scale per axis, nothing else: the exponent spread lies only across axes;
  /// along each axis the coordinates keep their local relative magnitudes.
  axes_only,
  /// Per-axis scales pushing one axis to the subnormal end (its lowest bit at 2^-1074..2^-1072)
  /// and another to the overflow end (its top bit at 2^1021..2^1023).
  extremes,
  /// Per-axis scales, then a translation m 2^f per axis (|m| <= 8) up to 2^48 times the axis's
  /// finest bit.
  translated,
  /// One or two shears x_i += c x_j (c in +-{1/2, 1, 2, 3}) in the local frame, then per-axis
  /// scales and translations.
  sheared,
};

/// Number of wide styles.
constexpr int kWideStyleCount = 4;

/// A short name of a style: "axes_only", "extremes", "translated", "sheared".
const char* wide_style_name(WideStyle style);

/// The family's instance at (k, toward) placed by a random exact affine map of the style: the
/// transformed coordinates are computed in rational arithmetic and kept only if every one is
/// exactly a double (converted back with GMP and compared); an inexact draw is discarded and
/// redrawn, never rounded. nullopt if no draw of a few was exact. The answer and time of impact
/// are those of the local configuration (an invertible affine map changes neither).
std::optional<Instance> make_wide(const Family& family, int k, bool toward, WideStyle style,
                                  std::mt19937_64& rng);

/// A random instance of a random family of `pool` (k uniform in [0, 60] or unperturbed, random
/// direction, random exact symmetry, offset and power-of-two scale): fuzz-against's mix.
Instance random_instance(std::mt19937_64& rng, const std::vector<const Family*>& pool);

/// A random instance of a random family of any kind.
Instance random_instance(std::mt19937_64& rng);

/// A random instance of a random family of the kind Kind (a description of lib/kinds).
template <class Kind>
Instance random_instance(std::mt19937_64& rng) {
  static const std::vector<const Family*> pool = families_of_kind<Kind>();
  return random_instance(rng, pool);
}

}  // namespace exactccd::families
