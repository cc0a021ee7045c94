#include <compare/joint_name.h>
#include <output/fem_report.h>
#include <output/numbering_note.h>

#include <fmt/format.h>

#include <algorithm>


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

    /** |applied load + support reactions| (N/m): the relative numerator. */
    double
    absolute_imbalance(const Contact::ForceBalance &balance)
    {
      return (balance.applied_load + balance.support_reaction).norm();
    }

    /** Worst force balance over the increments that carry load. */
    struct BalanceSummary
    {
      double       worst_relative = 0.;
      double       worst_absolute = 0.; ///< N/m, over every increment
      unsigned int n_unloaded     = 0;
      double       largest_round_off_force = 0.; ///< N/m
    };

    json
    balance_json(const BalanceSummary &summary, const std::size_t n_increments)
    {
      std::string status = "ok";
      std::string text   = fmt::format(
        "worst relative error over the {} increments that carry load",
        n_increments - summary.n_unloaded);
      if (n_increments == 0)
        {
          status = "no increment";
          text   = "no increment converged: nothing to balance";
        }
      else if (summary.n_unloaded == n_increments)
        {
          status = "no load";
          text   = fmt::format(
            "no increment carries load (the applied load, the support "
            "reactions and every joint force stay below the round-off of the "
            "elastic forces, at most {:.1e} N/m): a relative error of a zero "
            "load is undefined and reported as 0; the absolute error is the "
            "round-off",
            summary.largest_round_off_force);
        }
      else if (summary.n_unloaded > 0)
        text += fmt::format("; {} increments carry no load and are left out "
                            "(their relative error is reported as 0)",
                            summary.n_unloaded);
      return {{"force_balance_relative_error", summary.worst_relative},
              {"force_balance_absolute_error_N_per_m", summary.worst_absolute},
              {"force_balance_status", status},
              {"force_balance_status_text", text}};
    }
  } // namespace

  std::string
  no_load_text(const Compare::LoadCheck &check)
  {
    return fmt::format(
      "the FEM carries no load: the applied load, the support reactions and "
      "every joint force are at most {:.1e} N/m, below the round-off of the "
      "elastic forces its displacements cause ({:.0e} E |u|max = {:.1e} N/m), "
      "so there is nothing to compare",
      check.largest_force, Compare::round_off_force_fraction,
      check.round_off_force);
  }

  std::string
  force_balance_text(const json &fem)
  {
    const std::string status = fem["force_balance_status"];
    const double      absolute =
      fem["force_balance_absolute_error_N_per_m"].get<double>();
    if (status == "no load")
      return fmt::format("no load (force balance {:.1e} N/m, round-off)",
                         absolute);
    if (status != "ok")
      return "force balance: " + status;
    return fmt::format("force balance error {:.1e} ({:.1e} N/m)",
                       fem["force_balance_relative_error"].get<double>(),
                       absolute);
  }

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
    json           increments = json::array();
    unsigned int   n_newton   = 0;
    unsigned int   n_cutbacks = context.cutbacks_before_failure;
    BalanceSummary balance;
    for (const auto &increment : result.increments)
      {
        n_newton += increment.n_newton_iterations;
        n_cutbacks += increment.n_cutbacks;
        const Compare::LoadCheck load =
          Compare::check_load(increment, context.youngs_modulus);
        const double relative =
          load.carries_load() ? increment.balance.relative_imbalance : 0.;
        const double absolute = absolute_imbalance(increment.balance);
        balance.worst_relative = std::max(balance.worst_relative, relative);
        balance.worst_absolute = std::max(balance.worst_absolute, absolute);
        balance.n_unloaded += load.carries_load() ? 0 : 1;
        balance.largest_round_off_force =
          std::max(balance.largest_round_off_force, load.round_off_force);
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
           {"force_balance_relative_error", relative},
           {"force_balance_absolute_error_N_per_m", absolute},
           {"force_balance_status", load.carries_load() ? "ok" : "no load"},
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

    json fem = {{"status", context.status},
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
            {"linear_solves_above_tolerance", result.n_solves_above_tolerance},
            {"wall_time_s", result.wall_times},
            {"joints", joints},
            {"body_motions_by_material_id", blocks},
            {"increments", increments}};
    fem.update(balance_json(balance, result.increments.size()));
    return fem;
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
