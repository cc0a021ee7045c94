#include <fem/rigid_motion.h>

#include <deal.II/base/mpi.h>
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

    /**
     * Integrals over one body: area, first moments of position and
     * displacement, the moment x cross u and the polar moment |x|^2.
     */
    template <int dim>
    struct Moments
    {
      double                 area = 0.;
      dealii::Tensor<1, dim> position;
      dealii::Tensor<1, dim> displacement;
      double                 cross  = 0.;
      double                 radius = 0.;
    };

    /**
     * The bodies' integrals over the whole mesh: each process integrated
     * the cells it owns (on one process: unchanged).
     */
    template <int dim>
    std::map<dealii::types::material_id, Moments<dim>>
    sum_over_processes(
      const std::map<dealii::types::material_id, Moments<dim>> &local,
      const MPI_Comm                                            communicator)
    {
      if (dealii::Utilities::MPI::n_mpi_processes(communicator) == 1)
        return local;
      // Flat records: material, area, position, displacement, cross, radius.
      std::vector<double> packed;
      for (const auto &[material, body] : local)
        {
          packed.push_back(material);
          packed.push_back(body.area);
          for (unsigned int c = 0; c < dim; ++c)
            packed.push_back(body.position[c]);
          for (unsigned int c = 0; c < dim; ++c)
            packed.push_back(body.displacement[c]);
          packed.push_back(body.cross);
          packed.push_back(body.radius);
        }
      const unsigned int                                 record = 2 * dim + 4;
      std::map<dealii::types::material_id, Moments<dim>> total;
      for (const auto &part :
           dealii::Utilities::MPI::all_gather(communicator, packed))
        for (std::size_t r = 0; r + record <= part.size(); r += record)
          {
            const double *const values = part.data() + r;
            Moments<dim>       &body =
              total[static_cast<dealii::types::material_id>(values[0])];
            body.area += values[1];
            for (unsigned int c = 0; c < dim; ++c)
              {
                body.position[c] += values[2 + c];
                body.displacement[c] += values[2 + dim + c];
              }
            body.cross += values[2 + 2 * dim];
            body.radius += values[3 + 2 * dim];
          }
      return total;
    }
  } // namespace

  template <int dim>
  std::map<dealii::types::material_id, RigidMotion<dim>>
  fit_rigid_motions(const FeSpace<dim>                          &space,
                    const dealii::TrilinosWrappers::MPI::Vector &solution)
  {
    std::map<dealii::types::material_id, Moments<dim>> bodies;

    dealii::FEValues<dim>                    fe_values(space.mapping(),
                                    space.fe(),
                                    space.cell_quadrature(),
                                    dealii::update_values |
                                      dealii::update_quadrature_points |
                                      dealii::update_JxW_values);
    const dealii::FEValuesExtractors::Vector displacement(0);
    std::vector<dealii::Tensor<1, dim>> values(space.cell_quadrature().size());
    for (const auto &cell : space.dof_handler().active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        fe_values.reinit(cell);
        fe_values[displacement].get_function_values(solution, values);
        Moments<dim> &body = bodies[cell->material_id()];
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

    bodies = sum_over_processes(bodies, space.dof_handler().get_communicator());
    std::map<dealii::types::material_id, RigidMotion<dim>> motions;
    for (const auto &[material, body] : bodies)
      {
        const dealii::Tensor<1, dim> centroid = body.position / body.area;
        RigidMotion<dim>             motion;
        motion.translation = body.displacement / body.area;
        // About the centroid: int r x u = int x x u - c x int u, and
        // int |r|^2 = int |x|^2 - A |c|^2.
        const double moment = body.cross - (centroid[0] * body.displacement[1] -
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
