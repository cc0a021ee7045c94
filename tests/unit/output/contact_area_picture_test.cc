#include <output/contact_area_picture.h>

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace FloorBlock::Output
{
  namespace
  {
    Contact::JointNodeSample
    sample(const double              arc,
           const double              traction,
           const Contact::JointState state)
    {
      Contact::JointNodeSample node;
      node.arc_position    = arc;
      node.position        = dealii::Point<2>(0., 0.01 + arc);
      node.normal_traction = traction;
      node.state           = state;
      return node;
    }

    /** Two cross-sections of three pairs each: open, stuck, slipping. */
    Contact::JointReport
    two_sections()
    {
      Contact::JointReport joint;
      joint.name          = "vertical 6";
      joint.closed_length = 0.25;
      for (const auto &[z, from, to] :
           std::vector<std::tuple<double, double, double>>{{0., 0., 0.25},
                                                           {0.5, 0.25, 0.5}})
        {
          Contact::JointSection section;
          section.z       = z;
          section.z_from  = from;
          section.z_to    = to;
          section.profile = {sample(0., 0., Contact::JointState::open),
                             sample(0.1, 2e6, Contact::JointState::stick),
                             sample(0.3, 5e6, Contact::JointState::slip)};
          joint.along_face.push_back(section);
        }
      return joint;
    }

    std::vector<std::string>
    data_lines(const std::string &csv)
    {
      std::vector<std::string> lines;
      std::istringstream       stream(csv);
      std::string              line;
      while (std::getline(stream, line))
        if (!line.empty() && line[0] != '#')
          lines.push_back(line);
      return lines;
    }
  } // namespace

  // Each pair's patch runs from the midpoint to its previous pair to the
  // midpoint to its next one along the joint (the first and last end at
  // their own position), over its section's share of the face.
  TEST(ContactAreaCsv, PatchesRunBetweenMidpointsOverTheSectionsShare)
  {
    const auto lines = data_lines(contact_area_csv(two_sections()));
    ASSERT_EQ(lines.size(), 1u + 6u);
    EXPECT_EQ(lines[0].substr(0, 36), "z_m,z_from_m,z_to_m,arc_position_m,a");
    // Section 2, pair 2 (arc 0.1): z 0.5 over 0.25..0.5, arc 0.05..0.2.
    EXPECT_EQ(lines[5].substr(0, 4 * 16 - 1),
              "5.000000000e-01,2.500000000e-01,5.000000000e-01,"
              "1.000000000e-01");
    EXPECT_NE(lines[5].find(",5.000000000e-02,2.000000000e-01,"),
              std::string::npos)
      << lines[5];
    EXPECT_NE(lines[5].find(",stick"), std::string::npos) << lines[5];
    // The first pair's patch starts at itself, the last ends at itself.
    EXPECT_NE(lines[1].find(",0.000000000e+00,5.000000000e-02,"),
              std::string::npos)
      << lines[1];
    EXPECT_NE(lines[3].find(",2.000000000e-01,3.000000000e-01,"),
              std::string::npos)
      << lines[3];
  }

  TEST(ContactAreaCsv, TwoDimensionalJointHasNoRows)
  {
    Contact::JointReport joint;
    joint.name = "vertical 1";
    EXPECT_EQ(data_lines(contact_area_csv(joint)).size(), 1u);
  }

  TEST(ContactAreaPicture, WritesAPngForSectionsAndNothingWithout)
  {
    const std::string folder =
      (std::filesystem::temp_directory_path() /
       ("floorblock_contact_area_" + std::to_string(::getpid())))
        .string();
    std::filesystem::create_directories(folder);
    write_contact_area_picture(two_sections(), folder + "/area.png");
    EXPECT_GT(std::filesystem::file_size(folder + "/area.png"), 5000u);
    write_contact_area_picture(Contact::JointReport(), folder + "/none.png");
    EXPECT_FALSE(std::filesystem::exists(folder + "/none.png"));
    std::filesystem::remove_all(folder);
  }
} // namespace FloorBlock::Output
