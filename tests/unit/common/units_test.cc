#include <common/units.h>

#include <gtest/gtest.h>

using namespace FloorBlock::Units;

// The tool shall convert the chapter's tonnes-force with standard gravity.
TEST(Units, TonnesForceUseStandardGravity)
{
  EXPECT_DOUBLE_EQ(tonnes_force_to_newtons(1.0), 9806.65);
  EXPECT_DOUBLE_EQ(tonnes_force_to_newtons(650.0), 650.0 * 9806.65);
}

// The tool shall convert degrees and radians both ways without drift.
TEST(Units, DegreesRoundTrip)
{
  EXPECT_DOUBLE_EQ(degrees_to_radians(180.0), pi);
  EXPECT_NEAR(radians_to_degrees(degrees_to_radians(37.5)), 37.5, 1e-13);
}
