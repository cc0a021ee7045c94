#pragma once

#include <contact/joint_law.h>
#include <contact/results.h>
#include <loading/load_factors.h>

#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace FloorBlock::Contact
{
  /**
   * @brief Whoever wants the converged increments of a ContactSolver:
   * the solver computes, the observer reports and writes (post-processing
   * implements it, Postprocess::IncrementPostProcessor).
   *
   * The solver calls describe() with every converged increment before it
   * commits it, then record() if records() says so.
   */
  template <int dim>
  class IncrementObserver
  {
  public:
    virtual ~IncrementObserver() = default;

    /**
     * @brief Fills the report part of @p increment (force balance, joint
     * reports, rigid motions); the solver has set its Newton statistics.
     * @param[in] factors Load factors of the increment (-).
     * @param[in] responses Every pair's law at @p solution.
     * @param[in] solution Converged displacement (m), readable at the
     *   locally relevant DoFs and every pair's.
     */
    virtual void
    describe(const Loading::LoadFactors                  &factors,
             const std::vector<JointResponse<dim>>       &responses,
             const dealii::TrilinosWrappers::MPI::Vector &solution,
             IncrementResult                             &increment) = 0;

    /** @brief Whether record() keeps anything (the solver times it). */
    virtual bool
    records() const
    {
      return false;
    }

    /**
     * @brief Keeps the converged state, after describe() and the commit
     * (e.g. as a picture series); the arguments are describe()'s.
     */
    virtual void
    record(const std::vector<JointResponse<dim>>       &responses,
           const dealii::TrilinosWrappers::MPI::Vector &solution)
    {
      (void)responses;
      (void)solution;
    }
  };
} // namespace FloorBlock::Contact
