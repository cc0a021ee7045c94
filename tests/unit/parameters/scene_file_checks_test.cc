// Checks on the raw scene text, made before deal.II's reader sees it.

#include <common/input_error.h>
#include <parameters/scene_file_checks.h>

#include <gtest/gtest.h>

#include <string>

using FloorBlock::InputError;
using FloorBlock::Parameters::check_scene_file_text;

namespace
{
  /** The InputError text for @p text read as @p path, or "" if accepted. */
  std::string
  refusal(const std::string &path, const std::string &text)
  {
    try
      {
        check_scene_file_text(path, text);
      }
    catch (const InputError &error)
      {
        return error.what();
      }
    return "";
  }

  const std::string named_json =
    R"({"Geometry": {"Number of blocks": {"value": "3"}}})";
} // namespace

// The tool shall refuse JSON scenes with unnamed nodes (arrays, members named
// ""), which reach a Boost precondition inside deal.II's reader: the reduced
// input of the fuzz abort is "[[]]".
TEST(SceneFileChecks, JsonArraysAndEmptyNamesAreRefused)
{
  for (const std::string text : {"[[]]",
                                 "[1]",
                                 R"({"": 1})",
                                 R"({"Geometry": [1, 2]})",
                                 R"({"Geometry": [{"value": "3"}]})"})
    EXPECT_NE(refusal("scene.json", text).find("without a name"),
              std::string::npos)
      << text;
  // The message says where the unnamed node sits.
  EXPECT_NE(refusal("scene.json", R"({"Geometry": {"": {"value": "3"}}})")
              .find("'Geometry'"),
            std::string::npos);
  EXPECT_NE(refusal("scene.json", "[[]]").find("the top level"),
            std::string::npos);
  EXPECT_EQ(refusal("scene.json", "[[]]").rfind("scene.json", 0), 0u)
    << "the message starts with the file";
}

// The tool shall refuse names with an '_' that is not deal.II's escape
// ('_' + two lowercase hex digits): deal.II's demangle aborts on them in its
// debug library and reads past the name in its release library.
TEST(SceneFileChecks, NamesWithInvalidEscapesAreRefused)
{
  for (const std::string text : {R"({"a_": "1"})",
                                 R"({"_": {"x": "1"}})",
                                 R"({"Geometry": {"x_zz": "1"}})",
                                 R"({"Geometry": {"x_4": "1"}})",
                                 R"({"Geometry": {"x_2F": "1"}})"})
    EXPECT_NE(refusal("scene.json", text).find("escape"), std::string::npos)
      << text;
  EXPECT_NE(refusal("scene.xml",
                    "<ParameterHandler><Geometry><x_zz>1</x_zz></Geometry>"
                    "</ParameterHandler>")
              .find("'ParameterHandler/Geometry'"),
            std::string::npos);
}

// The tool shall check only the names deal.II reads: not those below an
// entry (its own JSON output has "default_value" there), and escapes as
// deal.II writes them pass.
TEST(SceneFileChecks, NamesBelowEntriesAndValidEscapesPass)
{
  EXPECT_EQ(refusal("scene.json",
                    R"({"Joints": {"Law": {"value": "rigid",)"
                    R"( "default_value": "compliant", "n": [1]}}})"),
            "");
  EXPECT_EQ(refusal("scene.json",
                    R"({"Geometry": {"Number_20of_20blocks": "3"}})"),
            "");
}

// The tool shall choose the file type as deal.II does (the text after the
// last '.', in any case), so that no spelling of the extension skips a check.
TEST(SceneFileChecks, FileTypeIsChosenAsDealIiChoosesIt)
{
  EXPECT_NE(refusal("scene.JSON", "[[]]"), "");
  EXPECT_NE(refusal("/a.b/.json", "[[]]"), "");
  EXPECT_NE(refusal("scene.Prm", "include x.prm\n"), "");
  EXPECT_EQ(refusal("scene.json.txt", "[[]]"), "")
    << "not a JSON file for deal.II";
}

// The tool shall refuse very deep nesting before Boost's recursive parsers
// read it: 200000 levels crashed the process with a stack overflow.
TEST(SceneFileChecks, VeryDeepNestingIsRefused)
{
  constexpr std::size_t n_levels = 200000;
  const std::string     json =
    std::string(n_levels, '[') + std::string(n_levels, ']');
  EXPECT_NE(refusal("scene.json", json).find("200000 levels deep"),
            std::string::npos);
  std::string xml = "<ParameterHandler>";
  for (std::size_t level = 0; level < n_levels; ++level)
    xml += "<a>";
  for (std::size_t level = 0; level < n_levels; ++level)
    xml += "</a>";
  xml += "</ParameterHandler>";
  EXPECT_NE(refusal("scene.xml", xml).find("levels deep"), std::string::npos);
  // Brackets inside strings do not count; 100 levels are allowed.
  EXPECT_EQ(refusal("scene.json",
                    R"({"Geometry": {"Number of blocks": ")" +
                      std::string(500, '[') + R"("}})"),
            "");
  EXPECT_EQ(refusal("scene.json",
                    "{\"Geometry\": " + std::string(99, '[') +
                      std::string(99, ']') + "}")
              .find("levels deep"),
            std::string::npos);
}

// The tool shall pass well-formed named scenes, and leave syntax errors to
// deal.II's reader, which names them.
TEST(SceneFileChecks, NamedScenesAndSyntaxErrorsPass)
{
  EXPECT_EQ(refusal("scene.json", named_json), "");
  EXPECT_EQ(refusal("scene.json", "{}"), "");
  EXPECT_EQ(refusal("scene.json", R"({"Geometry": {)"), "");
  EXPECT_EQ(refusal("scene.xml",
                    "<?xml version=\"1.0\"?><ParameterHandler><Geometry>"
                    "<Number_20of_20blocks><value>3</value>"
                    "</Number_20of_20blocks></Geometry></ParameterHandler>"),
            "");
  EXPECT_EQ(refusal("scene.xml", "<ParameterHandler><unclosed>"), "");
  // The JSON check does not apply to .prm text, nor the include check to JSON.
  EXPECT_EQ(refusal("scene.prm", "[[]]"), "");
  EXPECT_EQ(refusal("scene.json", "include /dev/zero"), "");
}

// The tool shall refuse include statements in .prm scenes, also when a
// backslash continuation splits the keyword.
TEST(SceneFileChecks, PrmIncludeStatementsAreRefused)
{
  for (const std::string text : {"include other.prm\n",
                                 "  INCLUDE /dev/zero # x\n",
                                 "incl\\\nude /dev/zero\n"})
    EXPECT_NE(refusal("scene.prm", text).find("'include'"), std::string::npos)
      << text;
  EXPECT_EQ(refusal("scene.prm", "# include in a comment\nset a = 1\n"), "");
}
