// The increment predictor (ContactSolverSettings::extrapolate_increments)
// changes where Newton starts, not the equations of an increment: the
// lifted floor must end in the same state with and without it.
#include "lifted_floor_case.h"

#include <gtest/gtest.h>

#include <iostream>

namespace
{
  using namespace FloorBlock;

  TEST(IncrementPredictor, SameEndStateAsStartingFromTheLastIncrement)
  {
    Testing::LiftedFloorCase floor_case;
    floor_case.n_blocks    = 3;
    floor_case.corner_size = 0.1; // m: coarse, the comparison is mesh-independent
    floor_case.extrapolate_increments = false;
    const Testing::LiftedFloorOutcome plain = Testing::run_lifted_floor(floor_case);
    floor_case.extrapolate_increments = true;
    const Testing::LiftedFloorOutcome predicted =
      Testing::run_lifted_floor(floor_case);

    std::cout << "Newton iterations: " << plain.n_newton_iterations
              << " from the last increment, " << predicted.n_newton_iterations
              << " with the predictor" << std::endl;
    ASSERT_EQ(plain.last.joints.size(), predicted.last.joints.size());
    for (unsigned int j = 0; j < plain.last.joints.size(); ++j)
      {
        const Contact::JointReport &a = plain.last.joints[j];
        const Contact::JointReport &b = predicted.last.joints[j];
        SCOPED_TRACE(a.name);
        EXPECT_EQ(a.counts.n_stick, b.counts.n_stick);
        EXPECT_EQ(a.counts.n_slip, b.counts.n_slip);
        EXPECT_EQ(a.counts.n_open, b.counts.n_open);
        // Both runs stop at a relative residual of 1e-10 of the load on the
        // same active set: the forces agree to that order. 1e-7 of the
        // largest joint force leaves room for the conditioning of the
        // joint springs (kn h / E about 1).
        const double scale = 1e-7 * plain.last.joints.back().normal_force;
        EXPECT_NEAR(a.normal_force, b.normal_force, scale);
        EXPECT_NEAR(a.shear_force, b.shear_force, scale);
      }
  }
} // namespace
