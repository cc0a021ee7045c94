#include <geometry/extruded_assembly.h>
#include <geometry/footprint_surfaces.h>
#include <geometry/ids.h>
#include <scene/support_footprint.h>

#include <algorithm>
#include <map>

namespace FloorBlock::Scene
{
  std::optional<SupportFootprint>
  support_footprint(const Parameters::ScenarioParameters &scene)
  {
    const double length = scene.loading.footprint_length;
    if (scene.geometry.dimension != 3 || !(length > 0.))
      return std::nullopt;
    const double     face_length = scene.geometry.face_length;
    SupportFootprint footprint;
    footprint.start = scene.loading.footprint_offset ?
                        *scene.loading.footprint_offset :
                        (face_length - length) / 2.;
    // An end within the parameters' slack of the face's end is the face's
    // end (scenario_parameters.cc), not a sliver slice beyond it.
    footprint.end = std::min(footprint.start + length, face_length);
    return footprint;
  }

  std::vector<double>
  swept_slices(const Parameters::ScenarioParameters &scene)
  {
    const auto footprint = support_footprint(scene);
    if (!footprint)
      return Geometry::uniform_slices(scene.geometry.face_length,
                                      scene.mesh.slice_size);
    return Geometry::footprint_slices(scene.geometry.face_length,
                                      scene.mesh.slice_size,
                                      footprint->start,
                                      footprint->end);
  }

  void
  tag_support_footprint(const Parameters::ScenarioParameters &scene,
                        dealii::Triangulation<3>             &solid)
  {
    if (const auto footprint = support_footprint(scene))
      Geometry::tag_footprint(scene.loaded_blocks(),
                              footprint->start,
                              footprint->end,
                              solid);
  }

  void
  load_support_footprint(const SupportFootprint     &footprint,
                         const double                support_width,
                         Contact::ContactProblem<3> &problem)
  {
    namespace Ids      = Geometry::Ids;
    auto        &model = problem.model;
    const double scale = support_width / footprint.length();
    std::map<dealii::types::boundary_id, double> pressures;
    for (const auto &[id, pressure] : model.pressures)
      {
        if (Ids::boundary_kind(id) != Ids::BoundaryKind::floor_surface)
          {
            pressures[id] = pressure;
            continue;
          }
        const auto under_support =
          Ids::footprint_surface(Ids::boundary_index(id));
        pressures[under_support] = pressure * scale;
        if (model.vertical_pressures.erase(id) > 0)
          model.vertical_pressures.insert(under_support);
      }
    model.pressures = pressures;
  }
} // namespace FloorBlock::Scene
