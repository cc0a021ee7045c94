#include <common/input_error.h>
#include <parameters/scenario_parameters.h>

#include <gtest/gtest.h>

#include <regex>

using namespace FloorBlock;
using Parameters::BlockModel;
using Parameters::read_scenario;

namespace
{
  const std::string default_scene =
    std::string(FLOORBLOCK_SOURCE_DIR) + "/params/default.prm";

  /// The InputError message for the default scene with overrides, or "".
  std::string
  error_of(const std::vector<std::string> &overrides)
  {
    try
      {
        read_scenario(default_scene, overrides);
      }
    catch (const InputError &error)
      {
        return error.what();
      }
    return "";
  }

  bool
  contains(const std::string &text, const std::string &part)
  {
    return text.find(part) != std::string::npos;
  }
} // namespace

// The tool shall solve a scene with the elastic FEM unless told otherwise.
TEST(ModelParameters, DefaultIsElastic)
{
  const auto scene = read_scenario(default_scene, {});
  EXPECT_EQ(scene.model.blocks, BlockModel::elastic);
  EXPECT_EQ(scene.model.chosen, BlockModel::elastic);
  EXPECT_EQ(scene.model.outputs, Parameters::RequestedOutputs::contact_stress);
  EXPECT_EQ(scene.model.rigid_points_per_joint, 400u);
}

// The tool shall run the model the scene asks for: elastic, rigid, or for
// auto rigid only when forces alone are requested.
TEST(ModelParameters, ValidValuesChooseTheModel)
{
  EXPECT_EQ(read_scenario(default_scene, {"Model/Blocks=rigid"}).model.chosen,
            BlockModel::rigid);
  EXPECT_EQ(read_scenario(default_scene, {"Model/Blocks=elastic"}).model.chosen,
            BlockModel::elastic);

  const auto forces =
    read_scenario(default_scene, {"Model/Blocks=auto", "Model/Outputs=forces"});
  EXPECT_EQ(forces.model.blocks, BlockModel::automatic);
  EXPECT_EQ(forces.model.chosen, BlockModel::rigid);
  EXPECT_TRUE(contains(forces.model.choice_reason, "forces"));

  const auto stress =
    read_scenario(default_scene,
                  {"Model/Blocks=auto", "Model/Outputs=contact stress"});
  EXPECT_EQ(stress.model.chosen, BlockModel::elastic);
  EXPECT_TRUE(contains(stress.model.choice_reason, "contact stress"));

  EXPECT_EQ(read_scenario(default_scene, {"Model/Rigid points per joint=50"})
              .model.rigid_points_per_joint,
            50u);
}

// The tool shall fall back to the elastic FEM under auto where the rigid
// model cannot represent the scene, and say why.
TEST(ModelParameters, AutoFallsBackToElasticForRigidJointLaw)
{
  const auto scene = read_scenario(default_scene,
                                   {"Model/Blocks=auto",
                                    "Model/Outputs=forces",
                                    "Joints/Law=rigid"});
  EXPECT_EQ(scene.model.chosen, BlockModel::elastic);
  EXPECT_TRUE(contains(scene.model.choice_reason, "Joints/Law"));
}

// The tool shall refuse bad values of the Model subsection, naming the
// parameter, the value and what is allowed.
TEST(ModelParameters, BadValuesAreInputErrors)
{
  const std::string blocks = error_of({"Model/Blocks=stiff"});
  EXPECT_TRUE(contains(blocks, "Model/Blocks")) << blocks;
  EXPECT_TRUE(contains(blocks, "stiff")) << blocks;
  EXPECT_TRUE(contains(blocks, "elastic|rigid|auto")) << blocks;

  const std::string outputs = error_of({"Model/Outputs=everything"});
  EXPECT_TRUE(contains(outputs, "Model/Outputs")) << outputs;
  EXPECT_TRUE(contains(outputs, "forces|contact stress")) << outputs;

  const std::string points = error_of({"Model/Rigid points per joint=1"});
  EXPECT_TRUE(contains(points, "Rigid points per joint")) << points;
  EXPECT_TRUE(contains(points, "2")) << points;
}

// The tool shall refuse rigid blocks where they cannot represent the scene:
// rigid joints (no springs) and a support load normal to an inclined top.
TEST(ModelParameters, RigidBlocksRefuseScenesTheyCannotRepresent)
{
  const std::string law = error_of({"Model/Blocks=rigid", "Joints/Law=rigid"});
  EXPECT_TRUE(contains(law, "Model/Blocks")) << law;
  EXPECT_TRUE(contains(law, "Joints/Law")) << law;

  const std::string inclined_top =
    error_of({"Model/Blocks=rigid",
              "Bedding/Floor uplift reading=inclined",
              "Loading/Support load direction=normal to block top"});
  EXPECT_TRUE(contains(inclined_top, "Support load direction")) << inclined_top;

  // On the lifted (level) bedding "normal to the top" is vertical: accepted.
  EXPECT_EQ(error_of({"Model/Blocks=rigid",
                      "Loading/Support load direction=normal to block top"}),
            "");
}

// The tool shall list the Model subsection in print-parameters.
TEST(ModelParameters, PrintedWithDocumentation)
{
  const std::string all = Parameters::describe_all_parameters();
  EXPECT_TRUE(contains(all, "subsection Model"));
  // Documentation lines are wrapped behind "#": join them before searching.
  const std::string joined =
    std::regex_replace(all, std::regex("\\s*\n\\s*#\\s*"), " ");
  for (const char *name :
       {"set Blocks", "set Outputs", "set Rigid points per joint"})
    EXPECT_TRUE(contains(all, name)) << name;
  EXPECT_TRUE(contains(joined, "auto: rigid when Model/Outputs = forces"));
  EXPECT_TRUE(contains(joined, "Units: none"));
}
