#include <common/input_error.h>
#include <common/units.h>
#include <parameters/scenario_parameters.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

using namespace FloorBlock;
using Parameters::read_scenario;

namespace
{
  const std::string default_scene =
    std::string(FLOORBLOCK_SOURCE_DIR) + "/params/default.prm";

  std::string
  write_scene(const std::string &name, const std::string &text)
  {
    const auto path = std::filesystem::temp_directory_path() /
                      ("floorblock_" + std::to_string(::getpid()) + "_" + name);
    std::ofstream(path) << text;
    return path.string();
  }

  /// The InputError message for a scene read, or "" if it was accepted.
  std::string
  error_of(const std::string &path, const std::vector<std::string> &overrides)
  {
    try
      {
        read_scenario(path, overrides);
      }
    catch (const InputError &error)
      {
        return error.what();
      }
    return "";
  }
} // namespace

// The tool shall declare every parameter name that other scripts depend on.
TEST(ScenarioParameters, DeclaresEveryRequiredName)
{
  const std::string all = Parameters::describe_all_parameters();
  for (const char *name : {"Number of blocks",
                           "Block width",
                           "Block height",
                           "Support width",
                           "Shape",
                           "Inclination",
                           "Curvature",
                           "Bulk modulus",
                           "Shear modulus",
                           "Density",
                           "Bedding friction angle",
                           "Vertical friction angle",
                           "Cohesion",
                           "Normal stiffness",
                           "Shear stiffness",
                           "Gravity",
                           "Support load",
                           "Loaded blocks from face",
                           "Floor lift",
                           "Corner rounding radius",
                           "Corner size",
                           "Far size",
                           "Growth rate"})
    EXPECT_NE(all.find(std::string("set ") + name), std::string::npos) << name;
  for (const char *section :
       {"Geometry", "Bedding", "Material", "Joints", "Loading", "Mesh"})
    EXPECT_NE(all.find(std::string("subsection ") + section),
              std::string::npos);
}

// The tool shall read the chapter's UDEC scene into SI units.
TEST(ScenarioParameters, DefaultSceneInSiUnits)
{
  const auto scene = read_scenario(default_scene, {});
  EXPECT_EQ(scene.scene_name, "default");
  EXPECT_EQ(scene.geometry.n_blocks, 6u);
  EXPECT_DOUBLE_EQ(scene.geometry.block_width, 1.0);
  EXPECT_DOUBLE_EQ(scene.geometry.block_height, 2.0);
  EXPECT_DOUBLE_EQ(scene.joints.bedding_friction_angle,
                   Units::degrees_to_radians(30.0));
  EXPECT_DOUBLE_EQ(scene.loading.support_load, 650.0 * 1000.0 * 9.80665);
  // 4th, 5th, 6th from the face are blocks 3, 2, 1 in the chapter's numbering.
  EXPECT_EQ(scene.loaded_blocks(), (std::vector<unsigned int>{3, 2, 1}));
  // E = 9KG/(3K+G) for K = 9 GPa, G = 6.7 GPa, by hand: 542.7e18/33.7e9.
  EXPECT_NEAR(scene.material.youngs_modulus(), 16.1038575667e9, 1e3);
  EXPECT_NEAR(scene.material.poissons_ratio(), 0.2017804154, 1e-9);
}

// The tool shall let a command-line override change the parsed value.
TEST(ScenarioParameters, OverrideChangesValue)
{
  const auto scene = read_scenario(default_scene,
                                   {"Joints/Bedding friction angle=20",
                                    "Geometry/Number of blocks = 7"});
  EXPECT_DOUBLE_EQ(scene.joints.bedding_friction_angle,
                   Units::degrees_to_radians(20.0));
  EXPECT_EQ(scene.geometry.n_blocks, 7u);
  // The echoed parameters.prm must carry the override (aligned "set" lines).
  EXPECT_TRUE(
    std::regex_search(scene.expanded_text,
                      std::regex("Bedding friction angle +=  *20\\b")));
}

// The tool shall name the parameter, the value and the range of a bad override.
TEST(ScenarioParameters, OutOfRangeOverrideNamesParameterValueAndRange)
{
  const std::string message =
    error_of(default_scene, {"Joints/Bedding friction angle=95"});
  EXPECT_NE(message.find("Joints/Bedding friction angle"), std::string::npos);
  EXPECT_NE(message.find("95"), std::string::npos);
  EXPECT_NE(message.find("89.9"), std::string::npos) << message;
}

// The tool shall refuse a negative size in a file, naming file line and range.
TEST(ScenarioParameters, NegativeWidthInFileIsRefusedWithLine)
{
  const std::string path =
    write_scene("negative.prm",
                "subsection Geometry\n  set Block width = -1\nend\n");
  const std::string message = error_of(path, {});
  EXPECT_NE(message.find("Block width"), std::string::npos) << message;
  EXPECT_NE(message.find("-1"), std::string::npos);
  EXPECT_NE(message.find("Line <2>"), std::string::npos) << message;
  std::filesystem::remove(path);
}

// The tool shall refuse unknown parameter names, in files and overrides.
TEST(ScenarioParameters, UnknownNamesAreRefused)
{
  const std::string path =
    write_scene("unknown.prm",
                "subsection Joints\n  set Bedding fricton angle = 20\nend\n");
  EXPECT_NE(error_of(path, {}).find("Bedding fricton angle"),
            std::string::npos);
  EXPECT_NE(
    error_of(default_scene, {"Joints/Frobnication=1"}).find("Frobnication"),
    std::string::npos);
  EXPECT_NE(error_of(default_scene, {"no equals sign"}).find("expected"),
            std::string::npos);
  std::filesystem::remove(path);
}

// The tool shall refuse a missing file and scenes that contradict themselves.
TEST(ScenarioParameters, MissingFileAndInconsistentScenes)
{
  EXPECT_NE(error_of("/nonexistent/scene.prm", {}).find("does not exist"),
            std::string::npos);
  EXPECT_NE(error_of(default_scene, {"Geometry/Number of blocks=2"})
              .find("Loading/Loaded blocks from face"),
            std::string::npos);
  EXPECT_NE(error_of(default_scene, {"Loading/Loaded blocks from face=1,1"})
              .find("only once"),
            std::string::npos);
  EXPECT_NE(error_of(default_scene, {"Geometry/Corner rounding radius=0.3"})
              .find("quarter"),
            std::string::npos);
}

// The tool shall accept scenes written as JSON too.
TEST(ScenarioParameters, JsonSceneIsAccepted)
{
  const std::string path = write_scene(
    "scene.json",
    R"({"Geometry": {"Number of blocks": "4"}, "Loading": {"Loaded blocks from face": "1,2"}})");
  const auto scene = read_scenario(path, {});
  EXPECT_EQ(scene.geometry.n_blocks, 4u);
  EXPECT_EQ(scene.loaded_blocks(), (std::vector<unsigned int>{4, 3}));
  std::filesystem::remove(path);
}

// The tool shall refuse a support footprint that does not lie on the face
// of a 3D scene, naming the parameter, the value and the allowed range.
TEST(ScenarioParameters, FootprintOutsideTheFaceIsRefused)
{
  const std::string footprint_scene =
    std::string(FLOORBLOCK_SOURCE_DIR) + "/params/footprint_3d.prm";
  const auto scene = read_scenario(footprint_scene, {});
  EXPECT_DOUBLE_EQ(scene.loading.footprint_length, 1.5);
  EXPECT_FALSE(scene.loading.footprint_offset); // centred
  EXPECT_EQ(read_scenario(footprint_scene, {"Loading/Footprint offset=3"})
              .loading.footprint_offset,
            3.);

  struct Refusal
  {
    std::vector<std::string> overrides;
    std::vector<std::string> mentions; ///< parameter, value, range
  };
  const Refusal refusals[] = {
    {{"Geometry/Dimension=2"},
     {"Loading/Footprint length", "1.5", "Geometry/Dimension = 2"}},
    {{"Loading/Footprint length=5"},
     {"Loading/Footprint length",
      "5",
      "between 0 and Geometry/Face length = 4.5"}},
    {{"Loading/Footprint length=-1"}, {"Footprint length", "-1"}},
    {{"Loading/Footprint offset=3.5"},
     {"Loading/Footprint offset", "3.5", "between 0 and", "= 3.0"}},
    {{"Loading/Footprint offset=-0.5"},
     {"Loading/Footprint offset", "-0.5", "-1 (centred"}},
    {{"Loading/Footprint length=0", "Loading/Footprint offset=1"},
     {"Loading/Footprint offset", "1", "Footprint length = 0"}},
  };
  for (const Refusal &refusal : refusals)
    {
      const std::string message = error_of(footprint_scene, refusal.overrides);
      for (const std::string &mention : refusal.mentions)
        EXPECT_NE(message.find(mention), std::string::npos)
          << refusal.overrides.front() << ": '" << mention
          << "' not in: " << message;
    }
  // An offset that puts the footprint's end on the face's end passes.
  EXPECT_EQ(error_of(footprint_scene, {"Loading/Footprint offset=3"}), "");
}

// The tool shall derive K and G from E and nu, E and nu from K and G, and
// take the chapter's Table 6.1 when neither pair is given.
TEST(ScenarioParameters, EitherPairOfModuliDescribesTheRock)
{
  const auto from_e_nu =
    Parameters::read_defaults("moduli",
                              {"Material/Young's modulus=12e9",
                               "Material/Poisson's ratio=0.25"});
  EXPECT_NEAR(from_e_nu.material.bulk_modulus, 8e9, 1e-6);
  EXPECT_NEAR(from_e_nu.material.shear_modulus, 4.8e9, 1e-6);
  EXPECT_NEAR(from_e_nu.material.youngs_modulus(), 12e9, 1e-5);
  EXPECT_NEAR(from_e_nu.material.poissons_ratio(), 0.25, 1e-15);

  const auto table = Parameters::read_defaults("moduli", {});
  EXPECT_EQ(table.material.bulk_modulus, 9e9);
  EXPECT_EQ(table.material.shear_modulus, 6.7e9);

  EXPECT_NE(error_of(default_scene,
                     {"Material/Young's modulus=12e9",
                      "Material/Poisson's ratio=0.25"})
              .find("Material/Bulk modulus"),
            std::string::npos);
}

// The tool shall solve with the joint stiffness derived from Barton-Bandis
// joint data where the scene asks for it, and echo it beside the entries.
// The default joint data (JRC 8, JCS 20 MPa, auto a_j = 0.48 mm in the 40
// MPa siltstone, phi_r 25 deg, sigma_n 1 MPa, L_x = block height 2 m) give
// kn = 1.16867e10 Pa/m and ks = 3.55440e7 Pa/m
// (tests/unit/strength/barton_bandis_test.cc derives both by hand).
TEST(ScenarioParameters, BartonBandisStiffnessReplacesTheGivenOne)
{
  const auto given = read_scenario(default_scene, {});
  EXPECT_DOUBLE_EQ(given.joints.normal_stiffness, 9e9);
  EXPECT_DOUBLE_EQ(given.joints.shear_stiffness, 6.7e9);
  EXPECT_TRUE(given.joints.stiffness_origin.empty());

  const auto derived =
    read_scenario(default_scene, {"Joints/Stiffness source=Barton-Bandis"});
  EXPECT_NEAR(derived.joints.normal_stiffness / 1.168671e10, 1., 1e-5);
  EXPECT_NEAR(derived.joints.shear_stiffness / 3.554397e7, 1., 1e-5);
  EXPECT_NE(derived.expanded_text.find("Barton-Bandis at sigma_n = 1 MPa"),
            std::string::npos);
  EXPECT_NE(derived.expanded_text.find(
              "unused: Stiffness source = Barton-Bandis"),
            std::string::npos);

  // A sheared length given halves ks when it doubles; kn stays.
  const auto longer = read_scenario(default_scene,
                                    {"Joints/Stiffness source=Barton-Bandis",
                                     "Joints/Sheared length=4"});
  EXPECT_DOUBLE_EQ(longer.joints.normal_stiffness,
                   derived.joints.normal_stiffness);
  EXPECT_NEAR(longer.joints.shear_stiffness,
              0.5 * derived.joints.shear_stiffness,
              1e-6);
}
