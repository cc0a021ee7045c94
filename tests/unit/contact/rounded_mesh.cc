#include "rounded_mesh.h"

#include <geometry/assembly_mesher.h>
#include <geometry/bedding_manifold.h>
#include <geometry/triangulation_reader.h>

#include <unistd.h>

#include <filesystem>

namespace FloorBlock::Testing
{
  Geometry::AssemblyDescription
  level_assembly(const unsigned int n_blocks,
                 const double       rounding,
                 const double       corner_size)
  {
    Geometry::AssemblyDescription description;
    description.n_blocks               = n_blocks;
    description.bedding_shape          = Geometry::BeddingShape::planar;
    description.inclination            = 0.;
    description.corner_rounding_radius = rounding;
    description.mesh_corner_size       = corner_size;
    return description;
  }

  void
  mesh_assembly(const Geometry::AssemblyDescription &description,
                const std::string                   &name,
                dealii::Triangulation<2>            &triangulation)
  {
    // One scratch folder per test process: parallel ctest runs do not collide.
    const std::filesystem::path folder =
      std::filesystem::temp_directory_path() /
      ("floorblock_contact_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const std::string msh_path = (folder / (name + ".msh")).string();
    Geometry::write_gmsh_mesh(description, msh_path);
    Geometry::read_triangulation(msh_path, triangulation);
    Geometry::attach_bedding_manifold(description, triangulation);
    std::filesystem::remove(msh_path);
    std::filesystem::remove(folder); // only if empty: no other mesh pending
  }
} // namespace FloorBlock::Testing
