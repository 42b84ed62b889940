// exactccd compare: the oracle for another CCD code's answers on a benchmark file.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <vector>

#include "cli_common.hpp"
#include "exact/degeneracy.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

constexpr const char* kHelp = R"(usage: exactccd compare [--kind vf|ee] --answers THEIRS.txt FILE.csv

Compares another code's answers with the exact ones. THEIRS.txt holds one answer per query of
FILE.csv (benchmark CSV format), 0 or 1, one per line, in file order. Prints the number of
queries, false positives and false negatives (against the exact answer, not the file's truth
column), then one line per disagreement: query index (0-based), FP or FN, and the query's
degeneracy categories (coplanar_for_all_t, root_at_t0, root_at_t1, multiple_root,
degenerate_triangle, parallel_edges, zero_length_edge, static, or generic), decided exactly.

options:
  --kind vf|ee        query kind (default: inferred from the path of FILE.csv)
  --answers FILE      the other code's answers (required)
  -h, --help          this help
exit codes: 0 ran (whatever it found), 2 bad usage or malformed input, 1 internal error.
)";

std::vector<bool> read_answers(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError("compare: cannot open '" + path + "'");
  std::vector<bool> out;
  std::string line;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const auto last = line.find_last_not_of(" \t\r");
    const std::string v = line.substr(first, last - first + 1);
    if (v != "0" && v != "1") throw io::ParseError(path, n, "expected 0 or 1, found '" + v + "'");
    out.push_back(v == "1");
  }
  return out;
}

}  // namespace

int run_compare(int argc, char** argv) {
  std::optional<QueryKind> kind;
  std::string answers_path, file;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      std::cout << kHelp;
      return kExitOk;
    } else if (a == "--kind") {
      kind = parse_kind(option_value(argc, argv, i));
    } else if (a == "--answers") {
      answers_path = option_value(argc, argv, i);
    } else if (!a.empty() && a[0] == '-') {
      throw UsageError("compare: unknown option '" + a + "' (see exactccd compare --help)");
    } else if (file.empty()) {
      file = a;
    } else {
      throw UsageError("compare: one benchmark file at a time");
    }
  }
  if (answers_path.empty() || file.empty()) throw UsageError("compare: needs --answers THEIRS.txt and FILE.csv");
  const Dataset d = load_dataset(file, kind);
  const std::vector<bool> theirs = read_answers(answers_path);
  if (theirs.size() != d.queries.size())
    throw UsageError("compare: " + answers_path + " has " + std::to_string(theirs.size()) + " answers but " +
                     file + " has " + std::to_string(d.queries.size()) + " queries");
  std::size_t fp = 0, fn = 0;
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < d.queries.size(); ++i) {
    const auto& r = d.queries.rows[i];
    const bool vf = d.kind == QueryKind::vertex_face;
    const bool exact = vf ? vertex_face_ccd(from_rows<RationalVertexFaceQuery>(r))
                          : edge_edge_ccd(from_rows<RationalEdgeEdgeQuery>(r));
    if (theirs[i] == exact) continue;
    (theirs[i] ? fp : fn)++;
    const auto labels = vf ? exact::degeneracy_categories(from_rows<RationalVertexFaceQuery>(r))
                           : exact::degeneracy_categories(from_rows<RationalEdgeEdgeQuery>(r));
    lines.push_back(std::to_string(i) + (theirs[i] ? " FP " : " FN ") + exact::join_categories(labels));
  }
  std::printf("queries %zu, false positives %zu, false negatives %zu\n", d.queries.size(), fp, fn);
  for (const std::string& l : lines) std::printf("%s\n", l.c_str());
  return kExitOk;
}

}  // namespace exactccd::cli
