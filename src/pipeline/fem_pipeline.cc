#include <pipeline/fem_pipeline.h>
#include <pipeline/deformed_view.h>
#include <pipeline/rigid_pipeline.h>
#include <common/units.h>
#include <contact/contact_solver.h>
#include <contact/joint_report.h>
#include <geometry/triangulation_reader.h>
#include <scene/assembly_inputs.h>
#include <scene/contact_inputs.h>
#include <scene/floor_scene.h>
#include <scene/rigid_inputs.h>

#include <deal.II/grid/tria.h>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace FloorBlock::Pipeline
{
  using nlohmann::json;

  namespace
  {
    std::string
    failure_text(const Contact::ContactSolveFailure &failure)
    {
      std::string text = failure.what();
      for (const std::string &attempt : failure.attempts)
        text += "; tried: " + attempt;
      return text;
    }

    /** What fem.json says about the work of a failed solve. */
    json
    failure_json(const Contact::ContactSolveFailure &failure,
                 const Parameters::SolverParameters &solver)
    {
      return {
        {"cutbacks_before_failure", solver.max_cutbacks},
        {"n_failed_attempts", failure.attempts.size()},
        {"failed_attempts", failure.attempts},
        {"failed_newton_iterations",
         failure.partial_result.n_failed_newton_iterations},
        {"counted",
         "n_increments, newton_iterations and increments cover every "
         "converged increment; cutbacks adds cutbacks_before_failure, the "
         "cutbacks of the increment that failed; failed_newton_iterations, "
         "linear_solves, lu_factorizations and wall_time_s include the "
         "failed attempts"}};
    }
    /**
     * Whether the joints overlap by more than small-strain contact allows:
     * 5 % of the smaller block side. The compliant law's overlap t_n / k_n
     * is 2.3 mm on the default scene with Table 6.1's k_n = 9e9 Pa/m, and
     * stays below 9 mm for the 77 MPa peaks of the steepest chapter floors
     * (the chapter's own joints, not to be flagged); with k_n = 1e6 Pa/m
     * the loaded blocks sink 2.2 m into the bed and the solver still
     * converges, so that answer needs a warning.
     */
    json
    overlap_check(const Contact::SolveResult            &result,
                  const Parameters::ScenarioParameters  &scene)
    {
      constexpr double relative_limit = 0.05;
      const double     limit =
        relative_limit *
        std::min(scene.geometry.block_width, scene.geometry.block_height);
      const double overlap =
        result.increments.empty() ?
          0. :
          Contact::largest_overlap(result.increments.back().joints);
      const bool large = overlap > limit;
      return {{"largest_overlap_m", overlap},
              {"limit_m", limit},
              {"status", large ? "large" : "ok"},
              {"text",
               large ?
                 fmt::format("the joint sides overlap by up to {:.3g} m, "
                             "more than 5 % of the smaller block side "
                             "({:.3g} m): Joints/Normal stiffness is too soft "
                             "for these loads, and the small-strain contact "
                             "answer is not physical",
                             overlap, limit) :
                 fmt::format("largest overlap {:.3g} m, within 5 % of the "
                             "smaller block side",
                             overlap)}};
    }
  } // namespace

  FemOutcome
  solve_scene(const Parameters::ScenarioParameters &scene,
              const Output::ResultFolder &          folder,
              const bool                            write_vtu,
              const SolveExtras &                   extras)
  {
    if (Scene::uses_rigid_blocks(scene))
      return solve_rigid_scene(scene, folder);
    dealii::Triangulation<2>       triangulation;
    const Geometry::MeshStatistics mesh =
      mesh_scene(scene, folder, extras.local_sizes, triangulation);
    return solve_meshed_scene(scene, triangulation, mesh, folder, write_vtu,
                              extras);
  }

  Geometry::MeshStatistics
  mesh_scene(const Parameters::ScenarioParameters   &scene,
             const Output::ResultFolder             &folder,
             const std::vector<Geometry::LocalSize> &local_sizes,
             dealii::Triangulation<2>               &triangulation)
  {
    // Gmsh writes the mesh itself, so the folder must exist first.
    std::filesystem::create_directories(folder.path_of(""));
    const Geometry::MeshStatistics mesh =
      Geometry::write_gmsh_mesh(Scene::assembly_description(scene),
                                folder.path_of("mesh.msh"), local_sizes);
    Geometry::read_triangulation(folder.path_of("mesh.msh"), triangulation);
    return mesh;
  }

  FemOutcome
  solve_meshed_scene(const Parameters::ScenarioParameters &scene,
                     const dealii::Triangulation<2>       &triangulation,
                     const Geometry::MeshStatistics       &mesh,
                     const Output::ResultFolder           &folder,
                     const bool                            write_vtu,
                     const SolveExtras                    &extras)
  {
    FemOutcome outcome;
    outcome.mesh = mesh;
    Output::FemReportContext context{scene.geometry.n_blocks,
                                     scene.geometry.support_width,
                                     "converged",
                                     "every loading increment converged",
                                     scene.material.youngs_modulus()};
    Contact::ContactSolver solver(
      triangulation,
      Scene::make_floor_scene(Scene::floor_scene_settings(scene)),
      Scene::contact_solver_settings(scene,
                                     write_vtu ? folder.path_of("vtu") : ""));
    json failure_record;
    try
      {
        outcome.result    = solver.run();
        outcome.converged = true;
      }
    catch (const Contact::ContactSolveFailure &failure)
      {
        context.status      = "not converged";
        context.status_text = failure_text(failure);
        context.cutbacks_before_failure = scene.solver.max_cutbacks;
        failure_record = failure_json(failure, scene.solver);
        outcome.result = failure.partial_result;
      }
    if (extras.inspect)
      extras.inspect(solver);
    if (write_vtu)
      write_deformed_view(solver, folder.path_of("deformed.png"));

    outcome.fem = Output::fem_json(outcome.result, context);
    if (!outcome.converged)
      {
        outcome.fem["failure"] = failure_record;
      }
    outcome.fem["joint_overlap"] = overlap_check(outcome.result, scene);
    outcome.fem["model"]        = "elastic FEM";
    outcome.fem["model_choice"] = scene.model.choice_reason;
    outcome.fem["mesh"] = {{"n_cells", outcome.mesh.n_cells},
                           {"n_nodes", outcome.mesh.n_nodes},
                           {"wall_time_s", outcome.mesh.wall_time}};
    folder.write_json("fem.json", outcome.fem);
    folder.write("joints.csv", Output::joints_csv(outcome.result, context));
    return outcome;
  }

  std::string
  fem_summary_text(const FemOutcome &outcome)
  {
    constexpr double kN  = Units::newtons_per_kilonewton;
    constexpr double MPa = Units::pascals_per_megapascal;
    const bool  meshed = outcome.fem["mesh"].is_object();
    // A failed solve keeps only its last converged increment (fem.json
    // "failure"): say so instead of passing it off as the whole run.
    const std::string increments =
      outcome.fem.contains("failure") ?
        fmt::format("{} converged increment(s) kept with {} Newton "
                    "iterations (failed attempts not counted), {} cutbacks",
                    outcome.result.increments.size(),
                    outcome.fem["newton_iterations"].get<unsigned int>(),
                    outcome.fem["cutbacks"].get<unsigned int>()) :
        fmt::format("{} increments, {} Newton iterations, {} cutbacks",
                    outcome.result.increments.size(),
                    outcome.fem["newton_iterations"].get<unsigned int>(),
                    outcome.fem["cutbacks"].get<unsigned int>());
    std::string text = fmt::format(
      "{}: {} ({}), {}{} DoFs, {}, {}\n",
      outcome.fem["model"].get<std::string>(),
      outcome.fem["status"].get<std::string>(),
      outcome.fem["status_text"].get<std::string>(),
      meshed ? fmt::format("{} cells, ", outcome.mesh.n_cells) : "",
      outcome.result.n_dofs, increments,
      Output::force_balance_text(outcome.fem));
    text += fmt::format("  {:<12} {:>12} {:>14} {:>12} {:>14} {:>10}\n",
                        "joint", "N (kN/m)", "contact (mm)",
                        "peak (MPa)", "averaged (MPa)", "state");
    for (const auto &joint : outcome.fem["joints"])
      text += fmt::format(
        "  {:<12} {:>12.1f} {:>14.1f} {:>12.2f} {:>14.2f} {:>10}\n",
        joint["name"].get<std::string>(),
        joint["normal_force_N_per_m"].get<double>() / kN,
        joint["contact_length_m"].get<double>() * 1e3,
        joint["sigma_max_Pa"].get<double>() / MPa,
        joint["sigma_max_averaged_Pa"].get<double>() / MPa,
        joint["state"].get<std::string>());
    std::string times =
      meshed ? fmt::format("mesh {:.3f} s", outcome.mesh.wall_time) : "";
    for (const auto &[section, seconds] : outcome.result.wall_times)
      times += fmt::format("{}{} {:.3f} s", times.empty() ? "" : ", ",
                           section, seconds);
    text += "  " + times + "\n";
    if (outcome.fem.contains("joint_overlap") &&
        outcome.fem["joint_overlap"]["status"] == "large")
      text += "  warning: " +
              outcome.fem["joint_overlap"]["text"].get<std::string>() + "\n";
    return text;
  }
} // namespace FloorBlock::Pipeline
