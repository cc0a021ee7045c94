#include <pipeline/distributed_swept_mesh.h>
#include <pipeline/fem_pipeline.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <vector>

namespace FloorBlock::Pipeline
{
  Geometry::MeshStatistics
  distribute_swept_mesh(
    const Parameters::ScenarioParameters                 &scene,
    const Output::ResultFolder                           &folder,
    dealii::parallel::fullydistributed::Triangulation<3> &triangulation)
  {
    const MPI_Comm     communicator = triangulation.get_communicator();
    const unsigned int n_processes =
      dealii::Utilities::MPI::n_mpi_processes(communicator);
    Geometry::MeshStatistics mesh;
    // One group of all processes: its first process alone builds the
    // serial mesh and sends every other process its part.
    const auto description = dealii::TriangulationDescription::Utilities::
      create_description_from_triangulation_in_groups<3, 3>(
        [&](dealii::Triangulation<3> &serial) {
          mesh = mesh_swept_scene(scene, folder, serial);
        },
        [](dealii::Triangulation<3> &serial,
           const MPI_Comm            group,
           const unsigned int) {
          dealii::GridTools::partition_triangulation(
            dealii::Utilities::MPI::n_mpi_processes(group), serial);
        },
        communicator,
        n_processes);
    triangulation.create_triangulation(description);

    std::vector<double> packed{static_cast<double>(mesh.n_cells),
                               static_cast<double>(mesh.n_nodes),
                               static_cast<double>(mesh.n_bodies),
                               static_cast<double>(mesh.n_matched_pairs),
                               mesh.wall_time};
    packed        = dealii::Utilities::MPI::broadcast(communicator, packed, 0);
    mesh.n_cells  = static_cast<std::size_t>(packed[0]);
    mesh.n_nodes  = static_cast<std::size_t>(packed[1]);
    mesh.n_bodies = static_cast<unsigned int>(packed[2]);
    mesh.n_matched_pairs = static_cast<unsigned int>(packed[3]);
    mesh.wall_time       = packed[4];
    return mesh;
  }
} // namespace FloorBlock::Pipeline
