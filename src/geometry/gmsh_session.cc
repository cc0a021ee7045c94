#include <geometry/gmsh_session.h>

#include <gmsh.h>

#include <stdexcept>

namespace FloorBlock::Geometry
{
  namespace
  {
    bool session_open = false;
  }

  GmshSession::GmshSession(const bool verbose)
  {
    if (session_open)
      throw std::logic_error("a Gmsh session is already open");
    // readConfigFiles = false: a user's ~/.gmshrc must not change our meshes.
    gmsh::initialize(0, nullptr, false);
    session_open = true;
    gmsh::option::setNumber("General.Terminal", verbose ? 1 : 0);
    gmsh::option::setNumber("General.Verbosity", verbose ? 5 : 0);
  }

  GmshSession::~GmshSession()
  {
    gmsh::finalize();
    session_open = false;
  }

  bool
  GmshSession::is_open()
  {
    return session_open;
  }
} // namespace FloorBlock::Geometry
