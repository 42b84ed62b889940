// exactccd compare: the oracle for another CCD code's answers on a benchmark file.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <vector>

#include "cli_common.hpp"
#include "degeneracy/degeneracy.hpp"
#include "io/answers.hpp"
#include "partial.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "compare";
    c.usage = "usage: exactccd compare [--kind KIND] [--min-distance D] [--tmax T] (--answers | --toi) THEIRS.txt FILE.csv";
    c.description =
        "Compares another code's answers with the exact ones. THEIRS.txt holds one answer per query of\n"
        "FILE.csv (benchmark CSV format), 0 or 1, one per line, in file order. Prints the number of\n"
        "queries, false positives and false negatives (against the exact answer, not the file's truth\n"
        "column), then one line per disagreement: query index (0-based), FP or FN, and the query's\n"
        "degeneracy categories (coplanar_for_all_t, root_at_t0, root_at_t1, multiple_root,\n"
        "degenerate_triangle, parallel_edges, zero_length_edge, static, or generic; vf and ee), decided\n"
        "exactly. With --min-distance and --tmax the exact answer is that of the question \"distance <= D\n"
        "at some t in [0, T]\".\n"
        "\n"
        "With --toi THEIRS.txt each line is 0, or 1 and the other code's time of impact T (a decimal\n"
        "number, read as the nearest double). Besides FP and FN it reports, for the collisions both\n"
        "find, how many TOIs are safe (T <= the exact TOI t*: a step to T does not pass through a\n"
        "contact; decided exactly: t* lies in the tightest double interval [lo, hi], so T <= t* iff\n"
        "T <= lo) and unsafe (T > t*), the gap t* - T of the safe ones (as lo - T, a lower bound\n"
        "within one ulp, rounded to double) and the relative gap (lo - T) / lo as quantiles (min,\n"
        "25%, median, 75%, max), then one line per unsafe TOI: its index, T and [lo, hi].\n";
    c.options = {
        kind_option("query kind (default: inferred from the path of FILE.csv)"),
        text_option("--answers", "FILE", "", "the other code's answers, 0 or 1 per line"),
        text_option("--toi", "FILE", "", "the other code's answers with times of impact: 0, or 1 T"),
    };
    for (OptionSpec& o : separation_option_specs()) c.options.push_back(o);
    c.options.push_back(shard_option("--shard", kMaxShards,
                                     "only the I-th of N contiguous blocks of the queries (a cluster job); needs\n"
                                     "--partial: `exactccd merge` of the N partial files prints the whole report"));
    c.options.push_back(text_option("--partial", "OUT", "",
                                    "write the partial results of this run or shard to OUT instead of the\n"
                                    "report (tools/cluster/, exactccd merge)"));
    c.epilogue = "exit codes: 0 ran (whatever it found), 2 bad usage or malformed input, 1 internal error.\n";
    return c;
  }();
  return spec;
}

using io::TheirAnswer;

/// "min q25 median q75 max" of the values (nearest-rank quantiles), or "-" for none.
std::string quantiles(std::vector<double> v) {
  if (v.empty()) return "-";
  std::sort(v.begin(), v.end());
  std::string out;
  for (const double q : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const std::size_t i = static_cast<std::size_t>(std::llround(q * static_cast<double>(v.size() - 1)));
    char buf[40];
    std::snprintf(buf, sizeof buf, "%s%.6g", out.empty() ? "" : " ", v[i]);
    out += buf;
  }
  return out;
}

/// What a compare report is made of, for a range of queries (a whole run, or one shard): the
/// counts, the disagreement lines and the unsafe TOIs in query order, the gaps of the safe TOIs.
struct CompareTally {
  std::size_t fp = 0, fn = 0, shared = 0;
  std::vector<std::string> lines, unsafe;
  std::vector<double> gaps, relative_gaps;
};

/// The tally of queries [begin, end) of `d` against `theirs`.
CompareTally tally_queries(const Dataset& d, const std::vector<TheirAnswer>& theirs, const CcdParams& params,
                           std::size_t begin, std::size_t end) {
  const RationalCcdParams exact_params{mpq_class(params.min_distance), mpq_class(params.tmax)};
  CompareTally t;
  for (std::size_t i = begin; i < end; ++i) {
    const bool they_collide = theirs[i].collides;
    const auto [exact, labels] = visit_kind(d.kind, [&](auto kind) {
      using Kind = decltype(kind);
      const auto q = io::query_at<typename Kind::template Query<mpq_class>>(d.queries, i);
      const std::optional<TimeInterval> toi_i = toi(q, exact_params);
      std::vector<std::string> categories;
      if constexpr (is_contact_kind<Kind>)
        if (they_collide != toi_i.has_value() && params.contact_over_whole_step())
          categories = exact::degeneracy_categories(q);
      return std::pair(toi_i, categories);
    });
    if (they_collide && exact && theirs[i].toi) {
      ++t.shared;
      const double T = *theirs[i].toi;
      if (T <= exact->lo) {  // T <= t* exactly (no double lies strictly inside (lo, hi))
        t.gaps.push_back(exact->lo - T);
        if (exact->lo > 0) t.relative_gaps.push_back((exact->lo - T) / exact->lo);
      } else {
        char buf[160];
        std::snprintf(buf, sizeof buf, "%zu unsafe T %.17g exact [%.17g, %.17g]", i, T, exact->lo, exact->hi);
        t.unsafe.push_back(buf);
      }
    }
    if (they_collide == exact.has_value()) continue;
    (they_collide ? t.fp : t.fn)++;
    t.lines.push_back(std::to_string(i) + (they_collide ? " FP " : " FN ") +
                      (labels.empty() ? std::string("-") : exact::join_categories(labels)));
  }
  return t;
}

/// The report of a whole run of `queries` queries (compare --help describes it).
void print_compare_report(const CompareTally& t, std::size_t queries, bool with_toi) {
  std::printf("queries %zu, false positives %zu, false negatives %zu\n", queries, t.fp, t.fn);
  for (const std::string& l : t.lines) std::printf("%s\n", l.c_str());
  if (with_toi) {
    std::printf("toi: shared collisions %zu, safe %zu, unsafe %zu\n", t.shared, t.gaps.size(), t.unsafe.size());
    std::printf("gap lo - T of the safe TOIs (min q25 median q75 max): %s\n", quantiles(t.gaps).c_str());
    std::printf("relative gap (lo - T) / lo (min q25 median q75 max): %s\n", quantiles(t.relative_gaps).c_str());
    for (const std::string& u : t.unsafe) std::printf("%s\n", u.c_str());
  }
}

/// The tally as partial records (partial.hpp): counts first, then lines and values in order.
void add_records(const CompareTally& t, Partial& p) {
  p.add("fp " + std::to_string(t.fp));
  p.add("fn " + std::to_string(t.fn));
  p.add("shared " + std::to_string(t.shared));
  for (const std::string& l : t.lines) p.add("line " + l);
  for (const std::string& u : t.unsafe) p.add("unsafe " + u);
  for (const double g : t.gaps) p.add("gap " + hex_double(g));
  for (const double g : t.relative_gaps) p.add("relgap " + hex_double(g));
}

/// The tally of merged partial records (several shards' records, in shard order: counts add up,
/// lines and values concatenate in query order).
CompareTally tally_from_records(const Partial& p) {
  CompareTally t;
  for (const PartialRecord& r : p.records) {
    const std::size_t space = r.text.find(' ');
    const std::string tag = r.text.substr(0, space), rest = space == std::string::npos ? "" : r.text.substr(space + 1);
    if (tag == "fp") t.fp += parse_count(rest, r.source, r.line);
    else if (tag == "fn") t.fn += parse_count(rest, r.source, r.line);
    else if (tag == "shared") t.shared += parse_count(rest, r.source, r.line);
    else if (tag == "line" && !rest.empty()) t.lines.push_back(rest);
    else if (tag == "unsafe" && !rest.empty()) t.unsafe.push_back(rest);
    else if (tag == "gap") t.gaps.push_back(parse_double(rest, r.source, r.line));
    else if (tag == "relgap") t.relative_gaps.push_back(parse_double(rest, r.source, r.line));
    else throw io::ParseError(r.source, r.line, "not a compare record: '" + r.text + "'");
  }
  return t;
}

}  // namespace

int run_compare(int argc, char** argv) {
  const ParsedOptions options = parse_options(command(), argc, argv);
  if (options.help()) {
    std::cout << help_text(command());
    return kExitOk;
  }
  const std::optional<QueryKind> kind = kind_of(options);
  const bool with_toi = options.has("--toi");
  if (with_toi == options.has("--answers"))
    throw UsageError("compare: give exactly one of --answers THEIRS.txt and --toi THEIRS.txt");
  const std::string answers_path = options.text(with_toi ? "--toi" : "--answers");
  if (options.positionals().size() > 1) throw UsageError("compare: one benchmark file at a time");
  if (options.positionals().empty()) throw UsageError("compare: needs --answers THEIRS.txt and FILE.csv");
  const std::string partial_path = options.has("--partial") ? options.text("--partial") : "";
  const auto [shard_index, shard_count] = options.shard("--shard");
  if (options.has("--shard") && partial_path.empty())
    throw UsageError("compare: --shard needs --partial FILE (the shards' reports are merged by exactccd merge)");
  const std::string file = options.positionals()[0];
  const Dataset d = load_dataset(file, kind, TruthSource{"", false});  // no truth needed
  const CcdParams params = separation_params(options);
  const std::vector<TheirAnswer> theirs = io::read_answers_file(answers_path, with_toi);
  if (theirs.size() != d.queries.size())
    throw UsageError("compare: " + answers_path + " has " + std::to_string(theirs.size()) + " answers but " +
                     file + " has " + std::to_string(d.queries.size()) + " queries");
  const std::size_t n = d.queries.size();
  if (partial_path.empty()) {
    print_compare_report(tally_queries(d, theirs, params, 0, n), n, with_toi);
    return kExitOk;
  }
  Partial p;
  p.command = "compare";
  p.settings = {{"file", file},
                {"kind", kind_name(d.kind)},
                {"theirs", answers_path},
                {"mode", with_toi ? "toi" : "answers"},
                {"min-distance", hex_double(params.min_distance)},
                {"tmax", hex_double(params.tmax)}};
  p.shard_index = shard_index;
  p.shard_count = shard_count;
  p.total = n;
  p.begin = n * shard_index / shard_count;
  p.end = n * (shard_index + 1) / shard_count;
  add_records(tally_queries(d, theirs, params, p.begin, p.end), p);
  write_partial(partial_path, p);
  return kExitOk;
}

int merge_compare(const Partial& merged, const std::string& source) {
  const std::string& mode = merged.setting("mode", source);
  if (mode != "toi" && mode != "answers") throw io::ParseError(source, 1, "compare mode '" + mode + "' is unknown");
  print_compare_report(tally_from_records(merged), merged.total, mode == "toi");
  return kExitOk;
}

}  // namespace exactccd::cli
