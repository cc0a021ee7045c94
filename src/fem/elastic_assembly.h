#pragma once

#include <fem/elastic_model.h>
#include <fem/fe_space.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace FloorBlock::Fem
{
  /**
   * @brief Cell stiffness matrices of a fixed mesh and fixed elastic laws,
   * kept between calls: linear elasticity has a constant stiffness, so the
   * Newton loop only recomputes loads and residuals. Indexed by active
   * cell index; empty until the first assembly fills it.
   */
  struct CellMatrixCache
  {
    std::vector<dealii::FullMatrix<double>> matrices;
  };

  /**
   * @brief What one pass of the single cell loop accumulates. Null
   * pointers are skipped.
   */
  template <int dim>
  struct ElasticAssemblyTargets
  {
    /** Stiffness matrix \f$K\f$ (N/m), added to. */
    dealii::TrilinosWrappers::SparseMatrix *matrix = nullptr;
    /** Residual \f$K u - f\f$ (N), added to. */
    dealii::TrilinosWrappers::MPI::Vector *residual = nullptr;
    /** Sum of all applied loads, body force plus pressure (N/m in 2D). */
    dealii::Tensor<1, dim> *applied_load_total = nullptr;
    /** Optional cache of the cell stiffness matrices (same mesh and laws). */
    CellMatrixCache *cache = nullptr;
  };

  /**
   * @brief The single cell-assembly loop of the bulk: linear elasticity
   * with gravity and boundary pressure.
   *
   * Matrix and residual come from the same local matrix and load vector,
   * \f$r_c = K_c u_c - f_c\f$, so they can never disagree. Contributions
   * are distributed with @p constraints; pass homogeneous constraints for
   * a Newton system, an empty object for the raw residual used for
   * reactions.
   *
   * @param[in] space FE space.
   * @param[in] model Elastic laws, densities and loads; every material id
   *   of the mesh must have a law (throws InputError otherwise).
   * @param[in] solution Current displacement (m).
   * @param[in] constraints Constraints used in distribution.
   * @param[in,out] targets What to accumulate.
   */
  template <int dim>
  void
  assemble_elastic_system(const FeSpace<dim>                          &space,
                          const ElasticModel<dim>                     &model,
                          const dealii::TrilinosWrappers::MPI::Vector &solution,
                          const dealii::AffineConstraints<double> &constraints,
                          const ElasticAssemblyTargets<dim>       &targets);
} // namespace FloorBlock::Fem
