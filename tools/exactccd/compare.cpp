// exactccd compare: the oracle for another CCD code's answers on a benchmark file.
#include <cstdio>
#include <iostream>
#include <vector>

#include "cli_common.hpp"
#include "exact/degeneracy.hpp"
#include "io/input_file.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "compare";
    c.usage = "usage: exactccd compare [--kind KIND] [--min-distance D] [--tmax T] --answers THEIRS.txt FILE.csv";
    c.description =
        "Compares another code's answers with the exact ones. THEIRS.txt holds one answer per query of\n"
        "FILE.csv (benchmark CSV format), 0 or 1, one per line, in file order. Prints the number of\n"
        "queries, false positives and false negatives (against the exact answer, not the file's truth\n"
        "column), then one line per disagreement: query index (0-based), FP or FN, and the query's\n"
        "degeneracy categories (coplanar_for_all_t, root_at_t0, root_at_t1, multiple_root,\n"
        "degenerate_triangle, parallel_edges, zero_length_edge, static, or generic; vf and ee), decided\n"
        "exactly. With --min-distance and --tmax the exact answer is that of the question \"distance <= D\n"
        "at some t in [0, T]\".\n";
    c.options = {
        kind_option("query kind (default: inferred from the path of FILE.csv)"),
        required(text_option("--answers", "FILE", "", "the other code's answers")),
    };
    for (OptionSpec& o : separation_option_specs()) c.options.push_back(o);
    c.epilogue = "exit codes: 0 ran (whatever it found), 2 bad usage or malformed input, 1 internal error.\n";
    return c;
  }();
  return spec;
}

std::vector<bool> read_answers(const std::string& path) {
  io::InputFile file(path);
  std::vector<bool> out;
  std::string line;
  for (std::size_t n = 1; std::getline(file.stream(), line); ++n) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const auto last = line.find_last_not_of(" \t\r");
    const std::string v = line.substr(first, last - first + 1);
    if (v != "0" && v != "1") throw io::ParseError(path, n, "expected 0 or 1, found '" + v + "'");
    out.push_back(v == "1");
  }
  file.check_read();
  return out;
}

}  // namespace

int run_compare(int argc, char** argv) {
  const ParsedOptions options = parse_options(command(), argc, argv);
  if (options.help()) {
    std::cout << help_text(command());
    return kExitOk;
  }
  const std::optional<QueryKind> kind = kind_of(options);
  const std::string answers_path = options.text("--answers");
  if (options.positionals().size() > 1) throw UsageError("compare: one benchmark file at a time");
  if (options.positionals().empty()) throw UsageError("compare: needs --answers THEIRS.txt and FILE.csv");
  const std::string file = options.positionals()[0];
  const Dataset d = load_dataset(file, kind, TruthSource{"", false});  // no truth needed
  const CcdParams params = separation_params(options);
  const RationalCcdParams exact_params{mpq_class(params.min_distance), mpq_class(params.tmax)};
  const std::vector<bool> theirs = read_answers(answers_path);
  if (theirs.size() != d.queries.size())
    throw UsageError("compare: " + answers_path + " has " + std::to_string(theirs.size()) + " answers but " +
                     file + " has " + std::to_string(d.queries.size()) + " queries");
  std::size_t fp = 0, fn = 0;
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < d.queries.size(); ++i) {
    const auto [exact, labels] = visit_kind(d.kind, [&](auto kind) {
      using Kind = decltype(kind);
      const auto q = io::query_at<typename Kind::template Query<mpq_class>>(d.queries, i);
      const bool collides = ccd(q, exact_params);
      std::vector<std::string> categories;
      if constexpr (is_contact_kind<Kind>)
        if (theirs[i] != collides) categories = exact::degeneracy_categories(q);
      return std::pair(collides, categories);
    });
    if (theirs[i] == exact) continue;
    (theirs[i] ? fp : fn)++;
    lines.push_back(std::to_string(i) + (theirs[i] ? " FP " : " FN ") + exact::join_categories(labels));
  }
  std::printf("queries %zu, false positives %zu, false negatives %zu\n", d.queries.size(), fp, fn);
  for (const std::string& l : lines) std::printf("%s\n", l.c_str());
  return kExitOk;
}

}  // namespace exactccd::cli
