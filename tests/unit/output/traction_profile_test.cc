#include <common/units.h>
#include <output/comparison_report.h>

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace FloorBlock::Output
{
  namespace
  {
    /** The rows of the inline data block @p name of a gnuplot script. */
    std::vector<std::vector<double>>
    traction_data_rows(const std::string &script, const std::string &name)
    {
      std::vector<std::vector<double>> rows;
      std::istringstream               lines(script);
      std::string                      line;
      bool                             inside = false;
      while (std::getline(lines, line))
        {
          if (line == name + " << EOD")
            inside = true;
          else if (line == "EOD")
            inside = false;
          else if (inside && !line.empty())
            {
              std::istringstream  fields(line);
              std::vector<double> row;
              for (double value; fields >> value;)
                row.push_back(value);
              rows.push_back(row);
            }
        }
      return rows;
    }

    Contact::JointNodeSample
    sample(const double arc_position,
           const double x,
           const double y,
           const double traction)
    {
      Contact::JointNodeSample node;
      node.arc_position    = arc_position;
      node.position        = dealii::Point<2>(x, y);
      node.normal_traction = traction;
      return node;
    }
  } // namespace

  // The tool shall draw the traction along a joint in order of position along
  // the joint, so that a rounded corner (nodes of almost equal height) does
  // not fold the curve back.
  TEST(TractionProfilePlot, DataRunInOrderAlongTheJoint)
  {
    Contact::JointReport joint;
    joint.name = "vertical 6";
    // A straight part up to 1.99 m, then a 0.01 m fillet whose nodes differ
    // in height by less than a millimetre; given out of order.
    joint.profile   = {sample(1.9878, -0.0029, 1.9971, 0.),
                       sample(0.0, 0., 0.01, 0.),
                       sample(1.98, 0., 1.99, 15.8e6),
                       sample(1.9839, -0.0008, 1.9938, 2.4e6),
                       sample(1.0, 0., 1.01, 0.),
                       sample(1.9956, -0.01, 2.0, 0.),
                       sample(1.9, 0., 1.91, 12.e6)};
    const auto rows = traction_data_rows(traction_profile_plot(joint), "$p");
    ASSERT_EQ(rows.size(), joint.profile.size());
    for (std::size_t k = 1; k < rows.size(); ++k)
      EXPECT_GT(rows[k][0], rows[k - 1][0])
        << "row " << k << ": position along the joint must increase";
    // The ordinate is the position along the joint (m), the abscissa the
    // normal traction (MPa).
    EXPECT_DOUBLE_EQ(rows.front()[0], 0.);
    EXPECT_DOUBLE_EQ(rows.back()[0], 1.9956);
    EXPECT_DOUBLE_EQ(rows[3][1], 15.8);
  }
} // namespace FloorBlock::Output
