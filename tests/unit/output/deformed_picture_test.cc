#include <geometry/ids.h>
#include <output/deformed_picture.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "test_meshes.h"

namespace FloorBlock::Output
{
  namespace
  {
    /** One closed polygon of the $cells block: its vertices and value. */
    struct DrawnCell
    {
      std::vector<std::array<double, 2>> vertices;
      std::vector<double>                values;
    };

    /** The polygons of the data blocks $cells and $base. */
    std::vector<DrawnCell>
    drawn_cells(const std::string &script)
    {
      std::vector<DrawnCell> cells;
      std::istringstream     lines(script);
      std::string            line;
      bool                   inside = false, new_cell = true;
      while (std::getline(lines, line))
        {
          if (line == "$cells << EOD" || line == "$base << EOD")
            inside = new_cell = true;
          else if (line == "EOD")
            inside = false;
          else if (inside && line.empty())
            new_cell = true;
          else if (inside)
            {
              if (new_cell)
                cells.emplace_back();
              new_cell = false;
              std::istringstream fields(line);
              double             x = 0., y = 0., value = 0.;
              fields >> x >> y >> value;
              EXPECT_FALSE(fields.fail()) << "x y value expected: " << line;
              cells.back().vertices.push_back({{x, y}});
              cells.back().values.push_back(value);
            }
        }
      return cells;
    }
  } // namespace

  // The tool shall colour every cell of the deformed picture by one stress
  // value and draw the face on the right, as the README's diagram does.
  TEST(DeformedPicture, EveryCellCarriesItsStressAndTheFaceIsOnTheRight)
  {
    namespace Ids = Geometry::Ids;
    const auto &triangulation =
      Geometry::Testing::meshed_scene("default").triangulation;
    const std::vector<dealii::Tensor<1, 2>> no_motion(
      triangulation.n_vertices());
    // The value of a cell is its material id: it names the body it is in.
    std::vector<double> stress(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      stress[cell->active_cell_index()] = cell->material_id() * 1e6;

    const std::string script =
      deformed_picture_script(triangulation, no_motion, stress, {}, 1., "");
    const std::vector<DrawnCell> cells = drawn_cells(script);
    ASSERT_EQ(cells.size(), triangulation.n_active_cells());

    double face_x_min = 1e300, block_1_x_max = -1e300;
    for (const DrawnCell &cell : cells)
      {
        ASSERT_EQ(cell.vertices.size(), 5u) << "closed quadrilateral";
        for (const double value : cell.values)
          EXPECT_EQ(value, cell.values.front()) << "one value per cell";
        // MPa in the picture, from Pa.
        const double material = cell.values.front();
        for (const auto &vertex : cell.vertices)
          {
            if (material == Ids::face_block_material)
              face_x_min = std::min(face_x_min, vertex[0]);
            if (material == Ids::block_material(1))
              block_1_x_max = std::max(block_1_x_max, vertex[0]);
          }
      }
    // Block 1 is the free end; every face-block cell lies right of it.
    EXPECT_GT(face_x_min, block_1_x_max);
    EXPECT_NE(script.find("face on the right"), std::string::npos);
  }
} // namespace FloorBlock::Output
