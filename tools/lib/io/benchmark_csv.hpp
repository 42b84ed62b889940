// The public CCD benchmark's CSV format (Wang et al. 2021): 8 rows per query, each row one
// point `x_num,x_den,y_num,y_den,z_num,z_den,truth`, coordinates exact rationals. Parsing and
// writing only: no file is opened here (the CLI opens files).
#pragma once

#include <array>
#include <cstddef>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "exactccd/rational.hpp"
#include "exactccd/types.hpp"
#include "io/input_file.hpp"  // InputError, ParseError

namespace exactccd::io {

/// The largest numerator or denominator read_benchmark_csv accepts, in bits (1233 decimal
/// digits). Every double fits with room to spare (its numerator has at most 1024 bits, its
/// denominator at most 1075). The bound caps the cost of the exact path, which grows with the
/// size of the rationals (a 10^5-digit coordinate ran for more than 15 minutes; at this limit
/// the worst query measured takes seconds and a few hundred MB, at 8192 bits four times
/// that): docs/formats.md, "Input files", gives the measured figures and the command.
constexpr std::size_t kMaxFieldBits = 4096;

/// The shape of a query file: rows per query (each point at t0, then at t1) and coordinates per
/// row (3; 2 for the 2D kinds). A row has 2 * dimension + 1 columns: num,den per coordinate,
/// then the truth; without the truth column (the Scalable CCD dataset's query files, whose
/// truth is a JSON file beside them: io/truth_json.hpp) 2 * dimension. The public benchmark's
/// layout is {8, 3, true}.
struct QueryLayout {
  int rows = 8;              ///< 2 * the kind's points: 8, 6 or 4
  int dimension = 3;         ///< 3, or 2
  bool truth_column = true;  ///< whether each row ends with the truth (0 or 1)
  /// Columns per row.
  int columns() const { return 2 * dimension + (truth_column ? 1 : 0); }
};

/// The layout of a kind's files (kinds::VertexFace, ...).
template <class Kind>
constexpr QueryLayout layout_of() {
  return {2 * Kind::points, Kind::dimension, true};
}

/// Queries of one benchmark file: rows[i] are query i's points in row order (the first
/// layout.rows of the array; a 2D point has z = 0), truth[i] its published ground truth.
struct BenchmarkQueries {
  QueryLayout layout;                             ///< rows per query and coordinates per row
  std::vector<std::array<RationalVec3, 8>> rows;  ///< layout.rows points per query, in row order
  std::vector<bool> truth;                        ///< the truth column, one per query (all false
                                                  ///< when the layout has no truth column)
  /// The 1-based line of each row, per query (filled by read_benchmark_csv; empty for queries
  /// built in memory).
  std::vector<std::array<std::size_t, 8>> lines;
  /// The number of queries.
  std::size_t size() const { return rows.size(); }
};

/// The number of comma-separated fields of the first non-blank line of `in` (0 when there is
/// none), read from the current position: tells a file with a truth column from one without.
int first_row_columns(std::istream& in);

/// Parses a benchmark CSV. Throws ParseError naming source_name and the line on: a wrong
/// number of columns (layout.columns()), a non-integer field, an integer of more than
/// kMaxFieldBits bits, a zero denominator, a truth other than 0/1 or not repeated on all rows of
/// a query, or a row count that is not a multiple of layout.rows. Rationals are canonicalized.
/// Tolerates CR line ends, spaces around fields, blank lines and a UTF-8 byte order mark at the start. An input
/// without rows gives no queries (callers reading a file reject that: docs/formats.md, "Input files").
BenchmarkQueries read_benchmark_csv(std::istream& in, const std::string& source_name,
                                    QueryLayout layout = {});

/// Writes queries in the benchmark format, each rational as its exact canonical
/// numerator,denominator pair (no truth column when queries.layout has none). read_benchmark_csv reads back the same queries. Throws
/// std::invalid_argument when queries.truth and queries.rows differ in size.
void write_benchmark_csv(std::ostream& out, const BenchmarkQueries& queries);

/// A query of any kind (double or rational coordinates) from the first rows of a benchmark
/// file's eight-row array (2D kinds take x and y).
template <class Query, class Point>
Query query_from_rows(const std::array<Point, 8>& r) {
  auto out = rows(Query{});
  static_assert(out.size() <= 8);
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].x = r[k].x;
    out[k].y = r[k].y;
    if constexpr (std::is_same_v<std::decay_t<decltype(out[k])>, std::decay_t<Point>>) out[k].z = r[k].z;
  }
  return from_rows<Query>(out);
}

/// Query i of `queries` as a rational query of the kind of `Query` (e.g.
/// RationalPointEdgeQuery), whose layout must be the file's.
template <class Query>
Query query_at(const BenchmarkQueries& queries, std::size_t i) {
  return query_from_rows<Query>(queries.rows.at(i));
}

/// Query i of `queries` as a rational vertex-face query (rows in benchmark order).
RationalVertexFaceQuery vertex_face_query(const BenchmarkQueries& queries, std::size_t i);

/// Query i of `queries` as a rational edge-edge query (rows in benchmark order).
RationalEdgeEdgeQuery edge_edge_query(const BenchmarkQueries& queries, std::size_t i);

/// x rounded to the nearest double, ties to even, as IEEE round-to-nearest does: subnormal
/// results are rounded at 2^-1074, magnitudes from DBL_MAX + ulp/2 on become +-infinity and
/// a nonzero x that rounds to zero gives the zero of its sign; x == 0 gives +0. Computed with
/// GMP integers only (no reliance on mpq_get_d, which truncates).
double nearest_double(const mpq_class& x);

/// The double equal to x, or nullopt when x is not exactly a double (not dyadic, more than 53
/// significant bits, below 2^-1074 in its last bit, or of magnitude 2^1024 or more).
std::optional<double> exact_double(const mpq_class& x);

/// The query in doubles when every coordinate is exactly a double, else nullopt.
std::optional<std::array<Vec3, 8>> exact_double_rows(const std::array<RationalVec3, 8>& rows);

/// Every coordinate rounded to the nearest double (nearest_double).
std::array<Vec3, 8> nearest_double_rows(const std::array<RationalVec3, 8>& rows);

}  // namespace exactccd::io
