#include <compare/joint_name.h>
#include <output/fem_report.h>
#include <output/numbering_note.h>

#include <fmt/format.h>


namespace FloorBlock::Output
{
  using nlohmann::json;

  namespace
  {
    std::string
    state_summary(const Contact::StateCounts &counts)
    {
      if (counts.n_closed() == 0)
        return "open";
      if (counts.n_slip == 0)
        return "stick";
      return counts.n_stick == 0 ? "slip" : "stick-slip";
    }
  } // namespace

  json
  joint_bodies(const std::string &kind,
               const unsigned int number,
               const unsigned int n_blocks)
  {
    if (kind != "vertical")
      return json{number, "base"};
    return number == n_blocks ? json{number, "face"} : json{number, number + 1};
  }

  std::string
  stage_name(const Contact::LoadStage stage)
  {
    switch (stage)
      {
        case Contact::LoadStage::gravity:
          return "gravity";
        case Contact::LoadStage::support_pressure:
          return "support_load";
        case Contact::LoadStage::uplift:
          return "uplift";
      }
    return "unknown";
  }

  json
  joint_json(const Contact::JointReport &joint,
             const FemReportContext &    context)
  {
    const auto name = Compare::parse_joint_name(joint.name);
    return {{"name", joint.name},
            {"kind", name.kind},
            {"blocks", joint_bodies(name.kind, name.number, context.n_blocks)},
            {"normal_force_N_per_m", joint.normal_force},
            {"normal_force_N_over_b", joint.normal_force * context.support_width},
            {"shear_force_N_per_m", joint.shear_force},
            {"contact_length_m", joint.closed_length},
            {"contact_area_m2", joint.closed_length * context.support_width},
            {"sigma_max_Pa", joint.peak_normal_stress},
            {"sigma_max_position_m",
             {joint.peak_position[0], joint.peak_position[1]}},
            {"sigma_max_averaged_Pa", joint.averaged_peak_normal_stress},
            {"averaging_length_m", joint.averaging_length},
            {"sigma_mean_Pa", joint.mean_normal_stress},
            {"state", state_summary(joint.counts)},
            {"n_stick", joint.counts.n_stick},
            {"n_slip", joint.counts.n_slip},
            {"n_open", joint.counts.n_open}};
  }

  json
  fem_json(const Contact::SolveResult &result,
           const FemReportContext &    context)
  {
    json increments = json::array();
    unsigned int n_newton = 0, n_cutbacks = 0;
    double       worst_imbalance = 0;
    for (const auto &increment : result.increments)
      {
        n_newton += increment.n_newton_iterations;
        n_cutbacks += increment.n_cutbacks;
        worst_imbalance =
          std::max(worst_imbalance, increment.balance.relative_imbalance);
        increments.push_back(
          {{"stage", stage_name(increment.stage)},
           {"stage_factor", increment.stage_factor},
           {"newton_iterations", increment.n_newton_iterations},
           {"multiplier_updates", increment.n_multiplier_updates},
           {"cutbacks", increment.n_cutbacks},
           {"relative_residual", increment.relative_residual},
           {"stopped_at_round_off_floor", increment.round_off_limited},
           {"n_stick", increment.counts.n_stick},
           {"n_slip", increment.counts.n_slip},
           {"n_open", increment.counts.n_open},
           {"force_balance_relative_error",
            increment.balance.relative_imbalance},
           {"wall_time_s", increment.wall_time}});
      }

    json joints = json::array();
    json blocks = json::object();
    if (!result.increments.empty())
      {
        const auto &last = result.increments.back();
        for (const auto &joint : last.joints)
          joints.push_back(joint_json(joint, context));
        for (const auto &[material, motion] : last.motions)
          blocks[std::to_string(material)] = {
            {"translation_m", {motion.translation[0], motion.translation[1]}},
            {"rotation_rad", motion.rotation}};
      }

    return {{"status", context.status},
            {"status_text", context.status_text},
            {"numbering", numbering_note},
            {"forces_per", "*_N_per_m per metre of face; *_N_over_b and "
                           "contact_area_m2 over the support width b"},
            {"b_m", context.support_width},
            {"n_dofs", result.n_dofs},
            {"n_contact_pairs", result.n_contact_pairs},
            {"n_increments", result.increments.size()},
            {"newton_iterations", n_newton},
            {"cutbacks", n_cutbacks},
            {"linear_solves", result.n_linear_solves},
            {"lu_factorizations", result.n_factorizations},
            {"krylov_iterations_on_lu_factors", result.n_krylov_iterations},
            {"force_balance_relative_error", worst_imbalance},
            {"wall_time_s", result.wall_times},
            {"joints", joints},
            {"body_motions_by_material_id", blocks},
            {"increments", increments}};
  }

  std::string
  joints_csv(const Contact::SolveResult &result,
             const FemReportContext &    context)
  {
    std::string csv = fmt::format(
      "# {}\n# Forces per metre of face; areas over b = {} m.\n"
      "increment,stage,stage_factor,joint,kind,normal_force_N_per_m,"
      "shear_force_N_per_m,contact_length_m,contact_area_m2,sigma_max_Pa,"
      "sigma_max_averaged_Pa,sigma_mean_Pa,n_stick,n_slip,n_open\n",
      numbering_note, context.support_width);
    for (std::size_t k = 0; k < result.increments.size(); ++k)
      {
        const auto &increment = result.increments[k];
        for (const auto &joint : increment.joints)
          csv += fmt::format(
            "{},{},{:.6f},{},{},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},"
            "{:.9e},{},{},{}\n",
            k + 1, stage_name(increment.stage), increment.stage_factor,
            joint.name, Compare::parse_joint_name(joint.name).kind,
            joint.normal_force, joint.shear_force, joint.closed_length,
            joint.closed_length * context.support_width,
            joint.peak_normal_stress, joint.averaged_peak_normal_stress,
            joint.mean_normal_stress, joint.counts.n_stick,
            joint.counts.n_slip, joint.counts.n_open);
      }
    return csv;
  }
} // namespace FloorBlock::Output
