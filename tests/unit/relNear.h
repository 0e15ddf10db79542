// Relative-tolerance comparison for the correlation unit tests.
#ifndef foamDEM_tests_unit_relNear_h
#define foamDEM_tests_unit_relNear_h

#include <gtest/gtest.h>

#include <cmath>

namespace foamDEMTest
{

inline ::testing::AssertionResult relNear
(
    const char* actualExpr,
    const char* expectedExpr,
    const char* /*tolExpr*/,
    double actual,
    double expected,
    double relTol
)
{
    if (std::isfinite(actual) && std::isfinite(expected)
     && std::fabs(actual - expected) <= relTol*std::fabs(expected))
    {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure()
        << actualExpr << " = " << ::testing::PrintToString(actual)
        << " differs from " << expectedExpr << " = "
        << ::testing::PrintToString(expected) << " by relative "
        << std::fabs(actual - expected)/std::fabs(expected)
        << " > " << relTol;
}

} // namespace foamDEMTest

#define EXPECT_REL(actual, expected, relTol) \
    EXPECT_PRED_FORMAT3(::foamDEMTest::relNear, actual, expected, relTol)

#endif
