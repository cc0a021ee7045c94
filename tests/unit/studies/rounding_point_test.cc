#include <gtest/gtest.h>
#include <studies/corner_zoom.h>
#include <studies/rounding_study.h>

namespace
{
  using namespace FloorBlock;

  std::vector<Studies::ZoomLevel>
  levels_with_peaks(const std::vector<double> &peaks)
  {
    std::vector<Studies::ZoomLevel> levels;
    for (const double peak : peaks)
      {
        Studies::ZoomLevel level;
        level.level                      = levels.size();
        level.profile.peak_traction      = peak;
        level.profile.edge_beyond_corner = 4e-4;
        level.requested_size             = 4e-6;
        level.wall_time                  = 2.;
        levels.push_back(level);
      }
    return levels;
  }
} // namespace

TEST(RoundingPoint, ConvergedNeedsTwoSmallChangesInARow)
{
  // 3.00 -> 3.09 (3 %), -> 3.10 (0.3 %), -> 3.105 (0.2 %).
  const auto point =
    Studies::rounding_point(0.01,
                            levels_with_peaks({3e8, 3.09e8, 3.10e8, 3.105e8}),
                            0.01);
  EXPECT_TRUE(point.converged);
  EXPECT_EQ(point.n_levels, 4u);
  EXPECT_DOUBLE_EQ(point.peak, 3.105e8);
  EXPECT_NEAR(point.last_change, 0.005 / 3.10, 1e-12);
  EXPECT_DOUBLE_EQ(point.wall_time, 8.);

  const auto once =
    Studies::rounding_point(0.01,
                            levels_with_peaks({3e8, 3.2e8, 3.201e8}),
                            0.01);
  EXPECT_FALSE(once.converged);
}

TEST(RoundingPoint, ACoarseFilletContactIsNotConvergedYet)
{
  auto levels = levels_with_peaks({3e8, 3.09e8, 3.10e8, 3.105e8});
  levels.back().requested_size = 5e-6; // 80 cells over the 0.4 mm reach
  EXPECT_FALSE(Studies::rounding_point(0.01, levels, 0.01).converged);
}

// The zoom and the rounding study share this rule: the last two changes,
// not any two, and never from fewer than three levels.
TEST(PeakSettled, TheLastTwoChangesMustBothBeSmall)
{
  EXPECT_TRUE(
    Studies::peak_settled(levels_with_peaks({3e8, 3.1e8, 3.101e8, 3.102e8}),
                          0.01));
  // Small then large: a calm pair earlier does not count.
  EXPECT_FALSE(
    Studies::peak_settled(levels_with_peaks({3e8, 3.001e8, 3.002e8, 3.2e8}),
                          0.01));
  EXPECT_FALSE(Studies::peak_settled(levels_with_peaks({3e8, 3.001e8}), 0.01));
  // A zero peak before is a change of 1, not a division by zero.
  EXPECT_DOUBLE_EQ(Studies::peak_change(levels_with_peaks({0., 3e8}), 1), 1.);
}
