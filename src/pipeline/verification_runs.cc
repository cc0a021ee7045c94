#include <common/input_error.h>
#include <common/units.h>
#include <pipeline/verification_runs.h>
#include <scene/contact_inputs.h>
#include <verification/hertz_verification.h>
#include <verification/incline_verification.h>
#include <verification/patch_verification.h>
#include <verification/punch_verification.h>
#include <verification/two_blocks_verification.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace FloorBlock::Pipeline
{
  namespace
  {
    /**
     * A verification case starts from exact contact (rigid law; stiff
     * springs if the user asks for the compliant law), then the user's
     * --set overrides apply on top.
     */
    const std::vector<std::string> verification_base = {
      "Joints/Law=rigid",
      "Joints/Normal stiffness=1e14",
      "Joints/Shear stiffness=1e14"};

    /** A quantity whose closed form may be 0: error relative to @p scale. */
    Output::CheckedQuantity
    scaled_quantity(const double computed,
                    const double closed_form,
                    const double scale,
                    const double tolerance)
    {
      const double error = std::abs(computed - closed_form) / scale;
      return {computed, closed_form, error, tolerance, error <= tolerance};
    }

    Output::CheckedQuantity
    quantity(const double computed,
             const double closed_form,
             const double tolerance)
    {
      return scaled_quantity(computed,
                             closed_form,
                             std::abs(closed_form),
                             tolerance);
    }

    /** A yes/no outcome: 1 = slips, 0 = stuck; error 0 or 1. */
    Output::CheckedQuantity
    decision(const bool computed, const bool closed_form)
    {
      return scaled_quantity(computed ? 1. : 0., closed_form ? 1. : 0., 1., 0.);
    }

    Output::VerificationResult
    verify_hertz(const Parameters::ScenarioParameters &scene)
    {
      Verification::HertzSettings settings;
      settings.radius               = scene.verify.hertz_radius;
      settings.line_load            = scene.verify.hertz_line_load;
      settings.youngs_modulus       = scene.verify.hertz_youngs_modulus;
      settings.poissons_ratio       = scene.verify.hertz_poissons_ratio;
      settings.cells_per_half_width = scene.verify.hertz_cells_per_half_width;
      settings.law                  = scene.joints.law;
      settings.compliant_stiffness  = scene.joints.normal_stiffness;
      settings.fe_degree            = scene.solver.fe_degree;

      const Verification::HertzResult result =
        Verification::run_hertz_verification(settings);
      Output::VerificationResult checked{
        {{"contact_half_width",
          quantity(result.half_width_computed,
                   result.half_width_exact,
                   Verification::hertz_half_width_tolerance)},
         {"peak_pressure",
          quantity(result.peak_pressure_computed,
                   result.peak_pressure_exact,
                   Verification::hertz_peak_pressure_tolerance)}},
        {{"contact_cell_size_m", result.contact_cell_size}},
        {{"n_dofs", result.n_dofs}}};
      // Depths a and 2a: "sigma_x_at_1a", "sigma_z_at_2a", each error
      // relative to |sigma_z| there (HertzAxisCheck::stress_scale()).
      for (const Verification::HertzAxisCheck &axis : result.axis)
        {
          const std::string depth = fmt::format(
            "{:.0f}a", axis.depth / result.half_width_exact);
          checked.checks.emplace(
            "sigma_x_at_" + depth,
            scaled_quantity(axis.sigma_x_computed,
                            axis.sigma_x_exact,
                            axis.stress_scale(),
                            Verification::hertz_axis_stress_tolerance));
          checked.checks.emplace(
            "sigma_z_at_" + depth,
            scaled_quantity(axis.sigma_z_computed,
                            axis.sigma_z_exact,
                            axis.stress_scale(),
                            Verification::hertz_axis_stress_tolerance));
        }
      return checked;
    }

    Output::VerificationResult
    verify_patch(const Parameters::ScenarioParameters &scene)
    {
      Verification::PatchSettings settings;
      settings.pressure  = scene.verify.patch_pressure;
      settings.law       = scene.joints.law;
      settings.fe_degree = scene.solver.fe_degree;
      const Verification::PatchResult result =
        Verification::run_patch_verification(settings);
      const Contact::JointReport &joint    = result.increment.joints.at(0);
      const double                pressure = result.applied_pressure;
      double                      lowest = pressure, highest = pressure;
      for (const auto &sample : joint.profile)
        {
          lowest  = std::min(lowest, sample.normal_traction);
          highest = std::max(highest, sample.normal_traction);
        }
      const double     force     = pressure * result.joint_length;
      constexpr double tolerance = Verification::patch_tolerance;
      return {
        {{"joint_normal_force", quantity(joint.normal_force, force, tolerance)},
         {"lowest_normal_traction", quantity(lowest, pressure, tolerance)},
         {"highest_normal_traction", quantity(highest, pressure, tolerance)},
         {"joint_shear_force_over_normal",
          scaled_quantity(joint.shear_force, 0., force, tolerance)}},
        {},
        {{"n_open_pairs", joint.counts.n_open}}};
    }

    Output::VerificationResult
    verify_incline(const Parameters::ScenarioParameters &scene)
    {
      Verification::InclineSettings settings;
      settings.friction_angle = scene.joints.bedding_friction_angle;
      // The case tilts the block to (1 -+ margin) tan(phi): with phi = 0
      // both inclines are 0 and the closed-form shear W sin(0) = 0 leaves
      // no relative error to state.
      if (!(settings.friction_angle > 0.))
        throw InputError("Joints/Bedding friction angle",
                         fmt::format("{} deg",
                                     Units::radians_to_degrees(
                                       settings.friction_angle)),
                         "> 0 deg for verify incline");
      settings.normal_stiffness = scene.joints.normal_stiffness;
      settings.shear_stiffness  = scene.joints.shear_stiffness;
      settings.law              = scene.joints.law;
      const double friction     = std::tan(settings.friction_angle);
      const double margin       = scene.verify.incline_margin;
      settings.incline          = std::atan((1. - margin) * friction);
      const Verification::InclineResult below =
        Verification::run_incline_verification(settings);
      const double incline_below = settings.incline;
      settings.incline           = std::atan((1. + margin) * friction);
      const Verification::InclineResult above =
        Verification::run_incline_verification(settings);
      Output::VerificationResult quantities = {
        {{"slips_below_threshold", decision(Verification::slips(below), false)},
         {"slips_above_threshold", decision(Verification::slips(above), true)}},
        {{"incline_below_deg", Units::radians_to_degrees(incline_below)},
         {"incline_above_deg", Units::radians_to_degrees(settings.incline)}},
        {}};
      if (below.stuck)
        {
          const Contact::JointReport &joint = below.stuck->joints.at(0);
          quantities.checks["joint_shear_force"] =
            quantity(std::abs(joint.shear_force),
                     below.weight * std::sin(incline_below),
                     Verification::incline_tolerance);
          quantities.checks["joint_normal_force"] =
            quantity(joint.normal_force,
                     below.weight * std::cos(incline_below),
                     Verification::incline_tolerance);
        }
      return quantities;
    }

    Output::VerificationResult
    verify_two_blocks(const Parameters::ScenarioParameters &scene)
    {
      Verification::TwoBlocksSettings settings;
      settings.cells_per_metre  = scene.verify.two_blocks_cells_per_metre;
      settings.law              = scene.joints.law;
      settings.joint_stiffness  = scene.joints.normal_stiffness;
      settings.lateral_pressure = scene.verify.two_blocks_lateral_pressure;
      const Verification::TwoBlocksResult result =
        Verification::run_two_blocks_verification(settings);
      return {{{"joint_normal_force",
                quantity(result.joint_normal_force,
                         result.applied_lateral_force,
                         Verification::two_blocks_tolerance)}},
              {{"closed_length_m", result.closed_length},
               {"relative_imbalance", result.relative_imbalance}},
              {}};
    }

    /**
     * The square-ended block on a similar base, stuck and frictionless:
     * the corner exponent fitted to the interface pressure against the
     * eigen-solver's. The error is absolute (exponents are O(1)).
     */
    Output::VerificationResult
    verify_punch(const Parameters::ScenarioParameters &scene)
    {
      Verification::PunchSettings settings;
      settings.pressure           = scene.verify.punch_pressure;
      settings.corner_refinements = scene.verify.punch_corner_refinements;
      settings.youngs_modulus     = scene.material.youngs_modulus();
      settings.poissons_ratio     = scene.material.poissons_ratio();
      Output::VerificationResult quantities;
      for (const auto &[name, state] :
           {std::pair{"stuck", Analytic::InterfaceState::stuck},
            std::pair{"frictionless", Analytic::InterfaceState::frictionless}})
        {
          const Verification::PunchCase result =
            Verification::run_punch_case(settings, state);
          const std::string prefix(name);
          quantities.checks[prefix + "_corner_exponent"] =
            scaled_quantity(result.fitted_exponent,
                            result.theory_exponent,
                            1.,
                            Verification::punch_exponent_tolerance);
          quantities.figures[prefix + "_fit_from_m"] = result.fit_from;
          quantities.figures[prefix + "_fit_to_m"]   = result.fit_to;
          quantities.figures[prefix + "_fit_rms_relative_residual"] =
            result.fit_residual;
          quantities.figures[prefix + "_one_term_fit_exponent"] =
            result.one_term_exponent;
          quantities.figures[prefix + "_second_theory_exponent"] =
            result.second_theory_exponent;
          quantities.figures[prefix + "_second_over_first_term"] =
            result.second_over_first;
          quantities.figures[prefix + "_one_term_within_10_percent_m"] =
            result.one_term_validity;
          quantities.figures[prefix + "_smallest_cell_m"] =
            result.smallest_cell;
          quantities.counts[prefix + "_fit_points"] = result.n_fit_points;
          quantities.counts[prefix + "_n_dofs"]     = result.n_dofs;
        }
      return quantities;
    }
  } // namespace

  /**
   * Hertz and the patch test start from exact contact (see
   * verification_base); the incline and the two blocks from the
   * chapter's compliant joints (Table 6.1), as their unit tests do.
   */
  const std::map<std::string, VerificationCase> &
  verification_cases()
  {
    static const std::map<std::string, VerificationCase> cases = {
      {"hertz", {verification_base, verify_hertz}},
      {"patch", {verification_base, verify_patch}},
      {"punch", {verification_base, verify_punch}},
      {"incline", {{}, verify_incline}},
      {"two-blocks", {{}, verify_two_blocks}}};
    return cases;
  }
} // namespace FloorBlock::Pipeline
