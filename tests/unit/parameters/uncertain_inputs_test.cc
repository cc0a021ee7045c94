#include <common/input_error.h>
#include <parameters/scenario_parameters.h>
#include <parameters/uncertain_inputs.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace FloorBlock;
using namespace FloorBlock::Parameters;

namespace
{
  /** The InputError message of @p action, or "" if it does not throw. */
  template <typename Action>
  std::string
  refusal(Action &&action)
  {
    try
      {
        action();
      }
    catch (const InputError &error)
      {
        return error.what();
      }
    return "";
  }

  std::string
  inputs_refusal(const std::string &text)
  {
    return refusal([&] { parse_uncertain_inputs(text); });
  }

  std::string
  scene_refusal(const std::string &inputs)
  {
    return refusal(
      [&] { read_defaults("uncertain", {"Uncertainty/Inputs=" + inputs}); });
  }
} // namespace

TEST(UncertainInputs, ReadsEveryFamilyWithItsArgumentsAndSupport)
{
  const auto inputs = parse_uncertain_inputs(
    "Joints/Bedding friction angle: normal(30, 3, 15, 45);"
    "  Joints/Vertical friction angle : Truncated  Normal(35, 4, 20, 50) ;"
    "Strength/Intact UCS: lognormal(40e6, 10e6);"
    "Loading/Support load: uniform(500, 800);"
    "Joints/Cohesion: triangular(0, 1e4, 5e4);"
    "Strength/GSI: beta(2, 3, 50, 90)");
  ASSERT_EQ(inputs.size(), 6u);
  EXPECT_EQ(inputs[0].path, "Joints/Bedding friction angle");
  EXPECT_EQ(inputs[0].family, DistributionFamily::normal);
  EXPECT_TRUE(inputs[0].truncated());
  EXPECT_EQ(inputs[0].support(), std::make_pair(15., 45.));
  EXPECT_EQ(inputs[1].path, "Joints/Vertical friction angle");
  EXPECT_EQ(inputs[1].family, DistributionFamily::normal);
  EXPECT_EQ(inputs[1].arguments, (std::vector<double>{35, 4, 20, 50}));
  EXPECT_EQ(inputs[2].family, DistributionFamily::lognormal);
  EXPECT_FALSE(inputs[2].truncated());
  EXPECT_EQ(inputs[2].support().first, 0.);
  EXPECT_TRUE(std::isinf(inputs[2].support().second));
  EXPECT_EQ(inputs[3].support(), std::make_pair(500., 800.));
  EXPECT_EQ(inputs[4].family, DistributionFamily::triangular);
  EXPECT_EQ(inputs[4].support(), std::make_pair(0., 5e4));
  EXPECT_EQ(inputs[5].family, DistributionFamily::beta);
  EXPECT_EQ(inputs[5].support(), std::make_pair(50., 90.));
  EXPECT_TRUE(parse_uncertain_inputs("  ").empty());
}

TEST(UncertainInputs, RefusesMalformedEntriesNamingTheEntry)
{
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"Joints/Cohesion normal(1, 2)", "Subsection/Entry: family(arguments)"},
    {"Cohesion: normal(1, 2)", "parameter path"},
    {"Joints/Cohesion: gamma(1, 2)", "(got 'gamma')"},
    {"Joints/Cohesion: normal 1, 2", "family(arguments)"},
    {"Joints/Cohesion: normal(1, 2, 3)", "got 3"},
    {"Joints/Cohesion: uniform(1, 2, 3, 4)", "got 4"},
    {"Joints/Cohesion: normal(1, two)", "(got 'two')"},
    {"Joints/Cohesion: normal(1, -2)", "sd > 0 (sd = -2 here)"},
    {"Joints/Cohesion: normal(1, 0)", "sd > 0"},
    {"Joints/Cohesion: lognormal(-1, 2)", "lognormal mean > 0"},
    {"Joints/Cohesion: lognormal(1, 2, -5, -1)", "truncation max > 0"},
    {"Joints/Cohesion: normal(1, 2, 5, 3)", "min = 5 must be below max = 3"},
    {"Joints/Cohesion: uniform(5, 5)", "min = 5 must be below max = 5"},
    {"Joints/Cohesion: triangular(0, 6, 5)", "min <= mode <= max"},
    {"Joints/Cohesion: beta(0, 1, 0, 1)", "alpha > 0 and beta > 0"},
    {"Joints/Cohesion: uniform(0, 1); Joints/Cohesion: uniform(0, 2)",
     "given twice"}};
  for (const auto &[text, phrase] : cases)
    {
      const std::string message = inputs_refusal(text);
      EXPECT_NE(message.find("Uncertainty/Inputs"), std::string::npos)
        << text << ": " << message;
      EXPECT_NE(message.find(phrase), std::string::npos)
        << text << ": " << message;
    }
}

TEST(UncertainInputs, ReadsAndRefusesCorrelations)
{
  const auto inputs =
    parse_uncertain_inputs("Joints/Bedding friction angle: uniform(20, 40);"
                           "Joints/Vertical friction angle: uniform(20, 40)");
  const auto correlations = parse_input_correlations(
    "Joints/Bedding friction angle, Joints/Vertical friction angle: 0.5",
    inputs);
  ASSERT_EQ(correlations.size(), 1u);
  EXPECT_EQ(correlations[0].first, "Joints/Bedding friction angle");
  EXPECT_EQ(correlations[0].second, "Joints/Vertical friction angle");
  EXPECT_EQ(correlations[0].value, 0.5);

  const std::vector<std::pair<std::string, std::string>> cases = {
    {"Joints/Bedding friction angle: 0.5", "Subsection/Entry, Subsection"},
    {"Joints/Bedding friction angle, Joints/Cohesion: 0.5",
     "'Joints/Cohesion' is not one of them"},
    {"Joints/Bedding friction angle, Joints/Bedding friction angle: 0.5",
     "two different inputs"},
    {"Joints/Bedding friction angle, Joints/Vertical friction angle: 1",
     "strictly between -1 and 1"},
    {"Joints/Bedding friction angle, Joints/Vertical friction angle: x",
     "strictly between -1 and 1"},
    {"Joints/Bedding friction angle, Joints/Vertical friction angle: 0.5;"
     "Joints/Vertical friction angle, Joints/Bedding friction angle: 0.2",
     "given twice"}};
  for (const auto &[text, phrase] : cases)
    {
      const std::string message =
        refusal([&] { parse_input_correlations(text, inputs); });
      EXPECT_NE(message.find("Uncertainty/Correlations"), std::string::npos)
        << text << ": " << message;
      EXPECT_NE(message.find(phrase), std::string::npos)
        << text << ": " << message;
    }
}

TEST(UncertainInputs, SceneTakesInputsWithinTheParametersRanges)
{
  const ScenarioParameters scene = read_defaults(
    "uncertain",
    {"Uncertainty/Inputs=Joints/Bedding friction angle: normal(30, 3, 15, "
     "45); Joints/Normal stiffness: lognormal(9e9, 4.5e9, 1e8, 1e12)"});
  ASSERT_EQ(scene.uncertainty.inputs.size(), 2u);
  // Each input knows its parameter's unit, from its documentation.
  EXPECT_EQ(scene.uncertainty.inputs[0].unit, "degrees");
  EXPECT_EQ(scene.uncertainty.inputs[1].unit, "Pa/m");
  // The range probes set the entries; they must put them back, or the
  // expanded parameters (parameters.prm) would show a probed value.
  const ScenarioParameters plain = read_defaults("plain", {});
  for (const std::string entry :
       {"set Bedding friction angle", "set Normal stiffness"})
    {
      const auto line_of = [&](const std::string &text) {
        const auto start = text.find(entry);
        return start == std::string::npos ?
                 std::string("missing") :
                 text.substr(start, text.find('\n', start) - start);
      };
      EXPECT_EQ(line_of(scene.expanded_text), line_of(plain.expanded_text));
      EXPECT_NE(line_of(plain.expanded_text), "missing");
    }
}

TEST(UncertainInputs, SceneRefusesInputsItCannotTake)
{
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"Joints/Bedding fricton angle: uniform(20, 40)",
     "did you mean Joints/Bedding friction angle"},
    {"Uncertainty/Seed: uniform(1, 2)", "outside subsection Uncertainty"},
    {"Joints/Law: uniform(1, 2)", "takes real numbers"},
    {"Geometry/Number of blocks: uniform(4, 8)", "Integer range"},
    {"Joints/Bedding friction angle: normal(30, 3)",
     "normal takes values down to -infinity"},
    {"Joints/Bedding friction angle: uniform(10, 95)",
     "uniform takes values up to 95"},
    {"Joints/Normal stiffness: normal(9e9, 1e9)",
     "normal takes values down to -infinity"},
    {"Joints/Normal stiffness: lognormal(9e9, 1e9)",
     "lognormal takes values down to 0"}};
  for (const auto &[text, phrase] : cases)
    {
      const std::string message = scene_refusal(text);
      EXPECT_NE(message.find("Uncertainty/Inputs"), std::string::npos)
        << text << ": " << message;
      EXPECT_NE(message.find(phrase), std::string::npos)
        << text << ": " << message;
    }
}
