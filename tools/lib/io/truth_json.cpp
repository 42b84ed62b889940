#include "io/truth_json.hpp"

#include <cctype>
#include <istream>
#include <iterator>

#include "io/input_file.hpp"

namespace exactccd::io {

std::vector<bool> read_truth_json(std::istream& in, const std::string& source) {
  skip_byte_order_mark(in);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t i = 0, line = 1;
  const auto skip_space = [&] {
    for (; i < text.size(); ++i) {
      const char c = text[i];
      if (c == '\n') ++line;
      else if (c != ' ' && c != '\t' && c != '\r') break;
    }
  };
  const auto found = [&]() -> std::string {
    if (i >= text.size()) return "the end of the input";
    std::size_t end = i + 1;
    while (end < text.size() && end - i < 12 && std::isalnum(static_cast<unsigned char>(text[end])) &&
           std::isalnum(static_cast<unsigned char>(text[i])))
      ++end;
    return "'" + text.substr(i, end - i) + "'";
  };
  // The line of an error: the line of position i, or at the end of the input its last line (a
  // final line break starts no line of its own).
  const auto where = [&] { return i >= text.size() && line > 1 && text.back() == '\n' ? line - 1 : line; };
  std::vector<bool> out;
  skip_space();
  if (i >= text.size() || text[i] != '[')
    throw ParseError(source, where(), "expected a JSON array of booleans ('['), found " + found());
  ++i;
  skip_space();
  if (i < text.size() && text[i] == ']') {
    ++i;
  } else {
    for (;;) {
      skip_space();
      if (text.compare(i, 4, "true") == 0) {
        out.push_back(true);
        i += 4;
      } else if (text.compare(i, 5, "false") == 0) {
        out.push_back(false);
        i += 5;
      } else {
        throw ParseError(source, where(), "value " + std::to_string(out.size() + 1) + " is not true or false: found " + found());
      }
      skip_space();
      if (i < text.size() && text[i] == ',') {
        ++i;
        continue;
      }
      if (i < text.size() && text[i] == ']') {
        ++i;
        break;
      }
      throw ParseError(source, where(), "expected ',' or ']' after value " + std::to_string(out.size()) + ", found " + found());
    }
  }
  skip_space();
  if (i != text.size()) throw ParseError(source, where(), "data after the array: " + found());
  return out;
}

std::vector<bool> read_truth_json_file(const std::string& path) {
  InputFile file(path);
  std::vector<bool> out = read_truth_json(file.stream(), path);
  file.check_read();
  return out;
}

}  // namespace exactccd::io
