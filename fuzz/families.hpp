// Degenerate query families: exactly degenerate configurations (contact through a vertex, an
// endpoint, grazing, coplanar sliding, ...) perturbed by delta = 2^-k times the scene scale,
// towards or away from contact. Used by the stability sweep, the fuzzers, fuzz-against and
// the tests. A library (no I/O), usable outside fuzzing.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "exactccd/types.hpp"

namespace exactccd::families {

/// A query of either kind.
using AnyQuery = std::variant<VertexFaceQuery, EdgeEdgeQuery>;

/// One generated instance.
struct Instance {
  AnyQuery query;
  /// The answer known by construction (derivation in families.cpp), when the perturbation is
  /// represented exactly; nullopt when only the exact path can tell (e.g. it was rounded away).
  std::optional<bool> expected;
};

/// A family: a name, a kind and a generator of instances for a perturbation exponent k
/// (delta = 2^-k times the scale; k = kUnperturbed gives the exact degeneracy itself).
struct Family {
  std::string name;
  bool vertex_face;  ///< kind: true for vertex-face, false for edge-edge
  /// toward: perturb towards contact (true) or away from it (false).
  Instance (*make)(int k, bool toward, std::mt19937_64& rng);
};

/// k meaning "no perturbation": the exact degenerate configuration, always in contact.
constexpr int kUnperturbed = -1;

/// Every family, vertex-face first.
const std::vector<Family>& all_families();

/// The family of that name, or nullptr.
const Family* find_family(const std::string& name);

/// A random instance of a random family (k uniform in [0, 60] or unperturbed, random direction,
/// random exact symmetry, offset and power-of-two scale): the fuzzers' and fuzz-against's mix.
Instance random_instance(std::mt19937_64& rng, std::optional<bool> vertex_face = std::nullopt);

}  // namespace exactccd::families
