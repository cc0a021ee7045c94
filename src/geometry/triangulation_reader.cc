#include <geometry/triangulation_reader.h>

#include <deal.II/grid/grid_in.h>

#include <fstream>
#include <stdexcept>

namespace FloorBlock::Geometry
{
  void
  read_triangulation(const std::string        &msh_path,
                     dealii::Triangulation<2> &triangulation)
  {
    std::ifstream input(msh_path);
    if (!input)
      throw std::runtime_error("cannot open mesh file " + msh_path);
    triangulation.clear();
    dealii::GridIn<2> grid_in;
    grid_in.attach_triangulation(triangulation);
    // The stream reader parses the file itself; the file-name overload
    // would initialise and finalise the Gmsh library behind our back.
    try
      {
        grid_in.read_msh(input);
      }
    catch (const std::exception &error)
      {
        throw std::runtime_error("cannot read mesh file " + msh_path + ": " +
                                 error.what());
      }
  }
} // namespace FloorBlock::Geometry
