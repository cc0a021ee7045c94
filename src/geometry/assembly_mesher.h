#pragma once

#include <geometry/assembly_description.h>
#include <geometry/local_size_field.h>

#include <cstddef>
#include <string>
#include <vector>

namespace FloorBlock::Geometry
{
  /** @brief What write_gmsh_mesh() produced. */
  struct MeshStatistics
  {
    /** Number of quadrilateral cells. */
    std::size_t n_cells = 0;
    /** Number of mesh nodes (joint sides have their own nodes). */
    std::size_t n_nodes = 0;
    /** Number of bodies (blocks, face block, base). */
    unsigned int n_bodies = 0;
    /** Number of joint-side pairs meshed with matching nodes. */
    unsigned int n_matched_pairs = 0;
    /** Wall time of geometry + meshing + writing. Units: s. */
    double wall_time = 0.0;
    /**
     * Where the contact-zone sizes came from (Scene::source_key(); empty for
     * a mesh not made from a scene), the same in words, and the contact
     * length (m) they were made for (0 without sizes).
     */
    std::string contact_zone_source;
    std::string contact_zone_sizing;
    double      contact_zone_length = 0.;
    /** Wall time of choosing those sizes, a first solve included. Units: s. */
    double sizing_wall_time = 0.;
  };

  /**
   * @brief Validate the description, build the block assembly with Gmsh's
   * OCC kernel, mesh it with quadrilaterals and write it as a Gmsh 4.1
   * .msh file with physical groups from ids.h.
   *
   * Cells are sized by the distance d to the nearest contact corner:
   * \f$h(d) = \min(h_{far}, h_{corner} + (g - 1) d)\f$, which is the size
   * reached when each cell is g times larger than its neighbour towards
   * the corner. With matching joints, every joint side pair is meshed
   * periodically with the identity map (same nodes on both sides); without,
   * the face-side/base-side curve of each pair gets a uniform spacing of
   * 1.5 times the corner size so the sides do not match.
   *
   * @param[in] description The scene; checked with validate() first.
   * @param[in] msh_path File to write; its directory must exist.
   * @param[in] local_sizes Extra requested sizes (adaptive re-meshing): the
   *   cell size is the minimum of h(d) above and local_size_at(); fillet
   *   arcs use the smaller of the corner size and the local size at their
   *   ends. Checked with validate_local_sizes().
   * @throws FloorBlock::InputError for bad geometry (before Gmsh runs).
   * @throws std::runtime_error if Gmsh fails or leaves non-quad cells.
   */
  MeshStatistics
  write_gmsh_mesh(const AssemblyDescription    &description,
                  const std::string            &msh_path,
                  const std::vector<LocalSize> &local_sizes = {});

  /**
   * @brief Area of every body as OpenCASCADE integrates it on the exact
   * CAD geometry (no mesh), in outline order: blocks 1..n, face block,
   * base. Units: m^2. Opens its own GmshScope.
   */
  std::vector<double>
  cad_body_areas(const AssemblyDescription &description);
} // namespace FloorBlock::Geometry
