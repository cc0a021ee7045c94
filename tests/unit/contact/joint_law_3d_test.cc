// Issue 16: the compliant Coulomb joint in 3D, where the tangential slip is
// a vector in the joint plane and the friction limit a cone: return
// mapping radially onto the cone, the consistent tangent against central
// differences, and the 2D law as its restriction to one tangent direction.
#include <contact/joint_law.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using namespace FloorBlock::Contact;
  using Vector3 = dealii::Tensor<1, 3>;
  using Vector2 = dealii::Tensor<1, 2>;

  constexpr double normal_stiffness = 1e10; // Pa/m
  constexpr double shear_stiffness  = 5e9;  // Pa/m
  const double     friction_angle   = std::atan(0.5);

  JointConstants
  constants()
  {
    JointConstants parameters;
    parameters.normal_stiffness = normal_stiffness;
    parameters.shear_stiffness  = shear_stiffness;
    parameters.friction_angle   = friction_angle;
    return parameters;
  }

  Vector3
  vector3(const double x, const double y, const double z)
  {
    Vector3 result;
    result[0] = x;
    result[1] = y;
    result[2] = z;
    return result;
  }

  // Normal along y; the joint plane is x-z.
  const Vector3 up = vector3(0., 1., 0.);

  // A trial traction outside the cone in an oblique direction of the
  // joint plane returns radially: same direction, magnitude mu t_n.
  TEST(JointLaw3d, SlipReturnsRadiallyOntoTheCone)
  {
    const CoulombJoint<3> joint(constants());
    const double          overlap  = 1e-4;                       // m
    const double          pressure = normal_stiffness * overlap; // Pa
    const double          limit    = 0.5 * pressure;             // Pa
    const double slip     = 3. * limit / shear_stiffness; // m, 3x the limit
    const double angle    = 0.7; // rad, in the joint plane
    const auto   response = joint.evaluate(vector3(slip * std::cos(angle),
                                                 -overlap,
                                                 slip * std::sin(angle)),
                                         up,
                                         {});
    EXPECT_EQ(response.state, JointState::slip);
    EXPECT_NEAR(response.normal_traction, pressure, 1e-12 * pressure);
    EXPECT_NEAR(response.tangential_traction.norm(), limit, 1e-12 * limit);
    EXPECT_NEAR(response.tangential_traction[0],
                limit * std::cos(angle),
                1e-12 * limit);
    EXPECT_NEAR(response.tangential_traction[2],
                limit * std::sin(angle),
                1e-12 * limit);
    EXPECT_NEAR(response.tangential_traction[1], 0., 1e-12 * limit);
  }

  // Inside the cone the shear spring acts in every tangent direction.
  TEST(JointLaw3d, StickInsideTheCone)
  {
    const CoulombJoint<3> joint(constants());
    const double          overlap = 1e-4, pressure = normal_stiffness * overlap;
    const double          slip =
      0.4 * 0.5 * pressure / shear_stiffness; // 40 % of the limit
    const auto response =
      joint.evaluate(vector3(0.6 * slip, -overlap, -0.8 * slip), up, {});
    EXPECT_EQ(response.state, JointState::stick);
    EXPECT_NEAR(response.tangential_traction[0],
                0.6 * shear_stiffness * slip,
                1e-9 * pressure);
    EXPECT_NEAR(response.tangential_traction[2],
                -0.8 * shear_stiffness * slip,
                1e-9 * pressure);
  }

  // The tangent is the derivative of the force density, in stick and in
  // slip (where the cone's curvature couples the two tangent directions).
  TEST(JointLaw3d, TangentMatchesCentralDifferences)
  {
    const CoulombJoint<3> joint(constants());
    const double overlap = 1e-4, limit = 0.5 * normal_stiffness * overlap;
    for (const double factor : {0.4, 3.0})
      {
        const double  slip     = factor * limit / shear_stiffness;
        const Vector3 jump     = vector3(0.8 * slip, -overlap, 0.6 * slip);
        const auto    response = joint.evaluate(jump, up, {});
        const double  h        = 1e-9; // m
        for (unsigned int j = 0; j < 3; ++j)
          {
            Vector3 step;
            step[j] = h;
            const Vector3 difference =
              (joint.evaluate(jump + step, up, {}).force_density -
               joint.evaluate(jump - step, up, {}).force_density) /
              (2. * h);
            for (unsigned int i = 0; i < 3; ++i)
              EXPECT_NEAR(response.tangent[i][j],
                          difference[i],
                          1e-5 * normal_stiffness)
                << "factor " << factor << ", entry " << i << j;
          }
      }
  }

  // With slip along x only, the 3D law is the 2D law of the x-y plane.
  TEST(JointLaw3d, ReducesToThe2dLawInItsPlane)
  {
    const CoulombJoint<3> joint3(constants());
    const CoulombJoint<2> joint2(constants());
    Vector2               up2;
    up2[1] = 1.;
    for (const double slip : {2e-7, 5e-6, -5e-6})
      {
        Vector2 jump2;
        jump2[0]      = slip;
        jump2[1]      = -1e-4;
        const auto r2 = joint2.evaluate(jump2, up2, {});
        const auto r3 = joint3.evaluate(vector3(slip, -1e-4, 0.), up, {});
        EXPECT_EQ(r3.state, r2.state) << slip;
        EXPECT_DOUBLE_EQ(r3.normal_traction, r2.normal_traction);
        EXPECT_NEAR(r3.tangential_traction[0],
                    r2.tangential_traction[0],
                    1e-12 * r2.normal_traction);
        EXPECT_EQ(r3.tangential_traction[2], 0.);
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            EXPECT_NEAR(r3.tangent[i][j],
                        r2.tangent[i][j],
                        1e-12 * normal_stiffness);
      }
  }
} // namespace
