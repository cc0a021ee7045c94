#include <convergence/equal_error.h>

#include <cmath>

namespace FloorBlock::Convergence
{
  namespace
  {
    /** The converged value with the most DoFs of either ladder. */
    std::optional<double>
    finest_value(const Ladder &uniform, const Ladder &adaptive,
                 const Quantity &quantity, std::string &source)
    {
      std::optional<double> value;
      unsigned int          most_dofs = 0;
      for (const auto *ladder : {&uniform, &adaptive})
        for (const LevelRecord &record : ladder->levels)
          if (record.converged() && record.n_dofs > most_dofs)
            {
              most_dofs = record.n_dofs;
              value     = quantity.value(record);
              source    = "finest converged level (" + record.mode +
                       " level " + std::to_string(record.level) + ", " +
                       std::to_string(record.n_dofs) +
                       " DoFs); its own error is 0 by construction";
            }
      return value;
    }

    std::optional<unsigned int>
    level_within(const Ladder &ladder, const Quantity &quantity,
                 const double reference, const double target)
    {
      std::optional<unsigned int> first;
      for (const LevelRecord &record : ladder.levels)
        {
          const bool within =
            record.converged() &&
            std::abs(quantity.value(record) - reference) <=
              target * std::abs(reference);
          if (!within)
            first.reset();
          else if (!first)
            first = record.level;
        }
      return first;
    }
  } // namespace

  void
  estimate_ladder_errors(Ladder &ladder, const std::vector<Quantity> &quantities)
  {
    ladder.errors.clear();
    for (const Quantity &quantity : quantities)
      ladder.errors.push_back(
        estimate_errors(quantity_series(ladder.levels, quantity)));
  }

  EqualErrorComparison
  compare_at_equal_error(const Ladder     &uniform,
                         const Ladder     &adaptive,
                         const Quantity   &quantity,
                         const std::size_t quantity_index,
                         const double     target_relative_error)
  {
    EqualErrorComparison comparison;
    comparison.quantity              = quantity.name;
    comparison.target_relative_error = target_relative_error;
    const SequenceErrors &uniform_errors  = uniform.errors.at(quantity_index);
    const SequenceErrors &adaptive_errors = adaptive.errors.at(quantity_index);
    if (uniform_errors.method == ErrorMethod::richardson)
      {
        comparison.reference        = uniform_errors.reference;
        comparison.reference_source = "Richardson value of the uniform ladder";
      }
    else if (adaptive_errors.method == ErrorMethod::richardson)
      {
        comparison.reference = adaptive_errors.reference;
        comparison.reference_source =
          "Richardson value of the adaptive ladder (the uniform one is "
          "irregular)";
      }
    else
      comparison.reference = finest_value(uniform, adaptive, quantity,
                                          comparison.reference_source);
    if (!comparison.reference || *comparison.reference == 0.)
      return comparison;

    comparison.uniform_level = level_within(
      uniform, quantity, *comparison.reference, target_relative_error);
    comparison.adaptive_level = level_within(
      adaptive, quantity, *comparison.reference, target_relative_error);
    if (comparison.uniform_level && comparison.adaptive_level)
      {
        const LevelRecord &fixed =
          uniform.levels.at(*comparison.uniform_level);
        const LevelRecord &adapted =
          adaptive.levels.at(*comparison.adaptive_level);
        comparison.dofs_ratio =
          static_cast<double>(adapted.n_dofs) / fixed.n_dofs;
        if (fixed.cost_wall_time > 0.)
          comparison.cost_ratio =
            adapted.cost_wall_time / fixed.cost_wall_time;
      }
    return comparison;
  }
} // namespace FloorBlock::Convergence
