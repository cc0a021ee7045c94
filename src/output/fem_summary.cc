#include <common/units.h>
#include <output/fem_summary.h>
#include <output/floor_safety_report.h>

#include <fmt/format.h>

namespace FloorBlock::Output
{
  std::string
  fem_summary_text(const FemReport                &report,
                   const Contact::SolveResult     &result,
                   const Geometry::MeshStatistics &mesh)
  {
    using Units::kN;
    using Units::MPa;
    const bool meshed = report.mesh.has_value();
    // A failed solve keeps only its last converged increment (fem.json
    // "failure"): say so instead of passing it off as the whole run.
    const std::string increments =
      report.failure ?
        fmt::format("{} converged increment(s) kept with {} Newton "
                    "iterations (failed attempts not counted), {} cutbacks",
                    result.increments.size(),
                    report.n_newton_iterations,
                    report.n_cutbacks) :
        fmt::format("{} increments, {} Newton iterations, {} cutbacks",
                    result.increments.size(),
                    report.n_newton_iterations,
                    report.n_cutbacks);
    std::string text =
      fmt::format("{}: {} ({}), {}{} DoFs, {}, {}\n",
                  report.model,
                  report.status,
                  report.status_text,
                  meshed ? fmt::format("{} cells, ", mesh.n_cells) : "",
                  result.n_dofs,
                  increments,
                  force_balance_text(report.force_balance));
    if (meshed && !mesh.contact_zone_sizing.empty())
      text += "  " + mesh.contact_zone_sizing + "\n";
    if (!result.increments.empty() &&
        !result.increments.back().joints.empty() &&
        result.increments.back().joints.front().swept())
      text += fmt::format(
        "  3D, face length {} m: N per metre of face, contact = contact "
        "area / face length\n",
        result.increments.back().joints.front().face_length);
    text += fmt::format("  {:<12} {:>12} {:>14} {:>12} {:>14} {:>10}\n",
                        "joint",
                        "N (kN/m)",
                        "contact (mm)",
                        "peak (MPa)",
                        "averaged (MPa)",
                        "state");
    if (!result.increments.empty())
      for (const auto &joint : result.increments.back().joints)
        text += fmt::format(
          "  {:<12} {:>12.1f} {:>14.1f} {:>12.2f} {:>14.2f} {:>10}\n",
          joint.name,
          joint.normal_force / kN,
          joint.closed_length * 1e3,
          joint.peak_normal_stress / MPa,
          joint.averaged_peak_normal_stress / MPa,
          state_summary(joint.counts));
    std::string times =
      meshed ? fmt::format("mesh {:.3f} s", mesh.wall_time) : "";
    for (const auto &[section, seconds] : result.wall_times)
      times += fmt::format("{}{} {:.3f} s",
                           times.empty() ? "" : ", ",
                           section,
                           seconds);
    text += floor_safety_text(report.corner_safety);
    text += "  " + times + "\n";
    if (report.joint_overlap && report.joint_overlap->large)
      text += "  warning: " + report.joint_overlap->text + "\n";
    return text;
  }
} // namespace FloorBlock::Output
