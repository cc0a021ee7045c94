#pragma once

#include <contact/results.h>

namespace FloorBlock::Compare
{
  /**
   * Fraction of E |u|max below which a force per metre of face is taken as
   * round-off. The elastic forces of a body moved by u carry a round-off of
   * about eps E |u| (eps = 2.2e-16) per nodal force; summed over a joint and
   * through the solve it was at most 2.6e-14 E |u| on the weightless scene
   * of tests/scenarios/hard_weightless.prm. 1e-10 leaves a factor of about
   * 4000 for finer meshes and is itself far below any load the solver
   * resolves (1e-10 x 16 GPa x 22.5 mm = 0.036 N/m).
   */
  constexpr double round_off_force_fraction = 1e-10;

  /** @brief Whether one converged increment carries any load at all. */
  struct LoadCheck
  {
    /** Largest |applied load|, |support reaction|, joint |N| or |T| (N/m). */
    double largest_force = 0.;
    /** round_off_force_fraction x E x the largest body translation (N/m). */
    double round_off_force = 0.;

    /**
     * False when nothing but round-off loads the blocks (no weight, no
     * support load, and a lift that moves them without pressing them
     * together). Relative measures of such a state (force balance, FEM
     * against a closed form) compare round-off with round-off.
     */
    bool
    carries_load() const
    {
      return largest_force > round_off_force;
    }
  };

  /**
   * @brief Compares the forces of @p increment with the round-off of the
   * elastic forces its displacements cause.
   * @param[in] increment A converged increment with its joint reports,
   * force balance and body motions.
   * @param[in] youngs_modulus E of the blocks (Pa), the stiffness that turns
   * displacements into forces per metre of face (E |u| in N/m).
   */
  LoadCheck
  check_load(const Contact::IncrementResult &increment,
             const double                    youngs_modulus);
} // namespace FloorBlock::Compare
