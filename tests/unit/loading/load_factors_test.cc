#include <loading/load_factors.h>

#include <gtest/gtest.h>

namespace FloorBlock::Loading
{
  namespace
  {
    void
    expect_factors(const LoadFactors &factors,
                   const double       gravity,
                   const double       support,
                   const double       uplift)
    {
      EXPECT_EQ(factors.gravity, gravity);
      EXPECT_EQ(factors.support, support);
      EXPECT_EQ(factors.uplift, uplift);
    }
  } // namespace

  // The tool shall apply each stage's load on top of the completed earlier
  // stages.
  TEST(StageFactors, EarlierStagesAreComplete)
  {
    expect_factors(stage_factors(LoadStage::gravity, 0.25, false),
                   0.25,
                   0.,
                   0.);
    expect_factors(stage_factors(LoadStage::support_pressure, 0.5, false),
                   1.,
                   0.5,
                   0.);
    expect_factors(stage_factors(LoadStage::uplift, 0.75, false), 1., 1., 0.75);
  }

  // The tool shall raise gravity with the support load when asked to.
  TEST(StageFactors, GravityRisesWithSupportLoad)
  {
    expect_factors(stage_factors(LoadStage::support_pressure, 0.5, true),
                   0.5,
                   0.5,
                   0.);
    expect_factors(stage_factors(LoadStage::uplift, 0.5, true), 1., 1., 0.5);
  }

  TEST(StageName, OneSpellingPerStage)
  {
    EXPECT_STREQ(stage_name(LoadStage::gravity), "gravity");
    EXPECT_STREQ(stage_name(LoadStage::support_pressure), "support load");
    EXPECT_STREQ(stage_name(LoadStage::uplift), "uplift");
  }
} // namespace FloorBlock::Loading
