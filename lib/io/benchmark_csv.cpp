#include "io/benchmark_csv.hpp"

#include <cmath>
#include <istream>
#include <ostream>
#include <sstream>

namespace exactccd::io {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

/// A base-10 integer with an optional sign and nothing else.
bool parse_integer(const std::string& field, mpz_class& out) {
  const std::string s = trim(field);
  if (s.empty()) return false;
  std::size_t i = (s[0] == '-' || s[0] == '+') ? 1 : 0;
  if (i == s.size()) return false;
  for (std::size_t j = i; j < s.size(); ++j)
    if (s[j] < '0' || s[j] > '9') return false;
  return out.set_str(s[0] == '+' ? s.substr(1) : s, 10) == 0;
}

}  // namespace

ParseError::ParseError(const std::string& source, std::size_t line, const std::string& what)
    : std::runtime_error(source + ":" + std::to_string(line) + ": " + what),
      source_(source),
      line_(line) {}

BenchmarkQueries read_benchmark_csv(std::istream& in, const std::string& source_name) {
  BenchmarkQueries result;
  std::array<RationalVec3, 8> current;
  int row_in_query = 0;
  bool query_truth = false;
  std::size_t line_number = 0, query_first_line = 0;
  std::string line;
  while (std::getline(in, line)) {
    ++line_number;
    if (trim(line).empty()) continue;
    std::vector<std::string> fields;
    std::stringstream ss(line);
    for (std::string f; std::getline(ss, f, ',');) fields.push_back(f);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    if (fields.size() != 7)
      throw ParseError(source_name, line_number,
                       "expected 7 comma-separated integers, found " + std::to_string(fields.size()) +
                           " fields");
    std::array<mpz_class, 7> v;
    for (int i = 0; i < 7; ++i)
      if (!parse_integer(fields[i], v[i]))
        throw ParseError(source_name, line_number,
                         "field " + std::to_string(i + 1) + " is not an integer: '" + trim(fields[i]) + "'");
    std::array<mpq_class, 3> coordinate;
    for (int c = 0; c < 3; ++c) {
      if (v[2 * c + 1] == 0)
        throw ParseError(source_name, line_number, "zero denominator in field " + std::to_string(2 * c + 2));
      coordinate[c] = mpq_class(v[2 * c], v[2 * c + 1]);
      coordinate[c].canonicalize();
    }
    if (v[6] != 0 && v[6] != 1)
      throw ParseError(source_name, line_number, "truth must be 0 or 1");
    const bool truth = v[6] == 1;
    if (row_in_query == 0) {
      query_truth = truth;
      query_first_line = line_number;
    } else if (truth != query_truth) {
      throw ParseError(source_name, line_number,
                       "truth differs from the query's first row (line " +
                           std::to_string(query_first_line) + ")");
    }
    current[row_in_query] = {coordinate[0], coordinate[1], coordinate[2]};
    if (++row_in_query == 8) {
      result.rows.push_back(current);
      result.truth.push_back(query_truth);
      row_in_query = 0;
    }
  }
  if (in.bad()) throw ParseError(source_name, line_number, "read error");
  if (row_in_query != 0)
    throw ParseError(source_name, line_number,
                     "incomplete query: " + std::to_string(row_in_query) +
                         " rows after line " + std::to_string(query_first_line - 1) +
                         " (a query has 8)");
  return result;
}

void write_benchmark_csv(std::ostream& out, const BenchmarkQueries& queries) {
  for (std::size_t i = 0; i < queries.size(); ++i)
    for (const RationalVec3& p : queries.rows[i]) {
      for (const mpq_class* c : {&p.x, &p.y, &p.z}) out << c->get_num() << ',' << c->get_den() << ',';
      out << (queries.truth[i] ? 1 : 0) << '\n';
    }
}

std::optional<double> exact_double(const mpq_class& x) {
  const double d = x.get_d();  // truncates towards zero
  if (!std::isfinite(d)) return std::nullopt;
  if (mpq_class(d) != x) return std::nullopt;
  return d;
}

std::optional<std::array<Vec3, 8>> exact_double_rows(const std::array<RationalVec3, 8>& rows) {
  std::array<Vec3, 8> out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto x = exact_double(rows[i].x), y = exact_double(rows[i].y), z = exact_double(rows[i].z);
    if (!x || !y || !z) return std::nullopt;
    out[i] = {*x, *y, *z};
  }
  return out;
}

}  // namespace exactccd::io
