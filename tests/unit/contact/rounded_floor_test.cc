// The chapter's default scene with rounded corners: the pairing accepts the
// fillets and the top corner of the face joint closes on its fillet.
#include <gtest/gtest.h>

#include <iostream>

#include "lifted_floor_case.h"

namespace
{
  using namespace FloorBlock;

  TEST(RoundedFloor, DefaultSceneSolvesAndTheFaceJointClosesOnItsFillet)
  {
    Testing::LiftedFloorCase floor_case;
    floor_case.rounding    = 0.01;   // m, 1 % of the block edge
    floor_case.corner_size = 0.0025; // m, r / 4: 8 cells on the fillet
    const Testing::LiftedFloorOutcome outcome =
      Testing::run_lifted_floor(floor_case);
    const Contact::IncrementResult &last = outcome.last;
    EXPECT_EQ(last.stage, Loading::LoadStage::uplift);
    EXPECT_DOUBLE_EQ(last.stage_factor, 1.);
    EXPECT_LT(last.balance.relative_imbalance, 1e-6);

    // Joint n = 6 is the face joint; its fillets start at y_s = H - r.
    const Contact::JointReport &face_joint = last.joints.at(5);
    ASSERT_EQ(face_joint.name, "vertical 6");
    constexpr double block_height       = 2.;
    const double     fillet_start       = block_height - floor_case.rounding;
    unsigned int     n_closed_on_fillet = 0;
    for (const auto &sample : face_joint.profile)
      if (sample.position[1] > fillet_start + 1e-9 &&
          sample.state != Contact::JointState::open)
        {
          ++n_closed_on_fillet;
          EXPECT_GT(sample.normal_traction, 0.);
        }
    std::cout << outcome.n_cells << " cells, " << outcome.n_pairs
              << " pairs; face joint Q = " << face_joint.normal_force
              << " N/m, peak " << face_joint.peak_normal_stress << " Pa at ("
              << face_joint.peak_position << "), " << n_closed_on_fillet
              << " fillet nodes closed" << std::endl;
    EXPECT_GT(n_closed_on_fillet, 0u);
  }
} // namespace
