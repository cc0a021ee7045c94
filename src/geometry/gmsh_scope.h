#pragma once

namespace FloorBlock::Geometry
{
  /**
   * @brief RAII owner of the Gmsh library state: initialises Gmsh on
   * construction and finalises it on destruction, silent unless asked.
   *
   * Gmsh is a process-wide singleton, so only one scope may be open at a
   * time; opening a second one throws std::logic_error. deal.II's
   * GridIn::read_msh(filename) initialises and finalises Gmsh by itself and
   * must therefore be called with no scope open.
   */
  class GmshScope
  {
  public:
    /** @param[in] verbose Let Gmsh print to the terminal (General.Terminal =
     * 1). */
    explicit GmshScope(const bool verbose = false);
    ~GmshScope();

    GmshScope(const GmshScope &) = delete;
    GmshScope &
    operator=(const GmshScope &) = delete;

    /** @brief Whether a scope is open in this process. */
    static bool
    is_open();
  };
} // namespace FloorBlock::Geometry
