#pragma once

#include <fem/elastic_model.h>
#include <fem/fe_space.h>
#include <fem/point_stress.h>

#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace FloorBlock::Fem
{
  /**
   * @brief The stress of every active cell at its centre, from the cell's
   * elastic law (tension positive, Pa), by active_cell_index(); cells
   * not locally owned keep a zero stress.
   */
  std::vector<PointStress>
  cell_centre_stresses(const FeSpace<2>                            &space,
                       const ElasticModel<2>                       &model,
                       const dealii::TrilinosWrappers::MPI::Vector &displacement);

  /**
   * @brief Major principal compressive stress of every active cell at its
   * centre, compression positive (Pa): \f$-\min(\sigma_1, \sigma_2,
   * \sigma_{zz})\f$ of the plane-strain stress from the cell's elastic law.
   * Negative where every principal stress is tensile.
   *
   * @param[in] space 2D FE space of @p displacement.
   * @param[in] model Elastic law per material id.
   * @param[in] displacement Solution on @p space (m); its locally relevant
   *   entries must be readable (one process: all).
   * @return One value per active cell, by active_cell_index() (Pa).
   */
  std::vector<double>
  cell_major_compressive_stress(
    const FeSpace<2>                            &space,
    const ElasticModel<2>                       &model,
    const dealii::TrilinosWrappers::MPI::Vector &displacement);
} // namespace FloorBlock::Fem
