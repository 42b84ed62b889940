// exactccd generate: writes the project's own query sets in the benchmark CSV format.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli_common.hpp"
#include "fuzz/catalogue.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kHelp = R"(usage: exactccd generate catalogue --out DIR

Writes query sets in the benchmark CSV format (8 rows per query, exact rationals, truth column).

  catalogue   the hand-derived degenerate catalogue (fuzz/catalogue.cpp) with its scaled and
              translated copies: DIR/catalogue-vertex-face.csv and DIR/catalogue-edge-edge.csv;
              the truth column is the hand-derived answer

options:
  --out DIR    output directory (created if missing)
  -h, --help   this help
exit codes: 0 written, 2 bad usage or unwritable output, 1 internal error.
)";

template <class E>
io::BenchmarkQueries to_benchmark(const std::vector<E>& entries) {
  io::BenchmarkQueries q;
  for (const E& e : entries) {
    q.rows.push_back(rows(e.query));
    q.truth.push_back(e.collides);
  }
  return q;
}

/// Writes to a temporary file and renames it: a failed run leaves no half-written file.
void write_atomically(const fs::path& path, const io::BenchmarkQueries& q) {
  const fs::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp);
    if (!out) throw UsageError("generate: cannot write '" + tmp.string() + "'");
    io::write_benchmark_csv(out, q);
    if (!out) throw UsageError("generate: write error on '" + tmp.string() + "'");
  }
  fs::rename(tmp, path);
  std::size_t positives = 0;
  for (bool t : q.truth) positives += t;
  std::printf("%s: %zu queries, %zu positives\n", path.string().c_str(), q.size(), positives);
}

}  // namespace

int run_generate(int argc, char** argv) {
  std::string what, out;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      std::cout << kHelp;
      return kExitOk;
    } else if (a == "--out") {
      out = option_value(argc, argv, i);
    } else if (!a.empty() && a[0] == '-') {
      throw UsageError("generate: unknown option '" + a + "' (see exactccd generate --help)");
    } else if (what.empty()) {
      what = a;
    } else {
      throw UsageError("generate: unexpected argument '" + a + "'");
    }
  }
  if (what != "catalogue") throw UsageError("generate: expected 'catalogue' (see exactccd generate --help)");
  if (out.empty()) throw UsageError("generate: --out DIR is required");
  fs::create_directories(out);
  write_atomically(fs::path(out) / "catalogue-vertex-face.csv", to_benchmark(catalogue::vertex_face_cases()));
  write_atomically(fs::path(out) / "catalogue-edge-edge.csv", to_benchmark(catalogue::edge_edge_cases()));
  return kExitOk;
}

}  // namespace exactccd::cli
