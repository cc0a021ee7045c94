#include <app/command_options.h>
#include <common/blas_threads.h>
#include <common/input_error.h>
#include <common/interrupt.h>
#include <common/singleton_mpi_environment.h>
#include <common/wall_clock.h>

#include <deal.II/base/mpi.h>

#include <CLI/CLI.hpp>

#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <set>

using namespace FloorBlock;

namespace
{
  using Command = std::function<int(const App::CommandOptions &)>;

  /// Subcommands that run the finite-element engine.
  const std::set<std::string> needs_mpi =
    {"mesh", "solve", "run", "verify", "converge", "sweep", "corner", "assess"};

  /**
   * Of those, the ones that use several processes under mpirun: `solve`
   * spreads one 3D mesh over them, `sweep` its cases. The others would
   * run whole on every process and write the same files side by side.
   */
  const std::set<std::string> uses_several_processes = {"solve",
                                                        "sweep",
                                                        "assess"};

  /** Refuses @p command on several processes when it uses only one. */
  void
  check_process_count(const std::string &command)
  {
    const unsigned int n_processes =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    if (n_processes > 1 && uses_several_processes.count(command) == 0)
      throw InputError("number of processes (mpirun -np)",
                       std::to_string(n_processes),
                       "1 for `floorblock " + command +
                         "`; several processes serve `solve` of a 3D scene, "
                         "`sweep` and `assess`");
  }

  /**
   * Under mpirun a process that fails cannot tell whether the others wait
   * for it in a collective call (rank 0 alone meshes, writes the folder,
   * ...): after saying why, it ends them all with its exit code instead of
   * leaving them blocked. One process just returns the code.
   */
  int
  end_all_processes_if_several(const int code)
  {
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (initialised &&
        dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      {
        std::cerr.flush();
        MPI_Abort(MPI_COMM_WORLD, code);
      }
    return code;
  }

  /** Adds one subcommand with the options every subcommand shares. */
  CLI::App *
  add_subcommand(CLI::App            &cli,
                 const std::string   &name,
                 const std::string   &description,
                 App::CommandOptions &options)
  {
    CLI::App *sub = cli.add_subcommand(name, description);
    sub
      ->add_option("scene",
                   options.scene_path,
                   "Scene parameter file (.prm or .json)")
      ->capture_default_str();
    sub
      ->add_option("--set",
                   options.overrides,
                   "Override a parameter: \"Subsection/Entry name=value\" "
                   "(repeatable)")
      ->allow_extra_args(false);
    sub->add_option("--output",
                    options.output_directory,
                    "Output folder (default: results/<scene>/)");
    return sub;
  }

  int
  run_guarded(const Command &command, const App::CommandOptions &options)
  {
    try
      {
        return command(options);
      }
    catch (const InputError &error)
      {
        std::cerr << "floorblock: error: " << error.what() << std::endl;
        return end_all_processes_if_several(exit_code::bad_input);
      }
    catch (const Interrupted &)
      {
        std::cerr << "floorblock: interrupted; finished results were kept, "
                     "the unfinished one was discarded"
                  << std::endl;
        return end_all_processes_if_several(exit_code::interrupted);
      }
    catch (const std::exception &error)
      {
        std::cerr << "floorblock: failed: " << error.what() << std::endl;
        return end_all_processes_if_several(exit_code::failure);
      }
  }

  /** Every subcommand: its description and the function that runs it. */
  const std::map<std::string, std::pair<std::string, Command>> &
  command_table()
  {
    static const std::map<std::string, std::pair<std::string, Command>>
      commands = {
        {"print-parameters",
         {"Print every parameter with default, range, unit and meaning",
          App::print_parameters_command}},
        {"analytic",
         {"Evaluate every closed-form case of the chapter for a scene",
          App::analytic_command}},
        {"sweep",
         {"Evaluate the chapter's figure grids (6.5-6.7, 6.10/6.11)",
          App::sweep_command}},
        {"mesh", {"Mesh the block assembly with Gmsh", App::mesh_command}},
        {"solve",
         {"Mesh and solve the scene with the frictional contact FEM",
          App::solve_command}},
        {"verify",
         {"Run a verification case against its closed form "
          "(hertz, patch, punch, incline, two-blocks)",
          App::verify_command}},
        {"run", {"The main job: mesh, solve, compare", App::run_command}},
        {"converge",
         {"Refinement study: error against cost, uniform and adaptive meshes",
          App::converge_command}},
        {"corner",
         {"Corner-stress field at a joint's floor-level corner: state, "
          "asymptotic exponent and intensity, rounding study",
          App::corner_command}},
        {"assess",
         {"Probability of floor failure under the scene's uncertain inputs "
          "(subsection Uncertainty): FEM cases, a surrogate, P(FS < 1), "
          "FORM, Sobol' indices",
          App::assess_command}}};
    return commands;
  }

  /** The options of verify, mesh and sweep beyond the shared ones. */
  void
  add_case_options(CLI::App &cli, App::CommandOptions &options)
  {
    // verify takes a case name where the others take a scene file.
    CLI::App *verify = cli.get_subcommand("verify");
    verify->remove_option(verify->get_option("scene"));
    verify
      ->add_option(
        "case",
        options.verification_case,
        "Verification case: hertz, patch, punch, incline, two-blocks")
      ->required();
    cli.get_subcommand("mesh")->add_flag(
      "--ids", options.print_ids, "Print the material/boundary id scheme");
    CLI::App *sweep = cli.get_subcommand("sweep");
    sweep->add_flag("--fem",
                    options.with_fem,
                    "Also run the FEM for every case");
    sweep->add_option("--figure",
                      options.figure,
                      "Only this figure: fig6_5, fig6_6, fig6_7, fig6_10_11; "
                      "or kn_safety: the FEM's floor safety factor against "
                      "the joints' kn (1e9-1e12 Pa/m and the rigid law), "
                      "kn_safety.csv and kn_safety.png");
    sweep->add_option("--limit",
                      options.case_limit,
                      "With --fem: run at most this many of the chosen cases, "
                      "in grid order (0 = all)");
    sweep
      ->add_option("--curvatures",
                   options.curvatures,
                   "With --fem: only the grid points with these k (m), e.g. "
                   "400,50; 0 is the planar bed of Figure 6.5")
      ->delimiter(',');
    sweep
      ->add_option("--loads",
                   options.load_range,
                   "With --fem: only the grid points whose support load lies "
                   "in MIN,MAX (t), e.g. 600,800")
      ->delimiter(',')
      ->expected(2);
  }

  /** The options of converge beyond the shared ones. */
  void
  add_converge_options(CLI::App &cli, App::CommandOptions &options)
  {
    CLI::App *converge = cli.get_subcommand("converge");
    converge->add_option("--levels",
                         options.n_levels,
                         "Number of refinement levels (2-10). Without it: "
                         "up to 5 levels within --budget-seconds 60");
    converge
      ->add_option("--mode",
                   options.refinement_mode,
                   "uniform, adaptive (deal.II hanging nodes), remesh "
                   "(Gmsh size field), both (uniform and adaptive, "
                   "default) or all three")
      ->check(CLI::IsMember({"uniform", "adaptive", "remesh", "both", "all"}));
    converge->add_option("--coarsen-fraction",
                         options.coarsen_fraction,
                         "Adaptive: fraction of cells with the smallest Kelly "
                         "indicator flagged for coarsening per level "
                         "(default 0.03, 0 = never coarsen)");
    converge->add_option("--bulk-fraction",
                         options.bulk_fraction,
                         "Adaptive: fraction of cells with the largest Kelly "
                         "indicator refined per level (default 0.1)");
    converge->add_option("--jump-fraction",
                         options.jump_fraction,
                         "Adaptive: joint segments whose normal-traction jump "
                         "exceeds this fraction of the largest are refined "
                         "(default 0.25)");
    converge->add_option("--budget-seconds",
                         options.budget_seconds,
                         "Wall time of the whole study (s; default 60 without "
                         "--levels, none with it): a ladder stops before a "
                         "level whose forecast (the last step's growth "
                         "repeated) does not fit");
    converge->add_option("--max-dofs",
                         options.max_dofs,
                         "Largest level a ladder may start (forecast DoFs, "
                         "default 400000)");
    converge
      ->add_option("--degrees",
                   options.fe_degrees,
                   "FE degrees to run the ladders with, e.g. 1,2: one "
                   "set of ladders per degree (named uniform, "
                   "uniform_q2, ...) and the degrees compared at equal "
                   "error (default: Solver/FE degree, 1 when auto)")
      ->delimiter(',');
    converge->add_option("--target-error",
                         options.target_error,
                         "Relative error at which uniform and adaptive costs "
                         "are compared (default 0.01)");
  }

  /** Runs the parsed subcommand, starting MPI first if it needs it. */
  int
  run_parsed(const std::map<CLI::App *, Command> &dispatch,
             const App::CommandOptions           &options,
             int                                 &argc,
             char                              **&argv)
  {
    // Closed-form commands skip MPI start-up (about 0.1 s with the singleton
    // settings, 0.4 s without). The environment is declared first so that
    // its session directory outlives MPI.
    std::optional<SingletonMpiEnvironment>                  mpi_environment;
    std::optional<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
    for (const auto &[sub, command] : dispatch)
      if (sub->parsed())
        {
          if (needs_mpi.count(sub->get_name()) > 0)
            {
              mpi_environment.emplace();
              mpi.emplace(argc, argv, 1);
              limit_blas_to_one_thread();
              // Again after MPI start-up, in case the MPI library installed
              // handlers of its own.
              install_interrupt_handlers();
              const std::string name = sub->get_name();
              return run_guarded(
                [&](const App::CommandOptions &parsed) {
                  check_process_count(name);
                  return command(parsed);
                },
                options);
            }
          return run_guarded(command, options);
        }
    return exit_code::bad_input;
  }

  /**
   * An option written before the command (`floorblock --output DIR run
   * scene.prm`) belongs to the command: CLI11 reports only that arguments
   * were not expected. Returns the message that says where it goes, or ""
   * when the first argument is no such option.
   */
  std::string
  option_before_command(const int argc, char **argv)
  {
    if (argc < 3 || argv[1][0] != '-' || std::string(argv[1]) == "-h" ||
        std::string(argv[1]) == "--help")
      return "";
    for (int position = 2; position < argc; ++position)
      if (command_table().count(argv[position]) > 0)
        {
          std::string options, rest;
          for (int k = 1; k < position; ++k)
            options += std::string(k > 1 ? " " : "") + argv[k];
          for (int k = position + 1; k < argc; ++k)
            rest += std::string(" ") + argv[k];
          return "'" + options + "' stands before the command '" +
                 argv[position] + "'; options belong after it: floorblock " +
                 argv[position] + rest + " " + options;
        }
    return "";
  }
} // namespace

int
main(int argc, char **argv)
{
  start_wall_clock();
  install_interrupt_handlers();

  CLI::App cli{"FloorBlock: FEM cross-check of the multiple sliding block "
               "model of longwall floor failure"};
  cli.require_subcommand(1);
  App::CommandOptions           options;
  std::map<CLI::App *, Command> dispatch;
  for (const auto &[name, entry] : command_table())
    dispatch[add_subcommand(cli, name, entry.first, options)] = entry.second;
  add_case_options(cli, options);
  add_converge_options(cli, options);

  try
    {
      cli.parse(argc, argv);
    }
  catch (const CLI::ParseError &error)
    {
      const std::string misplaced = option_before_command(argc, argv);
      if (!misplaced.empty())
        {
          std::cerr << "floorblock: error: " << misplaced << std::endl;
          return exit_code::bad_input;
        }
      const int code = cli.exit(error);
      return code == 0 ? exit_code::success : exit_code::bad_input;
    }
  return run_parsed(dispatch, options, argc, argv);
}
