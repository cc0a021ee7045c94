#pragma once

#include <geometry/assembly_mesher.h>
#include <output/result_folder.h>
#include <parameters/scenario_parameters.h>

#include <deal.II/distributed/fully_distributed_tria.h>

namespace FloorBlock::Pipeline
{
  /**
   * @brief The 3D scene's swept mesh spread over the processes of
   * @p triangulation's communicator: the first process meshes the scene
   * (mesh_swept_scene(), which writes mesh.msh) and partitions the cells
   * with METIS (fewest cut faces), then each process receives its own
   * cells and one layer of ghosts (parallel::fullydistributed). Only the
   * first process ever holds the whole mesh.
   *
   * @return The mesh statistics (as the first process measured them) on
   *   every process.
   */
  Geometry::MeshStatistics
  distribute_swept_mesh(
    const Parameters::ScenarioParameters                 &scene,
    const Output::ResultFolder                           &folder,
    dealii::parallel::fullydistributed::Triangulation<3> &triangulation);
} // namespace FloorBlock::Pipeline
