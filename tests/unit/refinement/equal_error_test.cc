// Equal-error comparison of two synthetic ladders with known values,
// DoFs and costs: which level each reaches the target at, and the ratios.
#include <gtest/gtest.h>
#include <refinement/equal_error.h>

namespace
{
  using namespace FloorBlock::Refinement;

  Quantity
  length()
  {
    return {"contact_length_face", "m", [](const LevelRecord &record) {
              return record.face_contact_length;
            }};
  }

  /** Levels with the given values, DoFs and cost wall times. */
  Ladder
  ladder(const std::string               &mode,
         const std::vector<double>       &values,
         const std::vector<unsigned int> &dofs,
         const std::vector<double>       &costs)
  {
    Ladder result;
    result.mode = mode;
    for (std::size_t level = 0; level < values.size(); ++level)
      {
        LevelRecord record;
        record.mode                = mode;
        record.level               = level;
        record.status              = "converged";
        record.face_contact_length = values[level];
        record.n_dofs              = dofs[level];
        record.cost_wall_time      = costs[level];
        result.levels.push_back(record);
      }
    estimate_ladder_errors(result, {length()});
    return result;
  }

  /** Uniform: DoFs x4 and cost x4 per level. */
  Ladder
  uniform_ladder(const std::vector<double> &values)
  {
    return ladder("uniform",
                  values,
                  {1000, 4000, 16000, 64000},
                  {1., 4., 16., 64.});
  }

  /**
   * Adaptive: finest-difference estimates 0.2, 0.008, 0.009, - -> within
   * 1 % from level 1 (2000 DoFs, cost 3).
   */
  Ladder
  adaptive_ladder()
  {
    return ladder("adaptive",
                  {1.2, 0.992, 1.009, 1.0},
                  {1000, 2000, 3000, 4000},
                  {1., 3., 6., 10.});
  }

  TEST(EqualError, LevelsAndRatiosAtTheTarget)
  {
    // Oscillating values: finest-difference estimates relative to the last.
    // Uniform: |q - 1|/1 = 0.1, 0.05, 0.005, - -> within 1 % from level 2.
    const Ladder uniform  = uniform_ladder({1.1, 0.95, 1.005, 1.0});
    const Ladder adaptive = adaptive_ladder();
    const auto   comparison =
      compare_at_equal_error(uniform, adaptive, length(), 0, 0.01);
    ASSERT_TRUE(comparison.uniform_level && comparison.adaptive_level);
    EXPECT_EQ(*comparison.uniform_level, 2u);
    EXPECT_EQ(*comparison.adaptive_level, 1u);
    EXPECT_DOUBLE_EQ(*comparison.dofs_ratio, 2000. / 16000.);
    EXPECT_DOUBLE_EQ(*comparison.cost_ratio, 3. / 16.);
    EXPECT_FALSE(comparison.ratios_are_upper_bounds);
    EXPECT_DOUBLE_EQ(*comparison.reference_difference, 0.);
  }

  TEST(EqualError, UniformNeverReachingGivesUpperBounds)
  {
    // Uniform estimates 0.1, 0.05, 0.03: never within 1 %.
    const Ladder uniform  = uniform_ladder({1.1, 0.95, 1.03, 1.0});
    const Ladder adaptive = adaptive_ladder();
    const auto   comparison =
      compare_at_equal_error(uniform, adaptive, length(), 0, 0.01);
    EXPECT_FALSE(comparison.uniform_level);
    ASSERT_TRUE(comparison.dofs_ratio && comparison.cost_ratio);
    EXPECT_TRUE(comparison.ratios_are_upper_bounds);
    // Against the finest uniform level, which is not enough.
    EXPECT_DOUBLE_EQ(*comparison.dofs_ratio, 2000. / 64000.);
    EXPECT_DOUBLE_EQ(*comparison.cost_ratio, 3. / 64.);
  }

  TEST(EqualError, ANonConvergedLevelBreaksTheRun)
  {
    Ladder adaptive           = adaptive_ladder();
    adaptive.levels[2].status = "not converged";
    estimate_ladder_errors(adaptive, {length()});
    const Ladder uniform = uniform_ladder({1.1, 0.95, 1.005, 1.0});
    const auto   comparison =
      compare_at_equal_error(uniform, adaptive, length(), 0, 0.01);
    // Level 3 is the reference of the finest difference (no estimate of
    // its own), level 2 failed: nothing is credited.
    EXPECT_FALSE(comparison.adaptive_level);
    EXPECT_FALSE(comparison.dofs_ratio);
  }
} // namespace
