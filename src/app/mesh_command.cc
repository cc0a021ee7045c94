#include <app/command_options.h>
#include <common/atomic_file.h>
#include <geometry/assembly_mesher.h>
#include <geometry/extruded_assembly.h>
#include <geometry/ids.h>
#include <geometry/triangulation_reader.h>
#include <output/mesh_picture.h>
#include <output/result_folder.h>
#include <scene/assembly_inputs.h>
#include <scene/mesh_sizing.h>
#include <scene/support_footprint.h>

#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/tria.h>

#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <sstream>

namespace FloorBlock::App
{
  namespace
  {
    /** The 3D scene: the 2D mesh swept along the face, as <scene>_3d.msh. */
    void
    write_extruded_mesh(const Parameters::ScenarioParameters &scene,
                        const dealii::Triangulation<2>       &assembly,
                        const std::string                    &mesh_folder)
    {
      dealii::Timer            timer;
      dealii::Triangulation<3> solid;
      Geometry::extrude_assembly(assembly, Scene::swept_slices(scene), solid);
      Scene::tag_support_footprint(scene, solid);
      const std::string path =
        (std::filesystem::path(mesh_folder) / (scene.scene_name + "_3d.msh"))
          .string();
      std::ostringstream msh;
      dealii::GridOut().write_msh(solid, msh);
      write_file_atomically(path, msh.str());
      std::cout << fmt::format(
        "extruded along the face over {} m: {} hexahedra, {} "
        "vertices in {:.3f} s\nwrote {}\n",
        scene.geometry.face_length,
        solid.n_active_cells(),
        solid.n_used_vertices(),
        timer.wall_time(),
        path);
    }
  } // namespace

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
    const Scene::ContactZoneSizing zones =
      Scene::closed_form_contact_zones(scene);
    const auto statistics =
      Geometry::write_gmsh_mesh(description, msh_path, zones.sizes);

    dealii::Triangulation<2> triangulation;
    Geometry::read_triangulation(msh_path, triangulation);
    const Output::ResultFolder folder(output_directory(options, scene));
    Output::write_mesh_picture(triangulation,
                               folder.path_of("mesh.png"),
                               {1600,
                                0,
                                fmt::format("{}: {} cells, {} bodies",
                                            scene.scene_name,
                                            statistics.n_cells,
                                            statistics.n_bodies),
                                {}});

    std::cout << fmt::format(
      "meshed '{}': {} quadrilaterals, {} nodes, {} bodies, {} "
      "matched joint pairs in {:.3f} s\nwrote {} and {}\n",
      scene.scene_name,
      statistics.n_cells,
      statistics.n_nodes,
      statistics.n_bodies,
      statistics.n_matched_pairs,
      statistics.wall_time,
      msh_path,
      folder.path_of("mesh.png"));
    std::cout << Scene::describe(zones, scene.mesh.cells_per_contact_length)
              << (zones.source == Scene::ContactZoneSource::none ?
                    " (solve and run size them from a first solve)\n" :
                    "\n");
    if (scene.geometry.dimension == 3)
      write_extruded_mesh(scene, triangulation, mesh_folder);
    return 0;
  }
} // namespace FloorBlock::App
