#include <geometry/extruded_assembly.h>
#include <geometry/footprint_surfaces.h>
#include <geometry/ids.h>

#include <gtest/gtest.h>

#include <map>

#include "test_meshes.h"

namespace FloorBlock::Geometry
{
  namespace
  {
    constexpr double face_length     = 4.5; // m
    constexpr double footprint_start = 1.5; // m
    constexpr double footprint_end   = 3.0; // m
  }                                         // namespace

  // The footprint's ends are slice positions, no slice is thicker than
  // the slice size, and each third of the face is divided evenly.
  TEST(FootprintSlices, EndsAreSlicePositionsAndSlicesAtMostTheSize)
  {
    const auto slices =
      footprint_slices(face_length, 0.4, footprint_start, footprint_end);
    EXPECT_EQ(slices.front(), 0.);
    EXPECT_EQ(slices.back(), face_length);
    // 1.5 m in slices of at most 0.4 m: 4 slices of 0.375 m, three times.
    ASSERT_EQ(slices.size(), 13u);
    EXPECT_EQ(slices[4], footprint_start);
    EXPECT_EQ(slices[8], footprint_end);
    for (std::size_t k = 1; k < slices.size(); ++k)
      EXPECT_NEAR(slices[k] - slices[k - 1], 0.375, 1e-12) << k;
  }

  // A footprint at a face end leaves no empty part and no sliver slice;
  // over the whole face it gives the uniform slices.
  TEST(FootprintSlices, FootprintAtTheFaceEndsAddsNoEmptySlice)
  {
    EXPECT_EQ(footprint_slices(3.0, 1.0, 0., 1.5),
              (std::vector<double>{0., 0.75, 1.5, 2.25, 3.0}));
    EXPECT_EQ(footprint_slices(3.0, 1.0, 1.5, 3.0),
              (std::vector<double>{0., 0.75, 1.5, 2.25, 3.0}));
    EXPECT_EQ(footprint_slices(1.0, 0.3, 0., 1.0), uniform_slices(1.0, 0.3));
  }

  // The loaded blocks' tops within the footprint, and nothing else, get
  // the footprint ids: per loaded block the area of its top's straight
  // part times the footprint length; the rest of its top keeps the floor
  // id, unloaded tops keep theirs.
  TEST(TagFootprint, LoadedTopsWithinTheFootprintOnly)
  {
    const auto              &scene = Testing::meshed_scene("default");
    dealii::Triangulation<3> solid;
    extrude_assembly(
      scene.triangulation,
      footprint_slices(face_length, 0.5, footprint_start, footprint_end),
      solid);
    std::map<dealii::types::boundary_id, double> area_before;
    for (const auto &cell : solid.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          area_before[face->boundary_id()] += face->measure();

    const std::vector<unsigned int> loaded{1, 2, 3};
    const unsigned int              n_tagged =
      tag_footprint(loaded, footprint_start, footprint_end, solid);
    EXPECT_GT(n_tagged, 0u);

    std::map<dealii::types::boundary_id, double> area_after;
    for (const auto &cell : solid.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            area_after[face->boundary_id()] += face->measure();
            if (Ids::boundary_kind(face->boundary_id()) ==
                Ids::BoundaryKind::footprint_surface)
              {
                EXPECT_GT(face->center()[2], footprint_start);
                EXPECT_LT(face->center()[2], footprint_end);
              }
          }
    const double fraction = (footprint_end - footprint_start) / face_length;
    for (unsigned int block = 1; block <= scene.description.n_blocks; ++block)
      {
        const double top       = area_before.at(Ids::floor_surface(block));
        const bool   is_loaded = block <= 3;
        EXPECT_NEAR(area_after[Ids::footprint_surface(block)],
                    is_loaded ? fraction * top : 0.,
                    1e-12 * top)
          << "block " << block;
        EXPECT_NEAR(area_after[Ids::floor_surface(block)],
                    is_loaded ? (1. - fraction) * top : top,
                    1e-12 * top)
          << "block " << block;
      }
  }
} // namespace FloorBlock::Geometry
