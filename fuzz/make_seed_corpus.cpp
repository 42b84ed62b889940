// Writes the fuzzers' seed corpus: OUT/vertex_face/ and OUT/edge_edge/ (each kind's function
// stem, lib/kinds), one small file per seed (fuzz_input.hpp format):
//   cat-NAME        every hand-derived catalogue case, bit-exact (raw mode);
//   catcopy-I       catalogue mode: a few of the 2^996 / 2^-1060 / 2^20 / 2^40 copies;
//   fam-NAME-K-DIR  family mode: every family of the kind, unperturbed and at k = 52,
//                   toward and away;
//   famwide-NAME-K-STYLE  family mode, wide placement (families::make_wide): every family
//                   unperturbed and at k = 20 toward, in two of the four styles (cycling);
//   wide-*          raw mode: wide-exponent queries an earlier filter answered wrongly (the
//                   reported stage-1 query and its edge-edge analogue);
//   grid-*          grid mode with degenerate edits (coplanar, shared vertex, subnormal, 1e300,
//                   per-axis scales from 2^-1070 to 2^1000).
// The wide seeds exceed the fuzzers' default exponent-spread limit: only the full-range
// configuration (docs/fuzzing.md) checks them; tests/datasets/test_fuzz_regressions.cpp checks them all.
// The committed corpus (fuzz/corpus/) is this program's output; CTest checks it is fresh.
// Usage: make_seed_corpus OUT_DIR
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "generators/catalogue.hpp"
#include "generators/families.hpp"
#include "generators/fuzz_input.hpp"

namespace {

namespace fs = std::filesystem;
using namespace exactccd;
using Bytes = std::vector<std::uint8_t>;

void write(const fs::path& path, const Bytes& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

/// The reported stage-1 query (static triangle (0,0,0), (2^200,0,1), (0,2^-538,0), p crossing
/// its plane inside at t = 1/2) and its edge-edge analogue (tests/datasets/test_wide_exponents.cpp).
void write_reported(const fs::path& dir, kinds::VertexFace) {
  const Vec3 a{0, 0, 0}, b{0x1p200, 0, 1}, c{0, 0x1p-538, 0};
  write(dir / "wide-reported-stage1",
        fuzzing::encode_raw({{{0x1p-360, 0x1p-539, 0}, a, b, c, {0x1p-360, 0x1p-539, 0x1p-559}, a, b, c}}));
}
void write_reported(const fs::path& dir, kinds::EdgeEdge) {
  const Vec3 a0{0, 0, 0}, a1{0x1p200, 0, 1};
  write(dir / "wide-reported-stage1-ee",
        fuzzing::encode_raw({{a0, a1, {0x1p-360, -0x1p-539, 0}, {0x1p-360, 0x1p-539, 0}, a0, a1,
                              {0x1p-360, -0x1p-539, 0x1p-559}, {0x1p-360, 0x1p-539, 0x1p-559}}}));
}

/// The seeds of one kind (a description of lib/kinds) in OUT/<its function stem>.
template <class Kind>
void write_kind(const fs::path& out, Kind kind) {
  const fs::path dir = out / std::string(Kind::function);
  const auto base = catalogue::base_cases(kind);
  const std::size_t all_count = catalogue::cases(kind).size();
  fs::create_directories(dir);
  for (const auto& e : base) {
    fuzzing::Rows r;
    const auto q = rows(e.query);
    for (std::size_t i = 0; i < 8; ++i) r[i] = {q[i].x.get_d(), q[i].y.get_d(), q[i].z.get_d()};
    write(dir / ("cat-" + e.name), fuzzing::encode_raw(r));
  }
  // Catalogue mode: five of the scaled / translated copies, spread over them.
  for (std::size_t j = 0; j < 5; ++j) {
    const std::size_t index = base.size() + j * (all_count - base.size()) / 5;
    write(dir / ("catcopy-" + std::to_string(index)), fuzzing::encode_catalogue(index));
  }
  std::size_t family_index = 0;
  for (const families::Family* family : families::families_of_kind<Kind>()) {
    const families::Family& f = *family;
    for (int k : {families::kUnperturbed, 52})
      for (bool toward : {true, false}) {
        if (k == families::kUnperturbed && !toward) continue;  // the same configuration
        const std::string name = "fam-" + f.name + "-" + (k < 0 ? std::string("u") : std::to_string(k)) +
                                 (toward ? "-toward" : "-away");
        write(dir / name, fuzzing::encode_family(family_index, k, toward, 12345));
      }
    for (int k : {families::kUnperturbed, 20}) {
      const auto style = static_cast<families::WideStyle>((family_index + (k < 0 ? 0 : 1)) %
                                                          families::kWideStyleCount);
      const std::string name = "famwide-" + f.name + "-" + (k < 0 ? std::string("u") : std::to_string(k)) +
                               "-" + families::wide_style_name(style);
      write(dir / name, fuzzing::encode_family(family_index, k, true, 4242, style));
    }
    ++family_index;
  }
  write_reported(dir, kind);
  // Grid mode, scale byte 0 (2^0): a unit-ish configuration with degenerate edits.
  Bytes grid{static_cast<std::uint8_t>(fuzzing::Mode::grid), 0};
  for (int c = 0; c < 24; ++c) grid.push_back(static_cast<std::uint8_t>((c * 5 + 3) % 17));
  Bytes coplanar = grid;
  fuzzing::append_edit(coplanar, 2, 2, 0);  // all points in one z plane
  write(dir / "grid-coplanar", coplanar);
  Bytes shared = grid;
  fuzzing::append_edit(shared, 0, 1, 0);  // p_t0 := a_t0 (shared vertex)
  fuzzing::append_edit(shared, 1, 1, 0);  // a static
  write(dir / "grid-shared-vertex", shared);
  Bytes collinear = grid;
  fuzzing::append_edit(collinear, 4, 0, 1 | (2 << 3));  // p_t0 := midpoint of a_t0, b_t0
  fuzzing::append_edit(collinear, 4, 4, 5 | (6 << 3));
  write(dir / "grid-collinear", collinear);
  Bytes subnormal = grid;
  subnormal[1] = 12;  // scale 2^-1072: subnormal coordinates
  write(dir / "grid-subnormal", subnormal);
  Bytes huge = grid;
  huge[1] = 15;  // scale 2^996: coordinates near 1e300
  fuzzing::append_edit(huge, 2, 0, 3);
  write(dir / "grid-huge-coplanar", huge);
  // Edit 14 scales one axis by 2^((b - 128) 9 + (a / 3) % 9): x by 2^-1070, z by 2^1000.
  Bytes axes = grid;
  fuzzing::append_edit(axes, 14, 0 + 3 * 1, 9);       // axis 0: (9 - 128) 9 + 1 = -1070
  fuzzing::append_edit(axes, 14, 2 + 3 * 1, 239);     // axis 2: (239 - 128) 9 + 1 = 1000
  write(dir / "grid-axis-scales", axes);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: make_seed_corpus OUT_DIR\n";
    return 2;
  }
  const fs::path out = argv[1];
  // The kinds the fuzzers cover (fuzz_vertex_face, fuzz_edge_edge).
  write_kind(out, kinds::VertexFace{});
  write_kind(out, kinds::EdgeEdge{});
  return 0;
}
