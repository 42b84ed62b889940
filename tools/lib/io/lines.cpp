#include "io/lines.hpp"

#include <algorithm>
#include <istream>
#include <sstream>
#include <utility>

namespace exactccd::io {

std::string_view trim(std::string_view text, std::string_view blanks) {
  const std::size_t first = text.find_first_not_of(blanks);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(blanks) - first + 1);
}

std::vector<std::string> split_fields(std::string_view line) {
  std::vector<std::string> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.emplace_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

std::vector<std::string> split_words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

LineReader::LineReader(std::istream& in, std::string source, char comment, LineEnd end)
    : in_(in), source_(std::move(source)), comment_(comment), end_(end) {
  if (skip_byte_order_mark(in_)) offset_ = 3;
}

bool LineReader::next(std::string& line) {
  if (!std::getline(in_, line)) return false;
  ++line_;
  offset_ += line.size() + (in_.eof() ? 0 : 1);  // the line break, when the line has one
  if (end_ == LineEnd::strip && !line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

bool LineReader::next_words(std::vector<std::string>& words) {
  for (std::string line; next(line);) {
    if (comment_ != '\0') line.erase(std::min(line.find(comment_), line.size()));
    words = split_words(line);
    if (!words.empty()) return true;
  }
  return false;
}

bool LineReader::next_nonblank(std::string& line, std::string_view blanks) {
  while (next(line))
    if (!trim(line, blanks).empty()) return true;
  return false;
}

void LineReader::fail(const std::string& reason) const { throw ParseError(source_, line_, reason); }

}  // namespace exactccd::io
