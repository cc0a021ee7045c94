#include <verification/block_assembly_mesh.h>

#include <deal.II/grid/tria_description.h>

#include <cmath>

namespace FloorBlock::Verification
{
  void
  make_block_assembly(const std::vector<BlockSpec> &blocks,
                      dealii::Triangulation<2>     &triangulation)
  {
    std::vector<dealii::Point<2>>    vertices;
    std::vector<dealii::CellData<2>> cells;
    for (const BlockSpec &block : blocks)
      {
        const unsigned int first = vertices.size();
        for (unsigned int j = 0; j <= block.n_y; ++j)
          for (unsigned int i = 0; i <= block.n_x; ++i)
            vertices.emplace_back(block.x_min +
                                    (block.x_max - block.x_min) * i / block.n_x,
                                  block.y_min + (block.y_max - block.y_min) *
                                                  j / block.n_y);
        for (unsigned int j = 0; j < block.n_y; ++j)
          for (unsigned int i = 0; i < block.n_x; ++i)
            {
              dealii::CellData<2> cell;
              const unsigned int  base = first + j * (block.n_x + 1) + i;
              cell.vertices            = {base,
                                          base + 1,
                                          base + block.n_x + 1,
                                          base + block.n_x + 2};
              cell.material_id         = block.material;
              cells.push_back(cell);
            }
      }
    triangulation.create_triangulation(vertices, cells, dealii::SubCellData());
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        {
          if (!face->at_boundary())
            continue;
          for (const BlockSpec &block : blocks)
            {
              if (block.material != cell->material_id())
                continue;
              const dealii::Point<2> centre = face->center();
              const double tolerance = 1e-9 * (block.x_max - block.x_min);
              if (std::abs(centre[0] - block.x_min) < tolerance)
                face->set_boundary_id(block.left);
              else if (std::abs(centre[0] - block.x_max) < tolerance)
                face->set_boundary_id(
                  centre[1] > block.split_y ? block.right_upper : block.right);
              else if (std::abs(centre[1] - block.y_min) < tolerance)
                face->set_boundary_id(block.bottom);
              else if (std::abs(centre[1] - block.y_max) < tolerance)
                face->set_boundary_id(
                  centre[0] > block.split_x ? block.top_right : block.top);
            }
        }
  }
} // namespace FloorBlock::Verification
