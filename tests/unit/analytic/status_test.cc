// The tool shall explain every status in words.

#include <analytic/status.h>

#include <gtest/gtest.h>

#include <set>

using namespace FloorBlock::Analytic;

TEST(Status, ShallDescribeEveryStatusInWordsWithADistinctName)
{
  const Status          all[] = {Status::ok,
                                 Status::invalid_input,
                                 Status::self_locking,
                                 Status::rotation_denominator_nonpositive,
                                 Status::vertical_friction_exceeded,
                                 Status::joint_opens,
                                 Status::base_lifts_off,
                                 Status::normal_force_outside_base,
                                 Status::zero_floor_lift,
                                 Status::whole_joint_in_contact};
  std::set<std::string> names;
  for (const Status status : all)
    {
      EXPECT_GT(describe(status).size(), 20u);
      EXPECT_NE(describe(status), "Unknown status.");
      names.insert(to_string(status));
    }
  EXPECT_EQ(names.size(), std::size(all));
}
