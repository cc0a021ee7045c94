#pragma once

#include <fem/fe_space.h>
#include <material/elastic_law.h>

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace FloorBlock::Corner
{
  /** @brief A value on a boundary face, with the face's two vertices. */
  struct FaceValue
  {
    dealii::Point<2> first;  ///< m, reference configuration
    dealii::Point<2> second; ///< m
    double           value = 0.;
  };

  /**
   * @brief The mean pressure -(sigma_xx + sigma_yy + sigma_zz) / 3 (Pa,
   * compression > 0; plane strain, sigma_zz from the law) of the cell
   * behind every boundary face with id @p side, from the displacement
   * @p solution, taken at the cell's centre: the point where a degree-1
   * element's gradient is most accurate (superconvergent). Nodal values
   * (the cells' gradients at a vertex, averaged) scatter by several
   * per cent where the zoom's hanging nodes join cells of two sizes,
   * enough to wreck an exponent fit.
   *
   * Why the mean pressure: it is the first stress invariant, linear in the
   * stress, so a sum of asymptotic terms stays a sum (a nonlinear
   * invariant such as von Mises mixes them), and it is the invariant the
   * issue asks to fit besides the traction.
   */
  std::vector<FaceValue>
  mean_pressure_on_side(const Fem::FeSpace<2>                       &space,
                        const dealii::TrilinosWrappers::MPI::Vector &solution,
                        dealii::types::boundary_id                   side,
                        const Material::ElasticLaw<2>               &law);
} // namespace FloorBlock::Corner
