// The comparator the scenario tests rely on (output_comparison.h): if it
// accepted changed numbers or missing keys, every scenario test would pass
// vacuously. Each test changes one thing in a small record and checks that
// the change is caught (or, for a timing field, ignored).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include "output_comparison.h"
#include "process.h"

using namespace FloorBlockTest;
using nlohmann::json;

namespace
{
  /** A record shaped like fem.json: nested objects, arrays, a timing. */
  json
  record()
  {
    return json::parse(R"({
      "status": "converged",
      "n_dofs": 1066,
      "wall_time_s": 0.93,
      "joints": [
        {"name": "face", "normal_force_N_per_m": 3739243.512345678,
         "contact_length_m": 0.686, "closed": true},
        {"name": "bedding 1", "normal_force_N_per_m": 1.0e-12,
         "contact_length_m": 0.375, "closed": false}
      ],
      "failure": null
    })");
  }

  /** A scratch folder for CSV files, removed at the end of the test. */
  class ScratchFolder
  {
  public:
    ScratchFolder()
      : folder(fresh_output_folder(
          "comparison_" +
          std::string(
            ::testing::UnitTest::GetInstance()->current_test_info()->name())))
    {
      std::filesystem::create_directories(folder);
    }

    ~ScratchFolder()
    {
      std::filesystem::remove_all(folder);
    }

    /** Writes @p text to the file @p name; returns its path. */
    std::string
    written(const std::string &name, const std::string &text) const
    {
      const std::string path = folder + "/" + name;
      std::ofstream(path) << text;
      return path;
    }

  private:
    std::string folder;
  };

  /** Joins a difference list for a failure message. */
  std::string
  listed(const std::vector<std::string> &differences)
  {
    std::string text;
    for (const std::string &difference : differences)
      text += difference + "\n";
    return text;
  }

  const std::string table = "# Q_i acts between block i and block i+1\n"
                            "block,Q_N_per_m,status,wall_time_s\n"
                            "1,1396213.25,ok,0.5\n"
                            "2,2768312.5,\"slip, open\",0.6\n";
} // namespace

// The tool shall compare two equal records as equal.
TEST(OutputComparison, EqualRecordsHaveNoDifference)
{
  const ScratchFolder scratch;
  EXPECT_TRUE(compare_json(record(), record(), "fem.json").empty());
  const std::string a = scratch.written("a.csv", table);
  const std::string b = scratch.written("b.csv", table);
  EXPECT_TRUE(compare_csv(a, b, "joints.csv").empty());
  EXPECT_TRUE(compare_files(a, b, "joints.csv").empty());
}

// The tool shall report a number changed beyond the tolerance, naming the
// file, the JSON path and both values, and accept one changed within it.
TEST(OutputComparison, ChangedNumberIsCaught)
{
  json changed = record();
  changed["joints"][0]["normal_force_N_per_m"] =
    3739243.512345678 * (1. + 1e-7);
  const auto differences = compare_json(record(), changed, "fem.json");
  ASSERT_EQ(differences.size(), 1u) << listed(differences);
  EXPECT_NE(differences[0].find("fem.json"), std::string::npos);
  EXPECT_NE(differences[0].find("/joints/0/normal_force_N_per_m"),
            std::string::npos)
    << differences[0];
  EXPECT_NE(differences[0].find("3739243.512345678"), std::string::npos)
    << differences[0];
  EXPECT_NE(differences[0].find("3739243.88"), std::string::npos)
    << differences[0];

  // Relative 1e-9 is within the default 1e-8.
  json close                                 = record();
  close["joints"][0]["normal_force_N_per_m"] = 3739243.512345678 * (1. + 1e-9);
  EXPECT_TRUE(compare_json(record(), close, "fem.json").empty());

  // Near zero the absolute bound 1e-10 decides: 1e-12 -> 5e-11 passes,
  // 1e-12 -> 1e-9 does not (relative difference near 1 in both).
  json tiny                                 = record();
  tiny["joints"][1]["normal_force_N_per_m"] = 5e-11;
  EXPECT_TRUE(compare_json(record(), tiny, "fem.json").empty());
  tiny["joints"][1]["normal_force_N_per_m"] = 1e-9;
  EXPECT_EQ(compare_json(record(), tiny, "fem.json").size(), 1u);
}

// The tool shall apply a declared looser tolerance only to its own field.
TEST(OutputComparison, LooserToleranceAppliesToItsFieldOnly)
{
  json changed = record();
  changed["joints"][0]["normal_force_N_per_m"] =
    3739243.512345678 * (1. + 1e-7);
  changed["joints"][0]["contact_length_m"] = 0.686 * (1. + 1e-7);
  ComparisonSettings settings;
  settings.looser_fields.push_back(
    {"normal_force_N_per_m", {1e-10, 1e-6}, "test"});
  const auto differences =
    compare_json(record(), changed, "fem.json", settings);
  ASSERT_EQ(differences.size(), 1u) << listed(differences);
  EXPECT_NE(differences[0].find("/joints/0/contact_length_m"),
            std::string::npos)
    << differences[0];
}

// The tool shall compare the value of an entry that names its quantity
// (summary.json's face_joint_figures) under that quantity's tolerance, so
// that a field declared looser or skipped is so in every file.
TEST(OutputComparison, NamedEntryValueTakesItsFieldsTolerance)
{
  const json reference = {
    {"face_joint_figures",
     {{{"field", "contact_length_m"}, {"value", 0.}},
      {{"field", "normal_force_N_per_m"}, {"value", 0.}}}}};
  json changed                              = reference;
  changed["face_joint_figures"][0]["value"] = 2.;
  changed["face_joint_figures"][1]["value"] = 6e-8;
  EXPECT_EQ(compare_json(reference, changed, "summary.json").size(), 2u);

  ComparisonSettings settings;
  settings.skipped_fields = {"contact_length_m"};
  settings.looser_fields.push_back(
    {"normal_force_N_per_m", {1e-4, 0.}, "test"});
  EXPECT_TRUE(
    compare_json(reference, changed, "summary.json", settings).empty())
    << listed(compare_json(reference, changed, "summary.json", settings));

  // The tolerance is the named field's, not a free pass.
  changed["face_joint_figures"][1]["value"] = 1e-3;
  EXPECT_EQ(compare_json(reference, changed, "summary.json", settings).size(),
            1u);
}

// The tool shall ignore the solver's cost counters (they follow round-off:
// reuse caps, a Newton iteration more or less) and compare the force
// balance residual to its round-off level, not to 1e-8 of itself.
TEST(OutputComparison, CostCountersAndRoundOffResidualsFollowTheMachine)
{
  EXPECT_TRUE(is_skipped_field("lu_factorizations"));
  EXPECT_TRUE(is_skipped_field("newton_iterations"));
  EXPECT_TRUE(is_skipped_field("krylov_iterations_with_amg"));
  EXPECT_FALSE(is_skipped_field("n_increments"));

  const json reference = {{"force_balance_absolute_error_N_per_m", 1.2e-6},
                          {"force_balance_relative_error", 3e-14},
                          {"normal_force_N_per_m", 1.2e-6}};
  json       other     = reference;
  other["force_balance_absolute_error_N_per_m"] = 5e-7;
  other["force_balance_relative_error"]         = 1e-14;
  EXPECT_TRUE(compare_json(reference, other, "fem.json").empty());
  // A force imbalance beyond round-off is still caught ...
  other["force_balance_absolute_error_N_per_m"] = 1e-3;
  EXPECT_EQ(compare_json(reference, other, "fem.json").size(), 1u);
  // ... and the round-off tolerance belongs to the residual fields only.
  other                         = reference;
  other["normal_force_N_per_m"] = 5e-7;
  EXPECT_EQ(compare_json(reference, other, "fem.json").size(), 1u);
}

// The tool shall skip a case's own skipped fields in JSON and CSV.
TEST(OutputComparison, CaseSkippedFieldIsNotCompared)
{
  const ScratchFolder scratch;
  ComparisonSettings  settings;
  settings.skipped_fields         = {"status"};
  const std::string a             = scratch.written("skip_a.csv", table);
  std::string       changed_table = table;
  changed_table.replace(changed_table.find(",ok,"), 4, ",slip,");
  const std::string b = scratch.written("skip_b.csv", changed_table);
  EXPECT_EQ(compare_csv(a, b, "joints.csv").size(), 1u);
  EXPECT_TRUE(compare_csv(a, b, "joints.csv", settings).empty());
}

// The tool shall ignore timing fields, and only those.
TEST(OutputComparison, TimingFieldIsIgnored)
{
  const ScratchFolder scratch;
  EXPECT_TRUE(is_skipped_field("wall_time_s"));
  EXPECT_TRUE(is_skipped_field("wall_time_linear_solve_s"));
  EXPECT_FALSE(is_skipped_field("normal_force_N_per_m"));
  EXPECT_FALSE(is_skipped_field("status"));
  json changed           = record();
  changed["wall_time_s"] = 17.5;
  EXPECT_TRUE(compare_json(record(), changed, "fem.json").empty());
  // A skipped key may also be absent on one side.
  changed.erase("wall_time_s");
  EXPECT_TRUE(compare_json(record(), changed, "fem.json").empty());

  const std::string a     = scratch.written("timing_a.csv", table);
  std::string       other = table;
  other.replace(other.find(",0.5\n"), 5, ",9.5\n");
  const std::string b = scratch.written("timing_b.csv", other);
  EXPECT_TRUE(compare_csv(a, b, "joints.csv").empty());
}

// The tool shall report a key missing from the output, a key the reference
// does not have, and a changed structure.
TEST(OutputComparison, MissingOrExtraKeyIsCaught)
{
  json missing = record();
  missing["joints"][1].erase("contact_length_m");
  auto differences = compare_json(record(), missing, "fem.json");
  ASSERT_EQ(differences.size(), 1u) << listed(differences);
  EXPECT_NE(differences[0].find("/joints/1/contact_length_m"),
            std::string::npos)
    << differences[0];
  EXPECT_NE(differences[0].find("missing"), std::string::npos);

  json extra          = record();
  extra["new_number"] = 1.;
  EXPECT_EQ(compare_json(record(), extra, "fem.json").size(), 1u);

  json shorter = record();
  shorter["joints"].erase(1);
  EXPECT_FALSE(compare_json(record(), shorter, "fem.json").empty());

  json retyped       = record();
  retyped["failure"] = 0.;
  EXPECT_EQ(compare_json(record(), retyped, "fem.json").size(), 1u);
}

// The tool shall compare strings and booleans exactly.
TEST(OutputComparison, ChangedStringIsCaught)
{
  json changed                   = record();
  changed["status"]              = "not converged";
  changed["joints"][1]["closed"] = true;
  EXPECT_EQ(compare_json(record(), changed, "fem.json").size(), 2u);
}

// The tool shall report a changed CSV field by row and column, a changed
// header, a missing row, a missing file, and a changed comment line.
TEST(OutputComparison, CsvDifferencesAreCaught)
{
  const ScratchFolder scratch;
  const std::string   reference = scratch.written("reference.csv", table);

  std::string number = table;
  number.replace(number.find("2768312.5"), 9, "2768312.7");
  auto differences =
    compare_csv(reference, scratch.written("number.csv", number), "joints.csv");
  ASSERT_EQ(differences.size(), 1u) << listed(differences);
  EXPECT_NE(differences[0].find("joints.csv: row 2, column Q_N_per_m"),
            std::string::npos)
    << differences[0];
  EXPECT_NE(differences[0].find("2768312.5"), std::string::npos);
  EXPECT_NE(differences[0].find("2768312.7"), std::string::npos);

  std::string text = table;
  text.replace(text.find("slip, open"), 10, "slip, closed");
  EXPECT_EQ(compare_csv(reference,
                        scratch.written("text.csv", text),
                        "joints.csv")
              .size(),
            1u);

  std::string header = table;
  header.replace(header.find("Q_N_per_m"), 9, "Q_N");
  EXPECT_EQ(compare_csv(reference,
                        scratch.written("header.csv", header),
                        "joints.csv")
              .size(),
            1u);

  const std::string shorter = table.substr(0, table.find("2,2768312.5"));
  EXPECT_EQ(compare_csv(reference,
                        scratch.written("rows.csv", shorter),
                        "joints.csv")
              .size(),
            1u);

  std::string comment = table;
  comment.replace(comment.find("block i+1"), 9, "block i-1");
  EXPECT_EQ(compare_csv(reference,
                        scratch.written("comment.csv", comment),
                        "joints.csv")
              .size(),
            1u);

  const auto missing =
    compare_files(reference, reference + ".absent", "joints.csv");
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_NE(missing[0].find("missing"), std::string::npos);
}
