#include <common/input_error.h>

#include <deal.II/base/timer.h>

#include <assessment/assessment.h>
#include <fmt/format.h>
#include <openturns/ComposedDistribution.hxx>
#include <openturns/ComposedFunction.hxx>
#include <openturns/LHSExperiment.hxx>
#include <openturns/Normal.hxx>
#include <openturns/ParametricFunction.hxx>
#include <openturns/RandomGenerator.hxx>
#include <openturns/SymbolicFunction.hxx>
#include <uncertainty/input_distribution.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <ostream>

namespace FloorBlock::Assessment
{
  namespace
  {
    /** Highest total degree of the chaos: cubic interactions at most, which
     * some 100 cases in five inputs can still select among. */
    constexpr std::uint64_t max_chaos_degree = 4;

    /** The surrogate's evaluations for P_f and Sobol' indices are cheap:
     * these bound them far beyond what the half-widths need. */
    constexpr std::uint64_t max_surrogate_evaluations = 20000000;
    constexpr std::uint64_t sobol_base_size           = 20000;
    constexpr std::uint64_t fs_sample_size            = 20000;
    /** Uncertainty/Refinement cases are solved in this many rounds. */
    constexpr unsigned int refinement_rounds = 2;

    CaseDraws
    draws_of(const std::string &prefix, const OT::Sample &sample)
    {
      CaseDraws draws;
      for (OT::UnsignedInteger i = 0; i < sample.getSize(); ++i)
        {
          draws.ids.push_back(fmt::format("{}_{:04d}", prefix, i + 1));
          const OT::Point point = sample[i];
          draws.points.emplace_back(point.begin(), point.end());
        }
      return draws;
    }

    /**
     * A Latin hypercube of @p size points in the standard normal space of
     * @p distribution, taken to the inputs by its inverse
     * iso-probabilistic transformation: the strata hold with correlated
     * inputs too.
     */
    OT::Sample
    latin_hypercube(const OT::Distribution &distribution,
                    const std::uint64_t     size)
    {
      const OT::Normal standard(distribution.getDimension());
      const OT::Sample u = OT::LHSExperiment(standard, size).generate();
      return distribution.getInverseIsoProbabilisticTransformation()(u);
    }

    /** FS = exp(ln FS + @p log_shift) from the surrogate of ln FS. */
    OT::Function
    safety_factor_of(const OT::Function &log_model, const double log_shift)
    {
      const OT::SymbolicFunction exponential(
        OT::Description(1, "g"),
        OT::Description(1, fmt::format("exp(g + ({:.17g}))", log_shift)));
      return OT::ComposedFunction(exponential, log_model);
    }

    std::vector<double>
    predictions(const OT::Function &model, const std::vector<SafetyCase> &cases)
    {
      std::vector<double> values;
      for (const SafetyCase &c : cases)
        values.push_back(model(OT::Point(c.inputs.begin(), c.inputs.end()))[0]);
      return values;
    }

    double
    summed_wall_time(const std::vector<SafetyCase> &cases)
    {
      double total = 0.;
      for (const SafetyCase &c : cases)
        total += c.wall_time;
      return total;
    }

    /**
     * P(FS < 1) with input @p index fixed at a grid of its 1 % to 99 %
     * quantiles, the others drawn from their joint distribution (the input
     * is uncorrelated with them, as the parameters check), and where the
     * curve reaches each target probability.
     */
    DesignLimit
    design_limit(const OT::Function                    &safety_factor,
                 const OT::Distribution                &distribution,
                 const std::size_t                      index,
                 const std::vector<double>             &targets,
                 const Uncertainty::SimulationSettings &simulation)
    {
      constexpr unsigned int n_values = 25;
      DesignLimit            limit;
      limit.input = index;
      OT::Indices others;
      for (std::size_t i = 0; i < distribution.getDimension(); ++i)
        if (i != index)
          others.add(i);
      const OT::Distribution input = distribution.getMarginal(index);
      const double           low   = input.computeQuantile(0.01)[0];
      const double           high  = input.computeQuantile(0.99)[0];
      for (unsigned int k = 0; k < n_values; ++k)
        {
          const double value = low + (high - low) * k / (n_values - 1.);
          limit.values.push_back(value);
          if (others.getSize() == 0)
            {
              const double fs = safety_factor(OT::Point(1, value))[0];
              limit.probabilities.push_back({fs < 1. ? 1. : 0., 0., 1});
              continue;
            }
          const OT::ParametricFunction fixed(safety_factor,
                                             OT::Indices(1, index),
                                             OT::Point(1, value));
          limit.probabilities.push_back(
            Uncertainty::monte_carlo_failure_probability(
              fixed, distribution.getMarginal(others), simulation));
        }
      for (const double target : targets)
        {
          std::optional<double> reached;
          for (unsigned int k = 0; k + 1 < n_values && !reached; ++k)
            {
              const double a = limit.probabilities[k].probability - target;
              const double b = limit.probabilities[k + 1].probability - target;
              if (a == 0.)
                reached = limit.values[k];
              else if (a * b < 0.)
                reached = limit.values[k] +
                          (limit.values[k + 1] - limit.values[k]) * a / (a - b);
            }
          limit.limits.emplace_back(target, reached);
        }
      return limit;
    }

    /**
     * @p n_cases random draws whose surrogate FS lies within the stated
     * error of 1 (|ln FS| <= e), in the order drawn; where too few of
     * 20,000 do, the nearest to FS = 1 fill the rest.
     */
    OT::Sample
    draws_near_failure(const Uncertainty::Surrogate &surrogate,
                       const OT::Distribution       &distribution,
                       const unsigned int            n_cases)
    {
      const OT::Sample candidates = distribution.getSample(20000);
      const OT::Sample log_fs     = surrogate.model(candidates);
      std::vector<OT::UnsignedInteger> order(candidates.getSize());
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) {
        const bool a_in = std::abs(log_fs(a, 0)) <= surrogate.stated_error;
        const bool b_in = std::abs(log_fs(b, 0)) <= surrogate.stated_error;
        if (a_in != b_in)
          return a_in;
        return !a_in && std::abs(log_fs(a, 0)) < std::abs(log_fs(b, 0));
      });
      OT::Sample chosen(0, candidates.getDimension());
      for (unsigned int k = 0; k < n_cases && k < order.size(); ++k)
        chosen.add(candidates[order[k]]);
      return chosen;
    }
  } // namespace

  std::pair<OT::Sample, OT::Sample>
  solved_samples(const std::vector<SafetyCase> &cases,
                 const std::size_t              dimension)
  {
    OT::Sample x(0, dimension), y(0, 1);
    for (const SafetyCase &c : cases)
      if (c.solved())
        {
          x.add(OT::Point(c.inputs.begin(), c.inputs.end()));
          y.add(OT::Point(1, std::log(c.safety_factor)));
        }
    return {x, y};
  }

  OT::Distribution
  checked_input_distribution(const Parameters::ScenarioParameters &scene)
  {
    if (scene.uncertainty.inputs.empty())
      throw InputError("Uncertainty/Inputs",
                       "",
                       "at least one uncertain scene parameter for `assess`, "
                       "e.g. \"Joints/Bedding friction angle: normal(30, 3, "
                       "15, 45)\"");
    return Uncertainty::input_distribution(scene.uncertainty.inputs,
                                           scene.uncertainty.correlations);
  }

  bool
  run_assessment(const Parameters::ScenarioParameters &scene,
                 const SceneSource                    &source,
                 const std::string                    &case_folder,
                 std::ostream                         &progress,
                 AssessmentResult                     &result,
                 AssessmentIncomplete                 &incomplete)
  {
    const auto            &settings     = scene.uncertainty;
    const OT::Distribution distribution = checked_input_distribution(scene);
    const std::size_t      dimension    = distribution.getDimension();
    result.inputs                       = settings.inputs;
    result.correlations                 = settings.correlations;

    OT::RandomGenerator::SetSeed(settings.seed);
    const CaseDraws training =
      draws_of("training",
               latin_hypercube(distribution, settings.training_cases));
    OT::RandomGenerator::SetSeed(settings.seed + 1);
    const CaseDraws validation =
      draws_of("validation", distribution.getSample(settings.validation_cases));

    // One batch, so that the ranks share all cases.
    CaseDraws all = training;
    all.ids.insert(all.ids.end(), validation.ids.begin(), validation.ids.end());
    all.points.insert(all.points.end(),
                      validation.points.begin(),
                      validation.points.end());
    const CaseBatch batch = solve_safety_cases(
      source, all, Output::CaseStore(case_folder), MPI_COMM_WORLD, progress);
    if (!batch.complete)
      {
        incomplete.n_cases_done  = batch.cases.size();
        incomplete.n_cases_total = all.ids.size();
        return false;
      }
    result.training.assign(batch.cases.begin(),
                           batch.cases.begin() + training.ids.size());
    result.validation.assign(batch.cases.begin() + training.ids.size(),
                             batch.cases.end());
    result.costs.push_back({"fem",
                            batch.cases.size(),
                            batch.n_from_earlier_runs,
                            summed_wall_time(batch.cases)});

    const auto fit = [&] {
      const auto [x, y] = solved_samples(result.training, dimension);
      if (x.getSize() < dimension + 2)
        throw std::runtime_error(fmt::format(
          "only {} of {} training cases solved (the others were refused or "
          "did not converge; cases.csv says why): a surrogate of {} inputs "
          "needs at least {}",
          x.getSize(),
          result.training.size(),
          dimension,
          dimension + 2));
      return Uncertainty::fit_surrogate(x, y, distribution, max_chaos_degree);
    };
    dealii::Timer surrogate_timer;
    result.surrogate = fit();

    // Where the surrogate's error can change the answer, FS within its
    // stated error of 1, more FEM cases sharpen it: rounds of draws in that
    // band join the training cases and the surrogate is fitted again.
    for (unsigned int round = 0; round < refinement_rounds; ++round)
      {
        const unsigned int n_cases =
          settings.refinement_cases / refinement_rounds +
          (round < settings.refinement_cases % refinement_rounds ? 1 : 0);
        if (n_cases == 0)
          continue;
        OT::RandomGenerator::SetSeed(settings.seed + 10 + round);
        const CaseDraws draws =
          draws_of(fmt::format("refinement{}", round + 1),
                   draws_near_failure(result.surrogate, distribution, n_cases));
        // The FEM's time is the FEM's cost, not the surrogate's.
        surrogate_timer.stop();
        const CaseBatch refinement =
          solve_safety_cases(source,
                             draws,
                             Output::CaseStore(case_folder),
                             MPI_COMM_WORLD,
                             progress);
        surrogate_timer.start();
        if (!refinement.complete)
          {
            incomplete.n_cases_done =
              batch.cases.size() + refinement.cases.size();
            incomplete.n_cases_total =
              all.ids.size() + settings.refinement_cases;
            return false;
          }
        result.training.insert(result.training.end(),
                               refinement.cases.begin(),
                               refinement.cases.end());
        result.costs[0].evaluations += refinement.cases.size();
        result.costs[0].from_earlier_runs += refinement.n_from_earlier_runs;
        result.costs[0].wall_time += summed_wall_time(refinement.cases);
        result.surrogate = fit();
      }

    const auto [x_check, y_check] =
      solved_samples(result.validation, dimension);
    result.held_out = Uncertainty::held_out_errors(
      result.surrogate.model, x_check, y_check, result.surrogate.stated_error);
    const OT::Function safety_factor =
      safety_factor_of(result.surrogate.model, 0.);
    result.surrogate_at_training = predictions(safety_factor, result.training);
    result.surrogate_at_validation =
      predictions(safety_factor, result.validation);

    const Uncertainty::SimulationSettings simulation{settings.half_width,
                                                     max_surrogate_evaluations,
                                                     1000,
                                                     settings.seed + 2};
    result.failure.monte_carlo =
      Uncertainty::monte_carlo_failure_probability(safety_factor,
                                                   distribution,
                                                   simulation);
    // Where P_f lies if the surrogate errs by its stated factor near FS = 1.
    const double                          error = result.surrogate.stated_error;
    const Uncertainty::FailureProbability lower =
      Uncertainty::monte_carlo_failure_probability(
        safety_factor_of(result.surrogate.model, error),
        distribution,
        simulation);
    const Uncertainty::FailureProbability upper =
      Uncertainty::monte_carlo_failure_probability(
        safety_factor_of(result.surrogate.model, -error),
        distribution,
        simulation);
    result.failure.lower_with_surrogate_error = lower.probability;
    result.failure.upper_with_surrogate_error = upper.probability;
    OT::RandomGenerator::SetSeed(settings.seed + 4);
    const OT::Sample fs_sample =
      safety_factor(distribution.getSample(fs_sample_size));
    for (OT::UnsignedInteger i = 0; i < fs_sample.getSize(); ++i)
      result.surrogate_fs_sample.push_back(fs_sample(i, 0));
    result.design_point =
      Uncertainty::form_design_point(safety_factor, distribution);

    for (std::size_t i = 0; i < dimension; ++i)
      if (settings.inputs[i].path == settings.design_limit_input)
        result.design_limit =
          design_limit(safety_factor,
                       distribution,
                       i,
                       settings.design_limit_probabilities,
                       {0.005, 20000, 1000, settings.seed + 5});

    OT::ComposedDistribution::DistributionCollection marginals;
    for (std::size_t i = 0; i < dimension; ++i)
      marginals.add(distribution.getMarginal(i));
    result.sobol =
      Uncertainty::sobol_indices(safety_factor,
                                 OT::ComposedDistribution(marginals),
                                 sobol_base_size,
                                 settings.seed + 3);
    result.costs.push_back(
      {"surrogate",
       result.sobol.evaluations + result.failure.monte_carlo.evaluations +
         lower.evaluations + upper.evaluations + fs_sample_size,
       0,
       surrogate_timer.wall_time()});
    return true;
  }
} // namespace FloorBlock::Assessment
