#pragma once

#include <material/elastic_law.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <map>
#include <set>

namespace FloorBlock::Fem
{
  /**
   * @brief Bulk physics of one load state: the elastic law and density of
   * every material id, the gravity acceleration and the pressures on
   * boundary ids. The load stepper scales gravity and pressures.
   */
  template <int dim>
  struct ElasticModel
  {
    /** Elastic law per material id. */
    std::map<dealii::types::material_id, Material::ElasticLaw<dim>> laws;
    /** Mass density per material id (kg/m^3). */
    std::map<dealii::types::material_id, double> densities;
    /** Gravity acceleration vector (m/s^2), e.g. (0, -9.81). */
    dealii::Tensor<1, dim> gravity;
    /** Pressure on a boundary id (Pa), positive pushing into the body. */
    std::map<dealii::types::boundary_id, double> pressures;
    /**
     * Boundary ids whose pressure p acts straight down (along @p down) as
     * a load per unit of horizontal projection: traction p |n . d| d on a
     * face with unit normal n. On a level face this equals the normal
     * pressure; on an inclined one it keeps the total vertical load and
     * adds no component along the face's normal direction only.
     */
    std::set<dealii::types::boundary_id> vertical_pressures;
    /**
     * Unit vector of the true vertical, downward, in the model's frame
     * (-e_{dim-1} unless the frame is turned, Bedding/Frame dip).
     */
    dealii::Tensor<1, dim> down =
      -dealii::Tensor<1, dim>(dealii::Point<dim>::unit_vector(dim - 1));
  };
} // namespace FloorBlock::Fem
