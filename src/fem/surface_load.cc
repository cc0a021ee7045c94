#include <fem/face_values.h>
#include <fem/surface_load.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <cmath>

namespace FloorBlock::Fem
{
  template <int dim>
  dealii::Tensor<1, dim>
  surface_traction(const ElasticModel<dim>         &model,
                   const dealii::types::boundary_id boundary_id,
                   const double                     pressure,
                   const dealii::Tensor<1, dim>    &normal)
  {
    if (model.vertical_pressures.count(boundary_id) == 0)
      return -pressure * normal; // pushes against the outward normal
    return pressure * std::abs(normal * model.down) * model.down;
  }

  template <int dim>
  SurfaceLoad<dim>
  applied_surface_load(const dealii::Triangulation<dim> &triangulation,
                       const ElasticModel<dim>          &model)
  {
    // A scalar Q1 element only to reach the faces' normals and JxW.
    const dealii::FE_Q<dim> fe(1);
    dealii::DoFHandler<dim> dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);
    const dealii::QGauss<dim - 1> quadrature(2);
    dealii::FEFaceValues<dim>     face_values = boundary_face_values(
      fe.reference_cell().template get_default_linear_mapping<dim>(),
      fe,
      quadrature);
    SurfaceLoad<dim> load;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        {
          // A distributed mesh: each process its own cells, summed below.
          if (!cell->is_locally_owned() || !face->at_boundary())
            continue;
          const auto pressure = model.pressures.find(face->boundary_id());
          if (pressure == model.pressures.end())
            continue;
          face_values.reinit(cell, face);
          for (const unsigned int q : face_values.quadrature_point_indices())
            {
              load.force += surface_traction(model,
                                             face->boundary_id(),
                                             pressure->second,
                                             face_values.normal_vector(q)) *
                            face_values.JxW(q);
              load.loaded_area += face_values.JxW(q);
            }
        }
    const MPI_Comm communicator = triangulation.get_communicator();
    load.force = dealii::Utilities::MPI::sum(load.force, communicator);
    load.loaded_area =
      dealii::Utilities::MPI::sum(load.loaded_area, communicator);
    return load;
  }

  template dealii::Tensor<1, 2>
  surface_traction(const ElasticModel<2> &,
                   const dealii::types::boundary_id,
                   const double,
                   const dealii::Tensor<1, 2> &);
  template dealii::Tensor<1, 3>
  surface_traction(const ElasticModel<3> &,
                   const dealii::types::boundary_id,
                   const double,
                   const dealii::Tensor<1, 3> &);
  template SurfaceLoad<2>
  applied_surface_load(const dealii::Triangulation<2> &,
                       const ElasticModel<2> &);
  template SurfaceLoad<3>
  applied_surface_load(const dealii::Triangulation<3> &,
                       const ElasticModel<3> &);
} // namespace FloorBlock::Fem
