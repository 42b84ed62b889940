// Seeds for the reader fuzz targets, cut at build time from the bundled data (the files are too
// large to be seeds whole, and generating keeps the seeds what the data is now): usage
//   make_reader_seeds SOURCE_DIR OUT_DIR
// writes OUT_DIR/<target>/<name> for the targets read_obj, read_ply, read_off, read_stl,
// read_benchmark_csv, read_rigid_csv, read_truth_json and read_answers (read_partial's seeds are
// the committed ones in fuzz/corpus/read_partial/). Each seed is at most a few kB:
// - meshes: the bundled tetrahedra (tests/data/meshes) as they are, and the first triangles of
//   every bundled scene (data/scenes/*/T*.obj) with their vertices, in every format and encoding;
// - query files: the first two queries of every bundled benchmark file (data/*/ and tests/data/),
//   with and without the truth column, and the first lines of every rigid query file;
// - truth and answers files: the truth columns of those queries, as JSON, as answers and as
//   answers with times of impact.
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz/readers/mesh_writers.hpp"
#include "io/mesh_file.hpp"

namespace fs = std::filesystem;
using exactccd::io::TriangleMesh;

namespace {

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

void write_seed(const fs::path& dir, const std::string& name, const std::string& bytes) {
  fs::create_directories(dir);
  std::ofstream out(dir / name, std::ios::binary);
  out << bytes;
}

/// The first `count` triangles of `mesh` with the vertices they use, renumbered in order of use.
TriangleMesh first_triangles(const TriangleMesh& mesh, std::size_t count) {
  TriangleMesh out;
  std::map<int, int> renumbered;
  for (std::size_t t = 0; t < std::min(count, mesh.triangles.size()); ++t) {
    std::array<int, 3> tri{};
    for (int c = 0; c < 3; ++c) {
      const int v = mesh.triangles[t][static_cast<std::size_t>(c)];
      const auto [it, inserted] = renumbered.emplace(v, static_cast<int>(out.vertices.size()));
      if (inserted) out.vertices.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
      tri[static_cast<std::size_t>(c)] = it->second;
    }
    out.triangles.push_back(tri);
  }
  return out;
}

/// The mesh with every coordinate rounded to float (binary STL holds floats).
TriangleMesh as_floats(TriangleMesh mesh) {
  for (exactccd::Vec3& v : mesh.vertices)
    for (double* x : {&v.x, &v.y, &v.z}) *x = static_cast<double>(static_cast<float>(*x));
  return mesh;
}

/// `mesh` in every format the targets read, named `stem`.<encoding>.
void write_mesh_seeds(const fs::path& out, const std::string& stem, const TriangleMesh& mesh) {
  using exactccd::fuzzing::PlyEncoding;
  std::ostringstream obj, off, stl, stl_binary;
  exactccd::io::write_obj(obj, mesh.vertices, mesh.triangles, "seed: " + stem);
  write_seed(out / "read_obj", stem + ".obj", obj.str());
  for (const auto& [encoding, name] : {std::pair{PlyEncoding::ascii, "ascii"},
                                       std::pair{PlyEncoding::binary_little_endian, "le"},
                                       std::pair{PlyEncoding::binary_big_endian, "be"}}) {
    std::ostringstream ply;
    exactccd::fuzzing::write_ply(ply, mesh, encoding);
    write_seed(out / "read_ply", stem + "-" + name + ".ply", ply.str());
  }
  exactccd::fuzzing::write_off(off, mesh);
  write_seed(out / "read_off", stem + ".off", off.str());
  exactccd::fuzzing::write_stl_ascii(stl, mesh);
  write_seed(out / "read_stl", stem + "-ascii.stl", stl.str());
  if (exactccd::fuzzing::write_stl_binary(stl_binary, as_floats(mesh)))
    write_seed(out / "read_stl", stem + "-binary.stl", stl_binary.str());
}

/// The first `lines` non-blank lines of `text`, each without its last `drop_columns` fields.
std::string first_lines(const std::string& text, std::size_t lines, int drop_columns) {
  std::istringstream in(text);
  std::string out;
  for (std::string line; lines > 0 && std::getline(in, line);) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    for (int k = 0; k < drop_columns; ++k) line = line.substr(0, line.rfind(','));
    out += line + "\n";
    --lines;
  }
  return out;
}

/// The truth column (the last field) of every `rows`-th line of a benchmark file's first lines.
std::vector<bool> truths(const std::string& csv, std::size_t rows) {
  std::vector<bool> out;
  std::istringstream in(csv);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);)
    if (line.find(',') != std::string::npos && n++ % rows == 0) out.push_back(line.substr(line.rfind(',') + 1) == "1");
  return out;
}

/// The truth, answers and --toi answers seeds of one benchmark file's first queries.
void write_truth_seeds(const fs::path& out, const std::string& stem, const std::vector<bool>& truth) {
  std::string json = "[", answers, toi;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    json += std::string(i ? ", " : "") + (truth[i] ? "true" : "false");
    answers += truth[i] ? "1\n" : "0\n";
    toi += truth[i] ? "1 0." + std::to_string(i * 37 % 100) + "\n" : "0\n";
  }
  write_seed(out / "read_truth_json", stem + ".json", json + "]\n");
  write_seed(out / "read_answers", stem + ".txt", answers);
  write_seed(out / "read_answers", stem + "-toi.txt", toi);
}

/// Benchmark CSV files: the bundled data (data/*/) and the test data (tests/data/*.csv).
std::vector<fs::path> benchmark_files(const fs::path& source) {
  std::vector<fs::path> out;
  for (const fs::path& dir : {source / "data" / "sim", source / "data" / "catalogue", source / "data" / "families",
                             source / "data" / "kinds", source / "tests" / "data"})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".csv") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

void write_query_seeds(const fs::path& source, const fs::path& out) {
  for (const fs::path& file : benchmark_files(source)) {
    const std::string text = read_file(file);
    const std::string stem = file.stem().string();
    // 8 rows per query for vf/ee, 6 for point-edge, 4 for point-point: two queries of each.
    const std::size_t rows = stem.find("point-point") != std::string::npos ? 4
                             : stem.find("point-edge") != std::string::npos ? 6 : 8;
    const std::string two = first_lines(text, 2 * rows, 0);
    write_seed(out / "read_benchmark_csv", stem + ".csv", two);
    write_seed(out / "read_benchmark_csv", stem + "-no-truth.csv", first_lines(text, 2 * rows, 1));
    write_truth_seeds(out, stem, truths(first_lines(text, 16 * rows, 0), rows));
  }
  for (const fs::path& dir : {source / "data" / "rigid", source / "tests" / "data" / "rigid"})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".csv") {
        const std::string text = read_file(e.path());
        // The comment lines and the first three queries.
        std::istringstream in(text);
        std::string seed;
        int queries = 0;
        for (std::string line; queries < 3 && std::getline(in, line);) {
          seed += line + "\n";
          queries += !line.empty() && line[0] != '#';
        }
        write_seed(out / "read_rigid_csv", e.path().stem().string() + ".csv", seed);
      }
}

void write_mesh_seeds_from_data(const fs::path& source, const fs::path& out) {
  for (const auto& e : fs::directory_iterator(source / "tests" / "data" / "meshes")) {
    const std::string ext = e.path().extension().string();
    if (ext == ".ply" || ext == ".off" || ext == ".stl")
      write_seed(out / ("read" + std::string("_") + ext.substr(1)), e.path().filename().string(), read_file(e.path()));
  }
  write_mesh_seeds(out, "tetra", exactccd::io::read_mesh((source / "tests" / "data" / "meshes" / "tetra.ply").string()));
  for (const auto& scene : fs::directory_iterator(source / "data" / "scenes")) {
    if (!scene.is_directory()) continue;
    for (const char* frame : {"T0", "T1"}) {
      const TriangleMesh mesh = exactccd::io::read_mesh((scene.path() / (std::string(frame) + ".obj")).string());
      const std::string stem = scene.path().filename().string() + "-" + frame;
      write_mesh_seeds(out, stem + "-6", first_triangles(mesh, 6));
      write_mesh_seeds(out, stem + "-1", first_triangles(mesh, 1));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: make_reader_seeds SOURCE_DIR OUT_DIR\n";
    return 2;
  }
  try {
    const fs::path source = argv[1], out = argv[2];
    for (const char* target : {"read_obj", "read_ply", "read_off", "read_stl", "read_benchmark_csv", "read_rigid_csv",
                               "read_truth_json", "read_answers"})
      fs::remove_all(out / target);  // only what this program writes
    write_mesh_seeds_from_data(source, out);
    write_query_seeds(source, out);
  } catch (const std::exception& e) {
    std::cerr << "make_reader_seeds: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
