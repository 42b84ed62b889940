// Queries that once made the filtered method disagree with the exact one; each must now agree.
#include <gtest/gtest.h>

#include "exactccd/exactccd.hpp"

namespace exactccd {
namespace {

// Folding-sheet edge-edge candidate (two grid edges along y, V with two roots within one ulp).
// The integer stage's interval-first oracle built its interval polynomials outside the FPU
// rounding mode Interval_nt<false> needs: the enclosures were wrong and it reported a
// collision (commit 1324b9d; found by the scene tests).
TEST(Regressions, IntegerStageIntervalsUnderTheRoundingMode) {
  const EdgeEdgeQuery q{{-0x1.fe5ccb12555fep-2, 0x1.8p-2, 0x1.a59ac9c3cb357p-5},
                        {-0x1.fe5ccb12555fep-2, 0x1p-1, 0x1.99219861dd25fp-5},
                        {-0x1.be9131b00ab3ep-1, 0x1.8p-2, 0x1.4bc46674ef33ep-4},
                        {-0x1.be9131b00ab3ep-1, 0x1p-1, 0x1.408a8f1d6696ap-4},
                        {-0x1.ffc505a355cf6p-2, 0x1.8p-2, 0x1.095c26b46ff87p-6},
                        {-0x1.ffc505a355cf6p-2, 0x1p-1, 0x1.0aa5bebf72832p-6},
                        {-0x1.bfcc64eeeb157p-1, 0x1.8p-2, 0x1.5edbf4ce8c4cep-6},
                        {-0x1.bfcc64eeeb157p-1, 0x1p-1, 0x1.81d4433c7f58ep-6}};
  EXPECT_FALSE(edge_edge_ccd(q, Method::exact));
  EXPECT_FALSE(edge_edge_ccd(q, Method::filtered));
  EXPECT_FALSE(edge_edge_toi(q, Method::filtered).has_value());
}

}  // namespace
}  // namespace exactccd
