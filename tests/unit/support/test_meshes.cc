#include "test_meshes.h"

#include <geometry/triangulation_reader.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>

namespace FloorBlock::Geometry::Testing
{
  namespace
  {
    /** Folder removed with everything in it when the test process ends. */
    struct ScratchFolder
    {
      std::filesystem::path path;
      ScratchFolder()
        : path(std::filesystem::temp_directory_path() /
               ("floorblock_geometry_tests_" + std::to_string(::getpid())))
      {
        std::filesystem::create_directories(path);
      }
      ~ScratchFolder()
      {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
      }
    };
  } // namespace

  std::string
  scratch_folder()
  {
    static const ScratchFolder folder;
    return folder.path.string();
  }

  AssemblyDescription
  scene_description(const std::string &name)
  {
    constexpr double    degree = M_PI / 180.0;
    AssemblyDescription description;
    if (name == "default")
      return description;
    if (name == "planar" || name == "non_matching")
      {
        description.n_blocks        = 4;
        description.bedding_shape   = BeddingShape::planar;
        description.inclination     = 10.0 * degree;
        description.matching_joints = name == "planar";
        return description;
      }
    if (name == "rounded")
      {
        description.n_blocks               = 5;
        description.curvature              = 100.0;
        description.corner_rounding_radius = 0.05;
        description.mesh_corner_size       = 0.02;
        return description;
      }
    if (name == "planar_rounded")
      {
        description.n_blocks               = 3;
        description.bedding_shape          = BeddingShape::planar;
        description.inclination            = 0.0;
        description.corner_rounding_radius = 0.1;
        return description;
      }
    if (name == "lifted")
      {
        description.floor_uplift = FloorUplift::lifted_flat_bedding;
        return description;
      }
    throw std::invalid_argument("unknown test scene " + name);
  }

  const MeshedScene &
  meshed_scene(const std::string &name)
  {
    static std::map<std::string, std::unique_ptr<MeshedScene>> scenes;
    auto &scene = scenes[name];
    if (!scene)
      {
        scene              = std::make_unique<MeshedScene>();
        scene->description = scene_description(name);
        scene->msh_path    = scratch_folder() + "/" + name + ".msh";
        scene->statistics =
          write_gmsh_mesh(scene->description, scene->msh_path);
        read_triangulation(scene->msh_path, scene->triangulation);
      }
    return *scene;
  }
} // namespace FloorBlock::Geometry::Testing
