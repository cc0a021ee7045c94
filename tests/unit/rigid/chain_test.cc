// A chain of blocks on a planar bed, the base translated along the dip
// towards the face, against the closed form of slip along all fractures
// without rotation (Analytic::slip_no_rotation, eqs. 6.1-6.13).
//
// The closed form assumes every joint at its Coulomb limit: the bedding
// with N tan(phi_h) (blocks slide up-dip relative to the bed) and every
// vertical joint with Q tan(phi_v) (block i moves up relative to block
// i+1). Translating the base drags every block by the same amount, so the
// bedding slips everywhere but neighbouring blocks do not move against
// each other: the vertical joints are loaded only by the elastic
// differences between blocks, not necessarily up to the friction limit. The
// chain is therefore compared in two steps:
//  - phi_v = 0: both models carry no vertical shear and the force balance
//    of every block is the same set of equations; only moments differ
//    (where N acts), which do not enter Q. Agreement to the Newton
//    tolerance is expected.
//  - phi_v > 0: the joints far from the face reach their limit through the
//    elastic differences of the bedding compression, those near the face
//    do not. Q_j must match the closed form up to the first joint below
//    its limit, and the remaining difference must be exactly the missing
//    vertical shear.

#include <analytic/slip_no_rotation.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "scene_fixture.h"

namespace FloorBlock::RigidBlocks
{
  namespace
  {
    constexpr unsigned int n_blocks        = 6;
    constexpr double       dip_degrees     = 5.;
    constexpr double       bedding_degrees = 10.;
    /** Base travel towards the face, far beyond elastic displacements (m). */
    constexpr double base_travel = 0.01;

    ModelDescription
    dragged_chain(const double vertical_degrees)
    {
      ModelDescription description =
        Testing::planar_scene(n_blocks,
                              Testing::radians(dip_degrees),
                              Testing::radians(bedding_degrees),
                              Testing::radians(vertical_degrees));
      description.uplift.mode      = Contact::UpliftMotion::dip_translation;
      description.uplift.dip_angle = Testing::radians(dip_degrees);
      // Negative magnitude: down the dip, towards the face.
      description.uplift.magnitude = -base_travel;
      description.steps            = {1, 0, 4};
      return description;
    }

    Analytic::ChainForces
    closed_form(const ModelDescription &description,
                const double            vertical_degrees)
    {
      const Geometry::AssemblyDescription &geometry = description.assembly;
      return Analytic::slip_no_rotation(
        Analytic::uniform_chain(n_blocks,
                                description.density * description.gravity *
                                  geometry.block_width * geometry.block_height,
                                0.,
                                Testing::radians(dip_degrees),
                                geometry.block_width,
                                geometry.block_height,
                                Testing::radians(bedding_degrees),
                                Testing::radians(vertical_degrees)));
    }
  } // namespace

  TEST(RigidChain, FrictionlessVerticalJointsMatchSlipNoRotation)
  {
    const ModelDescription description = dragged_chain(0.);
    const RigidSolveResult result      = Model(description).solve();
    ASSERT_EQ(result.status, SolveStatus::converged) << result.message;
    const IncrementReport      &last      = result.increments.back();
    const Analytic::ChainForces reference = closed_form(description, 0.);
    ASSERT_EQ(reference.status, Analytic::Status::ok);
    for (unsigned int number = 1; number <= n_blocks; ++number)
      {
        SCOPED_TRACE(number);
        const RigidJointReport &bedding =
          Testing::find_joint(last, JointKind::bedding, number);
        // Every closed bedding point is at the Coulomb limit...
        EXPECT_EQ(bedding.counts.n_stick, 0u);
        // ... so Q_j follows from force balance alone. The Newton residual
        // is below 1e-12 of the first residual of an uplift increment (at
        // most kn x travel / 4 x L = 2e7 N/m here, against Q of 1e5 N/m),
        // so 1e-9 relative covers it with margin.
        EXPECT_NEAR(
          Testing::find_joint(last, JointKind::vertical, number).normal_force /
            reference.lateral_force[number - 1],
          1.,
          1e-9);
      }
    std::printf(
      "  phi_v = 0: Q_n rigid %.6e N/m, slip_no_rotation %.6e N/m\n",
      Testing::find_joint(last, JointKind::vertical, n_blocks).normal_force,
      reference.lateral_force.back());
  }

  TEST(RigidChain, ClosedFormHoldsWhereVerticalJointsReachTheirLimit)
  {
    constexpr double       vertical_degrees = 10.;
    const ModelDescription description      = dragged_chain(vertical_degrees);
    const RigidSolveResult result           = Model(description).solve();
    ASSERT_EQ(result.status, SolveStatus::converged) << result.message;
    const IncrementReport      &last = result.increments.back();
    const Analytic::ChainForces reference =
      closed_form(description, vertical_degrees);
    ASSERT_EQ(reference.status, Analytic::Status::ok);
    const double friction = std::tan(Testing::radians(vertical_degrees));

    // Q_j of the closed form needs joints 1..j at their Coulomb limit,
    // V = Q tan(phi_v). No point can exceed its limit, so V at the limit
    // means every closed point is on it (some are reported stick: their
    // trial shear equals the limit to round-off). Where that holds the
    // rigid model must agree to the Newton tolerance (1e-9 as above).
    bool chain_at_limit = true;
    for (unsigned int number = 1; number <= n_blocks; ++number)
      {
        SCOPED_TRACE(number);
        const RigidJointReport &joint =
          Testing::find_joint(last, JointKind::vertical, number);
        const double limit = friction * joint.normal_force;
        const bool   at_limit =
          std::abs(joint.shear_force - limit) <= 1e-9 * limit;
        chain_at_limit = chain_at_limit && at_limit;
        if (chain_at_limit)
          {
            EXPECT_NEAR(joint.normal_force /
                          reference.lateral_force[number - 1],
                        1.,
                        1e-9);
          }
        std::printf("    joint %u: Q %.5e N/m, closed form %.5e N/m "
                    "(%+.2f %%), V %.4e N/m, limit %.4e N/m, "
                    "stick/slip/open %u/%u/%u\n",
                    number,
                    joint.normal_force,
                    reference.lateral_force[number - 1],
                    100. * (joint.normal_force /
                              reference.lateral_force[number - 1] -
                            1.),
                    joint.shear_force,
                    limit,
                    joint.counts.n_stick,
                    joint.counts.n_slip,
                    joint.counts.n_open);
      }
    // The assumption that fails here: uniform base travel moves all blocks
    // alike, so near the face the vertical joints only see the elastic
    // differences of the bedding compression and stay below their limit.
    const RigidJointReport &face =
      Testing::find_joint(last, JointKind::vertical, n_blocks);
    EXPECT_LT(face.shear_force, 0.5 * friction * face.normal_force);
    // ... and the agreement above must have covered the free end.
    EXPECT_NEAR(Testing::find_joint(last, JointKind::vertical, 1).shear_force /
                  (friction * Testing::find_joint(last, JointKind::vertical, 1)
                                .normal_force),
                1.,
                1e-9);

    // With the measured joint shears V_j in place of Q_j tan(phi_v), the
    // horizontal and vertical balance of block i with the bedding at its
    // limit,
    //   N_i (cos a - tan phi_h sin a) = W + V_i - V_{i-1},
    //   Q_i = Q_{i-1} + N_i (sin a + tan phi_h cos a),
    // must give the rigid model's Q_j: the whole difference to the closed
    // form is then the vertical shear. Same 1e-9 as above.
    const double dip     = Testing::radians(dip_degrees);
    const double bedding = std::tan(Testing::radians(bedding_degrees));
    const double weight  = description.density * description.gravity *
                          description.assembly.block_width *
                          description.assembly.block_height;
    double previous_force = 0.;
    double previous_shear = 0.;
    for (unsigned int number = 1; number <= n_blocks; ++number)
      {
        SCOPED_TRACE(number);
        const RigidJointReport &joint =
          Testing::find_joint(last, JointKind::vertical, number);
        const double normal = (weight + joint.shear_force - previous_shear) /
                              (std::cos(dip) - bedding * std::sin(dip));
        const double predicted =
          previous_force + normal * (std::sin(dip) + bedding * std::cos(dip));
        EXPECT_NEAR(joint.normal_force / predicted, 1., 1e-9);
        EXPECT_NEAR(
          Testing::find_joint(last, JointKind::bedding, number).normal_force /
            normal,
          1.,
          1e-9);
        previous_force = joint.normal_force;
        previous_shear = joint.shear_force;
      }
  }
} // namespace FloorBlock::RigidBlocks
