#include <common/atomic_file.h>
#include <common/input_error.h>
#include <common/units.h>
#include <compare/joint_name.h>
#include <contact/contact_solver.h>
#include <fem/surface_load.h>
#include <geometry/extruded_assembly.h>
#include <geometry/refinement_manifolds.h>
#include <geometry/triangulation_reader.h>
#include <output/contact_area_picture.h>
#include <output/floor_safety_report.h>
#include <pipeline/contact_zone_sizing.h>
#include <pipeline/corner_path_refinement.h>
#include <pipeline/deformed_view.h>
#include <pipeline/distributed_swept_mesh.h>
#include <pipeline/fem_pipeline.h>
#include <pipeline/fem_report_builder.h>
#include <pipeline/rigid_pipeline.h>
#include <pipeline/strength_factor_view.h>
#include <scene/assembly_inputs.h>
#include <scene/contact_inputs.h>
#include <scene/floor_contact_problem.h>
#include <scene/mesh_sizing.h>
#include <scene/rigid_inputs.h>
#include <scene/support_footprint.h>
#include <scene/swept_contact_problem.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/tria.h>

#include <fmt/format.h>
#include <postprocess/increment_post_processor.h>
#include <postprocess/joint_report.h>
#include <postprocess/vtu_writer.h>
#include <safety/strength_factor_field.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace FloorBlock::Pipeline
{
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

    /**
     * Whether the joints overlap by more than small-strain contact allows:
     * 5 % of the smaller block side. The compliant law's overlap t_n / k_n
     * is 2.3 mm on the default scene with Table 6.1's k_n = 9e9 Pa/m, and
     * stays below 9 mm for the 77 MPa peaks of the steepest chapter floors
     * (the chapter's own joints, not to be flagged); with k_n = 1e6 Pa/m
     * the loaded blocks sink 2.2 m into the bed and the solver still
     * converges, so that answer needs a warning.
     */
    Output::OverlapCheck
    overlap_check(const Contact::SolveResult           &result,
                  const Parameters::ScenarioParameters &scene)
    {
      constexpr double relative_limit = 0.05;
      const double     limit =
        relative_limit *
        std::min(scene.geometry.block_width, scene.geometry.block_height);
      const double overlap =
        result.increments.empty() ?
          0. :
          Postprocess::largest_overlap(result.increments.back().joints);
      const bool large = overlap > limit;
      return {overlap,
              limit,
              large,
              large ?
                fmt::format("the joint sides overlap by up to {:.3g} m, "
                            "more than 5 % of the smaller block side "
                            "({:.3g} m): Joints/Normal stiffness is too soft "
                            "for these loads, and the small-strain contact "
                            "answer is not physical",
                            overlap,
                            limit) :
                fmt::format("largest overlap {:.3g} m, within 5 % of the "
                            "smaller block side",
                            overlap)};
    }

    /**
     * What every increment adds in 2D: its floor safety factors (the
     * history along the floor lift, Output::safety_along_lift(); scenes
     * with Mesh/Cells per critical distance only) and the strength-factor
     * field of its VTU file. The full corner records of the latest
     * increment are kept in @p latest_corners, so that the solve's report
     * need not read the same stresses again.
     */
    template <int dim>
    Postprocess::IncrementExtras
    increment_extras(const Parameters::ScenarioParameters &scene,
                     const Contact::ContactSolver<dim>    &solver,
                     const Contact::ContactProblem<dim>   &problem,
                     std::vector<Safety::CornerSafety>    &latest_corners)
    {
      if constexpr (dim != 2)
        return {};
      else
        {
          Postprocess::IncrementExtras extras;
          // Only scenes that resolve the corner paths (Mesh/Cells per
          // critical distance) get a history: elsewhere every increment's
          // factors would be cells' values, at the cost of reading the
          // stresses at every increment.
          if (scene.mesh.cells_per_critical_distance > 0)
            extras.describe =
              [&scene,
               &solver,
               &problem,
               &latest_corners,
               // The mesh stays through the load path: its sample points
               // are located at the first increment and kept.
               sample_points =
                 std::make_shared<std::vector<Safety::CornerSamplePoints>>()](
                const dealii::TrilinosWrappers::MPI::Vector &solution,
                Contact::IncrementResult                    &increment) {
                if (sample_points->empty())
                  *sample_points =
                    Safety::locate_corner_samples(scene, solver.space());
                latest_corners = Safety::corner_safety(scene,
                                                       *sample_points,
                                                       solver.space(),
                                                       problem.model,
                                                       solution);
                for (const Safety::CornerSafety &corner : latest_corners)
                  increment.corner_factors.push_back(
                    {corner.path.label(),
                     corner.point_factor,
                     corner.line_factor,
                     corner.area_factor,
                     Safety::verdict_factor(corner),
                     Safety::to_string(corner.verdict_method),
                     corner.resolved()});
              };
          extras.cell_fields =
            [&scene, &solver, &problem](
              const dealii::TrilinosWrappers::MPI::Vector &solution) {
              return Postprocess::CellFields{
                {"strength_factor",
                 Safety::cell_strength_factors(
                   scene, solver.space(), problem.model, solution)}};
            };
          return extras;
        }
    }

    /**
     * The contact solve on a mesh and what it writes: fem.json (with the
     * failure record if the load path stopped), joints.csv,
     * joint_profiles.csv and the VTU series. @p after_solve sees the
     * solver once the loading path ended, converged or not.
     */
    template <int dim>
    FemOutcome
    solve_on_mesh(
      const Parameters::ScenarioParameters &scene,
      const dealii::Triangulation<dim>     &triangulation,
      const Contact::ContactProblem<dim>   &problem,
      const Geometry::MeshStatistics       &mesh,
      const Output::ResultFolder           &folder,
      const bool                            write_vtu,
      const std::function<void(const Contact::ContactSolver<dim> &)>
                                                    &after_solve,
      const std::optional<Output::SweptSupportLoad> &support_load = {})
    {
      FemOutcome outcome;
      outcome.mesh = mesh;
      const Contact::ContactSolverSettings numerics =
        Scene::contact_solver_settings(scene,
                                       write_vtu ? folder.path_of("vtu") : "");
      Contact::ContactSolver<dim> solver(triangulation, problem, numerics);
      std::string status_text = "every loading increment converged";
      std::optional<Output::SolveFailureRecord> failure_record;
      std::vector<Safety::CornerSafety>         corner_safety;
      try
        {
          outcome.result = Postprocess::solve_with_reports(
            solver,
            numerics,
            increment_extras(scene, solver, problem, corner_safety));
          outcome.converged = true;
        }
      catch (const Contact::ContactSolveFailure &failure)
        {
          status_text    = failure_text(failure);
          failure_record = Output::SolveFailureRecord{
            scene.solver.max_cutbacks,
            failure.attempts,
            failure.partial_result.n_failed_newton_iterations};
          outcome.result = failure.partial_result;
        }
      after_solve(solver);
      // A converged solve's last increment has left its corners in
      // corner_safety already (scenes with a history only); after a failure
      // they are read from the state the solver kept.
      if constexpr (dim == 2)
        if (!outcome.result.increments.empty() &&
            (!outcome.converged || corner_safety.empty()))
          corner_safety = Safety::corner_safety(scene,
                                                solver.space(),
                                                problem.model,
                                                solver.solution());
      outcome.report =
        make_fem_report(outcome.result,
                        scene,
                        "elastic FEM",
                        outcome.converged,
                        status_text,
                        failure_record ?
                          failure_record->cutbacks_before_failure :
                          0);
      outcome.report.failure       = failure_record;
      outcome.report.joint_overlap = overlap_check(outcome.result, scene);
      outcome.report.mesh          = outcome.mesh;
      outcome.report.support_load  = support_load;
      outcome.report.corner_safety = std::move(corner_safety);
      write_fem_files(outcome, folder);
      return outcome;
    }

    /**
     * The support load the 3D mesh carries: the pressures' resultant over
     * the faces that carry them, along the vertical, at full load.
     */
    Output::SweptSupportLoad
    swept_support_load(const Parameters::ScenarioParameters         &scene,
                       const std::optional<Scene::SupportFootprint> &footprint,
                       const dealii::Triangulation<3>               &solid,
                       const Fem::ElasticModel<3>                   &model)
    {
      const Fem::SurfaceLoad<3> applied =
        Fem::applied_surface_load(solid, model);
      Output::SweptSupportLoad load;
      load.support_load = scene.loading.support_load;
      load.applied_load = applied.force * model.down;
      load.loaded_area  = applied.loaded_area;
      load.on_footprint = footprint.has_value();
      if (footprint)
        {
          load.footprint_start = footprint->start;
          load.footprint_end   = footprint->end;
        }
      return load;
    }

    /**
     * A 3D solve's face joint: face_contact_area.csv and .png, the contact
     * area over the joint surface (Output::contact_area_csv()).
     */
    void
    write_face_contact_area(const FemOutcome                     &outcome,
                            const Parameters::ScenarioParameters &scene,
                            const Output::ResultFolder           &folder)
    {
      if (!folder.writes_files() || outcome.result.increments.empty())
        return;
      const std::string face =
        Compare::face_joint_name(scene.geometry.n_blocks);
      for (const Contact::JointReport &joint :
           outcome.result.increments.back().joints)
        if (joint.name == face)
          {
            folder.write("face_contact_area.csv",
                         Output::contact_area_csv(joint));
            Output::write_contact_area_picture(
              joint, folder.path_of("face_contact_area.png"));
          }
    }
  } // namespace

  FemOutcome
  solve_scene(const Parameters::ScenarioParameters &scene,
              const Output::ResultFolder           &folder,
              const bool                            write_vtu,
              const SolveExtras                    &extras)
  {
    if (scene.geometry.dimension == 3)
      {
        if (!extras.local_sizes.empty() || extras.inspect)
          throw std::logic_error("solve_scene: size requests and solver "
                                 "inspection are 2D only");
        return solve_swept_scene(scene, folder, write_vtu);
      }
    if (Scene::uses_rigid_blocks(scene))
      return solve_rigid_scene(scene, folder);
    dealii::Triangulation<2>       triangulation;
    const Geometry::MeshStatistics mesh =
      mesh_scene(scene, folder, extras.local_sizes, triangulation);
    return solve_meshed_scene(
      scene, triangulation, mesh, folder, write_vtu, extras);
  }

  Geometry::MeshStatistics
  mesh_scene(const Parameters::ScenarioParameters   &scene,
             const Output::ResultFolder             &folder,
             const std::vector<Geometry::LocalSize> &local_sizes,
             dealii::Triangulation<2>               &triangulation)
  {
    // Gmsh writes the mesh itself, so the folder must exist first.
    std::filesystem::create_directories(folder.path_of(""));
    const auto description = Scene::assembly_description(scene);
    // Contact-zone sizing (Eq. 6.51, else a first solve), then any requests
    // of the caller (converge --mode remesh); local_size_at() takes the
    // smallest.
    dealii::Timer                    sizing_timer;
    const Scene::ContactZoneSizing   zones = contact_zone_sizing(scene, folder);
    const double                     sizing_time = sizing_timer.wall_time();
    std::vector<Geometry::LocalSize> sizes       = zones.sizes;
    const std::vector<Geometry::LocalSize> corners =
      Scene::critical_distance_sizes(scene);
    sizes.insert(sizes.end(), corners.begin(), corners.end());
    sizes.insert(sizes.end(), local_sizes.begin(), local_sizes.end());
    Geometry::MeshStatistics mesh =
      Geometry::write_gmsh_mesh(description, folder.path_of("mesh.msh"), sizes);
    mesh.contact_zone_source = Scene::source_key(zones.source);
    mesh.contact_zone_sizing =
      Scene::describe(zones, scene.mesh.cells_per_contact_length);
    mesh.contact_zone_length = zones.contact_length;
    mesh.sizing_wall_time    = sizing_time;
    Geometry::read_triangulation(folder.path_of("mesh.msh"), triangulation);
    dealii::Timer      timer;
    const unsigned int n_refinements = Scene::global_refinements(scene);
    if (n_refinements > 0)
      Geometry::refine_globally_on_curves(description,
                                          n_refinements,
                                          triangulation);
    const unsigned int n_path_cells = refine_corner_paths(scene, triangulation);
    if (n_refinements > 0 || n_path_cells > 0)
      {
        write_solved_mesh(triangulation, folder.path_of("mesh.msh"), mesh);
        mesh.wall_time += timer.wall_time();
      }
    return mesh;
  }

  template <int dim>
  void
  write_solved_mesh(const dealii::Triangulation<dim> &triangulation,
                    const std::string                &msh_path,
                    Geometry::MeshStatistics         &statistics)
  {
    std::ostringstream msh;
    dealii::GridOut().write_msh(triangulation, msh);
    write_file_atomically(msh_path, msh.str());
    statistics.n_cells = triangulation.n_active_cells();
    statistics.n_nodes = triangulation.n_used_vertices();
  }

  template void
  write_solved_mesh(const dealii::Triangulation<2> &,
                    const std::string &,
                    Geometry::MeshStatistics &);
  template void
  write_solved_mesh(const dealii::Triangulation<3> &,
                    const std::string &,
                    Geometry::MeshStatistics &);

  FemOutcome
  solve_meshed_scene(const Parameters::ScenarioParameters &scene,
                     const dealii::Triangulation<2>       &triangulation,
                     const Geometry::MeshStatistics       &mesh,
                     const Output::ResultFolder           &folder,
                     const bool                            write_vtu,
                     const SolveExtras                    &extras)
  {
    // Kept here: the picture's stresses need the bodies' elastic laws.
    const Contact::ContactProblem<2> problem =
      Scene::make_floor_contact_problem(Scene::floor_problem_settings(scene));
    return solve_on_mesh<2>(
      scene,
      triangulation,
      problem,
      mesh,
      folder,
      write_vtu,
      [&](const Contact::ContactSolver<2> &solver) {
        if (extras.inspect)
          extras.inspect(solver);
        if (write_vtu)
          {
            write_deformed_view(solver,
                                problem.model,
                                folder.path_of("deformed.png"));
            write_strength_factor_view(scene,
                                       solver,
                                       problem.model,
                                       folder.path_of("strength_factor.png"));
          }
      });
  }

  void
  check_swept_scene(const Parameters::ScenarioParameters &scene)
  {
    if (Scene::uses_rigid_blocks(scene))
      throw InputError("Model/Blocks",
                       "rigid (chosen or by auto)",
                       "elastic when Geometry/Dimension = 3: the rigid-block "
                       "model is 2D");
    // deal.II extrudes coarse meshes only, and refining the swept mesh
    // would put the fillets' new nodes on chords, not on the arcs the 2D
    // refinement follows: the 3D scene takes the Gmsh mesh as it is.
    // Several processes share one mesh with the compliant law only: the
    // exact law's multipliers and its LU factors live on one process.
    if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1 &&
        scene.joints.law == Contact::JointLawKind::rigid)
      throw InputError("Joints/Law",
                       "rigid",
                       "compliant when a 3D scene runs on several processes "
                       "(mpirun -np " +
                         std::to_string(dealii::Utilities::MPI::n_mpi_processes(
                           MPI_COMM_WORLD)) +
                         "); the exact law runs on one process");
    if (const unsigned int n_refinements = Scene::global_refinements(scene))
      throw InputError("Mesh/Global refinements",
                       std::to_string(n_refinements) +
                         " (from the scene, \"auto\" included)",
                       "0 when Geometry/Dimension = 3: the 3D mesh is the "
                       "2D Gmsh mesh swept along the face; refine it with "
                       "Mesh/Corner size and Mesh/Slice size");
  }

  Geometry::MeshStatistics
  mesh_swept_scene(const Parameters::ScenarioParameters &scene,
                   const Output::ResultFolder           &folder,
                   dealii::Triangulation<3>             &solid)
  {
    check_swept_scene(scene);
    dealii::Triangulation<2> section;
    Geometry::MeshStatistics mesh = mesh_scene(scene, folder, {}, section);
    dealii::Timer            timer;
    Geometry::extrude_assembly(section, Scene::swept_slices(scene), solid);
    Scene::tag_support_footprint(scene, solid);
    write_solved_mesh(solid, folder.path_of("mesh.msh"), mesh);
    mesh.wall_time += timer.wall_time();
    return mesh;
  }


  FemOutcome
  solve_swept_scene(const Parameters::ScenarioParameters &scene,
                    const Output::ResultFolder           &folder,
                    const bool                            write_vtu)
  {
    check_swept_scene(scene);
    Contact::ContactProblem<3> problem =
      Scene::swept_contact_problem(Scene::make_floor_contact_problem(
                                     Scene::floor_problem_settings(scene)),
                                   scene.geometry.end_faces);
    const auto footprint = Scene::support_footprint(scene);
    if (footprint)
      Scene::load_support_footprint(*footprint,
                                    scene.geometry.support_width,
                                    problem);
    const auto solve = [&](const dealii::Triangulation<3> &solid,
                           const Geometry::MeshStatistics &mesh) {
      const FemOutcome outcome = solve_on_mesh<3>(
        scene,
        solid,
        problem,
        mesh,
        folder,
        write_vtu,
        [](const Contact::ContactSolver<3> &) {},
        swept_support_load(scene, footprint, solid, problem.model));
      write_face_contact_area(outcome, scene, folder);
      return outcome;
    };
    if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      {
        // mpirun -np N: one mesh over all processes.
        dealii::parallel::fullydistributed::Triangulation<3> solid(
          MPI_COMM_WORLD);
        const Geometry::MeshStatistics mesh =
          distribute_swept_mesh(scene, folder, solid);
        return solve(solid, mesh);
      }
    dealii::Triangulation<3>       solid;
    const Geometry::MeshStatistics mesh =
      mesh_swept_scene(scene, folder, solid);
    return solve(solid, mesh);
  }

  void
  write_fem_files(const FemOutcome &outcome, const Output::ResultFolder &folder)
  {
    folder.write_json("fem.json",
                      Output::fem_json(outcome.result, outcome.report));
    folder.write("joints.csv",
                 Output::joints_csv(outcome.result,
                                    outcome.report.support_width));
    folder.write("joint_profiles.csv",
                 Output::joint_profiles_csv(outcome.result));
    // Only where the mesh resolves the critical distance: elsewhere the
    // stresses along the paths are single cells' values.
    const auto &corners = outcome.report.corner_safety;
    if (!corners.empty() && Safety::governing_corner(corners).resolved())
      folder.write("floor_safety_paths.csv",
                   Output::floor_safety_paths_csv(
                     outcome.report.corner_safety));
  }
} // namespace FloorBlock::Pipeline
