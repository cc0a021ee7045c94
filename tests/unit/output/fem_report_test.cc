// The FEM report's words: stage names, the bodies a joint separates in the
// chapter's numbering, and the sentence printed for an unloaded increment.
#include <compare/load_check.h>
#include <contact/results.h>
#include <output/fem_report.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace
{
  using namespace FloorBlock;
  using nlohmann::json;

  TEST(FemReport, StageNames)
  {
    EXPECT_EQ(Output::stage_name(Loading::LoadStage::gravity), "gravity");
    EXPECT_EQ(Output::stage_name(Loading::LoadStage::support_pressure),
              "support_load");
    EXPECT_EQ(Output::stage_name(Loading::LoadStage::uplift), "uplift");
  }

  // Chapter numbering: vertical j lies between j and j+1, vertical n
  // against the face block, bedding i under block i.
  TEST(FemReport, JointBodiesInTheChaptersNumbering)
  {
    EXPECT_EQ(Output::joint_bodies("vertical", 2, 6), (json{2, 3}));
    EXPECT_EQ(Output::joint_bodies("vertical", 6, 6), (json{6, "face"}));
    EXPECT_EQ(Output::joint_bodies("bedding", 4, 6), (json{4, "base"}));
  }

  // The sentence names the largest force and the round-off bound, each
  // with 2 significant digits, and the fraction 1e-10.
  TEST(FemReport, NoLoadTextStatesBothForces)
  {
    Compare::LoadCheck check;
    check.largest_force    = 1.234e-3;
    check.round_off_force  = 1.6e-2;
    const std::string text = Output::no_load_text(check);
    EXPECT_NE(text.find("every joint force are at most 1.2e-03 N/m"),
              std::string::npos)
      << text;
    EXPECT_NE(text.find("(1e-10 E |u|max = 1.6e-02 N/m)"), std::string::npos)
      << text;
  }
} // namespace

namespace
{
  using namespace FloorBlock;

  Contact::IncrementResult
  increment_with_one_pair(const Loading::LoadStage stage, const double traction)
  {
    Contact::IncrementResult increment;
    increment.stage        = stage;
    increment.stage_factor = 1.;
    Contact::JointReport joint;
    joint.name = "vertical 1";
    Contact::JointNodeSample sample;
    sample.position        = dealii::Point<2>(5., 0.25);
    sample.arc_position    = 0.25;
    sample.gap             = 0.;
    sample.normal_traction = traction;
    sample.state           = Contact::JointState::stick;
    joint.profile.push_back(sample);
    increment.joints.push_back(joint);
    return increment;
  }

  // One block of rows per stage, from the stage's last increment; each row
  // carries the pair's position, traction and state.
  TEST(FemReport, JointProfilesAtTheEndOfEveryStage)
  {
    Contact::SolveResult result;
    result.increments.push_back(
      increment_with_one_pair(Loading::LoadStage::gravity, 1e5));
    result.increments.push_back(
      increment_with_one_pair(Loading::LoadStage::uplift, 2e5));
    result.increments.push_back(
      increment_with_one_pair(Loading::LoadStage::uplift, 3e5));
    const std::string csv = Output::joint_profiles_csv(result);
    EXPECT_NE(csv.find("increment,stage,stage_factor,joint,node,x_m,y_m,"
                       "arc_position_m,gap_m,normal_traction_Pa,"
                       "shear_traction_Pa,state\n"),
              std::string::npos);
    EXPECT_NE(csv.find("1,gravity,1.000000,vertical 1,0,5.000000000e+00,"
                       "2.500000000e-01,2.500000000e-01,0.000000000e+00,"
                       "1.000000000e+05,0.000000000e+00,stick\n"),
              std::string::npos);
    EXPECT_EQ(csv.find("2.000000000e+05"), std::string::npos);
    EXPECT_NE(csv.find("3,uplift,1.000000,vertical 1,0,"), std::string::npos);
  }
} // namespace
