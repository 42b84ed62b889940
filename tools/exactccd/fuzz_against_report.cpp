#include "fuzz_against_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "io/output_file.hpp"

namespace exactccd::cli::fuzz {
namespace {

namespace fs = std::filesystem;

std::string hex_rows(const Rows& r) {
  std::string out;
  for (const Vec3& p : r)
    for (const double x : {p.x, p.y, p.z}) out += " " + hex_double(x);
  return out;
}

/// Reads 24 coordinates from words[first..first+24).
Rows rows_from_words(const std::vector<std::string>& w, std::size_t first, const PartialRecord& r) {
  if (w.size() < first + 24) throw io::ParseError(r.source, r.line, "a query needs 24 coordinates");
  Rows rows{};
  for (std::size_t i = 0; i < 8; ++i)
    rows[i] = {parse_double(w[first + 3 * i], r.source, r.line), parse_double(w[first + 3 * i + 1], r.source, r.line),
               parse_double(w[first + 3 * i + 2], r.source, r.line)};
  return rows;
}

std::string toi_record(const char* tag, const FuzzTally::Toi& u) {
  return std::string(tag) + " " + std::to_string(u.index) + " " + std::to_string(u.group) + " " +
         hex_double(u.their_toi) + " " + hex_double(u.exact.lo) + " " + hex_double(u.exact.hi) + hex_rows(u.rows);
}

/// Reads the words of one record, each checked, with the record's file and line in errors.
struct RecordReader {
  const PartialRecord& r;
  std::vector<std::string> w;
  std::size_t group_count;

  std::size_t count(std::size_t i) const { return parse_count(w.at(i), r.source, r.line); }
  std::size_t group(std::size_t i) const {
    const std::size_t g = count(i);
    if (g >= group_count) throw io::ParseError(r.source, r.line, "group " + w[i] + " out of range");
    return g;
  }
  bool flag(std::size_t i) const {
    if (w.at(i) != "0" && w.at(i) != "1") throw io::ParseError(r.source, r.line, "expected 0 or 1, found '" + w[i] + "'");
    return w[i] == "1";
  }
  double real(std::size_t i) const { return parse_double(w.at(i), r.source, r.line); }

  void add_row(FuzzTally& t) const {
    Row row;
    std::size_t* counts[] = {&row.queries, &row.collide, &row.fp, &row.fn, &row.errors,
                             &row.shared, &row.unsafe, &row.early};
    for (std::size_t i = 0; i < 8; ++i) *counts[i] = count(2 + i);
    if (w[10] != "-") {
      std::istringstream ks(w[10]);
      for (std::string k; std::getline(ks, k, ',');) row.ks.insert(parse_int(k, r.source, r.line));
    }
    t.groups[group(1)].add(row);
  }
  FuzzTally::Toi toi() const { return {count(1), group(2), real(3), {real(4), real(5)}, rows_from_words(w, 6, r)}; }
  FuzzTally::Disagreement disagreement() const {
    FuzzTally::Disagreement d{count(1), group(2), flag(3), flag(4), flag(6), parse_int(w[5], r.source, r.line),
                              rows_from_words(w, 7, r), ""};
    // The note is the rest of the line after the 31st word (it has spaces of its own).
    std::size_t pos = 0;
    for (int skip = 0; skip < 31; ++skip) {
      pos = r.text.find_first_not_of(' ', pos);
      pos = r.text.find(' ', pos);
    }
    d.note = pos == std::string::npos ? "" : r.text.substr(pos + 1);
    return d;
  }
};

std::string number(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

/// The options that ask the run's question, as check takes them.
std::string question_options(const FuzzRun& run) {
  return "--min-distance " + number(run.params.min_distance) + " --tmax " + number(run.params.tmax);
}

/// An earlier run's output of this kind: NNNNNN-*-<kind>.csv, disagreements-<kind>.* and the
/// lists of unsafe and early times of impact.
bool is_output_of_kind(const std::string& name, const std::string& kind_suffix) {
  for (const char* list : {"disagreements-", "unsafe-toi-", "early-toi-"})
    for (const char* ext : {".csv", ".txt"})
      if (name == list + kind_suffix + ext) return true;
  const std::string tail = "-" + kind_suffix + ".csv";
  if (name.size() < 7 + tail.size() || name.compare(name.size() - tail.size(), tail.size(), tail) != 0)
    return false;
  return std::all_of(name.begin(), name.begin() + 6, [](char ch) { return ch >= '0' && ch <= '9'; }) &&
         name[6] == '-';
}

std::array<RationalVec3, 8> rational_rows(const Rows& r) {
  std::array<RationalVec3, 8> q;
  for (std::size_t p = 0; p < 8; ++p) q[p] = {mpq_class(r[p].x), mpq_class(r[p].y), mpq_class(r[p].z)};
  return q;
}

/// The query as hex floats, one named row per line.
std::string hex_lines(const FuzzKind& kind, const Rows& r) {
  std::string out;
  char line[200];
  for (int i = 0; i < 2 * kind.points; ++i) {
    const Vec3& p = r[static_cast<std::size_t>(i)];
    if (kind.dimension == 3)
      std::snprintf(line, sizeof line, "  %-5s %a %a %a\n", kind.row_names[i].c_str(), p.x, p.y, p.z);
    else
      std::snprintf(line, sizeof line, "  %-5s %a %a\n", kind.row_names[i].c_str(), p.x, p.y);
    out += line;
  }
  return out;
}

/// A benchmark CSV of the kind: the queries and their truth.
std::string benchmark_csv(const FuzzKind& kind, const std::vector<const Rows*>& rows, const std::vector<bool>& truth) {
  io::BenchmarkQueries q;
  q.layout = kind.layout;
  for (const Rows* r : rows) q.rows.push_back(rational_rows(*r));
  q.truth = truth;
  std::ostringstream csv;
  io::write_benchmark_csv(csv, q);
  return csv.str();
}

void write_to(const FuzzRun& run, const std::string& name, const std::string& text) {
  io::write_file_atomically((fs::path(run.out_dir) / name).string(), text);
}

Row total_of(const FuzzTally& t) {
  Row total;
  for (const Row& r : t.groups) total.add(r);
  total.ks.clear();
  return total;
}

void print_table(const ReportContext& c, const FuzzTally& t) {
  std::printf("fuzz-against %s (%s): %zu %s queries, seed %llu, %s, truth = the exact answer (Method::exact)\n\n",
              c.run.plugin_path.c_str(), c.symbol.c_str(), c.run.queries, c.kind.name.c_str(),
              static_cast<unsigned long long>(c.run.seed), question_options(c.run).c_str());
  std::printf("%-28s %8s %8s %7s %7s %7s %7s %7s  %s\n", "group", "queries", "collide", "FP", "FN", "errors", "unsafe",
              "early", "disagrees at k (families; -1 = unperturbed)");
  const auto print_row = [&](const std::string& name, const Row& r) {
    const std::string unsafe = c.reports_toi ? std::to_string(r.unsafe) : "-";
    const std::string early = c.reports_toi ? std::to_string(r.early) : "-";
    std::printf("%-28s %8zu %8zu %7zu %7zu %7zu %7s %7s  %s\n", name.c_str(), r.queries, r.collide, r.fp, r.fn,
                r.errors, unsafe.c_str(), early.c_str(), k_ranges(r.ks).c_str());
  };
  for (std::size_t g = 0; g < t.groups.size(); ++g) print_row(c.group_names[g], t.groups[g]);
  print_row("total", total_of(t));
}

void print_toi_summary(const ReportContext& c, const FuzzTally& t) {
  const Row total = total_of(t);
  std::vector<double> gaps = t.gaps;
  std::sort(gaps.begin(), gaps.end());
  const auto at = [&](double q) { return gaps[static_cast<std::size_t>(std::llround(q * (gaps.size() - 1)))]; };
  std::printf("\ntimes of impact (%s): %zu collisions both find, %zu safe (T <= exact), %zu unsafe (T after the "
              "exact time), %zu more than %s times early (%s T < exact)\n",
              c.symbol.c_str(), total.shared, gaps.size(), total.unsafe, total.early,
              number(c.run.early_factor).c_str(), number(c.run.early_factor).c_str());
  if (!gaps.empty())
    std::printf("gap lo - T of the safe ones: min %.3g, median %.3g, max %.3g\n", at(0), at(0.5), at(1));
}

/// Writes a list of times of impact (unsafe or early) as a CSV and its index.
void write_toi_list(const ReportContext& c, const std::vector<FuzzTally::Toi>& list, const std::string& stem,
                    const std::string& what) {
  std::string index;
  std::vector<const Rows*> rows;
  for (const FuzzTally::Toi& u : list) {
    char line[200];
    std::snprintf(line, sizeof line, "%06zu  %s  T %.17g  exact [%.17g, %.17g]\n", u.index,
                  c.group_names[u.group].c_str(), u.their_toi, u.exact.lo, u.exact.hi);
    index += line;
    rows.push_back(&u.rows);
  }
  const std::string name = stem + "-" + c.kind.name;
  write_to(c.run, name + ".csv", benchmark_csv(c.kind, rows, std::vector<bool>(rows.size(), true)));
  write_to(c.run, name + ".txt",
           "# exactccd fuzz-against " + c.run.plugin_path + " --kind " + c.kind.short_name + " " +
               question_options(c.run) + ": one line per collision whose reported time of impact T is " + what +
               " (index, group, T, exact TOI); the rows of " + name + ".csv in order\n" + index);
}

void write_disagreements(const ReportContext& c, const FuzzTally& t) {
  std::vector<const Rows*> rows;
  std::vector<bool> truth;
  std::string index;
  for (const FuzzTally::Disagreement& d : t.disagreements) {
    const char* type = d.truth ? "FN" : "FP";
    char prefix[32];
    std::snprintf(prefix, sizeof prefix, "%06zu", d.index);
    const std::string name = std::string(prefix) + "-" + c.group_names[d.group] + "-" + type + "-" + c.kind.name + ".csv";
    write_to(c.run, name, benchmark_csv(c.kind, {&d.shrunk}, {d.truth}));
    rows.push_back(&d.shrunk);
    truth.push_back(d.truth);
    index += name + "  " + type + "  " + c.group_names[d.group];
    if (d.family) index += " k " + std::to_string(d.k) + (d.toward ? " toward" : " away");
    index += "  " + d.note + "\n" + hex_lines(c.kind, d.shrunk);
  }
  write_to(c.run, "disagreements-" + c.kind.name + ".csv", benchmark_csv(c.kind, rows, truth));
  write_to(c.run, "disagreements-" + c.kind.name + ".txt",
           "# exactccd fuzz-against " + c.run.plugin_path + " --kind " + c.kind.short_name + " " +
               question_options(c.run) + " --queries " + std::to_string(c.run.queries) + " --seed " +
               std::to_string(c.run.seed) +
               ": one line per disagreement (file, FP/FN, group, shrinking), then the shrunk query in hex floats; "
               "the rows of disagreements-" + c.kind.name + ".csv in order\n" + index);
}

}  // namespace

std::string k_ranges(const std::set<int>& ks) {
  std::string out;
  for (auto it = ks.begin(); it != ks.end();) {
    const int first = *it;
    int last = first;
    while (++it != ks.end() && *it == last + 1) ++last;
    if (!out.empty()) out += ", ";
    out += std::to_string(first);
    if (last > first) out += (last == first + 1 ? ", " : "..") + std::to_string(last);
  }
  return out;
}

void Row::add(const Row& o) {
  queries += o.queries;
  collide += o.collide;
  fp += o.fp;
  fn += o.fn;
  errors += o.errors;
  shared += o.shared;
  unsafe += o.unsafe;
  early += o.early;
  ks.insert(o.ks.begin(), o.ks.end());
}

void add_records(const FuzzTally& t, Partial& p) {
  for (std::size_t g = 0; g < t.groups.size(); ++g) {
    const Row& r = t.groups[g];
    std::string ks;
    for (const int k : r.ks) ks += (ks.empty() ? "" : ",") + std::to_string(k);
    std::string record = "group " + std::to_string(g);
    for (const std::size_t n : {r.queries, r.collide, r.fp, r.fn, r.errors, r.shared, r.unsafe, r.early})
      record += " " + std::to_string(n);
    p.add(record + " " + (ks.empty() ? "-" : ks));
  }
  for (const double g : t.gaps) p.add("gap " + hex_double(g));
  for (const FuzzTally::Toi& u : t.unsafe) p.add(toi_record("unsafe", u));
  for (const FuzzTally::Toi& u : t.early) p.add(toi_record("early", u));
  for (const FuzzTally::Disagreement& d : t.disagreements)
    p.add("disagreement " + std::to_string(d.index) + " " + std::to_string(d.group) + " " + (d.truth ? "1" : "0") +
          " " + (d.family ? "1" : "0") + " " + std::to_string(d.k) + " " + (d.toward ? "1" : "0") + hex_rows(d.shrunk) +
          " " + d.note);
}

FuzzTally tally_from_records(const Partial& p, std::size_t group_count) {
  FuzzTally t;
  t.groups.resize(group_count);
  for (const PartialRecord& r : p.records) {
    const RecordReader in{r, split_words(r.text), group_count};
    const std::vector<std::string>& w = in.w;
    if (w.empty()) throw io::ParseError(r.source, r.line, "empty record");
    if (w[0] == "group" && w.size() == 11) in.add_row(t);
    else if (w[0] == "gap" && w.size() == 2) t.gaps.push_back(in.real(1));
    else if (w[0] == "unsafe" && w.size() == 6 + 24) t.unsafe.push_back(in.toi());
    else if (w[0] == "early" && w.size() == 6 + 24) t.early.push_back(in.toi());
    else if (w[0] == "disagreement" && w.size() >= 7 + 24) t.disagreements.push_back(in.disagreement());
    else
      throw io::ParseError(r.source, r.line, "not a fuzz-against record: '" + w[0] + "' with " +
                                                 std::to_string(w.size()) + " fields");
  }
  return t;
}

void report_fuzz(const ReportContext& c, const FuzzTally& t) {
  io::prepare_output_directory(c.run.out_dir);
  print_table(c, t);
  if (c.reports_toi) print_toi_summary(c, t);
  // Replace this kind's files of an earlier run, then write.
  for (const auto& entry : fs::directory_iterator(c.run.out_dir))
    if (entry.is_regular_file() && is_output_of_kind(entry.path().filename().string(), c.kind.name))
      fs::remove(entry.path());
  write_disagreements(c, t);
  if (c.reports_toi) {
    write_toi_list(c, t.unsafe, "unsafe-toi", "after the exact one");
    write_toi_list(c, t.early, "early-toi", "more than " + number(c.run.early_factor) + " times early");
  }
  const Row total = total_of(t);
  std::printf("\n%zu disagreements (FP %zu, FN %zu)%s, written to %s: one CSV each, all in "
              "disagreements-%s.csv, described in disagreements-%s.txt\n"
              "replay: exactccd check --kind %s %s %s/disagreements-%s.csv\n",
              t.disagreements.size(), total.fp, total.fn, c.run.shrinking ? ", shrunk" : "", c.run.out_dir.c_str(),
              c.kind.name.c_str(), c.kind.name.c_str(), c.kind.short_name.c_str(), question_options(c.run).c_str(),
              c.run.out_dir.c_str(), c.kind.name.c_str());
}

}  // namespace exactccd::cli::fuzz
