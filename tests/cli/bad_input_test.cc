#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "process.h"

using namespace FloorBlockTest;

namespace
{
  /**
   * One bad input: either a scene file text (written to a temporary .prm or
   * .json) or overrides of the default scene, and a phrase the error message
   * must contain (the parameter, or what is wrong).
   */
  struct BadInput
  {
    std::string name;
    std::string scene_text; ///< empty: params/default.prm
    std::string scene_extension;
    std::string arguments; ///< extra command-line arguments
    std::string must_mention;
    std::string command = ""; ///< empty: analytic on the scene
  };

  std::ostream &
  operator<<(std::ostream &out, const BadInput &input)
  {
    return out << input.name;
  }

  const BadInput bad_inputs[] = {
    {"friction_95_deg",
     "",
     "",
     "--set 'Joints/Bedding friction angle=95'",
     "Joints/Bedding friction angle"},
    {"friction_exactly_90_deg",
     "",
     "",
     "--set 'Joints/Vertical friction angle=90'",
     "89.9"},
    {"negative_block_width",
     "",
     "",
     "--set 'Geometry/Block width=-1'",
     "Geometry/Block width"},
    {"zero_block_height",
     "",
     "",
     "--set 'Geometry/Block height=0'",
     "Geometry/Block height"},
    {"zero_blocks",
     "",
     "",
     "--set 'Geometry/Number of blocks=0'",
     "Number of blocks"},
    {"too_many_blocks",
     "",
     "",
     "--set 'Geometry/Number of blocks=100'",
     "Number of blocks"},
    {"unknown_entry_override",
     "",
     "",
     "--set 'Joints/Friction=20'",
     "Friction"},
    {"unknown_subsection_override",
     "",
     "",
     "--set 'Rock/Density=20'",
     "Density"},
    {"override_without_equals",
     "",
     "",
     "--set 'Joints/Cohesion'",
     "Subsection/Entry name=value"},
    {"not_a_number", "", "", "--set 'Material/Density=heavy'", "heavy"},
    {"zero_target_error",
     "",
     "",
     "--set 'Mesh/Target relative error=0'",
     "Mesh/Target relative error"},
    {"unknown_target_figure",
     "",
     "",
     "--set 'Mesh/Target figures=area'",
     "Target figures"},
    {"solve_3d_with_global_refinements",
     "",
     "",
     "--set 'Geometry/Dimension=3' --set 'Mesh/Global refinements=1'",
     "Mesh/Global refinements",
     "solve params/default.prm"},
    {"solve_3d_with_rigid_blocks",
     "",
     "",
     "--set 'Geometry/Dimension=3' --set 'Model/Blocks=rigid'",
     "Model/Blocks",
     "solve params/default.prm"},
    {"run_in_three_dimensions",
     "",
     "",
     "--set 'Geometry/Dimension=3'",
     "Geometry/Dimension",
     "run params/default.prm"},
    {"unknown_dimension", "", "", "--set 'Geometry/Dimension=4'", "Dimension"},
    {"footprint_in_two_dimensions",
     "",
     "",
     "--set 'Loading/Footprint length=1.5'",
     "Loading/Footprint length",
     "solve params/default.prm"},
    {"footprint_longer_than_face",
     "",
     "",
     "--set 'Loading/Footprint length=5'",
     "Geometry/Face length = 4.5",
     "solve params/footprint_3d.prm"},
    {"negative_footprint_length",
     "",
     "",
     "--set 'Loading/Footprint length=-1'",
     "Footprint length",
     "solve params/footprint_3d.prm"},
    {"footprint_beyond_face_end",
     "",
     "",
     "--set 'Loading/Footprint offset=3.5'",
     "Loading/Footprint offset",
     "solve params/footprint_3d.prm"},
    {"footprint_offset_below_zero",
     "",
     "",
     "--set 'Loading/Footprint offset=-0.2'",
     "Loading/Footprint offset",
     "solve params/footprint_3d.prm"},
    {"footprint_offset_without_footprint",
     "",
     "",
     "--set 'Geometry/Dimension=3' --set 'Loading/Footprint offset=1'",
     "Loading/Footprint offset",
     "solve params/default.prm"},
    {"negative_support_load",
     "",
     "",
     "--set 'Loading/Support load=-5'",
     "Support load"},
    {"negative_bulk_modulus",
     "",
     "",
     "--set 'Material/Bulk modulus=-9e9'",
     "Bulk modulus"},
    {"both_pairs_of_moduli",
     "",
     "",
     "--set \"Material/Young's modulus=16e9\" "
     "--set \"Material/Poisson's ratio=0.2\"",
     "Young's modulus and Poisson's ratio, and set the other pair to auto"},
    {"half_a_pair_of_moduli",
     "",
     "",
     "--set 'Material/Bulk modulus=auto' --set 'Material/Shear modulus=auto' "
     "--set \"Material/Young's modulus=16e9\"",
     "Material/Poisson's ratio"},
    {"poissons_ratio_one_half",
     "",
     "",
     "--set 'Material/Bulk modulus=auto' --set 'Material/Shear modulus=auto' "
     "--set \"Material/Young's modulus=16e9\" "
     "--set \"Material/Poisson's ratio=0.5\"",
     "strictly between -1 and 0.5"},
    {"negative_intact_ucs",
     "",
     "",
     "--set 'Strength/Intact UCS=-25e6'",
     "Strength/Intact UCS"},
    {"gsi_below_ten", "", "", "--set 'Strength/GSI=5'", "Strength/GSI"},
    {"gsi_above_hundred", "", "", "--set 'Strength/GSI=101'", "10...100"},
    {"zero_m_i", "", "", "--set 'Strength/m_i=0'", "Strength/m_i"},
    {"zero_critical_distance",
     "",
     "",
     "--set 'Strength/Critical distance=0'",
     "Strength/Critical distance"},
    {"tensile_strength_above_ucs",
     "",
     "",
     "--set 'Strength/Tensile strength=50e6'",
     "must be below Strength/Intact UCS"},
    {"uncertain_input_unknown_path",
     "",
     "",
     "--set 'Uncertainty/Correlations=' --set 'Uncertainty/Inputs=Joints/Bedding fricton angle: normal(30, 3, "
     "15, 45)'",
     "there is no 'Joints/Bedding fricton angle' (did you mean "
     "Joints/Bedding friction angle",
     "assess params/default.prm"},
    {"uncertain_input_negative_standard_deviation",
     "",
     "",
     "--set 'Uncertainty/Correlations=' --set 'Uncertainty/Inputs=Loading/Support load: normal(650, -65, 300, "
     "1000)'",
     "'Uncertainty/Inputs' = 'Loading/Support load: normal(650, -65, 300, "
     "1000)': a standard deviation sd > 0",
     "assess params/default.prm"},
    {"uncertain_input_inverted_bounds",
     "",
     "",
     "--set 'Uncertainty/Correlations=' --set 'Uncertainty/Inputs=Strength/Intact UCS: uniform(60e6, 20e6)'",
     "min = 6e+07 must be below max = 2e+07",
     "assess params/default.prm"},
    {"uncertain_friction_above_90_deg",
     "",
     "",
     "--set 'Uncertainty/Correlations=' --set 'Uncertainty/Inputs=Joints/Vertical friction angle: normal(80, "
     "5, 60, 95)'",
     "[Double 0...89.9 (inclusive)]: normal takes values up to 95",
     "assess params/default.prm"},
    {"uncertain_negative_stiffness",
     "",
     "",
     "--set 'Uncertainty/Correlations=' --set 'Uncertainty/Inputs=Joints/Normal stiffness: normal(9e9, 3e9)'",
     "normal takes values down to -infinity",
     "assess params/default.prm"},
    {"uncertain_correlations_not_positive_definite",
     "",
     "",
     "--set 'Uncertainty/Inputs=Joints/Bedding friction angle: uniform(20, "
     "40); Joints/Vertical friction angle: uniform(20, 40); "
     "Joints/Cohesion: uniform(0, 1e4)' --set 'Uncertainty/Correlations="
     "Joints/Bedding friction angle, Joints/Vertical friction angle: 0.9; "
     "Joints/Vertical friction angle, Joints/Cohesion: 0.9; Joints/Bedding "
     "friction angle, Joints/Cohesion: -0.9'",
     "positive definite",
     "assess params/default.prm"},
    {"assess_without_uncertain_inputs",
     "",
     "",
     "--set 'Uncertainty/Inputs=' --set 'Uncertainty/Correlations='",
     "'Uncertainty/Inputs' = '': at least one uncertain scene parameter",
     "assess params/default.prm"},
    {"assess_with_rigid_blocks",
     "",
     "",
     "--set 'Model/Blocks=rigid' --set 'Uncertainty/Correlations=' --set "
     "'Uncertainty/Inputs=Joints/Bedding friction angle: uniform(20, 40)'",
     "elastic (or auto) for `assess`",
     "assess params/default.prm"},
    {"critical_distance_beyond_the_block",
     "",
     "",
     "--set 'Geometry/Block width=0.5' --set 'Loading/Floor lift=auto' "
     "--set 'Strength/Critical distance=0.9'",
     "'Strength/Critical distance' = '0.900000 m': must be below the "
     "smallest block side"},
    {"critical_distance_from_toughness_out_of_range",
     "",
     "",
     "--set 'Strength/Fracture toughness=1e7' "
     "--set 'Strength/Tensile strength=1e4'",
     "Strength/Critical distance"},
    {"barton_bandis_with_rigid_law",
     "",
     "",
     "--set 'Joints/Stiffness source=Barton-Bandis' --set 'Joints/Law=rigid'",
     "'Joints/Stiffness source' = 'Barton-Bandis': given while Joints/Law = "
     "rigid"},
    {"barton_bandis_with_a_given_normal_stiffness",
     "",
     "",
     "--set 'Joints/Stiffness source=Barton-Bandis' "
     "--set 'Joints/Normal stiffness=1e10'",
     "'Joints/Normal stiffness' = '1e10': its default 9e9"},
    {"joint_wall_stronger_than_the_rock",
     "",
     "",
     "--set 'Joints/Stiffness source=Barton-Bandis' "
     "--set 'Joints/Joint wall strength=50e6'",
     "'Joints/Joint wall strength' = '5e+07 Pa': at most Strength/Intact UCS"},
    {"roughness_coefficient_above_twenty",
     "",
     "",
     "--set 'Joints/Joint roughness coefficient=25'",
     "Joints/Joint roughness coefficient"},
    {"zero_normal_stress_for_stiffness",
     "",
     "",
     "--set 'Joints/Normal stress for stiffness=0'",
     "Joints/Normal stress for stiffness"},
    {"auto_aperture_of_a_smooth_joint",
     "",
     "",
     "--set 'Joints/Stiffness source=Barton-Bandis' "
     "--set 'Joints/Joint roughness coefficient=0'",
     "'Joints/Initial aperture' = 'auto = 0 m'"},
    // K_ni = -7.15 + 1.75 x 2 + 0.02 x 20 / 1 = -3.25 MPa/mm.
    {"aperture_with_no_positive_initial_normal_stiffness",
     "",
     "",
     "--set 'Joints/Stiffness source=Barton-Bandis' "
     "--set 'Joints/Joint roughness coefficient=2' "
     "--set 'Joints/Initial aperture=1e-3'",
     "'Joints/Initial aperture' = '0.001 m': between 6.005e-06 m and "
     "0.0001096 m"},
    // V_m = -0.2960 - 0.0448 + 2.2410 x 20000^-0.2450 = -0.14 mm.
    {"aperture_with_no_positive_maximum_closure",
     "",
     "",
     "--set 'Joints/Stiffness source=Barton-Bandis' "
     "--set 'Joints/Initial aperture=1e-6'",
     "'Joints/Initial aperture' = '1e-06 m': between 9.173e-06 m and any "
     "larger value"},
    // phi_peak = 20 log10(20 / 100) + 5 = -9 deg: ks < 0.
    {"normal_stress_above_the_wall_strength",
     "",
     "",
     "--set 'Joints/Stiffness source=Barton-Bandis' "
     "--set 'Joints/Joint roughness coefficient=20' "
     "--set 'Joints/Residual friction angle=5' "
     "--set 'Joints/Normal stress for stiffness=1e8'",
     "'Joints/Normal stress for stiffness' = '1e+08 Pa': from 11246.8 Pa to "
     "below 3.55656e+07 Pa"},
    // phi_peak = 20 log10(40 / 0.01) + 30 = 102 deg, beyond Barton's 70.
    {"peak_friction_angle_above_seventy_degrees",
     "",
     "",
     "--set 'Joints/Stiffness source=Barton-Bandis' "
     "--set 'Joints/Joint roughness coefficient=20' "
     "--set 'Joints/Joint wall strength=40e6' "
     "--set 'Joints/Residual friction angle=30' "
     "--set 'Joints/Normal stress for stiffness=1e4'",
     "'Joints/Normal stress for stiffness' = '10000 Pa': from 400000 Pa"},
    {"normal_stress_closing_the_whole_aperture",
     "",
     "",
     "--set 'Joints/Stiffness source=Barton-Bandis' "
     "--set 'Joints/Normal stress for stiffness=3e7'",
     "'Joints/Normal stress for stiffness' = '3e+07 Pa': below 2.64253e+07 "
     "Pa"},
    // A smooth, frictionless wall: phi_peak = 0, ks = 0.
    {"smooth_joint_without_residual_friction",
     "",
     "",
     "--set 'Joints/Stiffness source=Barton-Bandis' "
     "--set 'Joints/Joint roughness coefficient=0' "
     "--set 'Joints/Initial aperture=5e-5' "
     "--set 'Joints/Residual friction angle=0'",
     "'Joints/Residual friction angle' = '0': above 0 deg"},
    {"unknown_bedding_shape", "", "", "--set 'Bedding/Shape=curved'", "curved"},
    {"malformed_loaded_list",
     "",
     "",
     "--set 'Loading/Loaded blocks from face=4,x'",
     "Loaded blocks from face"},
    {"loaded_block_beyond_n",
     "",
     "",
     "--set 'Geometry/Number of blocks=3' --set 'Loading/Loaded blocks from face=4'",
     "Loading/Loaded blocks from face"},
    {"loaded_blocks_without_their_counting_direction",
     "",
     "",
     "--set 'Geometry/Number of blocks=8' --set 'Loading/Loaded blocks=6,7,8'",
     "Loaded blocks"},
    {"unknown_name_suggests_the_nearest",
     "",
     "",
     "--set 'Loading/Floor lfit=0.1'",
     "did you mean Loading/Floor lift"},
    {"unknown_name_in_file_suggests_the_nearest",
     "subsection Loading\n  set Loaded blocks = 6,7,8\nend\n",
     ".prm",
     "",
     "did you mean Loading/Loaded blocks from face"},
    {"missing_end_names_the_open_subsection",
     "subsection Geometry\n  set Number of blocks = 6\n"
     "subsection Bedding\n  set Curvature = 400\nend\n",
     ".prm",
     "",
     "Subsection 'Geometry' opened at line 1 is still open at line 3"},
    {"option_before_the_command",
     "",
     "",
     "",
     "stands before the command 'analytic'; options belong after it",
     "--set 'Loading/Gravity=9.81' analytic params/default.prm"},
    {"sweep_limit_without_fem",
     "",
     "",
     "",
     "--limit chooses the FEM cases of `sweep --fem` and does nothing "
     "without --fem",
     "sweep params/default.prm --limit 5"},
    {"sweep_curvature_not_in_the_grid",
     "",
     "",
     "",
     "one of the k (m) of fig6_6: 400",
     "sweep params/default.prm --fem --figure fig6_6 --curvatures 300"},
    {"sweep_load_range_holding_no_point",
     "",
     "",
     "",
     "400, 500, 600, 700, 800, 900 t",
     "sweep params/default.prm --fem --figure fig6_10_11 --loads 950,990"},
    {"kn_safety_sweep_with_grid_options",
     "",
     "",
     "",
     "--figure kn_safety solves its seven cases whole",
     "sweep params/default.prm --figure kn_safety --limit 2"},
    {"kn_safety_sweep_with_rigid_blocks",
     "",
     "",
     "--set 'Model/Blocks=rigid'",
     "'Model/Blocks' = 'rigid': elastic for `sweep --figure kn_safety`",
     "sweep params/default.prm --figure kn_safety"},
    {"duplicate_loaded_block",
     "",
     "",
     "--set 'Loading/Loaded blocks from face=2,2'",
     "only once"},
    {"corner_radius_too_large",
     "",
     "",
     "--set 'Geometry/Corner rounding radius=0.4'",
     "Corner rounding radius"},
    {"tensile_strength_with_rounded_corners",
     "",
     "",
     "--set 'Joints/Tensile strength=1e6'",
     "Joints/Tensile strength"},
    {"unknown_verification_case",
     "",
     "",
     "",
     "available: hertz",
     "verify sphere"},
    {"frictionless_incline_verification",
     "",
     "",
     "--set 'Joints/Bedding friction angle=0'",
     "Joints/Bedding friction angle",
     "verify incline"},
    {"corner_size_above_far_size",
     "",
     "",
     "--set 'Mesh/Corner size=0.5' --set 'Mesh/Far size=0.3'",
     "Corner size"},
    {"unknown_entry_in_file",
     "subsection Joints\n  set Bedding fricton angle = 20\nend\n",
     ".prm",
     "",
     "Bedding fricton angle"},
    {"unknown_subsection_in_file",
     "subsection Jonts\nend\n",
     ".prm",
     "",
     "Jonts"},
    {"out_of_range_in_file_names_line",
     "\nsubsection Geometry\n  set Block width = -2\nend\n",
     ".prm",
     "",
     "Line <3>"},
    {"unbalanced_subsection_in_file",
     "subsection Geometry\n",
     ".prm",
     "",
     "subsection"},
    {"file_ending_inside_a_subsection",
     "subsection Geometry\n  set Number of blocks = 6\n",
     ".prm",
     "",
     "Subsection 'Geometry' opened at line 1 is never closed"},
    {"malformed_json", "{\"Geometry\": {", ".json", "", ".json"},
    // The reduced fuzz input that tripped a Boost assertion in deal.II's
    // JSON reader (an array: nodes without a name).
    {"json_array", "[[]]", ".json", "", "without a name"},
    {"json_member_without_name",
     "{\"Geometry\": {\"\": {\"value\": \"3\"}}}",
     ".json",
     "",
     "'Geometry'"},
    // deal.II's demangle aborts (debug) or reads past the name (release).
    {"json_name_with_invalid_escape", "{\"a_\": \"1\"}", ".json", "", "escape"},
    // Boost's recursive parsers overflow the stack on very deep nesting.
    {"json_nested_too_deep",
     std::string(1000, '[') + std::string(1000, ']'),
     ".json",
     "",
     "1000 levels deep"},
    {"missing_scene_file", "", "", "", "does not exist"},
    {"unknown_command_line_option", "", "", "--frobnicate", "frobnicate"},
  };

  class BadInputTest : public ::testing::TestWithParam<BadInput>
  {};

  // The tool shall refuse each bad input with exit code 2, one message naming
  // what is wrong, and no results folder.
  TEST_P(BadInputTest, ExitsWithCodeTwoNamesTheProblemAndWritesNothing)
  {
    const BadInput   &input  = GetParam();
    const std::string output = fresh_output_folder(input.name);

    std::string scene = "params/default.prm";
    if (!input.scene_text.empty())
      {
        scene = output + "_scene" + input.scene_extension;
        std::ofstream(scene) << input.scene_text;
      }
    else if (input.name == "missing_scene_file")
      scene = "params/no_such_scene.prm";

    const std::string command =
      input.command.empty() ? "analytic " + shell_quoted(scene) : input.command;
    const ProcessResult result = run_floorblock(
      command + " " + input.arguments + " --output " + shell_quoted(output));

    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find(input.must_mention), std::string::npos)
      << "message does not mention '" << input.must_mention << "':\n"
      << result.output;
    EXPECT_FALSE(std::filesystem::exists(output))
      << "a results folder was written";
    if (!input.scene_text.empty())
      std::filesystem::remove(scene);
  }

  INSTANTIATE_TEST_SUITE_P(EveryDocumentedCase,
                           BadInputTest,
                           ::testing::ValuesIn(bad_inputs),
                           [](const ::testing::TestParamInfo<BadInput> &info) {
                             return info.param.name;
                           });
} // namespace
