#include <common/units.h>
#include <output/comparison_report.h>
#include <output/fem_report.h>
#include <output/floor_safety_lift.h>
#include <output/floor_safety_summary.h>
#include <output/governing_report.h>
#include <output/numbering_note.h>
#include <output/report_markdown.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace FloorBlock::Output
{
  namespace
  {
    std::string
    relative_error(const FigureError &error)
    {
      return error.relative_error ?
               fmt::format("{:.1f} %", *error.relative_error * 100.) :
               std::string("-");
    }

    std::string
    error_section(const std::optional<FemErrorEstimate> &estimate)
    {
      if (!estimate)
        return "No error estimate was made (Solver/Error estimate = none, or "
               "the solve did not converge).\n";
      if (!estimate->available)
        return "No error estimate: " + estimate->status_text + "\n";
      std::string text = fmt::format(
        "Method: {} ({} DoFs).\n\n| joint | Q rel. error | contact length "
        "rel. error | sigma_max averaged rel. error | sigma_max pointwise "
        "rel. error |\n|---|---|---|---|---|\n",
        estimate->method,
        estimate->refined_n_dofs);
      for (const auto &[name, errors] : estimate->joints)
        text += fmt::format("| {} | {} | {} | {} | {} |\n",
                            name,
                            relative_error(errors.normal_force),
                            relative_error(errors.contact_length),
                            relative_error(errors.sigma_max_averaged),
                            relative_error(errors.sigma_max));
      return text;
    }

    /** The loaded blocks in the output's numbering (1 = free end), rising. */
    std::string
    loaded_blocks_text(const Parameters::ScenarioParameters &scene)
    {
      std::vector<unsigned int> blocks = scene.loaded_blocks();
      std::sort(blocks.begin(), blocks.end());
      return blocks.empty() ? std::string("none") :
                              fmt::format("{}", fmt::join(blocks, ", "));
    }

    std::string
    lift_safety_markdown(const RunComparison &comparison)
    {
      const std::vector<LiftSafety> along =
        safety_along_lift(comparison.lift_history);
      if (along.empty())
        return {};
      return "\nAlong the floor lift: " + unit_safety_text(along) +
             ".\n\n![Floor safety along the lift](floor_safety_vs_lift.png)\n";
    }
  } // namespace

  std::string
  report_markdown(const Parameters::ScenarioParameters  &scene,
                  const Contact::SolveResult            &result,
                  const FemReport                       &report,
                  const std::optional<FemErrorEstimate> &error_estimate,
                  const RunComparison                   &comparison,
                  const std::vector<std::string>        &verdicts,
                  const Scene::ClosedForms              &closed_forms)
  {
    std::string text = fmt::format(
      "# FloorBlock report: scene '{}'\n\n{}\n\n"
      "Scene: {} blocks {} m x {} m, bed {}, phi_h = {:.1f} deg, phi_v = "
      "{:.1f} deg, support load {:.0f} t on blocks {} from the face (blocks "
      "{} in this report's numbering), b = {} m, floor lift {} m ({}), joints {}.\n\n"
      "Model: {} ({}): {} ({}); {} DoFs, {} increments, {} Newton "
      "iterations, {} cutbacks, {}.\n\n",
      scene.scene_name,
      numbering_note,
      scene.geometry.n_blocks,
      scene.geometry.block_width,
      scene.geometry.block_height,
      scene.bedding.shape == Geometry::BeddingShape::planar ?
        fmt::format("planar {:.1f} deg",
                    Units::radians_to_degrees(scene.bedding.inclination)) :
        fmt::format("y = x^2/{}", scene.bedding.curvature),
      Units::radians_to_degrees(scene.joints.bedding_friction_angle),
      Units::radians_to_degrees(scene.joints.vertical_friction_angle),
      scene.loading.support_load / Units::tonnes_force_to_newtons(1.),
      fmt::join(scene.loading.loaded_blocks_from_face, ","),
      loaded_blocks_text(scene),
      scene.geometry.support_width,
      scene.loading.floor_lift_origin.empty() ?
        fmt::format("{}", scene.loading.floor_lift) :
        fmt::format("{} ({})",
                    scene.loading.floor_lift,
                    scene.loading.floor_lift_origin),
      report.converged() ? "reached" : "not reached",
      scene.joints.law == Contact::JointLawKind::rigid ? "rigid" : "compliant",
      report.model,
      report.model_choice,
      report.status,
      report.status_text,
      result.n_dofs,
      result.increments.size(),
      report.n_newton_iterations,
      report.n_cutbacks,
      force_balance_text(report.force_balance));

    for (const std::string &warning : scene.warnings)
      text += "**Warning:** " + warning + "\n\n";
    if (report.model != "elastic FEM")
      text += "Columns and verdicts marked FEM hold the numbers of the " +
              report.model + " model.\n\n";
    text += "## Verdicts (face joint, final lift)\n\n";
    for (const auto &line : verdicts)
      text += "- " + line + "\n";
    if (!result.increments.empty())
      text += "\n## Governing joints (final lift)\n\nThe joint with the "
              "largest value of each figure, beside the face joint's "
              "(`governing_joints` in summary.json):\n\n" +
              governing_table_markdown(
                Compare::governing_joints(result.increments.back(),
                                          scene.geometry.n_blocks)) +
              "\n![Peak stress along the lift](stress_vs_lift.png)\n";
    text +=
      "\n## Lateral force per vertical joint\n\n" +
      force_table_markdown(comparison.final_joints, scene.geometry.n_blocks) +
      "\n![Q per joint](q_per_joint.png)\n\n"
      "## Corner contact: FEM against Eqs. 6.51-6.53 (FEM's own Q and "
      "y)\n\n" +
      contact_table_markdown(comparison.final_joints) +
      "\n![Face joint along the lift](face_joint_vs_lift.png)\n"
      "![Traction along the face joint](face_joint_traction.png)\n\n"
      "## Floor safety (final lift)\n\n" +
      floor_safety_markdown(report.corner_safety, error_estimate, closed_forms) +
      lift_safety_markdown(comparison) +
      "\n## Discretisation error\n\n" + error_section(error_estimate);
    text += "\n## Cost\n\n| stage | wall time (s) |\n|---|---|\n";
    if (report.mesh)
      text += fmt::format("| mesh | {:.3f} |\n", report.mesh->wall_time);
    for (const auto &[section, seconds] : result.wall_times)
      text += fmt::format("| {} | {:.3f} |\n", section, seconds);
    return text;
  }
} // namespace FloorBlock::Output
