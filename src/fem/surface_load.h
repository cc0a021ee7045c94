#pragma once

#include <fem/elastic_model.h>

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

namespace FloorBlock::Fem
{
  /**
   * @brief Traction (Pa) of the pressure @p pressure on a face of
   * @p boundary_id with outward unit normal @p normal: against the normal,
   * or for ElasticModel::vertical_pressures along ElasticModel::down per
   * unit of horizontal projection, \f$p\,|n\cdot d|\,d\f$. The one rule
   * the assembly (elastic_assembly.h) and applied_surface_load() share.
   */
  template <int dim>
  dealii::Tensor<1, dim>
  surface_traction(const ElasticModel<dim>         &model,
                   const dealii::types::boundary_id boundary_id,
                   const double                     pressure,
                   const dealii::Tensor<1, dim>    &normal);

  /** What the pressures of a model apply to a mesh, at full load. */
  template <int dim>
  struct SurfaceLoad
  {
    /** Resultant of every pressure's traction (N; N/m in 2D). */
    dealii::Tensor<1, dim> force;
    /** Area (m^2; length in m in 2D) of the faces that carry a pressure. */
    double loaded_area = 0.;
  };

  /**
   * @brief The resultant of ElasticModel::pressures over @p triangulation
   * (straight-sided cells, Gauss quadrature exact for the planar faces of
   * a swept mesh): the support load the FE model actually applies, from
   * the mesh's ids, independent of how the pressures were derived.
   */
  template <int dim>
  SurfaceLoad<dim>
  applied_surface_load(const dealii::Triangulation<dim> &triangulation,
                       const ElasticModel<dim>          &model);
} // namespace FloorBlock::Fem
