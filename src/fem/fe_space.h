#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <vector>

namespace FloorBlock::Fem
{
  /**
   * @brief The displacement space: vector-valued FE_Q of a given degree on
   * a triangulation that may consist of several bodies (blocks with
   * duplicated vertices on the joints), its DoF numbering, mapping,
   * quadrature and hanging-node constraints.
   *
   * The index sets are the locally owned/relevant ones so that a
   * distributed run is one step away; today everything runs on one rank.
   */
  template <int dim>
  class FeSpace
  {
  public:
    /**
     * @param[in] triangulation The mesh; must outlive this object.
     * @param[in] degree Polynomial degree, 1 or 2.
     */
    FeSpace(const dealii::Triangulation<dim> &triangulation,
            const unsigned int                degree);

    const dealii::DoFHandler<dim> &
    dof_handler() const;
    const dealii::FiniteElement<dim> &
    fe() const;
    const dealii::Mapping<dim> &
    mapping() const;
    /** @brief Cell quadrature, exact for the stiffness matrix on affine cells. */
    const dealii::Quadrature<dim> &
    cell_quadrature() const;
    /** @brief Face quadrature, same order. */
    const dealii::Quadrature<dim - 1> &
    face_quadrature() const;
    const dealii::IndexSet &
    locally_owned_dofs() const;
    const dealii::IndexSet &
    locally_relevant_dofs() const;
    /** @brief Hanging-node constraints only (closed). */
    const dealii::AffineConstraints<double> &
    hanging_node_constraints() const;
    unsigned int
    degree() const;
    /** @brief Smallest cell diameter (m). */
    double
    minimal_cell_diameter() const;

  private:
    const unsigned int                fe_degree;
    const dealii::FESystem<dim>       finite_element;
    const dealii::MappingQ<dim>       mapping_q;
    const dealii::QGauss<dim>         cell_gauss;
    const dealii::QGauss<dim - 1>     face_gauss;
    dealii::DoFHandler<dim>           dofs;
    dealii::IndexSet                  owned;
    dealii::IndexSet                  relevant;
    dealii::AffineConstraints<double> hanging;
    double                            min_diameter;
  };
} // namespace FloorBlock::Fem
