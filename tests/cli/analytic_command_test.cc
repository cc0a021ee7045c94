#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include "process.h"

using namespace FloorBlockTest;

namespace
{

  nlohmann::json
  analytic_for(const std::string &name, const std::string &overrides)
  {
    const std::string output = fresh_output_folder(name);
    const auto        result =
      run_floorblock("analytic params/default.prm " + overrides + " --output " +
                     shell_quoted(output));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    auto json = read_json(output + "/analytic.json");
    std::filesystem::remove_all(output);
    return json;
  }
} // namespace

// The tool shall write analytic.json with every documented key per case.
TEST(AnalyticCommand, WritesDocumentedKeysForEveryCase)
{
  const auto json = analytic_for("keys", "");
  for (const char *name :
       {"no_rotation", "rotation_no_vertical_slip", "rotation_vertical_slip"})
    {
      ASSERT_TRUE(json["cases"].contains(name)) << name;
      const auto &entry = json["cases"][name];
      for (const char *key : {"status", "Q_N_per_m", "contact"})
        EXPECT_TRUE(entry.contains(key)) << name << "." << key;
      for (const char *key :
           {"Q_N", "y_m", "A_m2", "sigma_avg_Pa", "sigma_max_Pa", "status"})
        EXPECT_TRUE(entry["contact"].contains(key))
          << name << ".contact." << key;
      const auto &q = entry["Q_N_per_m"];
      EXPECT_TRUE(q.empty() || q.size() == 6u) << name;
    }
  EXPECT_NE(json["numbering"].get<std::string>().find(
              "block 1 at the free end"),
            std::string::npos);
}

// The tool shall let a --set override change the computed result.
TEST(AnalyticCommand, OverrideChangesTheResult)
{
  const auto base = analytic_for("base", "");
  const auto lower =
    analytic_for("lower", "--set 'Joints/Bedding friction angle=15'");
  const double q_base =
    base["cases"]["no_rotation"]["Q_N_per_m"].back().get<double>();
  const double q_lower =
    lower["cases"]["no_rotation"]["Q_N_per_m"].back().get<double>();
  // Less bedding friction must lower the thrust on the face (Eq. 6.23).
  EXPECT_LT(q_lower, q_base);
}

// The tool shall print every parameter with its units.
TEST(PrintParameters, ListsEveryParameterWithUnits)
{
  const auto result = run_floorblock("print-parameters");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.output.find("Bedding friction angle"), std::string::npos);
  EXPECT_NE(result.output.find("Units: Pa/m"), std::string::npos);
}
