#include <scene/analytic_inputs.h>
#include <scene/contact_inputs.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace FloorBlock::Scene
{
  namespace
  {
    Contact::JointConstants
    joint_constants(const Parameters::JointParameters &joints,
                    const double                       friction_angle)
    {
      Contact::JointConstants parameters;
      parameters.normal_stiffness = joints.normal_stiffness;
      parameters.shear_stiffness  = joints.shear_stiffness;
      parameters.friction_angle   = friction_angle;
      parameters.cohesion         = joints.cohesion;
      parameters.tensile_strength = joints.tensile_strength;
      return parameters;
    }

    /// Slope angle of the bedding chord under the blocks, x from 0 to nL.
    double
    bedding_chord_angle(const Parameters::ScenarioParameters &scene)
    {
      if (scene.bedding.shape == Geometry::BeddingShape::planar)
        return scene.bedding.inclination;
      const double chain_length =
        scene.geometry.n_blocks * scene.geometry.block_width;
      return std::atan(chain_length / scene.bedding.curvature);
    }

    double
    bedding_height(const Parameters::ScenarioParameters &scene, const double x)
    {
      if (scene.bedding.floor_uplift ==
          Geometry::FloorUplift::lifted_flat_bedding)
        return 0.;
      if (scene.bedding.shape == Geometry::BeddingShape::planar)
        return x * std::tan(scene.bedding.inclination);
      return x * x / scene.bedding.curvature;
    }

    Contact::UpliftSettings
    uplift_settings(const Parameters::ScenarioParameters &scene)
    {
      const double lift = scene.loading.floor_lift;
      const double chain_length =
        scene.geometry.n_blocks * scene.geometry.block_width;
      Contact::UpliftSettings uplift;
      uplift.magnitude = lift;
      switch (scene.loading.uplift_mode)
        {
          case Parameters::UpliftMode::vertical:
            uplift.mode = Contact::UpliftMotion::vertical_translation;
            break;
          case Parameters::UpliftMode::dip_toward_face:
            uplift.mode      = Contact::UpliftMotion::dip_translation;
            uplift.dip_angle = bedding_chord_angle(scene) + M_PI;
            break;
          case Parameters::UpliftMode::dip_away_from_face:
            uplift.mode      = Contact::UpliftMotion::dip_translation;
            uplift.dip_angle = bedding_chord_angle(scene);
            break;
          case Parameters::UpliftMode::tilt:
            // Clockwise about the free end: the face end (dx = -nL) rises.
            uplift.mode      = Contact::UpliftMotion::tilt;
            uplift.magnitude = -std::asin(std::min(1.0, lift / chain_length));
            uplift.pivot_x   = chain_length;
            uplift.pivot_y   = bedding_height(scene, chain_length);
            break;
          case Parameters::UpliftMode::parabola:
            uplift.mode = Contact::UpliftMotion::parabola;
            // u_y = x^2/k reaches `lift` at x = nL; no lift, no bending.
            uplift.magnitude =
              lift > 0 ? chain_length * chain_length / lift : 0.;
            break;
          case Parameters::UpliftMode::slope:
            uplift.mode      = Contact::UpliftMotion::slope;
            uplift.magnitude = lift / chain_length;
            break;
        }
      return uplift;
    }
  } // namespace

  FloorProblemSettings
  floor_problem_settings(const Parameters::ScenarioParameters &scene)
  {
    const Analytic::BlockChain chain = block_chain(scene);
    // The pressure acts on the floor-surface id of a block, which is the
    // straight part of its top between the two top fillets: L - 2r (ids.h).
    // Dividing by L (as before) applied only (L - 2r)/L of P_i, 98 % on the
    // default scene. On an inclined top the vertical pressure's horizontal
    // projection is L - 2r up to O(r x slope).
    // In a turned frame (Bedding/Frame dip) a top that is level in the
    // frame is L cos(dip) wide horizontally, and the vertical pressure is a
    // load per unit horizontal width (Fem::ElasticModel::vertical_pressures),
    // so the pressure is raised by 1/cos(dip) to apply the whole support
    // load. A pressure normal to the top acts on the top's own length.
    const bool vertical_load = scene.loading.support_load_direction ==
                               Parameters::SupportLoadDirection::vertical;
    const double loaded_length =
      (scene.geometry.block_width -
       2. * scene.geometry.corner_rounding_radius) *
      (vertical_load ? std::cos(scene.bedding.frame_dip) : 1.);
    std::map<unsigned int, double> support_pressures;
    for (unsigned int block = 1; block <= chain.n_blocks(); ++block)
      if (chain.support_load[block - 1] > 0)
        support_pressures[block] =
          chain.support_load[block - 1] / loaded_length;

    // Aggregate initialisation in member order: the elastic law is an
    // immutable value (const members) and cannot be assigned afterwards.
    FloorProblemSettings settings{
      scene.geometry.n_blocks,
      Material::ElasticLaw<2>::from_bulk_shear(scene.material.bulk_modulus,
                                               scene.material.shear_modulus),
      scene.material.density,
      scene.loading.gravity,
      scene.joints.law,
      joint_constants(scene.joints, scene.joints.vertical_friction_angle),
      joint_constants(scene.joints, scene.joints.bedding_friction_angle),
      support_pressures,
      scene.loading.support_load_direction ==
        Parameters::SupportLoadDirection::vertical,
      {},
      {}};
    settings.frame_dip  = scene.bedding.frame_dip;
    settings.rigid_base = scene.bedding.rigid_base;
    settings.uplift     = uplift_settings(scene);
    settings.steps.gravity_with_pressure =
      scene.solver.gravity_with_support_load;
    settings.steps.n_gravity  = scene.solver.n_gravity_steps;
    settings.steps.n_pressure = scene.solver.n_support_steps;
    settings.steps.n_uplift   = scene.solver.n_uplift_steps;
    return settings;
  }

  Contact::ContactSolverSettings
  contact_solver_settings(const Parameters::ScenarioParameters &scene,
                          const std::string                    &vtu_folder)
  {
    const auto                    &solver = scene.solver;
    Contact::ContactSolverSettings settings;
    settings.fe_degree                 = solver.fe_degree;
    settings.newton.relative_tolerance = solver.newton_tolerance;
    settings.newton.max_iterations     = solver.max_newton_iterations;
    settings.linear.kind               = solver.linear_solver;
    settings.linear.max_direct_dofs =
      scene.geometry.dimension == 3 ?
        std::min(solver.max_direct_dofs, max_direct_dofs_3d) :
        solver.max_direct_dofs;
    settings.linear.max_reuse_iterations = solver.max_reuse_iterations;
    settings.linear.direct_solver        = solver.direct_solver;
    settings.max_cutbacks                = solver.max_cutbacks;
    settings.averaging_length            = solver.averaging_length;
    settings.complementarity_factor      = solver.complementarity_factor;
    settings.output_directory            = vtu_folder;
    return settings;
  }
} // namespace FloorBlock::Scene
