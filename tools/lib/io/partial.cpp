#include "io/partial.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <system_error>
#include <vector>

#include "io/input_file.hpp"
#include "io/lines.hpp"

namespace exactccd::io {
namespace {

/// The text after the first word of `line` and one space ("" when there is none).
std::string rest_after_word(const std::string& line) {
  const std::size_t space = line.find(' ');
  return space == std::string::npos ? std::string() : line.substr(space + 1);
}

std::string first_word(const std::string& line) { return line.substr(0, line.find(' ')); }

/// The lines of a partial file as they are (LF line breaks only: a CR stays in the line), each
/// one expected: the file ending where a line is expected is an error saying what was.
class PartialLines {
 public:
  explicit PartialLines(InputFile& file) : file_(file), lines_(file.stream(), file.path(), '\0', LineEnd::keep) {}
  /// The next line; `what` names it in the error when the file ends first.
  const std::string& next(const char* what) {
    if (!lines_.next(text_)) {
      file_.check_read();
      throw ParseError(path(), std::max<std::size_t>(lines_.line(), 1),
                       std::string("unexpected end of file, expected ") + what + " (a truncated partial file?)");
    }
    return text_;
  }
  /// The last line read, and its number.
  const std::string& text() const { return text_; }
  std::size_t number() const { return lines_.line(); }
  const std::string& path() const { return file_.path(); }
  /// word as a count; errors name the last line read.
  std::size_t count(const std::string& word) const { return parse_count(word, path(), lines_.line()); }
  /// Throws ParseError at the last line read.
  [[noreturn]] void fail(const std::string& reason) const { lines_.fail(reason); }
  /// Checks that only empty lines follow, and that the file was read without error.
  void read_to_end() {
    while (lines_.next(text_))
      if (!text_.empty()) fail("text after 'end'");
    file_.check_read();
  }

 private:
  InputFile& file_;
  LineReader lines_;
  std::string text_;
};

/// The magic line and `command NAME`.
void read_command(PartialLines& lines, Partial& p) {
  if (lines.next("the header 'exactccd-partial 1'") != kPartialMagic)
    lines.fail("not an exactccd partial file (expected 'exactccd-partial 1')");
  const std::string& line = lines.next("'command NAME'");
  if (first_word(line) != "command" || rest_after_word(line).empty()) lines.fail("expected 'command NAME'");
  p.command = rest_after_word(line);
}

/// The `setting KEY VALUE` lines, up to the first other line (then lines.text()).
void read_settings(PartialLines& lines, Partial& p) {
  for (;;) {
    const std::string& line = lines.next("'setting KEY VALUE' or 'shard I N'");
    if (first_word(line) != "setting") return;
    const std::string kv = rest_after_word(line);
    const std::size_t space = kv.find(' ');
    if (kv.empty() || space == 0) lines.fail("expected 'setting KEY VALUE'");
    p.settings.emplace_back(kv.substr(0, space), space == std::string::npos ? "" : kv.substr(space + 1));
  }
}

/// `shard I N` (the line after the settings): 0 <= I < N <= kMaxPartialShards.
void read_shard(const PartialLines& lines, Partial& p) {
  const std::vector<std::string> w = split_words(lines.text());
  if (w.size() != 3 || w[0] != "shard") lines.fail("expected 'shard I N'");
  p.shard_index = lines.count(w[1]);
  p.shard_count = lines.count(w[2]);
  if (p.shard_count == 0 || p.shard_index >= p.shard_count || p.shard_count > kMaxPartialShards)
    lines.fail("shard " + w[1] + " of " + w[2] + ": expected 0 <= I < N <= " + std::to_string(kMaxPartialShards));
}

/// `range BEGIN END TOTAL`, TOTAL bounded so that merge_partials' TOTAL * N (the shards' ranges)
/// cannot wrap around.
void read_range(PartialLines& lines, Partial& p) {
  const std::vector<std::string> w = split_words(lines.next("'range BEGIN END TOTAL'"));
  if (w.size() != 4 || w[0] != "range") lines.fail("expected 'range BEGIN END TOTAL'");
  p.begin = lines.count(w[1]);
  p.end = lines.count(w[2]);
  p.total = lines.count(w[3]);
  constexpr std::size_t kMaxTotal = std::numeric_limits<std::size_t>::max() / kMaxPartialShards;
  if (p.begin > p.end || p.end > p.total || p.total > kMaxTotal)
    lines.fail("range: expected BEGIN <= END <= TOTAL <= " + std::to_string(kMaxTotal));
}

/// The records, up to `end COUNT` with COUNT their number.
void read_records(PartialLines& lines, Partial& p) {
  for (;;) {
    const std::string& line = lines.next("a record or 'end COUNT'");
    if (first_word(line) == "end") break;
    p.records.push_back({line, lines.path(), lines.number()});
  }
  const std::vector<std::string> w = split_words(lines.text());
  if (w.size() != 2 || lines.count(w[1]) != p.records.size())
    lines.fail("'end " + (w.size() > 1 ? w[1] : std::string()) + "' does not match the " +
               std::to_string(p.records.size()) + " records read");
}

}  // namespace

Partial read_partial(const std::string& path) {
  InputFile file(path, ByteOrderMark::keep);  // the line reader skips the mark
  PartialLines lines(file);
  Partial p;
  read_command(lines, p);
  read_settings(lines, p);
  read_shard(lines, p);
  read_range(lines, p);
  read_records(lines, p);
  lines.read_to_end();
  return p;
}

const std::string& Partial::setting(const std::string& key, const std::string& source) const {
  for (const auto& [k, v] : settings)
    if (k == key) return v;
  throw ParseError(source, 1, "no setting '" + key + "' in this partial file");
}

std::string hex_double(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

double parse_double(const std::string& text, const std::string& source, std::size_t line) {
  // strtod reads hex floats exactly (C99); from_chars's hex form takes no "0x" prefix.
  const char* begin = text.c_str();
  char* end = nullptr;
  const double x = std::strtod(begin, &end);
  if (text.empty() || end != begin + text.size() || !std::isfinite(x))
    throw ParseError(source, line, "'" + text + "' is not a finite number");
  return x;
}

std::size_t parse_count(const std::string& text, const std::string& source, std::size_t line) {
  std::size_t n = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (text.empty() || error != std::errc() || end != text.data() + text.size())
    throw ParseError(source, line, "'" + text + "' is not a non-negative integer");
  return n;
}

int parse_int(const std::string& text, const std::string& source, std::size_t line) {
  int v = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || error != std::errc() || end != text.data() + text.size())
    throw ParseError(source, line, "'" + text + "' is not an integer");
  return v;
}

}  // namespace exactccd::io
