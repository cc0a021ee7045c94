#include <geometry/footprint_surfaces.h>
#include <geometry/ids.h>

#include <map>

namespace FloorBlock::Geometry
{
  unsigned int
  tag_footprint(const std::vector<unsigned int> &loaded_blocks,
                const double                     footprint_start,
                const double                     footprint_end,
                dealii::Triangulation<3>        &solid)
  {
    std::map<dealii::types::boundary_id, dealii::types::boundary_id> retag;
    for (const unsigned int block : loaded_blocks)
      retag[Ids::floor_surface(block)] = Ids::footprint_surface(block);
    unsigned int n_tagged = 0;
    for (const auto &cell : solid.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        {
          if (!face->at_boundary())
            continue;
          const auto   found = retag.find(face->boundary_id());
          const double z     = face->center()[2];
          if (found != retag.end() && z > footprint_start && z < footprint_end)
            {
              face->set_boundary_id(found->second);
              ++n_tagged;
            }
        }
    return n_tagged;
  }
} // namespace FloorBlock::Geometry
