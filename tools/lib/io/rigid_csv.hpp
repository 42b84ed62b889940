// The rigid query files of `exactccd check --motion rigid` (issue 24): one query per line, 41
// comma-separated numbers: cA0 (3), qA0 (4: w x y z), cA1 (3), qA1 (4), cB0 (3), qB0 (4), cB1 (3),
// qB1 (4), the body points (vertex-face: p of A, then a, b, c of B; edge-edge: a0, a1 of A, then
// b0, b1 of B; 12 numbers), then the truth (0 or 1). Each number is a decimal or hexadecimal
// floating-point literal read with strtod (the nearest double; "C" locale); '#' starts a comment
// line. Parsing and writing only: no file is opened here.
#pragma once

#include <array>
#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "io/benchmark_csv.hpp"  // ParseError
#include "rigid/rigid_layout.hpp"

namespace exactccd::io {

/// The queries of one rigid file, in file order.
struct RigidQueries {
  std::vector<std::array<double, rigid::kQueryNumbers>> numbers;  ///< each query's 40 numbers
  std::vector<bool> truth;                                         ///< each query's truth
  std::vector<std::size_t> lines;                                  ///< each query's 1-based line
  /// The number of queries.
  std::size_t size() const { return numbers.size(); }
};

/// Parses a rigid query file. Throws ParseError naming source_name and the line on: a line
/// with another number of fields than 41, an empty field, a field that is not one whole
/// floating-point literal (trailing characters), a number that is not finite (nan, inf, or a
/// magnitude beyond the double range), a truth other than 0 or 1, and a body whose quaternion
/// path vanishes in [0, 1] (a zero quaternion, or q1 a negative multiple of q0). Skips blank
/// lines, comment lines (first non-blank character '#'), CR line ends and a UTF-8 byte order
/// mark at the start.
RigidQueries read_rigid_csv(std::istream& in, const std::string& source_name);

/// Writes queries in that format, every number as a hexadecimal literal (%a: read back exactly)
/// and `comments` first (each line prefixed with "# ").
void write_rigid_csv(std::ostream& out, const RigidQueries& queries, const std::vector<std::string>& comments = {});

}  // namespace exactccd::io
