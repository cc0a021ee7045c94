#include <common/input_error.h>
#include <geometry/assembly_description.h>
#include <geometry/assembly_mesher.h>
#include <geometry/gmsh_scope.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>

#include "test_meshes.h"

namespace FloorBlock::Geometry
{
  namespace
  {
    /**
     * Apply @p change to the default scene and expect validate() and
     * write_gmsh_mesh() to refuse it with an InputError naming @p parameter,
     * without opening Gmsh or writing the file.
     */
    void
    expect_refused(const std::function<void(AssemblyDescription &)> &change,
                   const std::string                                &parameter)
    {
      AssemblyDescription description;
      change(description);
      try
        {
          validate(description);
          ADD_FAILURE() << "accepted, expected a complaint about " << parameter;
        }
      catch (const InputError &error)
        {
          EXPECT_NE(std::string(error.what()).find("'" + parameter + "'"),
                    std::string::npos)
            << error.what();
        }
      const std::string path = Testing::scratch_folder() + "/refused.msh";
      std::filesystem::remove(path);
      EXPECT_THROW(write_gmsh_mesh(description, path), InputError);
      EXPECT_FALSE(std::filesystem::exists(path));
      EXPECT_FALSE(GmshScope::is_open());
    }

    constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
  } // namespace

  TEST(Validate, DefaultSceneIsAccepted)
  {
    EXPECT_NO_THROW(validate(AssemblyDescription{}));
  }

  TEST(Validate, RefusesBlockCountOutsideIdScheme)
  {
    expect_refused([](auto &d) { d.n_blocks = 0; },
                   "Geometry/Number of blocks");
    expect_refused([](auto &d) { d.n_blocks = 100; },
                   "Geometry/Number of blocks");
  }

  TEST(Validate, RefusesNonPositiveOrNonFiniteSizes)
  {
    expect_refused([](auto &d) { d.block_width = 0.0; },
                   "Geometry/Block width");
    expect_refused([](auto &d) { d.block_width = not_a_number; },
                   "Geometry/Block width");
    expect_refused([](auto &d) { d.block_height = -2.0; },
                   "Geometry/Block height");
    expect_refused([](auto &d) { d.face_block_width = -1.0; },
                   "Geometry/Face block width");
    expect_refused([](auto &d) { d.base_thickness = 0.0; },
                   "Geometry/Base thickness");
  }

  TEST(Validate, RefusesSteepOrCurledBedding)
  {
    expect_refused(
      [](auto &d) {
        d.bedding_shape = BeddingShape::planar;
        d.inclination   = 1.2; // 69 deg
      },
      "Geometry/Inclination");
    expect_refused([](auto &d) { d.curvature = 0.0; }, "Geometry/Curvature");
    expect_refused([](auto &d) { d.curvature = -100.0; }, "Geometry/Curvature");
  }

  TEST(Validate, RefusesMoreBlocksThanFitOnTheParabola)
  {
    // Slope 2x/k at x = nL = 20 m on k = 10 m is 4: 76 deg > 60 deg.
    AssemblyDescription description;
    description.n_blocks  = 20;
    description.curvature = 10.0;
    try
      {
        validate(description);
        ADD_FAILURE() << "accepted";
      }
    catch (const InputError &error)
      {
        const std::string message = error.what();
        EXPECT_NE(message.find("'Geometry/Number of blocks' = '20'"),
                  std::string::npos)
          << message;
        // tan(60 deg) k / 2 = 8.66 m: 8 blocks of 1 m fit.
        EXPECT_NE(message.find("at most 8 blocks"), std::string::npos)
          << message;
      }
  }

  TEST(Validate, RefusesFilletsThatDoNotFit)
  {
    expect_refused([](auto &d) { d.corner_rounding_radius = -0.1; },
                   "Geometry/Corner rounding radius");
    expect_refused([](auto &d) { d.corner_rounding_radius = 0.5; },
                   "Geometry/Corner rounding radius");
    // Each fillet starts r from the corner on the vertical side, so two
    // fillets need 2 r < the side; the narrow face block sets the limit.
    expect_refused(
      [](auto &d) {
        d.face_block_width       = 0.3;
        d.corner_rounding_radius = 0.2;
      },
      "Geometry/Corner rounding radius");
  }

  TEST(Validate, RefusesBadMeshSizes)
  {
    expect_refused([](auto &d) { d.mesh_corner_size = 0.0; },
                   "Mesh/Corner size");
    expect_refused([](auto &d) { d.mesh_corner_size = 1e-6; },
                   "Mesh/Corner size");
    expect_refused(
      [](auto &d) {
        d.mesh_corner_size = 0.1;
        d.mesh_far_size    = 0.05;
      },
      "Mesh/Far size");
    expect_refused([](auto &d) { d.mesh_growth_rate = 1.0; },
                   "Mesh/Growth rate");
    expect_refused([](auto &d) { d.mesh_growth_rate = not_a_number; },
                   "Mesh/Growth rate");
  }
} // namespace FloorBlock::Geometry
