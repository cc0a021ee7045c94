// Eq. 6.51-6.53 as the Winkler reading of a rotated joint.
//
// src/analytic/README.md section 6 derives 6.51 from: the joint faces
// rotate against each other by theta, overlap delta(z) = theta (c - z) over
// the contact length c below floor level, and every fibre of length L
// shortens elastically, sigma = E delta / L: a joint of normal stiffness
// kn = E/L. The rigid-block model has exactly that joint. Here block 1 is
// given a prescribed rotation theta against the fixed face block and the
// joint integration must return c, Q and the peak traction that satisfy
// A = sqrt(2 b L^2 Q/(y E)) and sigma_max = 2 Q/A, with y = L theta (the
// model's rotations are linearised, so tan(theta) -> theta; see
// block_motion.h) and b = 1 m (forces per metre of face).

#include <analytic/corner_contact.h>

#include <gtest/gtest.h>

#include <cmath>

#include "scene_fixture.h"

namespace FloorBlock::RigidBlocks
{
  namespace
  {
    constexpr double youngs_modulus = 16.1e9; // Pa, Table 6.1 K and G
    constexpr double rotation       = 1e-3;   // rad
    // Not a multiple of any point spacing H/(N-1) below, so the end of the
    // contact zone falls inside a trapezoid interval.
    constexpr double contact_length = 0.123456; // m
    constexpr double unit_width     = 1.;       // m, per metre of face

    struct WinklerCheck
    {
      double measured_length = 0.;
      double lateral_force   = 0.;
      double peak_traction   = 0.;
      double peak_depth      = 0.;
      /** A from Eq. 6.51 with the measured Q, over the measured c b. */
      double area_ratio = 0.;
      /** 2 Q / A (Eq. 6.53 with A = c b) over the measured peak. */
      double peak_ratio = 0.;
      /** Relative error of Q against the exact triangle kn theta c^2 / 2. */
      double force_error = 0.;
    };

    WinklerCheck
    press_against_face(const unsigned int n_points)
    {
      ModelDescription description = Testing::planar_scene(
        1, 0., Testing::radians(30.), Testing::radians(30.));
      const double block_width = description.assembly.block_width;
      description.vertical_joint.normal_stiffness =
        youngs_modulus / block_width;
      description.solver.n_points_per_joint = n_points;
      const Model model(description);

      // Overlap at depth z below floor level: theta (y_top - y_c - z) -
      // u_x; choose u_x so that it vanishes at z = c.
      const double centroid_to_top =
        description.assembly.block_height - model.joint_set().centroids()[0][1];
      BlockMotion motion;
      motion.rotation       = rotation;
      motion.translation[0] = rotation * (centroid_to_top - contact_length);
      const std::vector<RigidJointReport> reports =
        model.evaluate_prescribed({motion}, 0.);
      const RigidJointReport &face = reports[0];
      EXPECT_EQ(face.kind, JointKind::vertical);
      EXPECT_EQ(face.number, 1u);

      WinklerCheck check;
      check.measured_length = face.contact_length;
      check.lateral_force   = face.normal_force;
      check.peak_traction   = face.peak_normal_traction;
      check.peak_depth      = face.peak_coordinate;
      const Analytic::CornerContact closed_form =
        Analytic::corner_contact(face.normal_force * unit_width,
                                 block_width * rotation,
                                 youngs_modulus,
                                 unit_width,
                                 block_width,
                                 description.assembly.block_height);
      EXPECT_EQ(closed_form.status, Analytic::Status::ok);
      check.area_ratio =
        closed_form.contact_area / (face.contact_length * unit_width);
      check.peak_ratio = 2. * face.normal_force * unit_width /
                         (face.contact_length * unit_width) /
                         face.peak_normal_traction;
      const double exact_force = youngs_modulus / block_width * rotation *
                                 contact_length * contact_length / 2.;
      check.force_error = (face.normal_force - exact_force) / exact_force;
      return check;
    }
  } // namespace

  TEST(RigidWinkler, PrescribedRotationSatisfiesEq651ToIntegrationError)
  {
    const double block_height = Geometry::AssemblyDescription().block_height;
    const double block_width  = Geometry::AssemblyDescription().block_width;
    for (const unsigned int n_points : {100u, 400u, 1600u, 6400u})
      {
        SCOPED_TRACE(n_points);
        const WinklerCheck check = press_against_face(n_points);
        // The overlap is linear along the joint, so the interpolated end of
        // the contact zone and the peak at the corner point are exact.
        EXPECT_NEAR(check.measured_length / contact_length, 1., 1e-12);
        EXPECT_EQ(check.peak_depth, 0.);
        EXPECT_NEAR(check.peak_traction / (youngs_modulus / block_width *
                                           rotation * contact_length),
                    1.,
                    1e-12);
        // Q carries the trapezoid error (always an overestimate) of the kinked
        // traction: on the interval containing z = c the rule is off by at most
        // kn theta h^2 / 8, i.e. a relative error <= h^2 / (4 c^2), with
        // h = H / (N - 1); the bound is the tolerance.
        const double spacing = block_height / (n_points - 1);
        const double bound =
          spacing * spacing / (4. * contact_length * contact_length);
        EXPECT_LE(std::abs(check.force_error), bound);
        // A ~ sqrt(Q): half the relative error; 2Q/A over the peak: the
        // full relative error of Q.
        EXPECT_NEAR(check.area_ratio, 1., bound / 2. + 1e-12);
        EXPECT_NEAR(check.peak_ratio, 1., bound + 1e-12);
        std::printf("  N = %5u: Q error %.3e (bound %.3e), A(6.51)/c b - 1 = "
                    "%.3e, 2Q/A / sigma_peak - 1 = %.3e\n",
                    n_points,
                    check.force_error,
                    bound,
                    check.area_ratio - 1.,
                    check.peak_ratio - 1.);
      }
  }
} // namespace FloorBlock::RigidBlocks

namespace FloorBlock::RigidBlocks
{
  TEST(RigidWinkler, SolvedLiftedParabolaJointsAreWinklerTriangles)
  {
    // The same relations in a full solve: in the lifted-parabola scene every
    // vertical joint in partial contact must carry the triangle of a
    // relative rotation theta_rel = theta_j - theta_{j+1}:
    // c = sqrt(2 Q / (kn theta_rel)) and sigma_peak = 2 Q / c at floor
    // level. The bounds are the trapezoid error of Q (h^2/(4 c^2)) and
    // half of it for c, as in the prescribed test.
    const ModelDescription description = Testing::lifted_parabola_scene(5);
    const RigidSolveResult result      = Model(description).solve();
    ASSERT_EQ(result.status, SolveStatus::converged) << result.message;
    const IncrementReport &last     = result.increments.back();
    const unsigned int     n_blocks = description.assembly.n_blocks;
    const double           spacing  = description.assembly.block_height /
                           (description.solver.n_points_per_joint - 1);
    const double stiffness = description.vertical_joint.normal_stiffness;
    unsigned int n_partial = 0;
    for (unsigned int number = 1; number <= n_blocks; ++number)
      {
        SCOPED_TRACE(number);
        const RigidJointReport &joint =
          Testing::find_joint(last, JointKind::vertical, number);
        if (!(joint.contact_length > 0. &&
              joint.contact_length < description.assembly.block_height))
          continue;
        ++n_partial;
        const double relative_rotation =
          last.motions[number - 1].rotation -
          (number < n_blocks ? last.motions[number].rotation : 0.);
        const double length = joint.contact_length;
        const double bound  = spacing * spacing / (4. * length * length);
        EXPECT_NEAR(std::sqrt(2. * joint.normal_force /
                              (stiffness * relative_rotation)) /
                      length,
                    1.,
                    bound / 2. + 1e-12);
        EXPECT_NEAR(2. * joint.normal_force / length /
                      joint.peak_normal_traction,
                    1.,
                    bound + 1e-12);
        EXPECT_EQ(joint.peak_coordinate, 0.);
        std::printf("    joint %u: theta_rel %.4e rad (bed chord rotation "
                    "L/k = %.4e), Q %.4e N/m, c %.4f m, peak %.4e Pa\n",
                    number,
                    relative_rotation,
                    description.assembly.block_width /
                      description.assembly.curvature,
                    joint.normal_force,
                    length,
                    joint.peak_normal_traction);
      }
    EXPECT_GE(n_partial, 3u);
  }
} // namespace FloorBlock::RigidBlocks
