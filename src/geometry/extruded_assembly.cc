#include <geometry/extruded_assembly.h>
#include <geometry/ids.h>

#include <deal.II/grid/grid_generator.h>

#include <cmath>
#include <set>

namespace FloorBlock::Geometry
{
  std::vector<double>
  uniform_slices(const double face_length, const double slice_size)
  {
    const auto n_slices = static_cast<unsigned int>(
      std::max(1., std::ceil(face_length / slice_size - 1e-9)));
    std::vector<double> slices(n_slices + 1);
    for (unsigned int k = 0; k <= n_slices; ++k)
      slices[k] = face_length * k / n_slices;
    return slices;
  }

  std::vector<double>
  footprint_slices(const double face_length,
                   const double slice_size,
                   const double footprint_start,
                   const double footprint_end)
  {
    const double ends[] = {0., footprint_start, footprint_end, face_length};
    std::vector<double> slices{0.};
    for (unsigned int part = 0; part < 3; ++part)
      {
        const double from = ends[part], to = ends[part + 1];
        if (!(to > from))
          continue;
        const std::vector<double> inside =
          uniform_slices(to - from, slice_size);
        for (unsigned int k = 1; k < inside.size(); ++k)
          slices.push_back(from + inside[k]);
        // The part's end exactly, not from + (to - from): a footprint end
        // must be the very z the tagging compares with.
        slices.back() = to;
      }
    return slices;
  }

  void
  extrude_assembly(const dealii::Triangulation<2> &assembly,
                   const std::vector<double>      &slice_coordinates,
                   dealii::Triangulation<3>       &result)
  {
    result.clear();
    dealii::GridGenerator::extrude_triangulation(assembly,
                                                 slice_coordinates,
                                                 result);
    // deal.II gives the end faces the next two free ids; ids.h names them.
    std::set<dealii::types::boundary_id> ids_2d;
    for (const auto &face : assembly.active_face_iterators())
      if (face->at_boundary())
        ids_2d.insert(face->boundary_id());
    const double length = slice_coordinates.back();
    for (const auto &cell : result.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && ids_2d.count(face->boundary_id()) == 0)
          {
            // An end face is normal to z: its centre sits on z = 0 or L.
            const double z = face->center()[2];
            face->set_boundary_id(std::abs(z) < 1e-9 * length ?
                                    Ids::end_face_near :
                                    Ids::end_face_far);
          }
  }
} // namespace FloorBlock::Geometry
