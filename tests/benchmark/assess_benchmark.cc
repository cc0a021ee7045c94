// The probability of floor failure of a scene (`floorblock assess`)
// against brute-force Monte Carlo over the FEM alone, under MPI:
//
//   mpirun -np 2 build/tests/benchmark/floorblock_assess_benchmark [scene.prm]
//     [--brute-force N] [--output DIR]
//
// 1. The study as `assess` runs it (FEM cases, surrogate, P(FS < 1), FORM,
//    Sobol' indices), timed whole, with its cost by model.
// 2. Monte Carlo over the FEM itself: N random draws (default 1000) of the
//    same inputs, one batch of FEM cases (Assessment::solve_safety_cases),
//    P(FS < 1) over the solved ones with its 95 % interval (OpenTURNS'
//    Bernoulli estimator); cases without FS are counted.
// 3. Whether the two estimates agree within their intervals (and within
//    the range the surrogate's stated error allows), and how the surrogate
//    predicts the held-out cases.
//
// Both studies keep their FEM cases under DIR (default
// results/<scene>/assess_benchmark/), so a rerun resumes. Rank 0 prints a
// markdown table labelled with the commit and writes it to
// DIR/assess_benchmark.md.
#include <common/input_error.h>
#include <common/singleton_mpi_environment.h>
#include <parameters/scenario_parameters.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <assessment/assessment.h>
#include <assessment/safety_cases.h>
#include <fmt/format.h>
#include <openturns/BernoulliFactory.hxx>
#include <openturns/RandomGenerator.hxx>
#include <uncertainty/reliability.h>
#include <uncertainty/surrogate.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace FloorBlock;

namespace
{
  std::string
  commit_of_tree()
  {
    std::string commit;
    if (FILE *git = ::popen("git rev-parse --short HEAD 2>/dev/null", "r"))
      {
        char line[64] = {};
        if (std::fgets(line, sizeof(line), git) != nullptr)
          commit = line;
        ::pclose(git);
      }
    while (!commit.empty() && (commit.back() == '\n' || commit.back() == ' '))
      commit.pop_back();
    return commit.empty() ? "unknown" : commit;
  }

  /** A process that fails ends the others, which may wait for it in a
   * collective call. */
  int
  end_all_processes(const int code)
  {
    if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      MPI_Abort(MPI_COMM_WORLD, code);
    return code;
  }

  std::string
  interval_text(const Uncertainty::FailureProbability &p)
  {
    return fmt::format("{:.4f} +- {:.4f}", p.probability, p.half_width);
  }
} // namespace

int
main(int argc, char **argv)
{
  SingletonMpiEnvironment                  environment;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               first =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  std::string  scene_path = "params/default.prm";
  std::string  output;
  unsigned int n_brute_force = 1000;
  for (int k = 1; k < argc; ++k)
    {
      const std::string argument = argv[k];
      if (argument == "--brute-force" && k + 1 < argc)
        n_brute_force = std::stoul(argv[++k]);
      else if (argument == "--output" && k + 1 < argc)
        output = argv[++k];
      else
        scene_path = argument;
    }

  try
    {
      const auto scene = Parameters::read_scenario(scene_path, {});
      if (output.empty())
        output = "results/" + scene.scene_name + "/assess_benchmark";
      const Assessment::SceneSource source{scene_path,
                                           {},
                                           scene.uncertainty.inputs};
      std::ostringstream            quiet;

      dealii::Timer                    study_timer;
      Assessment::AssessmentResult     study;
      Assessment::AssessmentIncomplete incomplete;
      if (!Assessment::run_assessment(scene,
                                      source,
                                      output + "/assess_cases",
                                      first ? std::cout : quiet,
                                      study,
                                      incomplete))
        throw std::runtime_error("the study stopped at its time budget");
      const double study_seconds = study_timer.wall_time();

      // Brute force: the same inputs, another seed, the FEM on every draw.
      const OT::Distribution distribution =
        Assessment::checked_input_distribution(scene);
      OT::RandomGenerator::SetSeed(scene.uncertainty.seed + 100);
      const OT::Sample      draws = distribution.getSample(n_brute_force);
      Assessment::CaseDraws brute_force_draws;
      for (OT::UnsignedInteger i = 0; i < draws.getSize(); ++i)
        {
          brute_force_draws.ids.push_back(fmt::format("mc_{:06d}", i + 1));
          brute_force_draws.points.emplace_back(draws[i].begin(),
                                                draws[i].end());
        }
      dealii::Timer               brute_force_timer;
      const Assessment::CaseBatch fem =
        Assessment::solve_safety_cases(source,
                                       brute_force_draws,
                                       Output::CaseStore(output +
                                                         "/brute_force_cases"),
                                       MPI_COMM_WORLD,
                                       first ? std::cout : quiet);
      const double brute_force_seconds = brute_force_timer.wall_time();
      OT::Sample   failed(0, 1);
      unsigned int n_without_fs = 0;
      for (const auto &c : fem.cases)
        if (c.solved())
          failed.add(OT::Point(1, c.safety_factor < 1. ? 1. : 0.));
        else
          ++n_without_fs;
      // Every brute-force case is one more held-out case of the surrogate.
      const auto [solved_inputs, solved_log_fs] =
        Assessment::solved_samples(fem.cases, distribution.getDimension());
      const Uncertainty::HeldOutErrors on_brute_force =
        Uncertainty::held_out_errors(study.surrogate.model,
                                     solved_inputs,
                                     solved_log_fs,
                                     study.surrogate.stated_error);
      const OT::DistributionFactoryResult estimate =
        OT::BernoulliFactory().buildEstimator(failed);
      const OT::Interval interval =
        estimate.getParameterDistribution().computeBilateralConfidenceInterval(
          0.95);
      Uncertainty::FailureProbability brute_force;
      brute_force.probability = estimate.getDistribution().getParameter()[0];
      brute_force.half_width =
        0.5 * (interval.getUpperBound()[0] - interval.getLowerBound()[0]);
      brute_force.evaluations = failed.getSize();

      if (!first)
        return 0;
      const auto  &surrogate = study.failure.monte_carlo;
      const double gap =
        std::abs(surrogate.probability - brute_force.probability);
      const bool agree = gap <= surrogate.half_width + brute_force.half_width;
      std::ostringstream table;
      table << fmt::format(
        "Measured at {} on {} MPI processes: `mpirun -np {} "
        "build/tests/benchmark/floorblock_assess_benchmark {} --brute-force "
        "{}`\n\n",
        commit_of_tree(),
        dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
        dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
        scene_path,
        n_brute_force);
      table << "| | assess (surrogate) | brute force (FEM only) |\n"
            << "|---|---|---|\n";
      table << fmt::format("| P(FS < 1), 95 % | {} | {} |\n",
                           interval_text(surrogate),
                           interval_text(brute_force));
      table << fmt::format(
        "| P_f if the surrogate errs by its stated factor {:.3f} | {:.4f} "
        "to {:.4f} | |\n",
        std::exp(study.surrogate.stated_error),
        study.failure.lower_with_surrogate_error,
        study.failure.upper_with_surrogate_error);
      table << fmt::format("| FEM solves | {} ({} from an earlier run) | {} "
                           "({} from an earlier run; {} without FS, left "
                           "out) |\n",
                           study.costs.at(0).evaluations,
                           study.costs.at(0).from_earlier_runs,
                           fem.cases.size(),
                           fem.n_from_earlier_runs,
                           n_without_fs);
      table << fmt::format("| surrogate evaluations | {} | |\n",
                           study.costs.at(1).evaluations);
      table << fmt::format("| wall time (s) | {:.0f} | {:.0f} |\n",
                           study_seconds,
                           brute_force_seconds);
      table << fmt::format(
        "\nThe estimates differ by {:.4f}: {} the sum of their half-widths "
        "({:.4f}).\n",
        gap,
        agree ? "within" : "OUTSIDE",
        surrogate.half_width + brute_force.half_width);
      table << fmt::format(
        "Surrogate of ln FS ({}): stated error {:.2f} % of FS (95 % of new "
        "cases within); on the study's {} held-out FEM cases rms {:.2f} %, "
        "largest {:.2f} %, {:.1f} % within the stated error; on the {} "
        "brute-force FEM cases rms {:.2f} %, largest {:.2f} %, {:.1f} % "
        "within the stated error.\n",
        study.surrogate.kind,
        100. * std::expm1(study.surrogate.stated_error),
        study.held_out.n_points,
        100. * std::expm1(study.held_out.rms),
        100. * std::expm1(study.held_out.largest),
        100. * study.held_out.share_within_stated,
        on_brute_force.n_points,
        100. * std::expm1(on_brute_force.rms),
        100. * std::expm1(on_brute_force.largest),
        100. * on_brute_force.share_within_stated);
      std::cout << table.str();
      std::filesystem::create_directories(output);
      std::ofstream(output + "/assess_benchmark.md") << table.str();
      return agree ? 0 : 1;
    }
  catch (const InputError &error)
    {
      std::cerr << "error: " << error.what() << std::endl;
      return end_all_processes(2);
    }
  catch (const std::exception &error)
    {
      std::cerr << "failed: " << error.what() << std::endl;
      return end_all_processes(1);
    }
}
