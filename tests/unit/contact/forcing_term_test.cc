// The inexact-Newton forcing term (Eisenstat-Walker choice 2 with its
// safeguards), value by value from its definition.
#include <contact/forcing_term.h>

#include <gtest/gtest.h>

namespace
{
  using namespace FloorBlock::Contact;

  constexpr double no_stop = 0.; // a stop residual that never binds

  TEST(ForcingTerm, FirstSolveOfALoadStateAsksForTheTightTerm)
  {
    const ForcingSettings settings;
    EXPECT_DOUBLE_EQ(forcing_term(settings, 1., 0., 0., no_stop),
                     settings.first);
    EXPECT_LT(settings.first, settings.maximum);
    // Still never tighter than the Newton stop needs: half of a stop
    // residual 1e-6 is 5e-7 of |R| = 1.
    EXPECT_NEAR(forcing_term(settings, 1., 0., 0., 1e-6), 5e-7, 1e-20);
  }

  TEST(ForcingTerm, FastConvergenceTightensAsTheSquaredRatio)
  {
    const ForcingSettings settings;
    // |R| fell by 100: eta = 0.9 (1e-2)^2 = 9e-5; the safeguard
    // 0.9 eta_prev^2 = 9e-5 (eta_prev = 1e-2) is below 0.1 and so inactive.
    EXPECT_NEAR(forcing_term(settings, 1e-2, 1., 1e-2, no_stop), 0.9e-4, 1e-18);
  }

  TEST(ForcingTerm, SlowConvergenceIsCappedAtTheMaximum)
  {
    const ForcingSettings settings;
    // An active-set change: the residual barely fell.
    EXPECT_DOUBLE_EQ(forcing_term(settings, 0.99, 1., 1e-4, no_stop),
                     settings.maximum);
  }

  TEST(ForcingTerm, SafeguardKeepsALooseSolveFromTighteningAtOnce)
  {
    ForcingSettings settings;
    settings.maximum = 0.9;
    // eta_prev = 0.5: 0.9 * 0.25 = 0.225 > 0.1, so a lucky 1000-fold drop
    // (ratio term 9e-7) still gets eta = 0.225.
    EXPECT_NEAR(forcing_term(settings, 1e-3, 1., 0.5, no_stop), 0.225, 1e-15);
  }

  TEST(ForcingTerm, NeverSolvesTighterThanTheNewtonStopNeeds)
  {
    const ForcingSettings settings;
    // |R| = 1e-6, Newton stops at 1e-9: half of that is 5e-4 of |R|,
    // looser than the squared-ratio term 9e-9.
    EXPECT_NEAR(forcing_term(settings, 1e-6, 1e-2, 1e-2, 1e-9), 5e-4, 1e-16);
    // ... but never looser than the maximum.
    EXPECT_DOUBLE_EQ(forcing_term(settings, 1e-9, 1e-6, 1e-2, 1e-9),
                     settings.maximum);
  }
} // namespace
