// The FEM report's words: stage names, the bodies a joint separates in the
// chapter's numbering, and the sentence printed for an unloaded increment.
#include <compare/load_check.h>
#include <contact/results.h>
#include <output/fem_report.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <string>

namespace
{
  using namespace FloorBlock;
  using nlohmann::json;

  TEST(FemReport, StageNames)
  {
    EXPECT_EQ(Output::stage_name(Contact::LoadStage::gravity), "gravity");
    EXPECT_EQ(Output::stage_name(Contact::LoadStage::support_pressure),
              "support_load");
    EXPECT_EQ(Output::stage_name(Contact::LoadStage::uplift), "uplift");
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
    check.largest_force   = 1.234e-3;
    check.round_off_force = 1.6e-2;
    const std::string text = Output::no_load_text(check);
    EXPECT_NE(text.find("every joint force are at most 1.2e-03 N/m"),
              std::string::npos)
      << text;
    EXPECT_NE(text.find("(1e-10 E |u|max = 1.6e-02 N/m)"), std::string::npos)
      << text;
  }
} // namespace
