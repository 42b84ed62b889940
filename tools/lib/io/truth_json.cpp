#include "io/truth_json.hpp"

#include <cctype>
#include <istream>
#include <iterator>
#include <string_view>
#include <utility>

#include "io/input_file.hpp"

namespace exactccd::io {

namespace {

/// The text of a JSON document read character by character, with the line of the position.
class JsonText {
 public:
  JsonText(std::string text, const std::string& source) : text_(std::move(text)), source_(source) {}

  /// Skips JSON whitespace, counting line breaks.
  void skip_space() {
    for (; i_ < text_.size(); ++i_) {
      const char c = text_[i_];
      if (c == '\n') ++line_;
      else if (c != ' ' && c != '\t' && c != '\r') break;
    }
  }
  /// Consumes `word` if the text continues with it.
  bool take(std::string_view word) {
    if (text_.compare(i_, word.size(), word) != 0) return false;
    i_ += word.size();
    return true;
  }
  bool at_end() const { return i_ == text_.size(); }
  /// What is at the position, for errors: a word of up to 12 letters and digits, one other
  /// character, or the end of the input.
  std::string found() const {
    if (i_ >= text_.size()) return "the end of the input";
    std::size_t end = i_ + 1;
    while (end < text_.size() && end - i_ < 12 && std::isalnum(static_cast<unsigned char>(text_[end])) &&
           std::isalnum(static_cast<unsigned char>(text_[i_])))
      ++end;
    return "'" + text_.substr(i_, end - i_) + "'";
  }
  /// Throws ParseError at the line of the position, or at the end of the input at its last line
  /// (a final line break starts no line of its own).
  [[noreturn]] void fail(const std::string& reason) const {
    throw ParseError(source_, i_ >= text_.size() && line_ > 1 && text_.back() == '\n' ? line_ - 1 : line_, reason);
  }

 private:
  std::string text_;
  const std::string& source_;
  std::size_t i_ = 0, line_ = 1;
};

/// The values after '[' up to and including the closing ']' (at least one value).
void read_values(JsonText& json, std::vector<bool>& out) {
  for (;;) {
    json.skip_space();
    if (json.take("true")) out.push_back(true);
    else if (json.take("false")) out.push_back(false);
    else json.fail("value " + std::to_string(out.size() + 1) + " is not true or false: found " + json.found());
    json.skip_space();
    if (json.take(",")) continue;
    if (json.take("]")) return;
    json.fail("expected ',' or ']' after value " + std::to_string(out.size()) + ", found " + json.found());
  }
}

}  // namespace

std::vector<bool> read_truth_json(std::istream& in, const std::string& source) {
  skip_byte_order_mark(in);
  JsonText json(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()), source);
  std::vector<bool> out;
  json.skip_space();
  if (!json.take("[")) json.fail("expected a JSON array of booleans ('['), found " + json.found());
  json.skip_space();
  if (!json.take("]")) read_values(json, out);
  json.skip_space();
  if (!json.at_end()) json.fail("data after the array: " + json.found());
  return out;
}

std::vector<bool> read_truth_json_file(const std::string& path) {
  InputFile file(path);
  std::vector<bool> out = read_truth_json(file.stream(), path);
  file.check_read();
  return out;
}

}  // namespace exactccd::io
