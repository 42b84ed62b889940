// Tests of the benchmark CSV reader and writer (lib/io/benchmark_csv).
#include "io/benchmark_csv.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace exactccd::io {
namespace {

std::string query_rows(int truth, const std::string& first_row = "1,2,3,4,-5,8") {
  std::string s;
  s += first_row + "," + std::to_string(truth) + "\n";
  for (int i = 1; i < 8; ++i) s += std::to_string(i) + ",1,0,1,0,1," + std::to_string(truth) + "\n";
  return s;
}

int error_line(const std::string& text) {
  std::istringstream in(text);
  try {
    read_benchmark_csv(in, "input.csv");
  } catch (const ParseError& e) {
    EXPECT_EQ(e.source(), "input.csv");
    EXPECT_NE(std::string(e.what()).find("input.csv:" + std::to_string(e.line()) + ":"),
              std::string::npos);
    return static_cast<int>(e.line());
  }
  return -1;
}

TEST(ReadBenchmarkCsv, ParsesRationalsAndTruth) {
  std::istringstream in(query_rows(1) + query_rows(0));
  const BenchmarkQueries q = read_benchmark_csv(in, "x");
  ASSERT_EQ(q.size(), 2u);
  EXPECT_EQ(q.rows[0][0].x, mpq_class(1, 2));
  EXPECT_EQ(q.rows[0][0].y, mpq_class(3, 4));
  EXPECT_EQ(q.rows[0][0].z, mpq_class(-5, 8));
  EXPECT_EQ(q.rows[1][7].x, mpq_class(7));
  EXPECT_TRUE(q.truth[0]);
  EXPECT_FALSE(q.truth[1]);
}

TEST(ReadBenchmarkCsv, CanonicalizesAndToleratesCrAndBlankLines) {
  std::string text = query_rows(1, "2,4,-6,-8,0,5");
  text.insert(text.find('\n'), "\r");
  std::istringstream in("\n" + text + "\n\n");
  const BenchmarkQueries q = read_benchmark_csv(in, "x");
  ASSERT_EQ(q.size(), 1u);
  EXPECT_EQ(q.rows[0][0].x, mpq_class(1, 2));
  EXPECT_EQ(q.rows[0][0].y, mpq_class(3, 4));
  EXPECT_EQ(q.rows[0][0].z, mpq_class(0));
}

TEST(ReadBenchmarkCsv, RejectsMalformedLinesNamingTheLine) {
  EXPECT_EQ(error_line(query_rows(1, "1,2,3,4,5")), 1);             // 6 fields
  EXPECT_EQ(error_line(query_rows(1, "1,2,3,4,5,6,7")), 1);         // 8 fields
  EXPECT_EQ(error_line(query_rows(1, "1,0,3,4,5,6")), 1);           // zero denominator
  EXPECT_EQ(error_line(query_rows(1, "1.5,2,3,4,5,6")), 1);         // not an integer
  EXPECT_EQ(error_line(query_rows(1, "x,2,3,4,5,6")), 1);           // not an integer
  EXPECT_EQ(error_line(query_rows(2)), 1);                          // truth not 0/1
  EXPECT_EQ(error_line(query_rows(1) + query_rows(0, "1,2,3,4,5,6,1")), 9);  // 8 fields, line 9
}

TEST(ReadBenchmarkCsv, RejectsTruthChangingWithinAQuery) {
  std::string text = query_rows(1);
  const auto third = text.find('\n', text.find('\n') + 1) + 1;  // start of line 3
  const auto end3 = text.find('\n', third);
  text[end3 - 1] = '0';
  EXPECT_EQ(error_line(text), 3);
}

TEST(ReadBenchmarkCsv, RejectsIncompleteQuery) {
  std::string text = query_rows(0);
  text += "1,1,1,1,1,1,0\n";
  EXPECT_EQ(error_line(text), 9);
}

TEST(WriteBenchmarkCsv, RoundTrips) {
  std::istringstream in(query_rows(1, "-7,3,1,1073741824,5,6") + query_rows(0));
  const BenchmarkQueries q = read_benchmark_csv(in, "x");
  std::ostringstream out;
  write_benchmark_csv(out, q);
  std::istringstream again(out.str());
  const BenchmarkQueries r = read_benchmark_csv(again, "y");
  ASSERT_EQ(r.size(), q.size());
  for (std::size_t i = 0; i < q.size(); ++i) {
    EXPECT_EQ(r.truth[i], q.truth[i]);
    for (int k = 0; k < 8; ++k) {
      EXPECT_EQ(r.rows[i][k].x, q.rows[i][k].x);
      EXPECT_EQ(r.rows[i][k].y, q.rows[i][k].y);
      EXPECT_EQ(r.rows[i][k].z, q.rows[i][k].z);
    }
  }
}

TEST(ExactDouble, AcceptsExactlyTheDoubles) {
  EXPECT_EQ(exact_double(mpq_class(1, 4)), 0.25);
  EXPECT_FALSE(exact_double(mpq_class(1, 10)).has_value());  // 0.1 is not a double
  EXPECT_FALSE(exact_double(mpq_class(1, 3)).has_value());
  const double tiny = std::numeric_limits<double>::denorm_min();  // 2^-1074
  mpq_class q_tiny(1);
  mpq_div_2exp(q_tiny.get_mpq_t(), q_tiny.get_mpq_t(), 1074);
  EXPECT_EQ(exact_double(q_tiny), tiny);
  mpq_class q_tinier(1);
  mpq_div_2exp(q_tinier.get_mpq_t(), q_tinier.get_mpq_t(), 1075);
  EXPECT_FALSE(exact_double(q_tinier).has_value());
  EXPECT_EQ(exact_double(mpq_class(1e300)), 1e300);
  mpq_class huge(1);
  mpq_mul_2exp(huge.get_mpq_t(), huge.get_mpq_t(), 1024);  // 2^1024 overflows
  EXPECT_FALSE(exact_double(huge).has_value());
  EXPECT_EQ(exact_double(mpq_class(-0.0)), 0.0);
}

}  // namespace
}  // namespace exactccd::io
