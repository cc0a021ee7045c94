#include <compare/joint_name.h>
#include <output/fem_report.h>
#include <output/floor_safety_report.h>
#include <output/numbering_note.h>

#include <fmt/format.h>

#include <algorithm>


namespace FloorBlock::Output
{
  using nlohmann::json;

  namespace
  {
    json
    balance_json(const ForceBalanceSummary &balance)
    {
      return {{"force_balance_relative_error", balance.worst_relative_error},
              {"force_balance_absolute_error_N_per_m",
               balance.worst_absolute_error},
              {"force_balance_status", balance.status},
              {"force_balance_status_text", balance.status_text}};
    }

    json
    failure_json(const SolveFailureRecord &failure)
    {
      return {
        {"cutbacks_before_failure", failure.cutbacks_before_failure},
        {"n_failed_attempts", failure.failed_attempts.size()},
        {"failed_attempts", failure.failed_attempts},
        {"failed_newton_iterations", failure.n_failed_newton_iterations},
        {"counted",
         "n_increments, newton_iterations and increments cover every "
         "converged increment; cutbacks adds cutbacks_before_failure, the "
         "cutbacks of the increment that failed; failed_newton_iterations, "
         "linear_solves, lu_factorizations and wall_time_s include the "
         "failed attempts"}};
    }

    json
    overlap_json(const OverlapCheck &overlap)
    {
      return {{"largest_overlap_m", overlap.largest_overlap},
              {"limit_m", overlap.limit},
              {"status", overlap.large ? "large" : "ok"},
              {"text", overlap.text}};
    }

    /** What the rigid model is, and what it does not produce. */
    void
    describe_rigid_model(const RigidModelNote &rigid, json &fem)
    {
      fem["rigid_status"] = rigid.rigid_status;
      fem["dofs"] = "3 per block: centroid translation x, y and rotation";
      fem["points_per_joint"] = rigid.points_per_joint;
      fem["tractions"] =
        "joint springs on rigid blocks: t_n = kn x overlap at each "
        "integration point (the Winkler reading of Eq. 6.51)";
      fem["force_balance_definition"] =
        "largest force or moment (over L) imbalance of a single block, from "
        "the joint resultants and the loads, over the larger of the total "
        "load and the largest joint resultant";
      fem["n_contact_pairs"] = nullptr;
      fem["mesh"]            = nullptr;
      fem["absent"]          = {{"mesh", "rigid blocks need no mesh"},
                                {"vtu", "no field to write: the blocks move rigidly"},
                                {"n_contact_pairs",
                                 "joints are integrated at points, not paired "
                                          "nodes"}};
      if (rigid.corner_rounding_radius > 0.)
        fem["geometry_note"] =
          "Geometry/Corner rounding radius = " +
          std::to_string(rigid.corner_rounding_radius) +
          " m is ignored: the rigid blocks have sharp corners";
    }
  } // namespace

  namespace
  {
    /**
     * The fields a joint has in 2D and in 3D alike: name and bodies,
     * forces per metre of face, the contact length, the peaks and the
     * state.
     */
    json
    common_joint_json(const Contact::JointReport &joint,
                      const std::string          &kind,
                      const json                 &bodies)
    {
      return {{"name", joint.name},
              {"kind", kind},
              {"blocks", bodies},
              {"normal_force_N_per_m", joint.normal_force},
              {"shear_force_N_per_m", joint.shear_force},
              {"contact_length_m", joint.closed_length},
              {"sigma_max_Pa", joint.peak_normal_stress},
              {"sigma_max_averaged_Pa", joint.averaged_peak_normal_stress},
              {"averaging_length_m", joint.averaging_length},
              {"sigma_mean_Pa", joint.mean_normal_stress},
              {"state", state_summary(joint.counts)},
              {"n_stick", joint.counts.n_stick},
              {"n_slip", joint.counts.n_slip},
              {"n_open", joint.counts.n_open}};
    }

    /**
     * A joint of a 3D scene: besides the common fields, the force in
     * total, the contact as an area, the peak's 3D position; no "over b"
     * figures (the 2D reading of a support width).
     */
    json
    swept_joint_json(const Contact::JointReport &joint,
                     const std::string          &kind,
                     const json                 &bodies)
    {
      json result                    = common_joint_json(joint, kind, bodies);
      result["normal_force_N"]       = joint.normal_force * joint.face_length;
      result["contact_area_m2"]      = joint.closed_length * joint.face_length;
      result["face_length_m"]        = joint.face_length;
      result["sigma_max_position_m"] = {joint.peak_position[0],
                                        joint.peak_position[1],
                                        joint.peak_position_z};
      json along_face                = json::array();
      for (const Contact::JointSection &section : joint.along_face)
        along_face.push_back({{"z_m", section.z},
                              {"z_range_m", {section.z_from, section.z_to}},
                              {"normal_force_N_per_m", section.normal_force},
                              {"shear_force_N_per_m", section.shear_force},
                              {"contact_length_m", section.closed_length},
                              {"sigma_max_Pa", section.peak_normal_stress}});
      result["along_face"] = along_face;
      return result;
    }

    /**
     * fem.json's account of a 3D scene's support load: the force applied
     * against the parameter, and where it stands.
     */
    void
    describe_support_load(const SweptSupportLoad &load, json &fem)
    {
      fem["applied_load_N"] = load.applied_load;
      fem["support_load_N"] = load.support_load;
      fem["loaded_area_m2"] = load.loaded_area;
      if (load.on_footprint)
        fem["support_footprint"] = {
          {"z_range_m", {load.footprint_start, load.footprint_end}},
          {"length_m", load.footprint_end - load.footprint_start},
          {"reading",
           "one support: its whole Support load on the loaded blocks' tops "
           "within the footprint (Loading/Footprint length), none elsewhere; "
           "applied_load_N, the force integrated over the loaded faces, "
           "equals support_load_N"}};
      else
        fem["support_footprint"] = {
          {"z_range_m", nullptr},
          {"length_m", nullptr},
          {"reading",
           "no footprint (Loading/Footprint length = 0): the 2D load per "
           "metre of face, Support load over the support width b, along the "
           "whole face, as under supports side by side; applied_load_N = "
           "support_load_N x face length / b"}};
    }

    /** The swept joints' face length (m), 0 for a 2D result. */
    double
    face_length_of(const Contact::SolveResult &result)
    {
      if (result.increments.empty() || result.increments.back().joints.empty())
        return 0.;
      return result.increments.back().joints.front().face_length;
    }
  } // namespace

  std::string
  state_summary(const Contact::StateCounts &counts)
  {
    if (counts.n_closed() == 0)
      return "open";
    if (counts.n_slip == 0)
      return "stick";
    return counts.n_stick == 0 ? "slip" : "stick-slip";
  }

  std::string
  no_load_text(const Compare::LoadCheck &check)
  {
    return fmt::format(
      "the FEM carries no load: the applied load, the support reactions and "
      "every joint force are at most {:.1e} N/m, below the round-off of the "
      "elastic forces its displacements cause ({:.0e} E |u|max = {:.1e} N/m), "
      "so there is nothing to compare",
      check.largest_force,
      Compare::round_off_force_fraction,
      check.round_off_force);
  }

  std::string
  force_balance_text(const ForceBalanceSummary &balance)
  {
    if (balance.status == "no load")
      return fmt::format("no load (force balance {:.1e} N/m, round-off)",
                         balance.worst_absolute_error);
    if (balance.status != "ok")
      return "force balance: " + balance.status;
    return fmt::format("force balance error {:.1e} ({:.1e} N/m)",
                       balance.worst_relative_error,
                       balance.worst_absolute_error);
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
  stage_name(const Loading::LoadStage stage)
  {
    switch (stage)
      {
        case Loading::LoadStage::gravity:
          return "gravity";
        case Loading::LoadStage::support_pressure:
          return "support_load";
        case Loading::LoadStage::uplift:
          return "uplift";
      }
    return "unknown";
  }

  json
  joint_json(const Contact::JointReport &joint,
             const unsigned int          n_blocks,
             const double                support_width)
  {
    const auto name   = Compare::parse_joint_name(joint.name);
    const json bodies = joint_bodies(name.kind, name.number, n_blocks);
    if (joint.swept())
      return swept_joint_json(joint, name.kind, bodies);
    json result = common_joint_json(joint, name.kind, bodies);
    result["normal_force_N_over_b"] = joint.normal_force * support_width;
    result["contact_area_m2"]       = joint.closed_length * support_width;
    result["sigma_max_position_m"]  = {joint.peak_position[0],
                                       joint.peak_position[1]};
    return result;
  }

  json
  fem_json(const Contact::SolveResult &result, const FemReport &report)
  {
    json increments = json::array();
    for (std::size_t k = 0; k < result.increments.size(); ++k)
      {
        const auto &increment = result.increments[k];
        const auto &balance   = report.increment_balances[k];
        increments.push_back(
          {{"stage", Output::stage_name(increment.stage)},
           {"stage_factor", increment.stage_factor},
           {"newton_iterations", increment.n_newton_iterations},
           {"cutbacks", increment.n_cutbacks},
           {"started_from_penalty", increment.started_from_penalty},
           {"complementarity_parameter_factor",
            increment.complementarity_factor},
           {"relative_residual", increment.relative_residual},
           {"stopped_at_round_off_floor", increment.round_off_limited},
           {"n_stick", increment.counts.n_stick},
           {"n_slip", increment.counts.n_slip},
           {"n_open", increment.counts.n_open},
           {"force_balance_relative_error", balance.relative_error},
           {"force_balance_absolute_error_N_per_m", balance.absolute_error},
           {"force_balance_status", balance.carries_load ? "ok" : "no load"},
           {"wall_time_s", increment.wall_time}});
      }

    json joints = json::array();
    json blocks = json::object();
    if (!result.increments.empty())
      {
        const auto &last = result.increments.back();
        for (const auto &joint : last.joints)
          joints.push_back(
            joint_json(joint, report.n_blocks, report.support_width));
        for (const auto &[material, motion] : last.motions)
          blocks[std::to_string(material)] = {
            {"translation_m", {motion.translation[0], motion.translation[1]}},
            {"rotation_rad", motion.rotation}};
      }

    const double      face_length = face_length_of(result);
    const std::string forces_per =
      face_length > 0. ?
        fmt::format("3D scene, face length L = {} m: *_N_per_m per metre of "
                    "face (the joint's total over L, divided by L), "
                    "normal_force_N the total; contact_area_m2 the closed "
                    "area of the joint surface, contact_length_m = "
                    "contact_area_m2 / L",
                    face_length) :
        "*_N_per_m per metre of face; *_N_over_b and contact_area_m2 over "
        "the support width b";
    json fem = {{"status", report.status},
                {"status_text", report.status_text},
                {"numbering", numbering_note},
                {"forces_per", forces_per},
                {"b_m", report.support_width},
                {"n_dofs", result.n_dofs},
                {"n_contact_pairs", result.n_contact_pairs},
                {"n_increments", result.increments.size()},
                {"newton_iterations", report.n_newton_iterations},
                {"cutbacks", report.n_cutbacks},
                {"linear_solves", result.n_linear_solves},
                {"lu_factorizations", result.n_factorizations},
                {"krylov_iterations_on_lu_factors", result.n_krylov_iterations},
                {"amg_setups", result.n_amg_setups},
                {"krylov_iterations_with_amg", result.n_amg_krylov_iterations},
                {"linear_solves_above_tolerance",
                 result.n_solves_above_tolerance},
                {"wall_time_s", result.wall_times},
                {"joints", joints},
                {"body_motions_by_material_id", blocks},
                {"increments", increments},
                {"model", report.model},
                {"model_choice", report.model_choice}};
    fem.update(balance_json(report.force_balance));
    if (report.failure)
      fem["failure"] = failure_json(*report.failure);
    if (report.joint_overlap)
      fem["joint_overlap"] = overlap_json(*report.joint_overlap);
    if (report.mesh)
      {
        const Geometry::MeshStatistics &mesh = *report.mesh;
        fem["mesh"] = {{"n_cells", mesh.n_cells},
                       {"n_nodes", mesh.n_nodes},
                       {"wall_time_s", mesh.wall_time}};
        // Meshes refined by deal.II from another mesh have no sizing.
        if (!mesh.contact_zone_source.empty())
          fem["mesh"].update(
            {{"contact_zone_sizing", mesh.contact_zone_source},
             {"contact_zone_sizing_text", mesh.contact_zone_sizing},
             {"contact_zone_length_m", mesh.contact_zone_length},
             {"contact_zone_sizing_wall_time_s", mesh.sizing_wall_time}});
      }
    if (!report.corner_safety.empty())
      fem["floor_safety"] = floor_safety_json(report.corner_safety);
    if (report.rigid)
      describe_rigid_model(*report.rigid, fem);
    if (report.support_load)
      describe_support_load(*report.support_load, fem);
    return fem;
  }

  std::string
  joints_csv(const Contact::SolveResult &result, const double support_width)
  {
    // 3D: the areas are the joints' own, over the face length.
    const double face_length = face_length_of(result);
    const double area_width  = face_length > 0. ? face_length : support_width;
    const std::string units =
      face_length > 0. ?
        fmt::format("3D scene, face length L = {} m: forces per metre of "
                    "face (totals over L divided by L); contact_area_m2 the "
                    "joint's closed area, contact_length_m = area / L.",
                    face_length) :
        fmt::format("Forces per metre of face; areas over b = {} m.",
                    support_width);
    std::string csv = fmt::format(
      "# {}\n# {}\n"
      "increment,stage,stage_factor,joint,kind,normal_force_N_per_m,"
      "shear_force_N_per_m,contact_length_m,contact_area_m2,sigma_max_Pa,"
      "sigma_max_averaged_Pa,sigma_mean_Pa,n_stick,n_slip,n_open\n",
      numbering_note,
      units);
    for (std::size_t k = 0; k < result.increments.size(); ++k)
      {
        const auto &increment = result.increments[k];
        for (const auto &joint : increment.joints)
          csv += fmt::format(
            "{},{},{:.6f},{},{},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},"
            "{:.9e},{},{},{}\n",
            k + 1,
            Output::stage_name(increment.stage),
            increment.stage_factor,
            joint.name,
            Compare::parse_joint_name(joint.name).kind,
            joint.normal_force,
            joint.shear_force,
            joint.closed_length,
            joint.closed_length * area_width,
            joint.peak_normal_stress,
            joint.averaged_peak_normal_stress,
            joint.mean_normal_stress,
            joint.counts.n_stick,
            joint.counts.n_slip,
            joint.counts.n_open);
      }
    return csv;
  }

  std::string
  joint_profiles_csv(const Contact::SolveResult &result)
  {
    std::string csv = fmt::format(
      "# {}\n# One row per node pair of a joint, in order along the joint; "
      "normal traction > 0 in compression, shear along the joint tangent "
      "(-n_y, n_x) of the pair's side-A normal n{}.\n"
      "increment,stage,stage_factor,joint,node,x_m,y_m,arc_position_m,gap_m,"
      "normal_traction_Pa,shear_traction_Pa,state\n",
      numbering_note,
      face_length_of(result) > 0. ?
        "; 3D scene: the cross-section nearest the middle of the face" :
        "");
    for (std::size_t k = 0; k < result.increments.size(); ++k)
      {
        const auto &increment = result.increments[k];
        const bool  stage_end =
          k + 1 == result.increments.size() ||
          result.increments[k + 1].stage != increment.stage;
        if (!stage_end)
          continue;
        for (const auto &joint : increment.joints)
          for (std::size_t i = 0; i < joint.profile.size(); ++i)
            {
              const auto &sample = joint.profile[i];
              csv += fmt::format(
                "{},{},{:.6f},{},{},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},"
                "{:.9e},{}\n",
                k + 1,
                Output::stage_name(increment.stage),
                increment.stage_factor,
                joint.name,
                i,
                sample.position[0],
                sample.position[1],
                sample.arc_position,
                sample.gap,
                sample.normal_traction,
                sample.tangential_traction,
                Contact::state_name(sample.state));
            }
      }
    return csv;
  }
} // namespace FloorBlock::Output
