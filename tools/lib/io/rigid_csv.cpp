#include "io/rigid_csv.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <istream>
#include <tuple>
#include <ostream>

#include "exactccd/rigid.hpp"
#include "rigid/validation.hpp"

namespace exactccd::io {
namespace {

std::string trimmed(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t");
  if (begin == std::string::npos) return "";
  const auto end = s.find_last_not_of(" \t");
  return s.substr(begin, end - begin + 1);
}

/// The number in `field` (trimmed), or a ParseError.
double number(const std::string& field, const std::string& source, std::size_t line, std::size_t index) {
  const std::string f = trimmed(field);
  const std::string where = "field " + std::to_string(index + 1) + ": ";
  if (f.empty()) throw ParseError(source, line, where + "empty");
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(f.c_str(), &end);
  if (end != f.c_str() + f.size()) throw ParseError(source, line, where + "'" + f + "' is not a number");
  if (!std::isfinite(v) || (errno == ERANGE && std::fabs(v) == HUGE_VAL))
    throw ParseError(source, line, where + "'" + f + "' is not a finite double");
  return v;
}

}  // namespace

RigidQueries read_rigid_csv(std::istream& in, const std::string& source) {
  RigidQueries out;
  std::string text;
  std::size_t line = 0;
  bool first = true;
  while (std::getline(in, text)) {
    ++line;
    if (first && text.size() >= 3 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
    first = false;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    const std::string t = trimmed(text);
    if (t.empty() || t[0] == '#') continue;
    std::vector<std::string> fields;
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = text.find(',', start);
      fields.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (fields.size() != rigid::kQueryNumbers + 1)
      throw ParseError(source, line, "expected 41 comma-separated numbers (40 and the truth), found " +
                                         std::to_string(fields.size()));
    std::array<double, rigid::kQueryNumbers> x;
    for (std::size_t i = 0; i < rigid::kQueryNumbers; ++i) x[i] = number(fields[i], source, line, i);
    const std::string truth = trimmed(fields.back());
    if (truth != "0" && truth != "1") throw ParseError(source, line, "the truth (field 41) must be 0 or 1, not '" + truth + "'");
    const auto q = rigid::from_numbers<RigidVertexFaceQuery>(x.data());  // the poses are the same for both kinds
    for (const auto& [name, t0, t1] : {std::tuple{"body A", q.a_t0, q.a_t1}, std::tuple{"body B", q.b_t0, q.b_t1}})
      if (const char* why = rigid::invalid_motion(t0, t1)) throw ParseError(source, line, std::string(name) + ": " + why);
    out.numbers.push_back(x);
    out.truth.push_back(truth == "1");
    out.lines.push_back(line);
  }
  return out;
}

void write_rigid_csv(std::ostream& out, const RigidQueries& queries, const std::vector<std::string>& comments) {
  for (const std::string& c : comments) out << "# " << c << "\n";
  char buf[64];
  for (std::size_t i = 0; i < queries.size(); ++i) {
    for (const double v : queries.numbers[i]) {
      std::snprintf(buf, sizeof buf, "%a,", v);
      out << buf;
    }
    out << (queries.truth[i] ? "1" : "0") << "\n";
  }
}

}  // namespace exactccd::io
