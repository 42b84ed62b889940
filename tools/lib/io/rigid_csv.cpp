#include "io/rigid_csv.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <istream>
#include <ostream>
#include <tuple>
#include <vector>

#include "exactccd/rigid.hpp"
#include "io/lines.hpp"
#include "rigid/validation.hpp"

namespace exactccd::io {
namespace {

/// The number in `field` (trimmed), or a ParseError.
double number(const std::string& field, const std::string& source, std::size_t line, std::size_t index) {
  const std::string f(trim(field, kSpaceAndTab));
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

/// One query's line: 40 numbers and the truth, both bodies' motions valid.
void read_query(const std::string& text, const LineReader& lines, RigidQueries& out) {
  const std::vector<std::string> fields = split_fields(text);
  if (fields.size() != rigid::kQueryNumbers + 1)
    lines.fail("expected 41 comma-separated numbers (40 and the truth), found " + std::to_string(fields.size()));
  std::array<double, rigid::kQueryNumbers> x;
  for (std::size_t i = 0; i < rigid::kQueryNumbers; ++i) x[i] = number(fields[i], lines.source(), lines.line(), i);
  const std::string truth(trim(fields.back(), kSpaceAndTab));
  if (truth != "0" && truth != "1") lines.fail("the truth (field 41) must be 0 or 1, not '" + truth + "'");
  const auto q = rigid::from_numbers<RigidVertexFaceQuery>(x.data());  // the poses are the same for both kinds
  for (const auto& [name, t0, t1] : {std::tuple{"body A", q.a_t0, q.a_t1}, std::tuple{"body B", q.b_t0, q.b_t1}})
    if (const char* why = rigid::invalid_motion(t0, t1)) lines.fail(std::string(name) + ": " + why);
  out.numbers.push_back(x);
  out.truth.push_back(truth == "1");
  out.lines.push_back(lines.line());
}

}  // namespace

RigidQueries read_rigid_csv(std::istream& in, const std::string& source) {
  RigidQueries out;
  LineReader lines(in, source);
  for (std::string text; lines.next_nonblank(text, kSpaceAndTab);)
    if (trim(text, kSpaceAndTab)[0] != '#') read_query(text, lines, out);  // not a comment line
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
