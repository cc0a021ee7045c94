// Adaptive re-meshing through the Gmsh size field: a local size request
// refines the mesh there, and both sides of the joint keep the same nodes
// (the node-to-node contact pairing depends on it).
#include <geometry/assembly_mesher.h>
#include <geometry/ids.h>
#include <geometry/triangulation_reader.h>

#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>

namespace
{
  using namespace FloorBlock::Geometry;

  constexpr double pairing_tolerance = 1e-12; // m, as the geometry tests

  /** Three 1 m x 2 m blocks on a flat bedding, coarse (0.1 m corners). */
  AssemblyDescription
  coarse_scene(const double rounding)
  {
    AssemblyDescription description;
    description.n_blocks               = 3;
    description.floor_uplift           = FloorUplift::lifted_flat_bedding;
    description.corner_rounding_radius = rounding;
    description.mesh_corner_size       = 0.1;
    description.mesh_far_size          = 0.5;
    return description;
  }

  std::vector<dealii::Point<2>>
  side_vertices(const dealii::Triangulation<2>  &triangulation,
                const dealii::types::boundary_id boundary)
  {
    std::vector<dealii::Point<2>> points;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == boundary)
          for (unsigned int v = 0; v < 2; ++v)
            if (std::none_of(points.begin(),
                             points.end(),
                             [&](const dealii::Point<2> &known) {
                               return known.distance(face->vertex(v)) <
                                      pairing_tolerance;
                             }))
              points.push_back(face->vertex(v));
    return points;
  }

  /** Length of the joint edge that contains height y (m). */
  double
  edge_length_at(const dealii::Triangulation<2>  &triangulation,
                 const dealii::types::boundary_id boundary,
                 const double                     height)
  {
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == boundary)
          {
            const double low = std::min(face->vertex(0)[1], face->vertex(1)[1]);
            const double high =
              std::max(face->vertex(0)[1], face->vertex(1)[1]);
            if (low <= height && height <= high)
              return face->measure();
          }
    return std::numeric_limits<double>::max();
  }

  struct Meshed
  {
    MeshStatistics           statistics;
    dealii::Triangulation<2> triangulation;
  };

  void
  mesh(const AssemblyDescription    &description,
       const std::vector<LocalSize> &requests,
       const std::string            &name,
       Meshed                       &meshed)
  {
    const auto folder = std::filesystem::temp_directory_path() /
                        ("floorblock_local_size_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const std::string path = (folder / (name + ".msh")).string();
    meshed.statistics      = write_gmsh_mesh(description, path, requests);
    read_triangulation(path, meshed.triangulation);
    std::filesystem::remove_all(folder);
  }

  TEST(LocalSizeMesh, RequestRefinesTheJointAndKeepsItsSidesMatching)
  {
    const AssemblyDescription description = coarse_scene(0.);
    constexpr double          requested   = 0.01; // m at mid-height
    constexpr double          height      = 1.0;  // m on the face joint x = 0
    Meshed                    plain, refined;
    mesh(description, {}, "plain", plain);
    mesh(description, {{{0., height}, requested}}, "refined", refined);

    const auto block_side = Ids::vertical_joint_free_side(3);
    const auto face_side  = Ids::vertical_joint_face_side(3);
    // Without the request the joint edge there has about
    // min(far, corner + 0.3 x 1 m) = 0.4 m; with it, the requested size
    // (Gmsh's quads deviate from the field; a factor 1.5 is allowed).
    EXPECT_GT(edge_length_at(plain.triangulation, block_side, height), 0.2);
    EXPECT_LT(edge_length_at(refined.triangulation, block_side, height),
              1.5 * requested);
    EXPECT_GT(refined.statistics.n_cells, plain.statistics.n_cells);

    const auto block_points = side_vertices(refined.triangulation, block_side);
    const auto face_points  = side_vertices(refined.triangulation, face_side);
    ASSERT_EQ(block_points.size(), face_points.size());
    for (const auto &point : block_points)
      EXPECT_TRUE(std::any_of(face_points.begin(),
                              face_points.end(),
                              [&](const dealii::Point<2> &other) {
                                return point.distance(other) <
                                       pairing_tolerance;
                              }))
        << point;
  }

  TEST(LocalSizeMesh, RequestAtAFilletRefinesBothFilletsAlike)
  {
    constexpr double          radius      = 0.1; // m
    const AssemblyDescription description = coarse_scene(radius);
    Meshed                    plain, refined;
    mesh(description, {}, "plain_rounded", plain);
    // At the lower end of the fillets of the face joint (y = H - r), where
    // the straight part of the joint ends. The fillet takes the smallest
    // local size at its two ends.
    mesh(description, {{{0., 2. - radius}, 0.01}}, "refined_rounded", refined);
    const auto on_fillet = [&](const dealii::Triangulation<2>  &triangulation,
                               const dealii::types::boundary_id id) {
      std::size_t count = 0;
      for (const auto &point : side_vertices(triangulation, id))
        count += point[1] > 2. - radius + pairing_tolerance;
      return count;
    };
    const auto block_side = Ids::vertical_joint_free_side(3);
    const auto face_side  = Ids::vertical_joint_face_side(3);
    // Arc length pi/2 x 0.1 = 0.157 m: 4 cells at the 0.1 m corner size
    // (the minimum), 2 x ceil(0.157 / 0.02) = 16 at the 0.01 m request.
    EXPECT_EQ(on_fillet(plain.triangulation, block_side), 4u);
    EXPECT_EQ(on_fillet(refined.triangulation, block_side), 16u);
    EXPECT_EQ(on_fillet(refined.triangulation, face_side), 16u);
  }
} // namespace
