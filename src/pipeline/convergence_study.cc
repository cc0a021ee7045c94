#include <pipeline/convergence_study.h>

#include <fmt/format.h>

#include <algorithm>
#include <optional>

namespace FloorBlock::Pipeline
{
  using Convergence::Ladder;
  using Convergence::Quantity;

  namespace
  {
    /// The quantities whose equal-error cost decides the adaptive target.
    const std::vector<std::string> target_quantities =
      {"contact_length_face", "sigma_max_averaged_face"};
  } // namespace

  std::vector<RefinementMode>
  refinement_modes(const std::string &choice)
  {
    std::vector<RefinementMode> modes;
    if (choice == "uniform" || choice == "both" || choice == "all")
      modes.push_back(RefinementMode::uniform);
    if (choice == "adaptive" || choice == "both" || choice == "all")
      modes.push_back(RefinementMode::adaptive);
    if (choice == "remesh" || choice == "all")
      modes.push_back(RefinementMode::remesh);
    return modes;
  }

  std::vector<Convergence::EqualErrorComparison>
  equal_error_comparisons(const std::vector<Ladder>   &ladders,
                          const std::vector<Quantity> &quantities,
                          const double                 target_error)
  {
    std::vector<Convergence::EqualErrorComparison> comparisons;
    if (ladders.empty() || ladders[0].mode != "uniform")
      return comparisons;
    for (std::size_t l = 1; l < ladders.size(); ++l)
      for (std::size_t q = 0; q < quantities.size(); ++q)
        comparisons.push_back(Convergence::compare_at_equal_error(
          ladders[0], ladders[l], quantities[q], q, target_error));
    return comparisons;
  }

  Output::TargetVerdict
  target_verdict(
    const std::vector<Convergence::EqualErrorComparison> &comparisons,
    const std::string                                    &adaptive_mode)
  {
    bool        evaluated = false;
    bool        met       = true;
    std::string text;
    for (const auto &comparison : comparisons)
      {
        if (comparison.adaptive_mode != adaptive_mode ||
            std::find(target_quantities.begin(),
                      target_quantities.end(),
                      comparison.quantity) == target_quantities.end())
          continue;
        evaluated        = true;
        const auto level = [](const std::optional<unsigned int> &value) {
          return value ? std::to_string(*value) : std::string("never");
        };
        const bool ok = comparison.dofs_ratio && comparison.cost_ratio &&
                        *comparison.dofs_ratio <= target_dofs_ratio &&
                        *comparison.cost_ratio < target_cost_ratio;
        met = met && ok;
        text += fmt::format("{}: uniform level {}, {} level {}",
                            comparison.quantity,
                            level(comparison.uniform_level),
                            comparison.adaptive_mode,
                            level(comparison.adaptive_level));
        if (comparison.dofs_ratio && comparison.cost_ratio)
          text += fmt::format(": DoFs x{:.3f}, time x{:.3f}{}",
                              *comparison.dofs_ratio,
                              *comparison.cost_ratio,
                              comparison.ratios_are_upper_bounds ?
                                " (upper bounds: uniform never reaches it)" :
                                "");
        if (comparison.reference_difference)
          text += fmt::format(", best values {:.2g} apart",
                              *comparison.reference_difference);
        text += ok ? " (met); " : " (missed); ";
      }
    if (!evaluated)
      return {false,
              false,
              "needs the uniform and the " + adaptive_mode +
                " ladder (--mode both or all)",
              target_dofs_ratio,
              target_cost_ratio};
    return {true, met, text, target_dofs_ratio, target_cost_ratio};
  }
  std::string
  degree_comparison_text(
    const std::vector<Convergence::EqualErrorComparison> &comparisons)
  {
    std::string text;
    for (const auto &comparison : comparisons)
      {
        if (comparison.adaptive_mode != "uniform_q2")
          continue;
        const auto level = [](const std::optional<unsigned int> &value) {
          return value ? "level " + std::to_string(*value) :
                         std::string("never");
        };
        text += fmt::format("\n  {}: degree 1 {}, degree 2 {}",
                            comparison.quantity,
                            level(comparison.uniform_level),
                            level(comparison.adaptive_level));
        if (comparison.dofs_ratio && comparison.cost_ratio)
          text += fmt::format(
            " (degree 2: DoFs x{:.2f}, time x{:.2f}{}; faster: degree {})",
            *comparison.dofs_ratio,
            *comparison.cost_ratio,
            comparison.ratios_are_upper_bounds ? ", upper bounds" : "",
            *comparison.cost_ratio < 1. ? 2 : 1);
        else
          text += " (neither reaches it: no comparison)";
      }
    return text;
  }
} // namespace FloorBlock::Pipeline
