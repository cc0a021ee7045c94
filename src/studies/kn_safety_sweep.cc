#include <common/input_error.h>
#include <common/interrupt.h>
#include <pipeline/fem_pipeline.h>

#include <deal.II/base/mpi.h>

#include <fmt/format.h>
#include <safety/corner_safety.h>
#include <studies/kn_safety_report.h>
#include <studies/kn_safety_sweep.h>

namespace FloorBlock::Studies
{
  namespace
  {
    /** The case's folder name: kn_1e+09, ..., rigid. */
    std::string
    case_name(const KnSafetyCase &record)
    {
      return record.law == Contact::JointLawKind::rigid ?
               "rigid" :
               fmt::format("kn_{:.0e}", record.normal_stiffness);
    }

    /** A corner's verdict: holds or fails (Safety::verdict_factor()). */
    std::string
    verdict(const Safety::CornerSafety &corner)
    {
      if (!corner.resolved())
        return "unresolved";
      return Safety::verdict_factor(corner) < 1. ? "fails" : "holds";
    }

    /** The face block's corner at the face joint (joint n), if any. */
    const Safety::CornerSafety *
    face_corner(const std::vector<Safety::CornerSafety> &corners,
                const unsigned int                       n_blocks)
    {
      for (const Safety::CornerSafety &corner : corners)
        if (corner.path.joint == n_blocks && corner.path.block == "face block")
          return &corner;
      return nullptr;
    }

    /**
     * The governing corner of a finished solve, as fem.json's floor_safety
     * states it, and the face corner; no factor where the solve did not
     * converge (the last converged increment is another load) or the
     * corner is unresolved.
     */
    void
    read_floor_safety(const Pipeline::FemOutcome &outcome,
                      const unsigned int          n_blocks,
                      KnSafetyCase               &record)
    {
      record.n_cells      = outcome.mesh.n_cells;
      const auto &corners = outcome.report.corner_safety;
      if (!outcome.converged || corners.empty())
        {
          record.status = record.face_status = "not converged";
          return;
        }
      const Safety::CornerSafety &governing = Safety::governing_corner(corners);
      record.governing_corner =
        governing.path.block + " at " + governing.path.joint_name;
      record.status = verdict(governing);
      if (governing.resolved())
        {
          record.point_factor = governing.point_factor;
          record.line_factor  = governing.line_factor;
          record.area_factor  = governing.area_factor;
        }
      record.verdict_method = Safety::to_string(governing.verdict_method);
      const Safety::CornerSafety *face = face_corner(corners, n_blocks);
      record.face_status               = face ? verdict(*face) : "none";
      if (face && face->resolved())
        {
          record.face_point_factor = face->point_factor;
          record.face_line_factor  = face->line_factor;
          record.face_area_factor  = face->area_factor;
        }
    }

    KnSafetyCase
    solve_case(const Parameters::ScenarioParameters &scene,
               KnSafetyCase                          record,
               const Output::ResultFolder           &folder)
    {
      Parameters::ScenarioParameters case_scene = scene;
      case_scene.joints.law                     = record.law;
      case_scene.joints.normal_stiffness        = record.normal_stiffness;
      case_scene.joints.shear_stiffness         = record.shear_stiffness;
      record.folder = folder.path_of("kn_safety/" + case_name(record));
      const Pipeline::FemOutcome outcome =
        Pipeline::solve_scene(case_scene,
                              Output::ResultFolder(record.folder),
                              false);
      read_floor_safety(outcome, scene.geometry.n_blocks, record);
      return record;
    }
  } // namespace

  void
  check_kn_safety_scene(const Parameters::ScenarioParameters &scene)
  {
    if (scene.model.chosen != Parameters::BlockModel::elastic)
      throw InputError(
        "Model/Blocks",
        scene.model.blocks == Parameters::BlockModel::rigid ? "rigid" : "auto",
        "elastic for `sweep --figure kn_safety` (" + scene.model.choice_reason +
          "): the floor's safety factor reads the stresses "
          "in the blocks, which rigid blocks do not have");
    const unsigned int n_processes =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    if (n_processes > 1)
      throw InputError("number of processes (mpirun -np)",
                       std::to_string(n_processes),
                       "1 for `sweep --figure kn_safety`: its seven solves "
                       "run one after the other");
  }

  KnSafetySweep
  kn_safety_sweep(const Parameters::ScenarioParameters   &scene,
                  const Output::ResultFolder             &folder,
                  const std::function<void(std::string)> &progress)
  {
    KnSafetySweep sweep;
    sweep.critical_distance = scene.strength.critical_distance;
    // The scene's own joints set the shear-to-normal ratio every kn keeps.
    sweep.stiffness_ratio =
      scene.joints.shear_stiffness / scene.joints.normal_stiffness;

    Parameters::ScenarioParameters swept = scene;
    if (swept.mesh.cells_per_critical_distance == 0)
      {
        swept.mesh.cells_per_critical_distance =
          kn_safety_cells_per_critical_distance;
        progress(fmt::format(
          "Mesh/Cells per critical distance = 0 resolves no corner path: "
          "the sweep solves with {} (cells of L/{} along the paths)",
          kn_safety_cells_per_critical_distance,
          kn_safety_cells_per_critical_distance));
      }
    sweep.cells_per_critical_distance = swept.mesh.cells_per_critical_distance;

    std::vector<KnSafetyCase> planned(kn_safety_normal_stiffnesses.size() + 1);
    for (std::size_t k = 0; k < kn_safety_normal_stiffnesses.size(); ++k)
      {
        planned[k].normal_stiffness = kn_safety_normal_stiffnesses[k];
        planned[k].shear_stiffness =
          sweep.stiffness_ratio * kn_safety_normal_stiffnesses[k];
      }
    planned.back().law = Contact::JointLawKind::rigid;
    for (const KnSafetyCase &record : planned)
      {
        stop_if_interrupted();
        sweep.cases.push_back(solve_case(swept, record, folder));
        progress(kn_safety_case_text(sweep.cases.back()));
      }
    return sweep;
  }
} // namespace FloorBlock::Studies
