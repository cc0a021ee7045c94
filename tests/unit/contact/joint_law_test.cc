// Unit tests of the Coulomb joint law without a mesh: states, return
// mapping, and the consistent tangent against finite differences.
#include <contact/joint_law.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using namespace FloorBlock::Contact;
  using Vector2 = dealii::Tensor<1, 2>;

  constexpr double normal_stiffness = 1e10; // Pa/m
  constexpr double shear_stiffness  = 5e9;  // Pa/m
  const double     friction_angle   = std::atan(0.5);

  CoulombJoint<2>
  make_joint(const double cohesion = 0., const double tensile_strength = 0.)
  {
    JointConstants parameters;
    parameters.normal_stiffness = normal_stiffness;
    parameters.shear_stiffness  = shear_stiffness;
    parameters.friction_angle   = friction_angle;
    parameters.cohesion         = cohesion;
    parameters.tensile_strength = tensile_strength;
    return CoulombJoint<2>(parameters);
  }

  Vector2
  vector2(const double x, const double y)
  {
    Vector2 result;
    result[0] = x;
    result[1] = y;
    return result;
  }

  const Vector2 up = vector2(0., 1.);

  TEST(JointLaw, OpenWhenGapPositive)
  {
    const auto response = make_joint().evaluate(vector2(1e-4, 1e-6), up, {});
    EXPECT_EQ(response.state, JointState::open);
    EXPECT_EQ(response.normal_traction, 0.);
    EXPECT_EQ(response.tangent.norm(), 0.);
  }

  TEST(JointLaw, ZeroGapCountsAsClosedAndStuck)
  {
    // The first Newton iterate of touching blocks must have stiffness.
    const auto response = make_joint().evaluate(Vector2(), up, {});
    EXPECT_EQ(response.state, JointState::stick);
    EXPECT_GT(response.tangent.norm(), 0.);
  }

  TEST(JointLaw, StickAndSlipAroundTheCoulombLimit)
  {
    const double overlap       = 1e-4;                       // m
    const double pressure      = normal_stiffness * overlap; // Pa
    const double limit         = 0.5 * pressure;
    const double slip_to_limit = limit / shear_stiffness; // m
    const auto   stuck =
      make_joint().evaluate(vector2(0.99 * slip_to_limit, -overlap), up, {});
    EXPECT_EQ(stuck.state, JointState::stick);
    EXPECT_NEAR(stuck.tangential_traction[0], 0.99 * limit, 1e-9 * limit);
    const auto sliding =
      make_joint().evaluate(vector2(1.01 * slip_to_limit, -overlap), up, {});
    EXPECT_EQ(sliding.state, JointState::slip);
    // Return mapping lands exactly on the cone.
    EXPECT_NEAR(sliding.tangential_traction[0], limit, 1e-12 * limit);
    EXPECT_NEAR(sliding.normal_traction, pressure, 1e-12 * pressure);
  }

  TEST(JointLaw, CohesionAndTensileStrengthWhileIntact)
  {
    const double tensile = 1e5, cohesion = 2e5; // Pa
    const double opening = 0.5 * tensile / normal_stiffness;
    const auto   intact =
      make_joint(cohesion, tensile).evaluate(vector2(0., opening), up, {});
    EXPECT_EQ(intact.state, JointState::stick);
    EXPECT_NEAR(intact.normal_traction, -0.5 * tensile, 1e-9 * tensile);
    JointHistory<2> broken;
    broken.intact = false;
    EXPECT_EQ(make_joint(cohesion, tensile)
                .evaluate(vector2(0., opening), up, broken)
                .state,
              JointState::open);
  }

  TEST(JointLaw, TangentMatchesFiniteDifferences)
  {
    // Central differences of a piecewise-smooth map: step 1e-7 of the
    // jump (1e-4 m) keeps both states fixed; truncation error is O(h^2).
    JointHistory<2> history;
    history.tangential_base = vector2(3e4, 0.);
    history.reference_slip  = vector2(1e-6, 0.);
    const Vector2 normal    = vector2(0.6, 0.8);
    for (const Vector2 &jump : {vector2(-2e-5, -1e-4), vector2(2e-4, -1e-4)})
      {
        const auto   joint    = make_joint();
        const auto   response = joint.evaluate(jump, normal, history);
        const double step     = 1e-11;
        for (unsigned int j = 0; j < 2; ++j)
          {
            Vector2 delta;
            delta[j] = step;
            const Vector2 difference =
              (joint.evaluate(jump + delta, normal, history).force_density -
               joint.evaluate(jump - delta, normal, history).force_density) /
              (2. * step);
            for (unsigned int i = 0; i < 2; ++i)
              EXPECT_NEAR(response.tangent[i][j],
                          difference[i],
                          1e-5 * normal_stiffness)
                << "state " << int(response.state) << " entry " << i << j;
          }
      }
  }
} // namespace
