#include "io/answers.hpp"

#include <charconv>
#include <cmath>
#include <istream>
#include <ostream>
#include <sstream>
#include <system_error>

#include "io/input_file.hpp"

namespace exactccd::io {

std::vector<TheirAnswer> read_answers(std::istream& in, const std::string& source, bool with_toi) {
  std::vector<TheirAnswer> out;
  std::string line;
  skip_byte_order_mark(in);
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    std::istringstream fields(line);
    std::vector<std::string> words;
    for (std::string w; fields >> w;) words.push_back(w);
    if (words.empty()) continue;
    const std::string expected = with_toi ? "expected 0, or 1 and a time of impact" : "expected 0 or 1";
    if (words[0] != "0" && words[0] != "1") throw ParseError(source, n, expected + ", found '" + words[0] + "'");
    TheirAnswer a{words[0] == "1", std::nullopt};
    const std::size_t fields_wanted = with_toi && a.collides ? 2 : 1;
    if (words.size() != fields_wanted)
      throw ParseError(source, n, expected + ", found " + std::to_string(words.size()) + " fields");
    if (fields_wanted == 2) {
      const std::string& w = words[1];
      double t = 0;
      const auto [end, error] = std::from_chars(w.data(), w.data() + w.size(), t);
      if (error != std::errc() || end != w.data() + w.size() || !std::isfinite(t))
        throw ParseError(source, n, "the time of impact '" + w + "' is not a finite number");
      // A time of the query's interval [0, tmax], tmax <= 1 (-0 is 0).
      if (!(t >= 0 && t <= 1)) throw ParseError(source, n, "the time of impact '" + w + "' is not in [0, 1]");
      a.toi = t;
    }
    out.push_back(a);
  }
  return out;
}

std::vector<TheirAnswer> read_answers_file(const std::string& path, bool with_toi) {
  InputFile file(path);
  std::vector<TheirAnswer> out = read_answers(file.stream(), path, with_toi);
  file.check_read();
  return out;
}

void write_answers(std::ostream& out, const std::vector<TheirAnswer>& answers) {
  char buf[64];
  for (const TheirAnswer& a : answers) {
    out << (a.collides ? "1" : "0");
    if (a.toi) out << ' ' << std::string(buf, std::to_chars(buf, buf + sizeof buf, *a.toi).ptr);
    out << '\n';
  }
}

}  // namespace exactccd::io
