// The kinds of fuzz-against at run time, each derived from its description in lib/kinds.
#include <type_traits>

#include "degeneracy/degeneracy.hpp"
#include "exactccd/plugin.h"
#include "generators/fuzz_input.hpp"
#include "fuzz_against.hpp"

namespace exactccd::cli::fuzz {
namespace {

/// The query of kind Kind in number type T from rows (the plane's kinds take x and y).
template <class Kind, class T = double>
typename Kind::template Query<T> query_of(const Rows& r) {
  if constexpr (std::is_same_v<T, double>) {
    return io::query_from_rows<typename Kind::template Query<double>>(r);
  } else {
    std::array<RationalVec3, 8> q;
    for (std::size_t i = 0; i < 8; ++i) q[i] = {mpq_class(r[i].x), mpq_class(r[i].y), mpq_class(r[i].z)};
    return io::query_from_rows<typename Kind::template Query<T>>(q);
  }
}

template <class Kind>
void add_contact_generators(FuzzKind& k) {
  if constexpr (is_contact_kind<Kind>) {
    k.answer_symbol = std::string(Kind::plugin_symbol);
    k.toi_symbol = std::string(Kind::plugin_toi_symbol);
    k.categories = [](const Rows& r) {
      return exact::join_categories(exact::degeneracy_categories(query_of<Kind, mpq_class>(r)));
    };
  }
  if constexpr (fuzzing::is_decodable_v<Kind>) {
    k.contact_families = families::families_of_kind<Kind>();
    k.random_contact_instance = [](std::mt19937_64& rng) { return families::random_instance<Kind>(rng); };
    k.decode = [](const std::uint8_t* data, std::size_t size) { return fuzzing::decode<Kind>(data, size); };
  }
}

template <class Kind>
FuzzKind describe() {
  FuzzKind k;
  k.kind = query_kind<Kind>();
  k.name = std::string(Kind::name);
  k.short_name = std::string(Kind::short_name);
  k.points = Kind::points;
  k.dimension = Kind::dimension;
  k.layout = io::layout_of<Kind>();
  for (int i = 0; i < 2 * Kind::points; ++i)
    k.row_names[static_cast<std::size_t>(i)] =
        std::string(Kind::point_names[static_cast<std::size_t>(i % Kind::points)]) + (i < Kind::points ? "_t0" : "_t1");
  k.query_symbol = EXACTCCD_PLUGIN_QUERY_PREFIX + k.short_name + EXACTCCD_PLUGIN_QUERY_SUFFIX;
  k.exact_answer = [](const Rows& r, const CcdParams& p) { return ccd(query_of<Kind>(r), p, Method::exact); };
  k.exact_toi = [](const Rows& r, const CcdParams& p) { return toi(query_of<Kind>(r), p, Method::exact); };
  add_contact_generators<Kind>(k);
  k.separation_families = separation_families::families_of_kind<Kind>();
  return k;
}

}  // namespace

const FuzzKind& fuzz_kind(QueryKind kind) {
  static const std::vector<FuzzKind> all = [] {
    std::vector<FuzzKind> out;
    kinds::for_each_kind([&](auto k) { out.push_back(describe<decltype(k)>()); });
    return out;
  }();
  return all.at(kind.index);
}

std::mt19937_64 query_rng(std::uint64_t seed, std::size_t i, std::uint32_t tag) {
  std::seed_seq s{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                  static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(std::uint64_t{i} >> 32), tag};
  return std::mt19937_64(s);
}

}  // namespace exactccd::cli::fuzz
