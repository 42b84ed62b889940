// Another code's answers, as `exactccd compare` reads them (--answers THEIRS.txt, --toi
// THEIRS.txt): one answer per non-blank line, in the benchmark file's query order. Parsing only:
// io::InputFile opens the file.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "io/benchmark_csv.hpp"  // ParseError

namespace exactccd::io {

/// One answer of the other code: collides, and its time of impact when given.
struct TheirAnswer {
  bool collides = false;       ///< the other code's answer
  std::optional<double> toi;   ///< its time of impact (with_toi and collides only)
};

/// Reads one answer per non-blank line (whitespace-separated words): "0" or "1" (with_toi
/// false), "0" or "1 T" (with_toi) with T a decimal in [0, 1] (the nearest double: a time of the
/// query's interval [0, tmax], tmax <= 1). Anything else
/// is a ParseError naming source_name and the line. A UTF-8 byte order mark is skipped.
std::vector<TheirAnswer> read_answers(std::istream& in, const std::string& source_name, bool with_toi);

/// read_answers on the file at `path` (InputError when it cannot be opened or read).
std::vector<TheirAnswer> read_answers_file(const std::string& path, bool with_toi);

/// Writes answers in that format ("0", "1", or "1 T" with T's shortest round-trip decimal when
/// a TOI is given): read_answers reads back the same answers.
void write_answers(std::ostream& out, const std::vector<TheirAnswer>& answers);

}  // namespace exactccd::io
