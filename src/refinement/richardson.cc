#include <refinement/richardson.h>

#include <cmath>
#include <sstream>

namespace FloorBlock::Refinement
{
  namespace
  {
    using Values = std::vector<std::optional<double>>;

    std::string
    text(const double value)
    {
      std::ostringstream stream;
      stream << value;
      return stream.str();
    }

    /** Order p_l from levels l-2, l-1, l, if defined. */
    std::optional<double>
    observed_order(const Values &values, const std::size_t level)
    {
      if (level < 2 || !values[level] || !values[level - 1] ||
          !values[level - 2])
        return std::nullopt;
      const double coarse_step = *values[level - 1] - *values[level - 2];
      const double fine_step   = *values[level] - *values[level - 1];
      // Opposite signs (oscillation) or a zero step: no geometric decay.
      if (!(coarse_step * fine_step > 0.))
        return std::nullopt;
      return std::log2(std::abs(coarse_step) / std::abs(fine_step));
    }

    /** Empty when Richardson applies, else why not. */
    std::string
    irregularity(const Values                             &values,
                 const std::vector<std::optional<double>> &orders,
                 const std::size_t                         finest)
    {
      if (finest < 2 || !values[finest - 1] || !values[finest - 2])
        return "the finest three levels are not all converged";
      const double round_off = round_off_level * std::abs(*values[finest]);
      if (std::abs(*values[finest] - *values[finest - 1]) <= round_off ||
          std::abs(*values[finest - 1] - *values[finest - 2]) <= round_off)
        return "the last two differences are at round-off level (below " +
               text(round_off_level) + " of the value)";
      if (!orders[finest])
        return "the last two differences are zero or change sign";
      if (!(*orders[finest] > 0.))
        return "the observed order is not positive (differences grow)";
      if (finest >= 3 && values[finest - 3])
        {
          if (!orders[finest - 1])
            return "the differences change sign or vanish before the "
                   "finest level";
          if (std::abs(*orders[finest] - *orders[finest - 1]) >
              order_consistency_band)
            return "the observed orders of the last two level triples "
                   "differ by more than " +
                   text(order_consistency_band);
        }
      return "";
    }

    void
    fill_relative(SequenceErrors &estimate)
    {
      estimate.relative_errors.assign(estimate.errors.size(), std::nullopt);
      if (!estimate.reference || *estimate.reference == 0.)
        return;
      for (std::size_t level = 0; level < estimate.errors.size(); ++level)
        if (estimate.errors[level])
          estimate.relative_errors[level] =
            *estimate.errors[level] / std::abs(*estimate.reference);
    }
  } // namespace

  std::string
  method_name(const ErrorMethod method)
  {
    switch (method)
      {
        case ErrorMethod::richardson:
          return "richardson";
        case ErrorMethod::finest_difference:
          return "finest_difference";
        case ErrorMethod::unavailable:
          return "unavailable";
      }
    return "unavailable";
  }

  SequenceErrors
  estimate_errors(const Values &values)
  {
    SequenceErrors estimate;
    estimate.errors.assign(values.size(), std::nullopt);
    estimate.observed_orders.assign(values.size(), std::nullopt);
    for (std::size_t level = 0; level < values.size(); ++level)
      estimate.observed_orders[level] = observed_order(values, level);

    std::optional<std::size_t> finest;
    unsigned int               n_usable = 0;
    for (std::size_t level = 0; level < values.size(); ++level)
      if (values[level])
        {
          finest = level;
          ++n_usable;
        }
    if (n_usable < 2)
      {
        estimate.reason = "fewer than two converged levels";
        fill_relative(estimate);
        return estimate;
      }

    // L: finest usable level, p: its observed order, q_inf: the
    // extrapolated value (the symbols of the formula in the header).
    const std::size_t L = *finest;
    const std::string reason =
      irregularity(values, estimate.observed_orders, L);
    if (reason.empty())
      {
        const double p = *estimate.observed_orders[L];
        const double q_inf =
          *values[L] + (*values[L] - *values[L - 1]) / (std::exp2(p) - 1.);
        estimate.method    = ErrorMethod::richardson;
        estimate.reason    = "regular convergence of the finest three levels";
        estimate.reference = q_inf;
        for (std::size_t level = 0; level < values.size(); ++level)
          if (values[level])
            estimate.errors[level] = std::abs(*values[level] - q_inf);
      }
    else
      {
        estimate.method    = ErrorMethod::finest_difference;
        estimate.reason    = reason;
        estimate.reference = values[L];
        for (std::size_t level = 0; level < L; ++level)
          if (values[level])
            estimate.errors[level] = std::abs(*values[level] - *values[L]);
      }
    fill_relative(estimate);
    return estimate;
  }
} // namespace FloorBlock::Refinement
