#include "scene_benchmarks.h"

#include <contact/contact_solver.h>
#include <scene/contact_inputs.h>
#include <scene/floor_contact_problem.h>
#include <verification/hertz_verification.h>

#include <benchmark/benchmark.h>
#include <postprocess/increment_post_processor.h>

#include <filesystem>
#include <memory>
#include <sstream>

#include "direct_solver_phases.h"
#include "measurements.h"
#include "refined_scene.h"

namespace FloorBlock::Benchmark
{
  namespace
  {
    /**
     * The mesh and linear system of the level being benchmarked, built on
     * first use and dropped when the next level starts (memory).
     */
    struct LevelFixture
    {
      double                               refinement = 0.;
      Parameters::ScenarioParameters       scene;
      dealii::Triangulation<2>             triangulation;
      std::unique_ptr<LinearElasticSystem> system;
    };

    std::string
    number_text(const double value)
    {
      std::ostringstream text;
      text << value;
      return text.str();
    }

    std::string
    msh_path(const BenchmarkOptions &options, const double refinement)
    {
      std::filesystem::create_directories(options.work_directory);
      return options.work_directory + "/default_r" + number_text(refinement) +
             ".msh";
    }

    LevelRecord &
    level_record(const double refinement)
    {
      LevelRecord &record = records().levels[refinement];
      record.refinement   = refinement;
      return record;
    }

    LevelFixture &
    fixture(const BenchmarkOptions &options, const double refinement)
    {
      static std::unique_ptr<LevelFixture> current;
      if (!current || current->refinement != refinement)
        {
          current.reset();
          current             = std::make_unique<LevelFixture>();
          current->refinement = refinement;
          current->scene      = refined_parameters(options.scene_path,
                                              options.overrides,
                                              refinement,
                                              "compliant");
          mesh_scene(current->scene,
                     msh_path(options, refinement),
                     current->triangulation);
          level_record(refinement).n_cells =
            current->triangulation.n_active_cells();
        }
      return *current;
    }

    LinearElasticSystem &
    linear_system(const BenchmarkOptions &options, const double refinement)
    {
      LevelFixture &level = fixture(options, refinement);
      if (!level.system)
        {
          level.system =
            std::make_unique<LinearElasticSystem>(level.scene,
                                                  level.triangulation);
          LevelRecord &record    = level_record(refinement);
          record.n_dofs          = level.system->n_dofs();
          record.n_contact_pairs = level.system->n_contact_pairs();
          record.direct_solver   = level.system->uses_direct_solver();
        }
      return *level.system;
    }

    /** Runs @p work once per benchmark iteration; records its mean time. */
    template <typename Work>
    void
    time_stage(benchmark::State  &state,
               const double       refinement,
               const std::string &stage,
               const Work        &work)
    {
      double wall = 0., cpu = 0.;
      for (auto _ : state)
        {
          const Stopwatch clock;
          if (!work())
            {
              state.SkipWithError((stage + " failed").c_str());
              break;
            }
          wall += clock.wall_seconds();
          cpu += clock.cpu_seconds();
        }
      const double n = std::max<double>(1, state.iterations());
      level_record(refinement).stages[stage] = {wall / n, cpu / n};
      if (level_record(refinement).n_dofs > 0)
        state.counters["dofs"] = level_record(refinement).n_dofs;
    }

    void
    mesh_benchmark(benchmark::State       &state,
                   const BenchmarkOptions &options,
                   const double            refinement)
    {
      const auto               scene = refined_parameters(options.scene_path,
                                            options.overrides,
                                            refinement,
                                            "compliant");
      dealii::Triangulation<2> triangulation;
      time_stage(state, refinement, "mesh", [&]() {
        mesh_scene(scene, msh_path(options, refinement), triangulation);
        return true;
      });
      level_record(refinement).n_cells = triangulation.n_active_cells();
      state.counters["cells"]          = triangulation.n_active_cells();
    }

    void
    assembly_benchmark(benchmark::State       &state,
                       const BenchmarkOptions &options,
                       const double            refinement,
                       const bool              warm)
    {
      LinearElasticSystem &system = linear_system(options, refinement);
      Fem::CellMatrixCache cache;
      system.assemble_bulk(&cache);
      time_stage(state,
                 refinement,
                 warm ? "assembly_warm" : "assembly_cold",
                 [&]() {
                   if (!warm)
                     cache.matrices.clear();
                   system.assemble_bulk(&cache);
                   return true;
                 });
    }

    void
    bulk_reuse_benchmark(benchmark::State       &state,
                         const BenchmarkOptions &options,
                         const double            refinement)
    {
      LinearElasticSystem &system = linear_system(options, refinement);
      system.reuse_bulk();
      time_stage(state, refinement, "bulk_reuse", [&]() {
        system.reuse_bulk();
        return true;
      });
    }

    void
    linear_solve_benchmark(benchmark::State       &state,
                           const BenchmarkOptions &options,
                           const double            refinement)
    {
      LinearElasticSystem &system = linear_system(options, refinement);
      system.assemble_bulk(nullptr);
      system.assemble_joints();
      time_stage(state, refinement, "linear_solve", [&]() {
        return system.solve();
      });
    }

    /** @p direct_solver: "KLU" (the contact solver's) or "UMFPACK". */
    void
    direct_phase_benchmark(benchmark::State       &state,
                           const BenchmarkOptions &options,
                           const double            refinement,
                           const std::string      &direct_solver)
    {
      LinearElasticSystem &system = linear_system(options, refinement);
      system.assemble_bulk(nullptr);
      system.assemble_joints();
      const auto package =
        Scene::contact_solver_settings(fixture(options, refinement).scene, "")
          .linear.direct_package;
      auto &phases = level_record(refinement).direct_phases[direct_solver];
      for (auto _ : state)
        phases = direct_solver == "KLU" ?
                   amesos_phase_times(system.system_matrix(),
                                      system.system_residual(),
                                      package) :
                   umfpack_phase_times(system.system_matrix(),
                                       system.system_residual());
      for (const auto &[phase, seconds] : phases)
        state.counters[phase + "_ms"] = 1e3 * seconds;
    }

    void
    newton_iteration_benchmark(benchmark::State       &state,
                               const BenchmarkOptions &options,
                               const double            refinement)
    {
      LinearElasticSystem &system = linear_system(options, refinement);
      time_stage(state, refinement, "newton_iteration", [&]() {
        return system.newton_iteration();
      });
    }

    /** Skip reason if this law's previous level ran too long or failed. */
    std::string
    skip_reason(const BenchmarkOptions &options,
                const double            refinement,
                const std::string      &law)
    {
      for (const auto &[coarser, record] : records().levels)
        {
          if (coarser >= refinement)
            break;
          const auto solve = record.solves.find(law);
          if (solve == record.solves.end())
            continue;
          if (!solve->second.failure.empty())
            return "skipped: the " + law + " solve failed at r" +
                   number_text(coarser);
          if (solve->second.time.wall > options.level_time_limit)
            return "skipped: the " + law + " solve took " +
                   number_text(solve->second.time.wall) + " s at r" +
                   number_text(coarser) + " (limit " +
                   number_text(options.level_time_limit) + " s)";
        }
      return "";
    }

    void
    fill_solve_record(const Contact::SolveResult &result,
                      const unsigned int          n_blocks,
                      ContactSolveRecord         &record)
    {
      record.n_dofs       = result.n_dofs;
      record.n_increments = result.increments.size();
      for (const auto &increment : result.increments)
        {
          record.n_newton_iterations += increment.n_newton_iterations;
          record.n_cutbacks += increment.n_cutbacks;
        }
      record.sections = result.wall_times;
      if (result.increments.empty())
        return;
      const std::string face_joint = "vertical " + std::to_string(n_blocks);
      for (const auto &joint : result.increments.back().joints)
        if (joint.name == face_joint)
          record.face_contact_length = joint.closed_length;
    }

    void
    contact_solve_benchmark(benchmark::State       &state,
                            const BenchmarkOptions &options,
                            const double            refinement,
                            const std::string      &law)
    {
      const std::string reason = skip_reason(options, refinement, law);
      if (!reason.empty())
        {
          state.SkipWithError(reason.c_str());
          return;
        }
      const LevelFixture &level = fixture(options, refinement);
      const auto          scene = refined_parameters(options.scene_path,
                                            options.overrides,
                                            refinement,
                                            law);
      ContactSolveRecord  record;
      for (auto _ : state)
        {
          record = ContactSolveRecord();
          const Stopwatch clock;
          try
            {
              const Contact::ContactSolverSettings numerics =
                Scene::contact_solver_settings(scene, "");
              Contact::ContactSolver<2> solver(
                level.triangulation,
                Scene::make_floor_contact_problem(
                  Scene::floor_problem_settings(scene)),
                numerics);
              fill_solve_record(Postprocess::solve_with_reports(solver,
                                                                numerics),
                                scene.geometry.n_blocks,
                                record);
              record.converged = true;
            }
          catch (const Contact::ContactSolveFailure &failure)
            {
              record.failure = failure.what();
              state.SkipWithError(failure.what());
            }
          record.time = {clock.wall_seconds(), clock.cpu_seconds()};
        }
      LevelRecord &level_data = level_record(refinement);
      level_data.solves[law]  = record;
      if (level_data.n_dofs == 0)
        level_data.n_dofs = record.n_dofs;
      state.counters["dofs"]            = level_data.n_dofs;
      state.counters["increments"]      = record.n_increments;
      state.counters["newton"]          = record.n_newton_iterations;
      state.counters["face_contact_mm"] = 1e3 * record.face_contact_length;
    }

    void
    hertz_benchmark(benchmark::State &state, const unsigned int cells)
    {
      HertzRecord record;
      record.cells_per_half_width = cells;
      for (auto _ : state)
        {
          Verification::HertzSettings settings;
          settings.cells_per_half_width = cells;
          const Stopwatch clock;
          try
            {
              const Verification::HertzResult result =
                Verification::run_hertz_verification(settings);
              record.n_dofs              = result.n_dofs;
              record.n_newton_iterations = result.n_newton_iterations;
              record.half_width_error    = result.half_width_error();
              record.peak_pressure_error = result.peak_pressure_error();
            }
          catch (const Contact::ContactSolveFailure &failure)
            {
              record.failure = failure.what();
              state.SkipWithError(failure.what());
            }
          record.time = {clock.wall_seconds(), clock.cpu_seconds()};
        }
      records().hertz[cells]                 = record;
      state.counters["dofs"]                 = record.n_dofs;
      state.counters["newton"]               = record.n_newton_iterations;
      state.counters["half_width_error_pct"] = 100. * record.half_width_error;
      state.counters["peak_pressure_error_pct"] =
        100. * record.peak_pressure_error;
    }
  } // namespace

  void
  register_scene_benchmarks(const BenchmarkOptions &options)
  {
    std::vector<double> refinements = options.refinements;
    std::sort(refinements.begin(), refinements.end());
    for (const double r : refinements)
      {
        const std::string prefix = "default/r" + number_text(r) + "/";
        const auto        add    = [&](const std::string &name, auto function) {
          return benchmark::RegisterBenchmark((prefix + name).c_str(), function)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime()
            ->MeasureProcessCPUTime();
        };
        add("mesh", [=](benchmark::State &state) {
          mesh_benchmark(state, options, r);
        });
        add("assembly_cold", [=](benchmark::State &state) {
          assembly_benchmark(state, options, r, false);
        });
        add("assembly_warm", [=](benchmark::State &state) {
          assembly_benchmark(state, options, r, true);
        });
        add("bulk_reuse", [=](benchmark::State &state) {
          bulk_reuse_benchmark(state, options, r);
        });
        add("linear_solve", [=](benchmark::State &state) {
          linear_solve_benchmark(state, options, r);
        });
        add("klu_phases", [=](benchmark::State &state) {
          direct_phase_benchmark(state, options, r, "KLU");
        })->Iterations(1);
        add("umfpack_phases", [=](benchmark::State &state) {
          direct_phase_benchmark(state, options, r, "UMFPACK");
        })->Iterations(1);
        add("newton_iteration", [=](benchmark::State &state) {
          newton_iteration_benchmark(state, options, r);
        });
        for (const std::string &law : options.joint_laws)
          add("contact_solve/" + law,
              [=](benchmark::State &state) {
                contact_solve_benchmark(state, options, r, law);
              })
            ->Iterations(1)
            ->Unit(benchmark::kSecond);
      }
  }

  void
  register_hertz_benchmarks(const BenchmarkOptions &options)
  {
    for (const unsigned int cells : options.hertz_cells_per_half_width)
      benchmark::RegisterBenchmark(
        ("hertz/cells" + std::to_string(cells)).c_str(),
        [=](benchmark::State &state) { hertz_benchmark(state, cells); })
        ->Iterations(1)
        ->Unit(benchmark::kSecond)
        ->UseRealTime()
        ->MeasureProcessCPUTime();
  }
} // namespace FloorBlock::Benchmark
