#include <geometry/extruded_assembly.h>
#include <geometry/ids.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "test_meshes.h"

namespace FloorBlock::Geometry
{
  namespace
  {
    using dealii::types::boundary_id;
    using dealii::types::material_id;

    constexpr double face_length = 1.5; // m
    constexpr double slice_size  = 0.5; // m: three slices


    /** The named 2D test scene swept through three 0.5 m slices. */
    const dealii::Triangulation<3> &
    extruded(const std::string &name)
    {
      static std::map<std::string, dealii::Triangulation<3>> cache;
      auto [entry, inserted] = cache.try_emplace(name);
      if (inserted)
        extrude_assembly(Testing::meshed_scene(name).triangulation,
                         uniform_slices(face_length, slice_size),
                         entry->second);
      return entry->second;
    }

    /** Sum of cell measures per material id. Units: m^2 or m^3. */
    template <int dim>
    std::map<material_id, double>
    measure_by_material(const dealii::Triangulation<dim> &triangulation)
    {
      std::map<material_id, double> measures;
      for (const auto &cell : triangulation.active_cell_iterators())
        measures[cell->material_id()] += cell->measure();
      return measures;
    }
  } // namespace

  TEST(UniformSlices, EqualSlicesCoveringTheFaceLength)
  {
    EXPECT_EQ(uniform_slices(3.0, 1.0), (std::vector<double>{0., 1., 2., 3.}));
    const auto slices = uniform_slices(1.0, 0.3); // 3.33 -> 4 slices of 0.25
    ASSERT_EQ(slices.size(), 5u);
    EXPECT_DOUBLE_EQ(slices[1], 0.25);
    EXPECT_DOUBLE_EQ(slices.back(), 1.0);
    EXPECT_EQ(uniform_slices(1.0, 2.0), (std::vector<double>{0., 1.}));
  }

  // Every body is its 2D area swept over the face length: three
  // hexahedra per quadrilateral, the material ids of the 2D cells.
  TEST(ExtrudedAssembly, EveryBodyIsItsAreaTimesTheFaceLength)
  {
    for (const std::string name : {"default", "rounded"})
      {
        const auto &flat  = Testing::meshed_scene(name).triangulation;
        const auto &solid = extruded(name);
        EXPECT_EQ(solid.n_active_cells(), 3 * flat.n_active_cells()) << name;
        const auto areas   = measure_by_material(flat);
        const auto volumes = measure_by_material(solid);
        ASSERT_EQ(volumes.size(), areas.size()) << name;
        for (const auto &[material, area] : areas)
          EXPECT_NEAR(volumes.at(material),
                      area * face_length,
                      1e-12 * area * face_length)
            << name << ", material " << material;
      }
  }

  // The end faces carry the ids of ids.h and tile the 2D assembly's area
  // at z = 0 and at z = L; every other boundary face keeps a 2D id.
  TEST(ExtrudedAssembly, EndFacesAreTaggedAndTileTheSection)
  {
    const auto &flat       = Testing::meshed_scene("default").triangulation;
    const auto &solid      = extruded("default");
    double      total_area = 0.;
    for (const auto &cell : flat.active_cell_iterators())
      total_area += cell->measure();
    std::set<boundary_id> ids_2d;
    for (const auto &face : flat.active_face_iterators())
      if (face->at_boundary())
        ids_2d.insert(face->boundary_id());
    std::map<boundary_id, double> end_area;
    for (const auto &cell : solid.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const boundary_id id = face->boundary_id();
            if (id == Ids::end_face_near || id == Ids::end_face_far)
              {
                end_area[id] += face->measure();
                EXPECT_NEAR(face->center()[2],
                            id == Ids::end_face_near ? 0. : face_length,
                            1e-12);
              }
            else
              EXPECT_EQ(ids_2d.count(id), 1u) << "boundary id " << id;
          }
    EXPECT_NEAR(end_area[Ids::end_face_near], total_area, 1e-12 * total_area);
    EXPECT_NEAR(end_area[Ids::end_face_far], total_area, 1e-12 * total_area);
  }

  // A joint in 3D is two surfaces of the same nodes: every face of one
  // side has a face of the other side with coincident vertices (to
  // 1e-12 m), and the two are distinct vertices of different bodies.
  TEST(ExtrudedAssembly, JointSidesCarryTheSameNodesOnDistinctVertices)
  {
    const auto        &solid = extruded("default");
    const unsigned int n_blocks =
      Testing::meshed_scene("default").description.n_blocks;
    for (unsigned int joint = 1; joint <= n_blocks; ++joint)
      {
        struct SideAFace
        {
          dealii::Point<3>              centre;
          std::set<unsigned int>        vertices;
          std::vector<dealii::Point<3>> points;
        };
        std::vector<SideAFace>                     side_a;
        std::vector<std::vector<unsigned int>>     side_b;
        std::vector<std::vector<dealii::Point<3>>> side_b_points;
        for (const auto &cell : solid.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                if (face->boundary_id() == Ids::vertical_joint_free_side(joint))
                  {
                    SideAFace a{face->center(), {}, {}};
                    for (const unsigned int v : face->vertex_indices())
                      {
                        a.vertices.insert(face->vertex_index(v));
                        a.points.push_back(face->vertex(v));
                      }
                    side_a.push_back(a);
                  }
                else if (face->boundary_id() ==
                         Ids::vertical_joint_face_side(joint))
                  {
                    std::vector<unsigned int>     indices;
                    std::vector<dealii::Point<3>> points;
                    for (const unsigned int v : face->vertex_indices())
                      {
                        indices.push_back(face->vertex_index(v));
                        points.push_back(face->vertex(v));
                      }
                    side_b.push_back(indices);
                    side_b_points.push_back(points);
                  }
              }
        ASSERT_FALSE(side_a.empty()) << "joint " << joint;
        ASSERT_EQ(side_a.size(), side_b.size()) << "joint " << joint;
        for (std::size_t b = 0; b < side_b.size(); ++b)
          {
            dealii::Point<3> centre;
            for (const auto &point : side_b_points[b])
              centre += point / 4.;
            std::size_t n_partners = 0;
            for (const SideAFace &a : side_a)
              if (a.centre.distance(centre) < 1e-12)
                {
                  ++n_partners;
                  for (const unsigned int index : side_b[b])
                    EXPECT_EQ(a.vertices.count(index), 0u)
                      << "joint " << joint << " shares vertex " << index;
                  for (const auto &point : side_b_points[b])
                    {
                      double nearest = 1.;
                      for (const auto &a_point : a.points)
                        nearest = std::min(nearest, a_point.distance(point));
                      EXPECT_LT(nearest, 1e-12) << "joint " << joint;
                    }
                }
            EXPECT_EQ(n_partners, 1u) << "joint " << joint << ", face " << b;
          }
      }
  }
} // namespace FloorBlock::Geometry
