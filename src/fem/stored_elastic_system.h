#pragma once

#include <fem/elastic_model.h>
#include <fem/fe_space.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

namespace FloorBlock::Fem
{
  /**
   * @brief The bulk of a Newton system kept for the whole solve: small-
   * strain linear elasticity has a constant stiffness and loads linear in
   * the load factors, so a Newton iteration needs one matrix copy and one
   * matrix-vector product instead of a cell loop (0.2 ms against 4 ms on
   * the default mesh).
   *
   * Built by assemble_elastic_system, the single cell loop, so it agrees
   * with a fresh assembly to round-off (unit test StoredElasticSystem.*).
   *
   * Two stiffness matrices are stored: the one condensed with the
   * homogeneous constraints (the Newton tangent) and the unconstrained
   * one, because the residual must include the coupling to prescribed
   * non-zero displacements (floor uplift), which condensation removes.
   */
  template <int dim>
  class StoredElasticSystem
  {
  public:
    /**
     * @param[in] space FE space (only read here).
     * @param[in] model Laws, densities and loads at factor one; the
     *   gravity part and the pressure part are stored separately.
     * @param[in] homogeneous_constraints Constraints of the Newton update:
     *   zero Dirichlet values and hanging nodes (u_i = sum a_ij u_j). A
     *   constrained row's residual is moved to its masters with the
     *   weights a_ij, as distribute_local_to_global does cell by cell.
     *   Inhomogeneous lines throw std::logic_error, and so does a master
     *   that is not locally owned (distributed meshes would need ghosted
     *   residuals here).
     * @param[in] tangent_pattern Pattern of the Newton matrix (bulk plus
     *   joint couplings); the condensed stiffness is stored on it so that
     *   it can be copied into that matrix by value.
     */
    StoredElasticSystem(
      const FeSpace<dim>                              &space,
      const ElasticModel<dim>                         &model,
      const dealii::AffineConstraints<double>         &homogeneous_constraints,
      const dealii::TrilinosWrappers::SparsityPattern &tangent_pattern);

    /** @brief Condensed bulk stiffness K (N/m) on the tangent pattern. */
    const dealii::TrilinosWrappers::SparseMatrix &
    condensed_stiffness() const;

    /**
     * @brief Bulk residual \f$K u - g f_g - p f_p\f$ (N) with zero rows at
     * the constrained DoFs, as assemble_elastic_system gives it with the
     * homogeneous constraints.
     * @param[in] solution Displacement u (m).
     * @param[in] gravity_factor g (-).
     * @param[in] pressure_factor p (-).
     * @param[out] residual Overwritten.
     */
    void
    residual(const dealii::TrilinosWrappers::MPI::Vector &solution,
             const double                                 gravity_factor,
             const double                                 pressure_factor,
             dealii::TrilinosWrappers::MPI::Vector       &residual) const;

    /**
     * @brief Round-off scale of residual() at @p solution (N): the l2 norm
     * of |K| |u| + g |f_g| + p |f_p|, entry by entry. residual() sums
     * terms of this size that cancel, so its error is of order eps times
     * this (times the few entries per row).
     */
    double
    residual_magnitude(const dealii::TrilinosWrappers::MPI::Vector &solution,
                       const double gravity_factor,
                       const double pressure_factor) const;

    /**
     * @brief Residual norm (N) that round-off alone can produce in
     * residual() at @p solution: (longest stiffness row + 2) eps times
     * residual_magnitude(). The Newton stop test accepts a stable contact
     * set whose residual is at this floor.
     */
    double
    round_off_floor(const dealii::TrilinosWrappers::MPI::Vector &solution,
                    const double                                 gravity_factor,
                    const double pressure_factor) const;

  private:
    dealii::TrilinosWrappers::SparsityPattern full_pattern;
    /** Entries of the longest row of the unconstrained stiffness. */
    std::size_t max_row_length = 0;
    /** |K| entry by entry, for residual_magnitude(). */
    dealii::TrilinosWrappers::SparseMatrix absolute_stiffness;
    dealii::TrilinosWrappers::SparseMatrix full_stiffness;
    dealii::TrilinosWrappers::SparseMatrix tangent_stiffness;
    /** Loads at factor one (N): gravity alone, pressures alone. */
    dealii::TrilinosWrappers::MPI::Vector gravity_load;
    dealii::TrilinosWrappers::MPI::Vector pressure_load;
    /**
     * Locally owned constrained DoFs as indices into the owned storage:
     * residual moved to the masters (same indexing) with their weights,
     * then zeroed.
     */
    std::vector<std::size_t>                                 constrained_rows;
    std::vector<std::vector<std::pair<std::size_t, double>>> constraint_entries;
  };
} // namespace FloorBlock::Fem
