// libFuzzer target: io::read_benchmark_csv on arbitrary bytes, in every layout a kind can have
// (8, 6 or 4 rows of 3D or 2D points), with or without the truth column as the CLI decides it
// (io::first_row_columns). Besides reader_oracle.hpp's checks: an accepted file has one query per
// `rows` non-blank lines, canonical rationals of at most io::kMaxFieldBits bits (z = 0 in 2D),
// lines in increasing order, and written back (io::write_benchmark_csv) reads as the same
// queries. docs/fuzzing.md, section 5.
#include <cstddef>
#include <cstdint>
#include <sstream>

#include "fuzz/readers/reader_oracle.hpp"
#include "io/benchmark_csv.hpp"

namespace exactccd::fuzzing {
namespace {

bool canonical(const mpq_class& x) {
  mpz_class g;
  mpz_gcd(g.get_mpz_t(), x.get_num().get_mpz_t(), x.get_den().get_mpz_t());
  return x.get_den() > 0 && g == 1 && mpz_sizeinbase(x.get_num().get_mpz_t(), 2) <= io::kMaxFieldBits &&
         mpz_sizeinbase(x.get_den().get_mpz_t(), 2) <= io::kMaxFieldBits;
}

bool same_queries(const io::BenchmarkQueries& a, const io::BenchmarkQueries& b) {
  if (a.size() != b.size() || a.truth != b.truth) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int k = 0; k < a.layout.rows; ++k)
      if (a.rows[i][k].x != b.rows[i][k].x || a.rows[i][k].y != b.rows[i][k].y || a.rows[i][k].z != b.rows[i][k].z)
        return false;
  return true;
}

void check_queries(const io::BenchmarkQueries& q, std::string_view input) {
  const std::string_view body = input.substr(0, 3) == "\xEF\xBB\xBF" ? input.substr(3) : input;
  require(q.size() * static_cast<std::size_t>(q.layout.rows) == nonblank_lines(body),
          "queries x rows != the non-blank lines", input);
  require(q.truth.size() == q.size() && q.lines.size() == q.size(), "truth or lines of another count", input);
  std::size_t last = 0;
  for (std::size_t i = 0; i < q.size(); ++i)
    for (int k = 0; k < q.layout.rows; ++k) {
      const RationalVec3& p = q.rows[i][k];
      require(canonical(p.x) && canonical(p.y) && canonical(p.z), "a coordinate not canonical or too large", input);
      require(q.layout.dimension == 3 || p.z == 0, "a 2D point with z != 0", input);
      require(q.lines[i][k] > last && q.lines[i][k] <= line_count(input), "row lines out of order or range", input);
      last = q.lines[i][k];
    }
  std::ostringstream written;
  io::write_benchmark_csv(written, q);
  const auto read = [&](std::istream& in) { return io::read_benchmark_csv(in, "written.csv", q.layout); };
  require(same_queries(q, read_back(read, written.str(), input)),
          "written back, the queries read differently:\n" + written.str(), input);
}

void check_layout(std::string_view input, io::QueryLayout layout) {
  const auto read = [layout](std::istream& in, const std::string& source) {
    return io::read_benchmark_csv(in, source, layout);
  };
  fuzz_stream_reader(read, "input.csv", input, [&](const io::BenchmarkQueries& q) { check_queries(q, input); });
}

}  // namespace
}  // namespace exactccd::fuzzing

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace exactccd::fuzzing;
  const std::string_view input = as_text(data, size);
  std::istringstream peek{std::string(input)};
  const int columns = exactccd::io::first_row_columns(peek);
  for (const int dimension : {3, 2})
    for (const int rows : {8, 6, 4}) check_layout(input, {rows, dimension, columns != 2 * dimension});
  return 0;
}
