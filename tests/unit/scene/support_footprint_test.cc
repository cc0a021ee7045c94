// The support footprint of a 3D scene from its parameters, and the
// support pressure it carries, against values worked out by hand.
#include <common/units.h>
#include <geometry/ids.h>
#include <parameters/scenario_parameters.h>
#include <scene/contact_inputs.h>
#include <scene/floor_contact_problem.h>
#include <scene/support_footprint.h>
#include <scene/swept_contact_problem.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace
{
  using namespace FloorBlock;
  namespace Ids = Geometry::Ids;

  Parameters::ScenarioParameters
  scene_3d(const std::vector<std::string> &footprint)
  {
    std::vector<std::string> overrides{"Geometry/Dimension=3",
                                       "Geometry/Face length=4.5",
                                       "Mesh/Slice size=0.5"};
    overrides.insert(overrides.end(), footprint.begin(), footprint.end());
    return Parameters::read_defaults("support_footprint_test", overrides);
  }

  Contact::ContactProblem<3>
  swept_problem(const Parameters::ScenarioParameters &scene)
  {
    return Scene::swept_contact_problem(Scene::make_floor_contact_problem(
                                          Scene::floor_problem_settings(scene)),
                                        scene.geometry.end_faces);
  }

  // Centred unless an offset is given; none in 2D or with length 0.
  TEST(SupportFootprint, CentredByDefaultOrAtTheOffset)
  {
    const auto centred =
      Scene::support_footprint(scene_3d({"Loading/Footprint length=1.5"}));
    ASSERT_TRUE(centred);
    EXPECT_DOUBLE_EQ(centred->start, 1.5);
    EXPECT_DOUBLE_EQ(centred->end, 3.0);
    const auto placed = Scene::support_footprint(
      scene_3d({"Loading/Footprint length=1", "Loading/Footprint offset=3.5"}));
    ASSERT_TRUE(placed);
    EXPECT_DOUBLE_EQ(placed->start, 3.5);
    EXPECT_EQ(placed->end, 4.5);
    EXPECT_FALSE(Scene::support_footprint(scene_3d({})));
    EXPECT_FALSE(Scene::support_footprint(
      Parameters::read_defaults("support_footprint_test", {})));
    // The slices run through both ends: 0.5 m slices on 1.5 m thirds.
    const auto slices =
      Scene::swept_slices(scene_3d({"Loading/Footprint length=1.5"}));
    ASSERT_EQ(slices.size(), 10u);
    EXPECT_EQ(slices[3], 1.5);
    EXPECT_EQ(slices[6], 3.0);
  }

  // The whole support load on the footprint: the 2D pressure times b / l
  // on the footprint tops of the loaded blocks, none on the rest of their
  // tops; with l = b (1.5 m, the default support width) the 2D pressure
  // itself. Other loads (none here) and the vertical direction stay.
  TEST(SupportFootprint, PressureOfTheWholeSupportLoadOnTheFootprint)
  {
    for (const double length : {1.5, 0.5})
      {
        const auto scene =
          scene_3d({"Loading/Footprint length=" + std::to_string(length)});
        const auto uniform = swept_problem(scene);
        auto       problem = uniform;
        Scene::load_support_footprint(*Scene::support_footprint(scene),
                                      scene.geometry.support_width,
                                      problem);
        ASSERT_EQ(problem.model.pressures.size(),
                  uniform.model.pressures.size());
        for (const unsigned int block : scene.loaded_blocks())
          {
            const double pressure_2d =
              uniform.model.pressures.at(Ids::floor_surface(block));
            EXPECT_EQ(problem.model.pressures.count(Ids::floor_surface(block)),
                      0u);
            EXPECT_NEAR(problem.model.pressures.at(
                          Ids::footprint_surface(block)),
                        pressure_2d * 1.5 / length,
                        1e-12 * pressure_2d)
              << "block " << block;
            EXPECT_EQ(problem.model.vertical_pressures.count(
                        Ids::footprint_surface(block)),
                      1u);
            EXPECT_EQ(problem.model.vertical_pressures.count(
                        Ids::floor_surface(block)),
                      0u);
          }
        if (length == 1.5)
          for (const unsigned int block : scene.loaded_blocks())
            {
              EXPECT_EQ(problem.model.pressures.at(
                          Ids::footprint_surface(block)),
                        uniform.model.pressures.at(Ids::floor_surface(block)));
            }
      }
  }
} // namespace
