#include "io/answers.hpp"

#include <charconv>
#include <cmath>
#include <istream>
#include <ostream>
#include <system_error>

#include "io/input_file.hpp"
#include "io/lines.hpp"

namespace exactccd::io {

namespace {

/// A time of impact: a finite decimal in [0, 1] (the query's interval [0, tmax], tmax <= 1; -0 is 0).
double read_time(const std::string& w, const LineReader& lines) {
  double t = 0;
  const auto [end, error] = std::from_chars(w.data(), w.data() + w.size(), t);
  if (error != std::errc() || end != w.data() + w.size() || !std::isfinite(t))
    lines.fail("the time of impact '" + w + "' is not a finite number");
  if (!(t >= 0 && t <= 1)) lines.fail("the time of impact '" + w + "' is not in [0, 1]");
  return t;
}

/// One answer's words: "0", "1", or with_toi "1 T".
TheirAnswer read_answer(const std::vector<std::string>& words, const LineReader& lines, bool with_toi) {
  const std::string expected = with_toi ? "expected 0, or 1 and a time of impact" : "expected 0 or 1";
  if (words[0] != "0" && words[0] != "1") lines.fail(expected + ", found '" + words[0] + "'");
  TheirAnswer a{words[0] == "1", std::nullopt};
  const std::size_t fields_wanted = with_toi && a.collides ? 2 : 1;
  if (words.size() != fields_wanted) lines.fail(expected + ", found " + std::to_string(words.size()) + " fields");
  if (fields_wanted == 2) a.toi = read_time(words[1], lines);
  return a;
}

}  // namespace

std::vector<TheirAnswer> read_answers(std::istream& in, const std::string& source, bool with_toi) {
  std::vector<TheirAnswer> out;
  LineReader lines(in, source);
  for (std::vector<std::string> words; lines.next_words(words);) out.push_back(read_answer(words, lines, with_toi));
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
