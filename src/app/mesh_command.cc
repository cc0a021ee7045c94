#include <app/command_options.h>
#include <geometry/assembly_mesher.h>
#include <geometry/ids.h>
#include <geometry/triangulation_reader.h>
#include <output/mesh_picture.h>
#include <output/result_folder.h>
#include <scene/assembly_inputs.h>
#include <scene/contact_zone_sizing.h>

#include <deal.II/grid/tria.h>

#include <fmt/format.h>

#include <filesystem>
#include <iostream>

namespace FloorBlock::App
{
  int
  mesh_command(const CommandOptions &options)
  {
    const auto scene       = read_scene(options);
    const auto description = Scene::assembly_description(scene);
    Geometry::validate(description);
    if (options.print_ids)
      std::cout << Geometry::Ids::id_table(description.n_blocks) << std::endl;

    // The mesh goes to meshes/ (or --output), its picture to the results.
    const std::string mesh_folder =
      options.output_directory.empty() ? "meshes" : options.output_directory;
    std::filesystem::create_directories(mesh_folder);
    const std::string msh_path =
      (std::filesystem::path(mesh_folder) / (scene.scene_name + ".msh"))
        .string();
    const auto statistics = Geometry::write_gmsh_mesh(
      description, msh_path, Scene::contact_zone_sizes(scene));

    dealii::Triangulation<2> triangulation;
    Geometry::read_triangulation(msh_path, triangulation);
    const Output::ResultFolder folder(output_directory(options, scene));
    Output::write_mesh_picture(
      triangulation, folder.path_of("mesh.png"),
      {1600, 0,
       fmt::format("{}: {} cells, {} bodies", scene.scene_name,
                   statistics.n_cells, statistics.n_bodies),
       {}});

    std::cout << fmt::format(
                   "meshed '{}': {} quadrilaterals, {} nodes, {} bodies, {} "
                   "matched joint pairs in {:.3f} s\nwrote {} and {}\n",
                   scene.scene_name, statistics.n_cells, statistics.n_nodes,
                   statistics.n_bodies, statistics.n_matched_pairs,
                   statistics.wall_time, msh_path, folder.path_of("mesh.png"));
    return 0;
  }
} // namespace FloorBlock::App
