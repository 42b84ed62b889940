// What every reader fuzz target checks besides its format's own properties (docs/fuzzing.md,
// section 5): a reader either returns or throws io::InputError, whose message names the source
// and the line (text) or byte offset (binary) inside the input; no other exception, no crash;
// the memory it holds stays within a small multiple of the input's size (an untrusted count in
// a header must not reserve memory before the file is seen to hold it); trailing garbage is
// never accepted. A violation prints what was wrong and abort()s: libFuzzer keeps the input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

#include "io/input_file.hpp"

namespace exactccd::fuzzing {

/// Prints "reader fuzz violation: <what>" and the input (escaped, first 2000 bytes) to stderr
/// and aborts.
[[noreturn]] void fail(const std::string& what, std::string_view input);

/// fail(what, input) unless `ok`.
inline void require(bool ok, const std::string& what, std::string_view input) {
  if (!ok) fail(what, input);
}

/// How an error of a reader must say where it is.
enum class Location {
  line,         ///< a ParseError whose line is one of the input's lines
  line_or_byte, ///< that, or "<source>: byte offset N (...)" with N at most the input's size
  any,          ///< that, or a whole-file reason "<source>: <reason>" (read_mesh's "no faces", ...)
};

/// The lines of `text` as read_* count them: newlines, plus one for a last line without one (at
/// least 1, so that an empty input's errors may name line 1).
std::size_t line_count(std::string_view text);

/// The number of lines of `text` with a non-whitespace character (\r\n and \n line ends).
std::size_t nonblank_lines(std::string_view text);

/// Checks an error of a reader given `source` as its name: what() starts with "<source>:", and
/// the location is of the kind `where` allows and inside the input (fail() otherwise).
void check_error(const io::InputError& error, const std::string& source, Location where, std::string_view input);

/// What a reader did with an input: returned (accepted), or threw io::InputError (its message).
struct ReaderOutcome {
  bool accepted = false;
  std::string error;  ///< what() of the InputError ("" when accepted)
};

/// Runs `parse` with every heap allocation of this thread counted (malloc, new, GMP's and the
/// standard library's): the peak of the bytes held at once, above those held before, must stay
/// within kBytesPerInputByte times the input's size plus kFixedBytes (fail() otherwise). An
/// io::InputError is checked by check_error and returned; any other exception propagates
/// (libFuzzer reports it as a crash).
ReaderOutcome run_reader(const std::function<void()>& parse, const std::string& source, Location where,
                         std::string_view input);

/// The bound of run_reader: a reader may hold this many bytes per input byte (its parsed mesh or
/// rationals, a copy of the text, a line and its words) ...
constexpr std::size_t kBytesPerInputByte = 64;
/// ... plus this many for fixed costs (stream buffers, locale facets, error messages).
constexpr std::size_t kFixedBytes = 256 * 1024;

/// The whole check of a text reader on an input: `read(stream, source)` under run_reader (errors
/// with a line); when it accepts, `check(what it returned)` (the target's own properties) and
/// check_rejects_trailing_garbage.
template <class Read, class Check>
void fuzz_stream_reader(const Read& read, const std::string& source, std::string_view input, const Check& check) {
  decltype(read(std::declval<std::istream&>(), source)) result{};
  const ReaderOutcome outcome = run_reader(
      [&] {
        std::istringstream in{std::string(input)};
        result = read(in, source);
      },
      source, Location::line, input);
  if (!outcome.accepted) return;
  check(result);
  check_rejects_trailing_garbage([&](std::istream& in) { read(in, source); }, input);
}

/// A file in the temporary directory for readers that take a path (io::read_mesh,
/// cli::read_partial): one per process and name, rewritten for every input, removed at exit.
class ScratchFile {
 public:
  /// The file "<tmp>/exactccd-fuzz-<pid>-<name>".
  explicit ScratchFile(const std::string& name);
  ~ScratchFile();
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  /// Replaces the file's content with `bytes`; returns its path.
  const std::string& write(std::string_view bytes);
  /// The path.
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// The input as a string (libFuzzer's bytes).
inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// What `read` (a reader taking an std::istream&) makes of `written`, text the target wrote
/// itself from what the reader returned (a round trip): fail() when the reader refuses it.
template <class Read>
auto read_back(const Read& read, const std::string& written, std::string_view input) {
  std::istringstream in(written);
  try {
    return read(static_cast<std::istream&>(in));
  } catch (const io::InputError& e) {
    fail(std::string("written back, the reader refuses it: ") + e.what() + "\nwritten:\n" + written, input);
  }
}

/// Checks that `read` throws io::InputError on the input with a line of garbage appended
/// ("\nx\n"), as it must when it accepted the input: no format here ends with free text that a
/// line "x" would extend, so accepting it means data after the end is ignored.
void check_rejects_trailing_garbage(const std::function<void(std::istream&)>& read, std::string_view input);

}  // namespace exactccd::fuzzing
