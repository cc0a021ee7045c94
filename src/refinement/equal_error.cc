#include <refinement/equal_error.h>

#include <cmath>

namespace FloorBlock::Refinement
{
  namespace
  {
    /**
     * First level from which on the estimate stays within the target. The
     * finest level of a finest_difference estimate has no estimate of its
     * own (it is the reference) and neither breaks nor starts a run; a
     * non-converged level breaks it.
     */
    std::optional<unsigned int>
    level_within(const Ladder     &ladder,
                 const std::size_t quantity_index,
                 const double      target)
    {
      const auto &relative = ladder.errors.at(quantity_index).relative_errors;
      std::optional<unsigned int> first;
      for (std::size_t level = 0; level < ladder.levels.size(); ++level)
        {
          if (!ladder.levels[level].converged())
            {
              first.reset();
              continue;
            }
          if (!relative.at(level))
            continue;
          if (*relative[level] > target)
            first.reset();
          else if (!first)
            first = ladder.levels[level].level;
        }
      return first;
    }
  } // namespace

  void
  estimate_ladder_errors(Ladder                      &ladder,
                         const std::vector<Quantity> &quantities)
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
                         const double      target_relative_error)
  {
    EqualErrorComparison comparison;
    comparison.quantity              = quantity.name;
    comparison.adaptive_mode         = adaptive.mode;
    comparison.target_relative_error = target_relative_error;
    const auto &uniform_reference = uniform.errors.at(quantity_index).reference;
    const auto &adaptive_reference =
      adaptive.errors.at(quantity_index).reference;
    if (uniform_reference && adaptive_reference && *uniform_reference != 0.)
      comparison.reference_difference =
        std::abs(*uniform_reference - *adaptive_reference) /
        std::abs(*uniform_reference);

    comparison.uniform_level =
      level_within(uniform, quantity_index, target_relative_error);
    comparison.adaptive_level =
      level_within(adaptive, quantity_index, target_relative_error);
    const LevelRecord *fixed = nullptr;
    if (comparison.uniform_level)
      fixed = &uniform.levels.at(*comparison.uniform_level);
    else if (comparison.adaptive_level)
      {
        // Not reached by uniform refinement: compare with its finest
        // converged level, which the uniform ladder would need to exceed.
        for (const LevelRecord &record : uniform.levels)
          if (record.converged())
            fixed = &record;
        comparison.ratios_are_upper_bounds = fixed != nullptr;
      }
    if (fixed && comparison.adaptive_level)
      {
        const LevelRecord &adapted =
          adaptive.levels.at(*comparison.adaptive_level);
        comparison.dofs_ratio =
          static_cast<double>(adapted.n_dofs) / fixed->n_dofs;
        if (fixed->cost_wall_time > 0.)
          comparison.cost_ratio =
            adapted.cost_wall_time / fixed->cost_wall_time;
      }
    return comparison;
  }
} // namespace FloorBlock::Refinement
