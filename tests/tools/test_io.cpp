// Tests of the benchmark CSV reader and writer (tools/lib/io/benchmark_csv), and of the truth
// JSON (io/truth_json) and answers (io/answers) readers.
#include "io/benchmark_csv.hpp"
#include "io/truth_json.hpp"
#include "io/answers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
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
  EXPECT_EQ(error_line(query_rows(1, "1,2,3,4,5,6,")), 1);          // trailing comma: 8 fields
  EXPECT_EQ(error_line(query_rows(1, "1,,3,4,5,6")), 1);            // empty field
  EXPECT_EQ(error_line(query_rows(1, "1 2,2,3,4,5,6")), 1);         // space inside a number
  EXPECT_EQ(error_line(query_rows(1, "-,2,3,4,5,6")), 1);           // a sign alone
  EXPECT_EQ(error_line(query_rows(1, "0x1,2,3,4,5,6")), 1);         // not base 10
  EXPECT_EQ(error_line(query_rows(0) + query_rows(1, "1,2,3,4,5,0")), 9);  // zero z denominator
}

TEST(ReadBenchmarkCsv, MessageIsSourceLineReason) {
  std::istringstream in(query_rows(1, "1,0,3,4,5,6"));
  try {
    read_benchmark_csv(in, "dir/a.csv");
    FAIL() << "no ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), "dir/a.csv:1: zero denominator in field 2");
    EXPECT_EQ(e.source(), "dir/a.csv");
    EXPECT_EQ(e.line(), 1u);
  }
}

TEST(ReadBenchmarkCsv, AcceptsSignsSpacesHugeIntegersAndNoFinalNewline) {
  std::string text = query_rows(0, " +3 , -6 ,123456789012345678901234567890,1, -0,7 \t");
  text.pop_back();  // no newline after the last row
  std::istringstream in(text);
  const BenchmarkQueries q = read_benchmark_csv(in, "x");
  ASSERT_EQ(q.size(), 1u);
  EXPECT_EQ(q.rows[0][0].x, mpq_class(-1, 2));
  EXPECT_EQ(q.rows[0][0].y, mpq_class("123456789012345678901234567890"));
  EXPECT_EQ(q.rows[0][0].z, 0);
  EXPECT_FALSE(q.truth[0]);
}

TEST(ReadBenchmarkCsv, RecordsTheLineOfEveryRow) {
  std::istringstream in("\n" + query_rows(1) + "\n" + query_rows(0));
  const BenchmarkQueries q = read_benchmark_csv(in, "x");
  ASSERT_EQ(q.lines.size(), 2u);
  EXPECT_EQ(q.lines[0][0], 2u);
  EXPECT_EQ(q.lines[0][7], 9u);
  EXPECT_EQ(q.lines[1][0], 11u);  // after the blank line 10
}

TEST(ReadBenchmarkCsv, SkipsAUtf8ByteOrderMark) {
  std::istringstream in("\xEF\xBB\xBF" + query_rows(1));
  const BenchmarkQueries q = read_benchmark_csv(in, "x");
  ASSERT_EQ(q.size(), 1u);
  EXPECT_EQ(q.rows[0][0].x, mpq_class(1, 2));
  EXPECT_EQ(error_line("\xEF\xBB" + query_rows(1)), 1);  // an incomplete mark is no mark
}

/// The first row of a query with its x numerator (field 1) or denominator (field 2) set.
std::string with_field(int field, const std::string& value) {
  return query_rows(0, field == 1 ? value + ",1,0,1,0,1" : "1," + value + ",0,1,0,1");
}

TEST(ReadBenchmarkCsv, FieldsUpToTheSizeLimit) {
  // 2^kMaxFieldBits - 1 has kMaxFieldBits bits: accepted, as numerator and denominator, with
  // a sign and leading zeros; 2^kMaxFieldBits has one bit more: refused.
  const mpz_class limit = (mpz_class(1) << kMaxFieldBits) - 1;
  const std::string at = limit.get_str(), over = mpz_class(limit + 1).get_str();
  for (int field : {1, 2}) {
    for (const std::string& v : {at, "-" + at, "000" + at, "+" + at}) {
      std::istringstream in(with_field(field, v));
      const BenchmarkQueries q = read_benchmark_csv(in, "x");
      ASSERT_EQ(q.size(), 1u);
      EXPECT_EQ(abs(field == 1 ? q.rows[0][0].x.get_num() : q.rows[0][0].x.get_den()), limit);
    }
    for (const std::string& v : {over, "-" + over, "00" + over, std::string(100000, '9')}) {
      std::istringstream in(with_field(field, v));
      try {
        read_benchmark_csv(in, "big.csv");
        ADD_FAILURE() << "accepted a field of " << v.size() << " characters";
      } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 1u);
        EXPECT_NE(std::string(e.what()).find("big.csv:1: field " + std::to_string(field) + " has "),
                  std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("more than the limit of 4096 bits"), std::string::npos) << e.what();
      }
    }
  }
  // Every double fits: the largest numerator (DBL_MAX) and denominator (2^-1074).
  const mpq_class largest(std::numeric_limits<double>::max()), smallest(std::numeric_limits<double>::denorm_min());
  std::istringstream in(query_rows(0, largest.get_num().get_str() + ",1," + smallest.get_num().get_str() + "," +
                                          smallest.get_den().get_str() + ",0,1"));
  EXPECT_EQ(read_benchmark_csv(in, "x").size(), 1u);
}

TEST(ReadBenchmarkCsv, EmptyInputHasNoQueries) {
  std::istringstream in("\n\r\n");
  EXPECT_EQ(read_benchmark_csv(in, "x").size(), 0u);
}

TEST(ReadBenchmarkCsv, RejectsTruthChangingWithinAQuery) {
  std::string text = query_rows(1);
  const auto third = text.find('\n', text.find('\n') + 1) + 1;  // start of line 3
  const auto end3 = text.find('\n', third);
  text[end3 - 1] = '0';
  EXPECT_EQ(error_line(text), 3);
}

TEST(ReadBenchmarkCsv, RejectsTruthChangingOnTheLastRow) {
  std::string text = query_rows(0) + query_rows(1);
  text[text.size() - 2] = '0';  // line 16
  EXPECT_EQ(error_line(text), 16);
}

TEST(ReadBenchmarkCsv, RejectsIncompleteQueryNamingItsLastRow) {
  std::string text = query_rows(0);
  text += "1,1,1,1,1,1,0\n";
  EXPECT_EQ(error_line(text), 9);
  EXPECT_EQ(error_line(text + "\n\n"), 9);  // trailing blank lines do not move the error
  std::string three_rows = query_rows(1);
  three_rows.resize(three_rows.find('\n', three_rows.find('\n', three_rows.find('\n') + 1) + 1));
  EXPECT_EQ(error_line(three_rows), 3);
}

TEST(ReadBenchmarkCsv, SixColumnsWithoutTruthColumn) {
  // The Scalable CCD dataset's query files: ", " separators, no truth column.
  std::string text;
  for (int i = 0; i < 16; ++i) text += std::to_string(i) + ", 4, -3, 8, 0, 1\n";
  std::istringstream peek(text);
  EXPECT_EQ(first_row_columns(peek), 6);
  std::istringstream in(text);
  const BenchmarkQueries q = read_benchmark_csv(in, "227vf.csv", {8, 3, false});
  ASSERT_EQ(q.size(), 2u);
  EXPECT_EQ(q.truth, (std::vector<bool>{false, false}));
  EXPECT_EQ(q.rows[1][2].x, mpq_class(5, 2));  // row 10: 10/4, canonicalized
  EXPECT_EQ(q.rows[0][0].y, mpq_class(-3, 8));
  // A truth column where none is expected is a wrong field count, and the other way round.
  std::istringstream seven(query_rows(1));
  EXPECT_THROW(read_benchmark_csv(seven, "x.csv", {8, 3, false}), ParseError);
  std::istringstream six(text);
  EXPECT_THROW(read_benchmark_csv(six, "x.csv"), ParseError);
  // Written back without a truth column.
  std::stringstream out;
  write_benchmark_csv(out, q);
  EXPECT_EQ(out.str().substr(0, out.str().find('\n')), "0,1,-3,8,0,1");
  const BenchmarkQueries back = read_benchmark_csv(out, "back.csv", {8, 3, false});
  ASSERT_EQ(back.size(), q.size());
  for (std::size_t i = 0; i < q.size(); ++i)
    for (std::size_t k = 0; k < 8; ++k) {
      EXPECT_EQ(back.rows[i][k].x, q.rows[i][k].x);
      EXPECT_EQ(back.rows[i][k].y, q.rows[i][k].y);
      EXPECT_EQ(back.rows[i][k].z, q.rows[i][k].z);
    }
  std::istringstream blank("\n  \n");
  EXPECT_EQ(first_row_columns(blank), 0);
}

std::string truth_error(const std::string& text) {
  std::istringstream in(text);
  try {
    read_truth_json(in, "t.json");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

TEST(TruthJson, ReadsArraysOfBooleansStrictly) {
  std::istringstream in("\xEF\xBB\xBF [true,false,\r\n  true ]\n");
  EXPECT_EQ(read_truth_json(in, "t.json"), (std::vector<bool>{true, false, true}));
  std::istringstream empty("[]");
  EXPECT_TRUE(read_truth_json(empty, "t.json").empty());
  EXPECT_EQ(truth_error(""), "t.json:1: expected a JSON array of booleans ('['), found the end of the input");
  EXPECT_EQ(truth_error("[true,\n1]"), "t.json:2: value 2 is not true or false: found '1'");
  EXPECT_EQ(truth_error("[true,\n\nnull]"), "t.json:3: value 2 is not true or false: found 'null'");
  EXPECT_EQ(truth_error("[true false]"), "t.json:1: expected ',' or ']' after value 1, found 'false'");
  EXPECT_EQ(truth_error("[true,]"), "t.json:1: value 2 is not true or false: found ']'");
  EXPECT_EQ(truth_error("[true"), "t.json:1: expected ',' or ']' after value 1, found the end of the input");
  EXPECT_EQ(truth_error("[true]\n[false]"), "t.json:2: data after the array: '['");
  EXPECT_EQ(truth_error("[[true]]"), "t.json:1: value 1 is not true or false: found '['");
  EXPECT_EQ(truth_error("[trueish]"), "t.json:1: expected ',' or ']' after value 1, found 'ish'");
}

// Found by the reader fuzz target (fuzz/readers/fuzz_read_truth_json.cpp): an error at the end
// of an input ending in a line break named the line after the last ("[true \n": line 2).
TEST(TruthJson, AnErrorAtTheEndNamesTheLastLine) {
  EXPECT_EQ(truth_error("[true \n"), "t.json:1: expected ',' or ']' after value 1, found the end of the input");
  EXPECT_EQ(truth_error("[true,\nfalse\n\n"), "t.json:3: expected ',' or ']' after value 2, found the end of the input");
  EXPECT_EQ(truth_error("\n"), "t.json:1: expected a JSON array of booleans ('['), found the end of the input");
}

std::string answers_error(const std::string& text, bool with_toi) {
  std::istringstream in(text);
  try {
    read_answers(in, "theirs.txt", with_toi);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

// `compare`'s answers (moved from tools/exactccd/compare.cpp into io/answers for the fuzz
// target). Found by it: a time of impact outside [0, 1] was accepted (and a negative one
// counted as a safe TOI), though the query's interval is [0, tmax], tmax <= 1.
TEST(TheirAnswers, ReadsAnswersAndTimesOfImpactInTheQueryInterval) {
  std::istringstream in("\xEF\xBB\xBF" "1 0.5\n\n0\n 1   1e-300 \r\n1 1\n1 -0\n");
  const std::vector<TheirAnswer> a = read_answers(in, "theirs.txt", true);
  ASSERT_EQ(a.size(), 5u);
  EXPECT_EQ(*a[0].toi, 0.5);
  EXPECT_FALSE(a[1].collides);
  EXPECT_FALSE(a[1].toi);
  EXPECT_EQ(*a[2].toi, 1e-300);
  EXPECT_EQ(*a[3].toi, 1.0);
  EXPECT_EQ(*a[4].toi, 0.0);
  EXPECT_EQ(answers_error("0\n1 1.37\n", true), "theirs.txt:2: the time of impact '1.37' is not in [0, 1]");
  EXPECT_EQ(answers_error("1 -0.25\n", true), "theirs.txt:1: the time of impact '-0.25' is not in [0, 1]");
  EXPECT_EQ(answers_error("1 nan\n", true), "theirs.txt:1: the time of impact 'nan' is not a finite number");
  EXPECT_EQ(answers_error("1 0.5\n", false), "theirs.txt:1: expected 0 or 1, found 2 fields");
  EXPECT_EQ(answers_error("1\n", true), "theirs.txt:1: expected 0, or 1 and a time of impact, found 1 fields");
  std::stringstream written;
  write_answers(written, a);
  const std::vector<TheirAnswer> back = read_answers(written, "written.txt", true);
  ASSERT_EQ(back.size(), a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(back[i].collides, a[i].collides);
    EXPECT_EQ(back[i].toi, a[i].toi);
  }
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

TEST(WriteBenchmarkCsv, WritesCanonicalNumeratorDenominator) {
  std::istringstream in(query_rows(1, "2,4,-6,-8,0,-5"));
  std::ostringstream out;
  write_benchmark_csv(out, read_benchmark_csv(in, "x"));
  EXPECT_EQ(out.str().substr(0, out.str().find('\n')), "1,2,3,4,0,1,1");
}

TEST(WriteBenchmarkCsv, RejectsTruthOfAnotherSize) {
  BenchmarkQueries q;
  q.rows.resize(2);
  q.truth = {true};
  std::ostringstream out;
  EXPECT_THROW(write_benchmark_csv(out, q), std::invalid_argument);
}

TEST(QueryHelpers, KeepTheBenchmarkRowOrder) {
  std::string text;
  for (int i = 0; i < 8; ++i) text += std::to_string(i) + ",1,0,1,0,1,0\n";
  std::istringstream in(text);
  const BenchmarkQueries q = read_benchmark_csv(in, "x");
  const RationalVertexFaceQuery vf = vertex_face_query(q, 0);
  EXPECT_EQ(vf.p_t0.x, 0);
  EXPECT_EQ(vf.c_t0.x, 3);
  EXPECT_EQ(vf.p_t1.x, 4);
  EXPECT_EQ(vf.c_t1.x, 7);
  const RationalEdgeEdgeQuery ee = edge_edge_query(q, 0);
  EXPECT_EQ(ee.b0_t0.x, 2);
  EXPECT_EQ(ee.a1_t1.x, 5);
  EXPECT_EQ(ee.b1_t1.x, 7);
  EXPECT_THROW(vertex_face_query(q, 1), std::out_of_range);
}

mpq_class pow2(int e) {
  mpq_class q(1);
  if (e >= 0)
    mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
  else
    mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
  return q;
}

/// True iff the last bit of d's significand is 0 (the raw encoding's lowest bit).
bool has_even_significand(double d) {
  std::uint64_t bits;
  std::memcpy(&bits, &d, sizeof bits);
  return (bits & 1) == 0;
}

/// True iff d is the double nearest to x with ties to even (d finite), checked exactly against
/// both neighbouring doubles.
::testing::AssertionResult is_nearest(const mpq_class& x, double d) {
  if (!std::isfinite(d)) return ::testing::AssertionFailure() << "not finite: " << d;
  const mpq_class err = abs(x - mpq_class(d));
  for (double n : {std::nextafter(d, -HUGE_VAL), std::nextafter(d, HUGE_VAL)}) {
    if (!std::isfinite(n)) continue;
    const mpq_class other = abs(x - mpq_class(n));
    if (other < err || (other == err && !has_even_significand(d)))
      return ::testing::AssertionFailure() << x.get_str() << " -> " << d << ", but " << n << " is nearer";
  }
  return ::testing::AssertionSuccess();
}

TEST(NearestDouble, RoundsToNearestTiesToEven) {
  EXPECT_EQ(nearest_double(mpq_class(1, 10)), 0.1);
  EXPECT_EQ(nearest_double(mpq_class(-1, 3)), -1.0 / 3.0);
  EXPECT_EQ(nearest_double(mpq_class(2, 3)), 2.0 / 3.0);
  EXPECT_EQ(nearest_double(1 + pow2(-53)), 1.0);                             // tie, to even
  EXPECT_EQ(nearest_double(1 + 3 * pow2(-53)), 1.0 + std::ldexp(1.0, -51));  // tie, to even
  EXPECT_EQ(nearest_double(1 + pow2(-53) + pow2(-200)), std::nextafter(1.0, 2.0));
  EXPECT_EQ(nearest_double(mpq_class(0)), 0.0);
  EXPECT_FALSE(std::signbit(nearest_double(mpq_class(0))));
}

TEST(NearestDouble, SubnormalsAndUnderflow) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(nearest_double(pow2(-1074)), tiny);
  EXPECT_EQ(nearest_double(pow2(-1075)), 0.0);                 // tie between 0 and 2^-1074
  EXPECT_EQ(nearest_double(pow2(-1075) + pow2(-2000)), tiny);  // just above the tie
  EXPECT_EQ(nearest_double(3 * pow2(-1075)), 2 * tiny);        // tie, to even
  EXPECT_EQ(nearest_double(-pow2(-1076)), 0.0);
  EXPECT_TRUE(std::signbit(nearest_double(-pow2(-1076))));     // IEEE: -0 for a negative x
  EXPECT_EQ(nearest_double(mpq_class(1, 3) * pow2(-1030)), std::ldexp(1.0 / 3.0, -1030));
  const double min_normal = std::numeric_limits<double>::min();
  EXPECT_EQ(nearest_double(pow2(-1022) - pow2(-1076)), min_normal);  // rounds up into normals
}

TEST(NearestDouble, OverflowAndHugeValues) {
  const double max = std::numeric_limits<double>::max();
  const mpq_class q_max(max);
  const mpq_class half_ulp = pow2(970);  // the ulp of DBL_MAX is 2^971
  EXPECT_EQ(nearest_double(q_max), max);
  EXPECT_EQ(nearest_double(q_max + half_ulp - pow2(-10)), max);
  EXPECT_EQ(nearest_double(q_max + half_ulp), HUGE_VAL);  // the tie goes to even: 2^1024
  EXPECT_EQ(nearest_double(-pow2(5000)), -HUGE_VAL);
  EXPECT_EQ(nearest_double(mpq_class(1e300)), 1e300);
  EXPECT_EQ(nearest_double(mpq_class(7) * pow2(1000) / 3), std::ldexp(7.0 / 3.0, 1000));
}

TEST(NearestDouble, IsNearestOnPseudoRandomRationals) {
  std::mt19937_64 gen(20240601);
  std::uniform_int_distribution<int> shift(-1100, 1030);
  for (int i = 0; i < 3000; ++i) {
    mpz_class num, den;
    mpz_set_ui(num.get_mpz_t(), static_cast<unsigned long>(gen() >> 1));
    num = num * static_cast<unsigned long>(gen() >> 11) + static_cast<unsigned long>(i);
    den = mpz_class(static_cast<unsigned long>(gen() >> (i % 60))) + 1;
    mpq_class x(num, den);
    x.canonicalize();
    x *= pow2(shift(gen) - 60);
    if (i % 2) x = -x;
    const double d = nearest_double(x);
    if (std::isinf(d)) {
      EXPECT_GE(abs(x), mpq_class(std::numeric_limits<double>::max()) + pow2(970)) << x.get_str();
      continue;
    }
    ASSERT_TRUE(is_nearest(x, d)) << "i = " << i;
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
  EXPECT_FALSE(std::signbit(*exact_double(mpq_class(-0.0))));  // a rational zero has no sign
  EXPECT_EQ(exact_double(-mpq_class(1e300)), -1e300);
  EXPECT_EQ(exact_double(-q_tiny), -tiny);
  EXPECT_EQ(exact_double(mpq_class(3) * q_tinier), std::nullopt);      // 1.5 * 2^-1074
  const double max_subnormal = std::numeric_limits<double>::min() - tiny;  // 52 one bits
  EXPECT_EQ(exact_double(mpq_class(max_subnormal)), max_subnormal);
  EXPECT_EQ(exact_double(mpq_class(std::numeric_limits<double>::max())),
            std::numeric_limits<double>::max());
  EXPECT_EQ(exact_double(pow2(1024) - pow2(970)), std::nullopt);  // between DBL_MAX and 2^1024
  EXPECT_EQ(exact_double(pow2(53) + 1), std::nullopt);             // 54 significant bits
  EXPECT_EQ(exact_double(pow2(53) + 2), 9007199254740994.0);
  EXPECT_EQ(exact_double(mpq_class(1, 10)), std::nullopt);
}

TEST(ExactDouble, RoundTripsEveryDoubleItTries) {
  std::mt19937_64 gen(7);
  for (int i = 0; i < 3000; ++i) {
    std::uint64_t bits = gen();
    double d;
    static_assert(sizeof d == sizeof bits);
    std::memcpy(&d, &bits, sizeof d);
    if (!std::isfinite(d)) continue;
    const auto back = exact_double(mpq_class(d));
    ASSERT_TRUE(back.has_value()) << d;
    EXPECT_EQ(*back, d);
    EXPECT_EQ(nearest_double(mpq_class(d)), d);
  }
}

}  // namespace
}  // namespace exactccd::io
