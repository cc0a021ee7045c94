#pragma once

#include <string>
#include <utility>
#include <vector>

namespace FloorBlock::Parameters
{
  /**
   * @brief The families of distribution an uncertain input may follow,
   * with their arguments in the parameter's own units:
   * - normal(mean, sd), or normal(mean, sd, min, max): a normal truncated
   *   to [min, max] (mean and sd of the normal before truncation);
   *   "truncated normal" is the same with its bounds required;
   * - lognormal(mean, sd) of the value itself (not of its logarithm), or
   *   lognormal(mean, sd, min, max) truncated to [min, max];
   * - uniform(min, max); triangular(min, mode, max);
   * - beta(alpha, beta, min, max): shape exponents alpha, beta > 0 on
   *   [min, max].
   */
  enum class DistributionFamily
  {
    normal,
    lognormal,
    uniform,
    triangular,
    beta
  };

  /** One entry of Uncertainty/Inputs. */
  struct UncertainInput
  {
    std::string         path; ///< "Joints/Bedding friction angle"
    DistributionFamily  family;
    std::vector<double> arguments; ///< as written, in the parameter's units
    std::string         text;      ///< the entry as written, for messages
    /** The parameter's unit as its documentation states it ("degrees",
     * "Pa", "t"; "none"), set when the scene checks the input. */
    std::string unit;

    /** @brief Whether the distribution is cut to [min, max]. */
    bool
    truncated() const;

    /**
     * @brief The values the input takes with non-zero probability:
     * [min, max] of a bounded or truncated family, (0, inf) of a lognormal,
     * (-inf, inf) of a normal (infinite ends as +-infinity).
     */
    std::pair<double, double>
    support() const;

    /** @brief The distribution's mean, or its mode where that is simpler to
     * state (not used for statistics: only as a typical value to probe the
     * parameter's pattern with). */
    double
    typical_value() const;
  };

  /** One entry of Uncertainty/Correlations. */
  struct InputCorrelation
  {
    std::string first;  ///< path of an uncertain input
    std::string second; ///< path of another
    double      value;  ///< correlation of their Gaussian copula, in (-1, 1)
    std::string text;   ///< the entry as written
  };

  /**
   * @brief Reads Uncertainty/Inputs: entries "Subsection/Entry: family(a,
   * b, ...)" separated by ';'.
   * @throws InputError naming Uncertainty/Inputs, the entry and what is
   *   allowed: an entry without ':', an unknown family, a wrong number of
   *   arguments, an argument that is not a number, a standard deviation or
   *   shape exponent that is not positive, bounds not in increasing order
   *   (min < max, min <= mode <= max), a lognormal of mean <= 0, truncation
   *   bounds that leave no probability, or the same path twice.
   */
  std::vector<UncertainInput>
  parse_uncertain_inputs(const std::string &text);

  /**
   * @brief Reads Uncertainty/Correlations: entries "Subsection/Entry,
   * Subsection/Entry: value" separated by ';', each pair naming two
   * different paths of @p inputs once.
   * @throws InputError naming Uncertainty/Correlations, the entry and what
   *   is allowed.
   */
  std::vector<InputCorrelation>
  parse_input_correlations(const std::string                 &text,
                           const std::vector<UncertainInput> &inputs);

  /** @brief "normal", "lognormal", ... */
  std::string
  to_string(DistributionFamily family);
} // namespace FloorBlock::Parameters
