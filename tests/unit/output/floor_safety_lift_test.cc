// The floor safety factor along the lift (output/floor_safety_lift): the
// governing corner per increment and the lift at which FS reaches 1.

#include <gtest/gtest.h>
#include <output/floor_safety_lift.h>

using namespace FloorBlock;

namespace
{
  Output::LiftHistoryPoint
  increment(const double lift, const double face, const double other,
            const bool face_resolved = true)
  {
    Output::LiftHistoryPoint point;
    point.base_lift      = lift;
    // Point, line and area factors; the verdict goes by the line method's.
    point.corner_factors = {{"face block at vertical 6", face - 0.1, face, face + 0.2, face, "line", face_resolved},
                            {"block 6 at vertical 6", other - 0.1, other, other + 0.2, other, "line", true}};
    return point;
  }
} // namespace

// The governing corner is the resolved one with the smallest verdict
// factor (Safety::verdict_factor()).
TEST(SafetyAlongLift, GoverningCornerIsTheSmallestResolvedOne)
{
  const auto along = Output::safety_along_lift(
    {increment(0.01, 2.0, 3.0), increment(0.02, 1.5, 1.2, false)});
  ASSERT_EQ(along.size(), 2u);
  EXPECT_EQ(along[0].corner, "face block at vertical 6");
  EXPECT_DOUBLE_EQ(along[0].verdict_factor, 2.0);
  EXPECT_DOUBLE_EQ(along[0].area_factor, 2.2);
  EXPECT_EQ(along[1].corner, "block 6 at vertical 6");
}

// FS = 1 (the verdict's method) is found between the increments around it,
// linearly: 1.5 at 20 mm and 0.5 at 30 mm give 25 mm.
TEST(SafetyAlongLift, UnitSafetyIsInterpolatedBetweenIncrements)
{
  const auto along = Output::safety_along_lift({increment(0.01, 2.0, 3.0),
                                                increment(0.02, 1.5, 3.0),
                                                increment(0.03, 0.5, 3.0)});
  const auto lift = Output::lift_at_unit_safety(along);
  ASSERT_TRUE(lift.has_value());
  EXPECT_NEAR(*lift, 0.025, 1e-15);
  EXPECT_NE(Output::unit_safety_text(along).find("25.00 mm"), std::string::npos);
  EXPECT_DOUBLE_EQ(Output::safety_along_lift_json(along)["lift_at_safety_factor_1_m"].get<double>(), *lift);
}

// No crossing: FS above 1 throughout, or below 1 from the first increment
// on (the floor fails before the lift); each says so.
TEST(SafetyAlongLift, NoCrossingIsSaidInWords)
{
  const auto above = Output::safety_along_lift(
    {increment(0.01, 2.0, 3.0), increment(0.02, 1.5, 3.0)});
  EXPECT_FALSE(Output::lift_at_unit_safety(above).has_value());
  EXPECT_NE(Output::unit_safety_text(above).find("stays above 1"), std::string::npos);
  EXPECT_FALSE(Output::safety_along_lift_json(above).contains("lift_at_safety_factor_1_m"));
  const auto below = Output::safety_along_lift(
    {increment(0.01, 0.8, 3.0), increment(0.02, 0.5, 3.0)});
  EXPECT_FALSE(Output::lift_at_unit_safety(below).has_value());
  EXPECT_NE(Output::unit_safety_text(below).find("before the lift"), std::string::npos);
  EXPECT_NE(Output::unit_safety_text({}).find("no increment"), std::string::npos);
}
