// Writes the fuzzers' seed corpus: OUT/vertex_face/ and OUT/edge_edge/, one small file per
// seed (fuzz_input.hpp format):
//   cat-NAME        every hand-derived catalogue case, bit-exact (raw mode);
//   catcopy-I       catalogue mode: a few of the 2^996 / 2^-1060 / 2^20 / 2^40 copies;
//   fam-NAME-K-DIR  family mode: every family of the kind, unperturbed and at k = 52,
//                   toward and away;
//   grid-*          grid mode with degenerate edits (coplanar, shared vertex, subnormal, 1e300).
// The committed corpus (fuzz/corpus/) is this program's output; CTest checks it is fresh.
// Usage: make_seed_corpus OUT_DIR
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "fuzz/catalogue.hpp"
#include "fuzz/families.hpp"
#include "fuzz/fuzz_input.hpp"

namespace {

namespace fs = std::filesystem;
using namespace exactccd;
using Bytes = std::vector<std::uint8_t>;

void write(const fs::path& path, const Bytes& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

template <class Entries>
void write_kind(const fs::path& dir, bool vertex_face, const Entries& base, std::size_t all_count) {
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
  for (const families::Family& f : families::all_families()) {
    if (f.vertex_face != vertex_face) continue;
    for (int k : {families::kUnperturbed, 52})
      for (bool toward : {true, false}) {
        if (k == families::kUnperturbed && !toward) continue;  // the same configuration
        const std::string name = "fam-" + f.name + "-" + (k < 0 ? std::string("u") : std::to_string(k)) +
                                 (toward ? "-toward" : "-away");
        write(dir / name, fuzzing::encode_family(family_index, k, toward, 12345));
      }
    ++family_index;
  }
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
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: make_seed_corpus OUT_DIR\n";
    return 2;
  }
  const fs::path out = argv[1];
  write_kind(out / "vertex_face", true, catalogue::vertex_face_base_cases(),
             catalogue::vertex_face_cases().size());
  write_kind(out / "edge_edge", false, catalogue::edge_edge_base_cases(),
             catalogue::edge_edge_cases().size());
  return 0;
}
