#include <geometry/gmsh_scope.h>

#include <gmsh.h>

#include <stdexcept>

namespace FloorBlock::Geometry
{
  namespace
  {
    bool gmsh_initialized = false;
  }

  GmshScope::GmshScope(const bool verbose)
  {
    if (gmsh_initialized)
      throw std::logic_error(
        "Gmsh is already initialised by another GmshScope");
    // readConfigFiles = false: a user's ~/.gmshrc must not change our meshes.
    gmsh::initialize(0, nullptr, false);
    gmsh_initialized = true;
    gmsh::option::setNumber("General.Terminal", verbose ? 1 : 0);
    gmsh::option::setNumber("General.Verbosity", verbose ? 5 : 0);
  }

  GmshScope::~GmshScope()
  {
    gmsh::finalize();
    gmsh_initialized = false;
  }

  bool
  GmshScope::is_open()
  {
    return gmsh_initialized;
  }
} // namespace FloorBlock::Geometry
