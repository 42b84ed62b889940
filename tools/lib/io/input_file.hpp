// Opening input files for reading with errors that name the file and say what is wrong
// (missing, a directory, unreadable), and skipping a UTF-8 byte order mark so that no reader
// loses its first line to it. Every input error of the readers derives from InputError.
#pragma once

#include <fstream>
#include <iosfwd>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace exactccd::io {

/// An input that cannot be used: what() is "<source>: <reason>" (ParseError, which derives
/// An error of the caller's request that the tools report and stop on (a bad option, an output
/// path that cannot be written, files that are not the shards of one run): the programs print
/// "exactccd: <message>" and exit 2 (tools/exactccd/cli_common.hpp, ExitCode).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// from it, adds the line: "<source>:<line>: <reason>").
class InputError : public std::runtime_error {
 public:
  /// An error about the whole of `source` (usually a file path); `reason` says what is wrong.
  InputError(const std::string& source, const std::string& reason);
  /// The source name (usually the file path).
  const std::string& source() const { return source_; }

 protected:
  /// For derived errors that format what() themselves.
  InputError(const std::string& source, const std::string& what, bool preformatted);

 private:
  std::string source_;
};

/// A malformed input: what is wrong, where (source name and 1-based line). what() is
/// "<source>:<line>: <reason>".
class ParseError : public InputError {
 public:
  /// An error in `source` at 1-based `line`; `what` is the reason.
  ParseError(const std::string& source, std::size_t line, const std::string& what);
  /// The 1-based line of the error.
  std::size_t line() const { return line_; }

 private:
  std::size_t line_;
};

/// Consumes a UTF-8 byte order mark (EF BB BF) at the stream's current position, if there is
/// one; returns whether it did. Anything else is left unread.
bool skip_byte_order_mark(std::istream& in);

/// What InputFile does with a UTF-8 byte order mark at the start of the file.
enum class ByteOrderMark {
  skip,  ///< consume it: the stream starts after it (text readers)
  keep,  ///< leave it: the stream starts at byte 0 (readers of binary formats, which skip it
         ///< themselves where the content is text, so that byte offsets are the file's)
};

/// A file opened for reading, positioned after its UTF-8 byte order mark if it has one (unless
/// asked to keep it).
class InputFile {
 public:
  /// Opens `path`. Throws InputError "<path>: no such file", "<path>: is a directory" or
  /// "<path>: cannot open: <system reason>" (e.g. permission denied).
  explicit InputFile(const std::string& path, ByteOrderMark mark = ByteOrderMark::skip);
  /// The stream to read from (after the byte order mark).
  std::istream& stream() { return in_; }
  /// The path as given.
  const std::string& path() const { return path_; }
  /// Whether the file started with a UTF-8 byte order mark (skipped; always false when kept).
  bool had_byte_order_mark() const { return had_bom_; }
  /// Throws InputError "<path>: read error" when the stream failed for another reason than
  /// reaching the end of the file (call after reading everything).
  void check_read() const;

 private:
  std::string path_;
  std::ifstream in_;
  bool had_bom_ = false;
};

}  // namespace exactccd::io
