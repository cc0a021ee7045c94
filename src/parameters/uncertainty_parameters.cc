#include <common/input_error.h>
#include <parameters/parameter_error_text.h>
#include <parameters/sections.h>
#include <parameters/value_text.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Anything;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;

  namespace
  {
    /**
     * Sets one entry of @p prm by its path for the duration of a probe:
     * whether the entry's pattern takes a value, and what it says if not.
     * The entry's value is put back on destruction.
     */
    class EntryProbe
    {
    public:
      EntryProbe(ParameterHandler &prm, const std::string &path)
        : prm(prm)
        , levels(dealii::Utilities::split_string_list(path, '/'))
      {
        enter();
        saved = prm.get(levels.back());
        leave();
      }

      ~EntryProbe()
      {
        enter();
        prm.set(levels.back(), saved);
        leave();
      }

      /** "" if the pattern takes @p value, else deal.II's reason. */
      std::string
      refusal(const std::string &path, const std::string &value)
      {
        enter();
        std::string reason;
        try
          {
            prm.set(levels.back(), value);
          }
        catch (const dealii::ExceptionBase &error)
          {
            reason = parameter_error_text(error, path, value);
          }
        leave();
        return reason;
      }

    private:
      void
      enter()
      {
        for (std::size_t level = 0; level + 1 < levels.size(); ++level)
          prm.enter_subsection(levels[level]);
      }
      void
      leave()
      {
        for (std::size_t level = 0; level + 1 < levels.size(); ++level)
          prm.leave_subsection();
      }

      ParameterHandler              &prm;
      const std::vector<std::string> levels;
      std::string                    saved;
    };

    /** The pattern a ParameterHandler refusal quotes, or the refusal. */
    std::string
    allowed_values(const std::string &refusal)
    {
      const auto open  = refusal.find("pattern <");
      const auto close = refusal.rfind('>');
      if (open == std::string::npos || close == std::string::npos ||
          close < open)
        return refusal;
      return refusal.substr(open + 9, close - open - 9);
    }

    /**
     * An uncertain input must name a numeric scene parameter whose declared
     * range holds every value its distribution takes with non-zero
     * probability: a case drawn outside it would be refused half way
     * through a study.
     */
    void
    check_against_scene(ParameterHandler               &prm,
                        const std::vector<std::string> &paths,
                        const UncertainInput           &input)
    {
      const auto refuse = [&](const std::string &allowed) {
        throw InputError("Uncertainty/Inputs", input.text, allowed);
      };
      if (std::find(paths.begin(), paths.end(), input.path) == paths.end())
        {
          std::string hint;
          for (const std::string &name : nearest_names(input.path, paths))
            hint += (hint.empty() ? " (did you mean " : ", ") + name;
          refuse("the path of a declared scene parameter; there is no '" +
                 input.path + "'" + (hint.empty() ? "" : hint + "?)"));
        }
      if (input.path.rfind("Uncertainty/", 0) == 0)
        refuse("a scene parameter outside subsection Uncertainty");

      // A value a little inside the support from a typical one: an integer
      // entry (a block count) refuses it, as it would a drawn value.
      const auto [low, high] = input.support();
      const double typical   = input.typical_value();
      const double nudge     = 1e-6 * std::max(1., std::abs(typical));
      const double real_value =
        typical < high ? typical + nudge : typical - nudge;
      EntryProbe        probe(prm, input.path);
      const std::string numeric = probe.refusal(input.path, number(real_value));
      if (!numeric.empty())
        refuse("a scene parameter that takes real numbers; " + input.path +
               " allows " + allowed_values(numeric));

      // An unbounded end is probed with the largest finite double, which
      // any open-ended Double pattern takes.
      constexpr double largest = std::numeric_limits<double>::max();
      for (const double end : {low, high})
        {
          const double probed =
            std::isfinite(end) ? end : (end < 0 ? -largest : largest);
          const std::string reason = probe.refusal(input.path, number(probed));
          if (!reason.empty())
            refuse("a distribution inside the parameter's range, " +
                   allowed_values(reason) + ": " + to_string(input.family) +
                   " takes values " + (end == low ? "down" : "up") + " to " +
                   (std::isfinite(end) ?
                      number(end) :
                      (end < 0 ? "-infinity" : "+infinity")) +
                   " with non-zero probability. Truncate it (normal(mean, "
                   "sd, min, max), lognormal(mean, sd, min, max)) or choose "
                   "bounds within the range");
        }
    }
  } // namespace

  void
  UncertaintyParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Uncertainty");
    prm.declare_entry(
      "Inputs",
      "",
      Anything(),
      "Scene parameters `floorblock assess` treats as random, separated by "
      "';': \"Subsection/Entry: family(arguments)\" with the arguments in "
      "that parameter's units, e.g. \"Joints/Bedding friction angle: "
      "normal(30, 3, 15, 45); Strength/Intact UCS: lognormal(40e6, 10e6, "
      "5e6, 2e8)\". Families: normal(mean, sd[, min, max]) (truncated to "
      "[min, max] when given; mean and sd of the normal before truncation), "
      "truncated normal(mean, sd, min, max), lognormal(mean, sd[, min, "
      "max]) (mean and sd of the value, not of its logarithm), "
      "uniform(min, max), triangular(min, mode, max), beta(alpha, beta, "
      "min, max). Every value a distribution can take must lie in the "
      "parameter's own range: truncate normals and lognormals. Empty: no "
      "uncertain input (`assess` refuses). Units: those of each parameter.");
    prm.declare_entry(
      "Correlations",
      "",
      Anything(),
      "Correlated pairs of uncertain inputs, separated by ';': "
      "\"Subsection/Entry, Subsection/Entry: rho\" with rho in (-1, 1), the "
      "correlation of a Gaussian copula (of the inputs' normal scores); "
      "pairs not listed are independent. The matrix must be positive "
      "definite. Units: none.");
    prm.declare_entry(
      "Failure probability half width",
      "0.02",
      Double(1e-4, 0.5),
      "Largest half-width of the 95 % confidence interval of P(FS < 1) "
      "the Monte Carlo estimate stops at. Units: none (probability).");
    prm.declare_entry(
      "Training cases",
      "120",
      Integer(3, 100000),
      "FEM cases (a Latin hypercube over the inputs) the surrogate of the "
      "safety factor is fitted on; at least the number of inputs + 2. "
      "Units: none.");
    prm.declare_entry(
      "Validation cases",
      "50",
      Integer(0, 100000),
      "FEM cases drawn at random and held out of the fit, on which the "
      "surrogate's error is measured. Units: none.");
    prm.declare_entry(
      "Refinement cases",
      "40",
      Integer(0, 100000),
      "FEM cases added to the training cases where the surrogate's FS lies "
      "within its stated error of 1 (where its error could change the "
      "answer), in two rounds, the surrogate fitted again after each. "
      "Units: none.");
    prm.declare_entry("Seed",
                      "1",
                      Integer(0, 2147483647),
                      "Seed of every random design and sample of `assess`: "
                      "a rerun with the same seed draws the same cases. "
                      "Units: none.");
    prm.declare_entry(
      "Time budget",
      "3600",
      Double(1, 1e7),
      "Wall time of the whole `assess` command: past it no new FEM case "
      "starts, finished cases are kept and a rerun resumes. Units: s.");
    prm.declare_entry(
      "Design limit input",
      "Loading/Support load",
      Anything(),
      "The uncertain input (a path of Inputs) over which `assess` draws "
      "the design limit curve: P(FS < 1) with that input fixed, over its "
      "1 % to 99 % quantiles, and the values at which P(FS < 1) reaches "
      "Design limit probabilities. It must not be correlated with another "
      "input. Empty, or not among the Inputs: no curve. Units: none.");
    prm.declare_entry(
      "Design limit probabilities",
      "0.01, 0.1",
      List(Double(1e-6, 0.999), 1, 10),
      "Failure probabilities P(FS < 1) whose design limit (the value of "
      "Design limit input at which they are reached) is reported. Units: "
      "none (probability).");
    prm.leave_subsection();
  }

  void
  UncertaintyParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Uncertainty");
    const std::string inputs_text       = prm.get("Inputs");
    const std::string correlations_text = prm.get("Correlations");
    half_width         = prm.get_double("Failure probability half width");
    training_cases     = prm.get_integer("Training cases");
    validation_cases   = prm.get_integer("Validation cases");
    refinement_cases   = prm.get_integer("Refinement cases");
    seed               = prm.get_integer("Seed");
    time_budget        = prm.get_double("Time budget");
    design_limit_input = dealii::Utilities::trim(prm.get("Design limit input"));
    design_limit_probabilities.clear();
    for (const std::string &value : dealii::Utilities::split_string_list(
           prm.get("Design limit probabilities")))
      design_limit_probabilities.push_back(std::stod(value));
    prm.leave_subsection();

    inputs       = parse_uncertain_inputs(inputs_text);
    correlations = parse_input_correlations(correlations_text, inputs);
    if (inputs.empty())
      return;
    const auto named = [&](const std::string &path) {
      return std::any_of(inputs.begin(), inputs.end(), [&](const auto &input) {
        return input.path == path;
      });
    };
    if (named(design_limit_input))
      for (const InputCorrelation &correlation : correlations)
        if (correlation.first == design_limit_input ||
            correlation.second == design_limit_input)
          throw InputError("Uncertainty/Design limit input",
                           design_limit_input,
                           "an input without correlations (the curve fixes "
                           "it and draws the others from their own "
                           "distribution); it is correlated in '" +
                             correlation.text + "'");
    if (training_cases < inputs.size() + 2)
      throw InputError("Uncertainty/Training cases",
                       std::to_string(training_cases),
                       "at least the number of uncertain inputs + 2 = " +
                         std::to_string(inputs.size() + 2) +
                         ", the fewest a surrogate can be fitted and "
                         "cross-validated on");
    // One walk over the printed parameters gives both the declared paths
    // and their units: this runs on every read of a scene with inputs.
    const std::map<std::string, std::string> units = entry_units(prm);
    std::vector<std::string>                 paths;
    for (const auto &[path, unit] : units)
      paths.push_back(path);
    for (UncertainInput &input : inputs)
      {
        check_against_scene(prm, paths, input);
        const std::string &unit = units.at(input.path);
        input.unit              = unit.empty() ? "none" : unit;
      }
  }
} // namespace FloorBlock::Parameters
