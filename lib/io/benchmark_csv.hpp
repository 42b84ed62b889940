// The public CCD benchmark's CSV format (Wang et al. 2021): 8 rows per query, each row one
// point `x_num,x_den,y_num,y_den,z_num,z_den,truth`, coordinates exact rationals. Parsing and
// writing only: no file is opened here (the CLI opens files).
#pragma once

#include <array>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "exactccd/types.hpp"

namespace exactccd::io {

/// A malformed input: what is wrong, where (source name and 1-based line).
class ParseError : public std::runtime_error {
 public:
  ParseError(const std::string& source, std::size_t line, const std::string& what);
  const std::string& source() const { return source_; }
  std::size_t line() const { return line_; }

 private:
  std::string source_;
  std::size_t line_;
};

/// Queries of one benchmark file: rows[i] are query i's eight points in row order, truth[i]
/// its published ground truth.
struct BenchmarkQueries {
  std::vector<std::array<RationalVec3, 8>> rows;
  std::vector<bool> truth;
  std::size_t size() const { return rows.size(); }
};

/// Parses a benchmark CSV. Throws ParseError naming source_name and the line on: a wrong
/// number of columns, a non-integer field, a zero denominator, a truth other than 0/1 or not
/// repeated on all 8 rows of a query, or a row count that is not a multiple of 8. Tolerates
/// CR line ends, surrounding spaces and blank lines.
BenchmarkQueries read_benchmark_csv(std::istream& in, const std::string& source_name);

/// Writes queries in the benchmark format, each rational as its exact numerator/denominator.
void write_benchmark_csv(std::ostream& out, const BenchmarkQueries& queries);

/// The double equal to x, or nullopt when x is not exactly a double.
std::optional<double> exact_double(const mpq_class& x);

/// The query in doubles when every coordinate is exactly a double.
std::optional<std::array<Vec3, 8>> exact_double_rows(const std::array<RationalVec3, 8>& rows);

}  // namespace exactccd::io
