#include "io/benchmark_csv.hpp"

#include <algorithm>
#include <cmath>
#include <istream>
#include <limits>
#include <ostream>
#include <string_view>
#include <vector>

#include "io/lines.hpp"

namespace exactccd::io {
namespace {

/// Why a field is not accepted as an integer.
enum class FieldError { none, not_an_integer, too_large };

/// A base-10 integer with an optional sign and nothing else, of at most kMaxFieldBits bits.
/// Too many digits are refused before any conversion (converting 10^5 digits alone is slow).
FieldError parse_integer(const std::string& field, mpz_class& out) {
  const std::string s(trim(field, kSpaceTabAndCr));
  if (s.empty()) return FieldError::not_an_integer;
  std::size_t i = (s[0] == '-' || s[0] == '+') ? 1 : 0;
  if (i == s.size()) return FieldError::not_an_integer;
  for (std::size_t j = i; j < s.size(); ++j)
    if (s[j] < '0' || s[j] > '9') return FieldError::not_an_integer;
  // 2^kMaxFieldBits has floor(kMaxFieldBits log10 2) + 1 = 1234 digits: more significant
  // digits than that is surely too large.
  constexpr std::size_t kMaxDigits = kMaxFieldBits * 30103 / 100000 + 1;
  const std::size_t first_significant = std::min(s.find_first_not_of('0', i), s.size());
  if (s.size() - first_significant > kMaxDigits) return FieldError::too_large;
  if (out.set_str(s[0] == '+' ? s.substr(1) : s, 10) != 0) return FieldError::not_an_integer;
  if (out != 0 && mpz_sizeinbase(out.get_mpz_t(), 2) > kMaxFieldBits) return FieldError::too_large;
  return FieldError::none;
}

/// The number of decimal digits of an integer field (without sign, spaces and leading zeros).
std::size_t significant_digits(const std::string& field) {
  const std::string_view s = trim(field, kSpaceTabAndCr);
  const std::size_t from = s.find_first_not_of("+-0");
  return from == std::string::npos ? 0 : s.size() - from;
}

/// A row's fields (`columns` of them) as integers; errors name the field.
std::array<mpz_class, 7> read_integers(const std::vector<std::string>& fields, int columns, const LineReader& lines) {
  std::array<mpz_class, 7> v;
  for (int i = 0; i < columns; ++i) {
    const FieldError error = parse_integer(fields[i], v[i]);
    if (error == FieldError::not_an_integer)
      lines.fail("field " + std::to_string(i + 1) + " is not an integer: '" +
                 std::string(trim(fields[i], kSpaceTabAndCr)) + "'");
    if (error == FieldError::too_large)
      lines.fail("field " + std::to_string(i + 1) + " has " + std::to_string(significant_digits(fields[i])) +
                 " digits, more than the limit of " + std::to_string(kMaxFieldBits) +
                 " bits per numerator or denominator (docs/formats.md, \"Input files\")");
  }
  return v;
}

/// One row: a point (z = 0 in 2D; rationals canonical) and its truth (false without the column).
struct Row {
  RationalVec3 point;
  bool truth = false;
};

/// A non-blank line as a row of `layout`.
Row read_row(const std::string& line, const QueryLayout& layout, const LineReader& lines) {
  if (trim(line, kSpaceTabAndCr)[0] == '#')  // the rigid query files' comment lines: say which command reads them
    lines.fail("a '#' comment line: benchmark query files have none (rigid query files do: "
               "exactccd check --motion rigid --kind vf|ee FILE.csv)");
  const int columns = layout.columns();
  const std::vector<std::string> fields = split_fields(line);
  if (fields.size() != static_cast<std::size_t>(columns))
    lines.fail("expected " + std::to_string(columns) + " comma-separated integers, found " +
               std::to_string(fields.size()) + " fields");
  const std::array<mpz_class, 7> v = read_integers(fields, columns, lines);
  std::array<mpq_class, 3> coordinate{0, 0, 0};
  for (int c = 0; c < layout.dimension; ++c) {
    if (v[2 * c + 1] == 0) lines.fail("zero denominator in field " + std::to_string(2 * c + 2));
    coordinate[c] = mpq_class(v[2 * c], v[2 * c + 1]);
    coordinate[c].canonicalize();
  }
  const mpz_class& truth_field = v[columns - 1];
  if (layout.truth_column && truth_field != 0 && truth_field != 1) lines.fail("truth must be 0 or 1");
  return {{coordinate[0], coordinate[1], coordinate[2]}, layout.truth_column && truth_field == 1};
}

/// Rows gathered into queries of layout.rows rows, each row's truth that of the query's first.
class QueryRows {
 public:
  explicit QueryRows(BenchmarkQueries& queries) : queries_(queries) {}
  /// The row read on the current line of `lines`.
  void add(const Row& row, const LineReader& lines) {
    last_row_line_ = lines.line();
    if (row_in_query_ == 0) {
      query_truth_ = row.truth;
      query_first_line_ = lines.line();
    } else if (row.truth != query_truth_) {
      lines.fail("truth differs from the query's first row (line " + std::to_string(query_first_line_) + ")");
    }
    rows_[row_in_query_] = row.point;
    row_lines_[row_in_query_] = lines.line();
    if (++row_in_query_ < queries_.layout.rows) return;
    queries_.rows.push_back(rows_);
    queries_.truth.push_back(query_truth_);
    queries_.lines.push_back(row_lines_);
    row_in_query_ = 0;
  }
  /// At the end of the input: throws when the last query lacks rows.
  void finish(const std::string& source) const {
    if (row_in_query_ != 0)
      throw ParseError(source, last_row_line_,
                       "incomplete query: the input ends after " + std::to_string(row_in_query_) + " of its " +
                           std::to_string(queries_.layout.rows) + " rows (it starts on line " +
                           std::to_string(query_first_line_) + ")");
  }

 private:
  BenchmarkQueries& queries_;
  std::array<RationalVec3, 8> rows_;
  std::array<std::size_t, 8> row_lines_{};
  int row_in_query_ = 0;
  bool query_truth_ = false;
  std::size_t query_first_line_ = 0, last_row_line_ = 0;
};

}  // namespace

int first_row_columns(std::istream& in) {
  LineReader lines(in, "");
  std::string line;
  if (!lines.next_nonblank(line, kSpaceTabAndCr)) return 0;
  return static_cast<int>(std::count(line.begin(), line.end(), ',')) + 1;
}

BenchmarkQueries read_benchmark_csv(std::istream& in, const std::string& source_name, QueryLayout layout) {
  if (layout.rows < 1 || layout.rows > 8 || (layout.dimension != 2 && layout.dimension != 3))
    throw std::invalid_argument("read_benchmark_csv: unsupported layout");
  BenchmarkQueries result;
  result.layout = layout;
  QueryRows rows(result);
  LineReader lines(in, source_name);
  for (std::string line; lines.next_nonblank(line, kSpaceTabAndCr);) rows.add(read_row(line, layout, lines), lines);
  if (in.bad()) throw ParseError(source_name, lines.line(), "read error");
  rows.finish(source_name);
  return result;
}

void write_benchmark_csv(std::ostream& out, const BenchmarkQueries& queries) {
  if (queries.truth.size() != queries.rows.size())
    throw std::invalid_argument("write_benchmark_csv: " + std::to_string(queries.rows.size()) +
                                " queries but " + std::to_string(queries.truth.size()) +
                                " truth values");
  for (std::size_t i = 0; i < queries.size(); ++i)
    for (int k = 0; k < queries.layout.rows; ++k) {
      const RationalVec3& p = queries.rows[i][k];
      const char* separator = "";
      for (const mpq_class* c : {&p.x, &p.y, &p.z})
        if (c != &p.z || queries.layout.dimension == 3) {
          out << separator << c->get_num() << ',' << c->get_den();
          separator = ",";
        }
      if (queries.layout.truth_column) out << ',' << (queries.truth[i] ? 1 : 0);
      out << '\n';
    }
}

RationalVertexFaceQuery vertex_face_query(const BenchmarkQueries& queries, std::size_t i) {
  return from_rows<RationalVertexFaceQuery>(queries.rows.at(i));
}

RationalEdgeEdgeQuery edge_edge_query(const BenchmarkQueries& queries, std::size_t i) {
  return from_rows<RationalEdgeEdgeQuery>(queries.rows.at(i));
}

double nearest_double(const mpq_class& x) {
  const int sign = sgn(x);
  if (sign == 0) return 0.0;
  const mpz_class n = abs(x.get_num());
  const mpz_class& d = x.get_den();
  // floor(log2 |x|) is bits(n) - bits(d) or one less.
  long e = static_cast<long>(mpz_sizeinbase(n.get_mpz_t(), 2)) -
           static_cast<long>(mpz_sizeinbase(d.get_mpz_t(), 2));
  const bool at_least_2e = e >= 0 ? n >= (d << static_cast<mp_bitcnt_t>(e))
                                  : (n << static_cast<mp_bitcnt_t>(-e)) >= d;
  if (!at_least_2e) --e;
  constexpr long kMaxExponent = 1023, kMinUlpExponent = -1074, kSignificandBits = 53;
  if (e > kMaxExponent) return sign * std::numeric_limits<double>::infinity();
  // The exponent of the last significand bit: 52 below the leading bit, or the subnormal ulp.
  const long u = std::max(e - (kSignificandBits - 1), kMinUlpExponent);
  mpz_class scaled_num = n, scaled_den = d;
  if (u >= 0)
    scaled_den <<= static_cast<mp_bitcnt_t>(u);
  else
    scaled_num <<= static_cast<mp_bitcnt_t>(-u);
  mpz_class m, r;
  mpz_fdiv_qr(m.get_mpz_t(), r.get_mpz_t(), scaled_num.get_mpz_t(), scaled_den.get_mpz_t());
  const int half = cmp(r << 1, scaled_den);
  if (half > 0 || (half == 0 && mpz_odd_p(m.get_mpz_t()))) ++m;
  // m <= 2^53 is exact in a double; ldexp is exact unless it overflows to infinity (x rounded
  // up to 2^1024), which is the IEEE result.
  return std::copysign(std::ldexp(m.get_d(), static_cast<int>(u)), sign);
}

std::optional<double> exact_double(const mpq_class& x) {
  const double d = nearest_double(x);
  if (!std::isfinite(d) || mpq_class(d) != x) return std::nullopt;
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

std::array<Vec3, 8> nearest_double_rows(const std::array<RationalVec3, 8>& rows) {
  std::array<Vec3, 8> out;
  for (std::size_t i = 0; i < rows.size(); ++i)
    out[i] = {nearest_double(rows[i].x), nearest_double(rows[i].y), nearest_double(rows[i].z)};
  return out;
}

}  // namespace exactccd::io
