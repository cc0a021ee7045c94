#include <pipeline/contact_zone_sizing.h>
#include <pipeline/fem_pipeline.h>

#include <deal.II/grid/tria.h>

#include <iostream>

namespace FloorBlock::Pipeline
{
  Scene::ContactZoneSizing
  contact_zone_sizing(const Parameters::ScenarioParameters &scene,
                      const Output::ResultFolder           &folder)
  {
    Scene::ContactZoneSizing sizing = Scene::closed_form_contact_zones(scene);
    if (sizing.source != Scene::ContactZoneSource::none)
      return sizing;
    if (scene.geometry.dimension == 3)
      {
        sizing.reason += "; a 3D scene is not solved first";
        return sizing;
      }

    std::cout << "contact zones: " << sizing.reason
              << "; sizing them from a first solve on the plain mesh"
              << std::endl;
    Parameters::ScenarioParameters plain = scene;
    plain.mesh.cells_per_contact_length = 0;
    plain.mesh.global_refinements       = 0;
    dealii::Triangulation<2>       triangulation;
    const Geometry::MeshStatistics mesh =
      mesh_scene(plain, folder, {}, triangulation);
    const Output::ResultFolder nowhere(folder.path_of(""), false);
    const FemOutcome           first =
      solve_meshed_scene(plain, triangulation, mesh, nowhere, false, {});
    if (!first.converged || first.result.increments.empty())
      {
        sizing.reason +=
          "; the first solve on the plain mesh did not converge (" +
          first.report.status_text + ")";
        return sizing;
      }
    return Scene::computed_contact_zones(scene,
                                         first.result.increments.back().joints);
  }
} // namespace FloorBlock::Pipeline
