#pragma once

#include <fem/elastic_model.h>
#include <fem/fe_space.h>

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace FloorBlock::Fem
{
  /** @brief The plane-strain stress at one point (Pa, tension positive). */
  struct PointStress
  {
    dealii::SymmetricTensor<2, 2> in_plane;
    double                        out_of_plane = 0.; ///< sigma_zz
    /** Size of the cell the point lies in, diameter / sqrt(2) (m). */
    double cell_size = 0.;
  };

  /**
   * @brief The stress of the displacement field at arbitrary points: the
   * strain of the finite element field in the cell that holds each point,
   * through that cell's elastic law (ElasticModel::laws by material id).
   *
   * The stress of a displacement FE field jumps between cells; a point on
   * a cell face takes the cell deal.II's find_active_cell_around_point()
   * returns, so ask for points inside the body, away from its boundary by
   * more than round-off. One process: every cell must be locally owned.
   * Throws dealii's ExcPointNotFound for a point outside the mesh.
   */
  std::vector<PointStress>
  stresses_at_points(const FeSpace<2>                            &space,
                     const ElasticModel<2>                       &model,
                     const dealii::TrilinosWrappers::MPI::Vector &displacement,
                     const std::vector<dealii::Point<2>>         &points);
} // namespace FloorBlock::Fem
