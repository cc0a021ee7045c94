#include <fem/rigid_motion.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <vector>

namespace FloorBlock::Fem
{
  namespace
  {
    /** |r|^2 of the x-y part: the polar moment about the z axis. */
    template <int dim>
    double
    in_plane_norm_square(const dealii::Tensor<1, dim> &vector)
    {
      if constexpr (dim == 2)
        return vector.norm_square();
      else
        return vector[0] * vector[0] + vector[1] * vector[1];
    }
  } // namespace

  template <int dim>
  std::map<dealii::types::material_id, RigidMotion<dim>>
  fit_rigid_motions(const FeSpace<dim>                          &space,
                    const dealii::TrilinosWrappers::MPI::Vector &solution)
  {
    // Integrals over each body: area, first moments of position and
    // displacement, the moment x cross u and the polar moment |x|^2.
    struct Moments
    {
      double                 area = 0.;
      dealii::Tensor<1, dim> position;
      dealii::Tensor<1, dim> displacement;
      double                 cross  = 0.;
      double                 radius = 0.;
    };
    std::map<dealii::types::material_id, Moments> bodies;

    dealii::FEValues<dim> fe_values(space.mapping(),
                                    space.fe(),
                                    space.cell_quadrature(),
                                    dealii::update_values |
                                      dealii::update_quadrature_points |
                                      dealii::update_JxW_values);
    const dealii::FEValuesExtractors::Vector displacement(0);
    std::vector<dealii::Tensor<1, dim>>      values(
      space.cell_quadrature().size());
    for (const auto &cell : space.dof_handler().active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values[displacement].get_function_values(solution, values);
        Moments &body = bodies[cell->material_id()];
        for (unsigned int q = 0; q < values.size(); ++q)
          {
            const dealii::Point<dim> &x = fe_values.quadrature_point(q);
            const double              w = fe_values.JxW(q);
            body.area += w;
            body.position += w * x;
            body.displacement += w * values[q];
            body.cross += w * (x[0] * values[q][1] - x[1] * values[q][0]);
            body.radius += w * in_plane_norm_square<dim>(x);
          }
      }

    std::map<dealii::types::material_id, RigidMotion<dim>> motions;
    for (const auto &[material, body] : bodies)
      {
        const dealii::Tensor<1, dim> centroid = body.position / body.area;
        RigidMotion<dim>             motion;
        motion.translation = body.displacement / body.area;
        // About the centroid: int r x u = int x x u - c x int u, and
        // int |r|^2 = int |x|^2 - A |c|^2.
        const double moment =
          body.cross - (centroid[0] * body.displacement[1] -
                        centroid[1] * body.displacement[0]);
        const double inertia =
          body.radius - body.area * in_plane_norm_square(centroid);
        motion.rotation   = inertia > 0. ? moment / inertia : 0.;
        motions[material] = motion;
      }
    return motions;
  }

  template std::map<dealii::types::material_id, RigidMotion<2>>
  fit_rigid_motions(const FeSpace<2> &,
                    const dealii::TrilinosWrappers::MPI::Vector &);
  template std::map<dealii::types::material_id, RigidMotion<3>>
  fit_rigid_motions(const FeSpace<3> &,
                    const dealii::TrilinosWrappers::MPI::Vector &);
} // namespace FloorBlock::Fem
