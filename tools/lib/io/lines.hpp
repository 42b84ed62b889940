// The line loop every text reader of tools/lib/io shares (OBJ, PLY, OFF, ASCII STL, benchmark
// and rigid CSV, answers, partial files): lines numbered from 1 after a UTF-8 byte order mark,
// a CR before the line break stripped (unless the format keeps it), a line's words split as
// operator>> splits them with the format's comments cut, and errors naming the source and the
// line. With it the one trimmer (trim) and the one splitter of comma-separated fields.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "io/input_file.hpp"  // ParseError

namespace exactccd::io {

/// Spaces and tabs: the blanks around a rigid query file's fields.
constexpr std::string_view kSpaceAndTab = " \t";
/// Those and CR: the blanks of a benchmark CSV line, which may hold a CR beside any field.
constexpr std::string_view kSpaceTabAndCr = " \t\r";

/// `text` without the leading and trailing characters that are in `blanks`.
std::string_view trim(std::string_view text, std::string_view blanks);

/// The fields of `line` between its commas, empty ones kept: n commas give n + 1 fields.
std::vector<std::string> split_fields(std::string_view line);

/// The whitespace-separated words of `line`, as operator>> reads them from a stream.
std::vector<std::string> split_words(const std::string& line);

/// What a reader does with a CR that ends a line (the CR of a CR LF line break).
enum class LineEnd {
  strip,  ///< removed: CR LF and LF line breaks read alike
  keep,   ///< left in the line, for formats that take only LF (partial files)
};

/// The lines of a stream, counted, for a reader whose errors name `source` and the line.
class LineReader {
 public:
  /// Reads `in` from its current position, after a UTF-8 byte order mark there. `comment` starts
  /// a comment to the end of the line in next_words ('\0': the format has no comments).
  LineReader(std::istream& in, std::string source, char comment = '\0', LineEnd end = LineEnd::strip);
  /// The next line, without its line break; false at the end of the input.
  bool next(std::string& line);
  /// The words of the next line that has any once its comment is cut; false at the end.
  bool next_words(std::vector<std::string>& words);
  /// The next line holding a character that is not in `blanks`; false at the end.
  bool next_nonblank(std::string& line, std::string_view blanks);
  /// The 1-based number of the last line read (0 before the first).
  std::size_t line() const { return line_; }
  /// The bytes read so far, byte order mark and line breaks included: where the next line (or
  /// a binary body after a text header) starts in the stream.
  std::size_t offset() const { return offset_; }
  /// The source name the errors give.
  const std::string& source() const { return source_; }
  /// Throws ParseError "<source>:<line>: <reason>" for the last line read.
  [[noreturn]] void fail(const std::string& reason) const;

 private:
  std::istream& in_;
  std::string source_;
  char comment_;
  LineEnd end_;
  std::size_t line_ = 0;
  std::size_t offset_ = 0;
};

}  // namespace exactccd::io
