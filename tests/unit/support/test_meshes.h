#pragma once

#include <geometry/assembly_description.h>
#include <geometry/assembly_mesher.h>

#include <deal.II/grid/tria.h>

#include <string>

namespace FloorBlock::Geometry::Testing
{
  /** A scene meshed once per test process and read back into deal.II. */
  struct MeshedScene
  {
    AssemblyDescription      description;
    MeshStatistics           statistics;
    std::string              msh_path;
    dealii::Triangulation<2> triangulation;
  };

  /**
   * @brief The named test scenes, meshed on first use into a scratch folder
   * (never into results/):
   *  - "default": AssemblyDescription{} (6 blocks on y = x^2/400, sharp);
   *  - "planar": 4 blocks on a 10 deg plane, sharp;
   *  - "rounded": 5 blocks on y = x^2/100 with 0.05 m fillets;
   *  - "planar_rounded": flat 3 blocks with 0.1 m fillets;
   *  - "non_matching": like "planar" with matching joints off;
   *  - "lifted": the default profile read as a lifted flat bedding.
   */
  const MeshedScene &
  meshed_scene(const std::string &name);

  /** @brief The description of a named scene (without meshing it). */
  AssemblyDescription
  scene_description(const std::string &name);

  /** @brief A scratch folder for this test process, created on first use. */
  std::string
  scratch_folder();
} // namespace FloorBlock::Geometry::Testing
