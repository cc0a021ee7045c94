// Issue #6 "Hard cases": one scene per hard case (tests/scenarios/hard_*.prm,
// each header says what it checks; the measured numbers are in
// tests/scenarios/HARD_CASES.md). Every case must either converge to a
// physically sensible answer or stop with a clear, named failure (exit code
// 1, status "not converged" and the reason); no output file may hold NaN or
// inf.
//
// The physical checks shared by every converged case follow from the free
// bodies of the chain (lifted reading: the mesh starts flat, so every block
// is an axis-aligned free body loaded only by its weight W, its share P of
// the support load and its joint forces; the base carries the lift):
//  - block i:  N_bed,i = W_i + P_i + T_v,i - T_v,i-1  (vertical),
//              Q_i - Q_i-1 + T_bed,i = 0               (horizontal),
//    with Q_i, T_v,i the normal and shear force of vertical joint i
//    (Q_0 = T_v,0 = 0) and N_bed,i, T_bed,i those of bedding joint i;
//  - every joint within Coulomb: |T| <= N tan(phi), N >= 0;
//  - summing the block balances over blocks 1..i and using Coulomb on the
//    beddings and on vertical joint i gives the all-slip chain bound
//      Q_i <= tan(phi_h) sum_{k<=i}(W_k + P_k) / (1 - tan(phi_h) tan(phi_v)),
//    Eq. 6.12 at alpha = 0, reached exactly when bedding joints 1..i slip
//    (or are open) and vertical joint i slips.
// The solver's own tolerance is 1e-10 of the load norm; the balances are
// checked to 1e-8 of the largest block load or force (measured: at most
// 8e-11 over all cases, the soft joints whose increments stop at the
// round-off floor; 3e-11 for the others).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "process.h"

using namespace FloorBlockTest;
using nlohmann::json;

namespace
{
  /** Relative tolerance of balances and exact identities (see the top). */
  constexpr double balance_tolerance = 1e-8;
  /**
   * Young's modulus of the scenes' rock, Table 6.1's K = 9 GPa and
   * G = 6.7 GPa: E = 9KG/(3K+G) = 16.1 GPa.
   */
  constexpr double youngs_modulus = 9. * 9e9 * 6.7e9 / (3. * 9e9 + 6.7e9);

  double
  tan_degrees(const double angle)
  {
    return std::tan(angle * M_PI / 180.);
  }

  /**
   * The numbers of a hard-case scene that the physical checks need: the
   * values of tests/scenarios/three_blocks.prm and params' defaults
   * (density 2500 kg/m^3, g = 9.81 m/s^2, L = 1 m, b = 1.5 m), changed per
   * case as its .prm changes them.
   */
  struct SceneNumbers
  {
    unsigned int              n_blocks       = 3;
    double                    block_height   = 2.;   // m
    double                    block_width    = 1.;   // m
    double                    support_load_t = 650.; // tonnes-force
    std::vector<unsigned int> loaded_from_face{2, 3};
    double                    phi_h_deg = 30.;
    double                    phi_v_deg = 30.;

    double
    weight() const // N/m
    {
      return 2500. * 9.81 * block_width * block_height;
    }

    /** W_i + P_i of block i (chapter numbering, 1 at the free end). */
    double
    block_load(const unsigned int block) const
    {
      double load = weight();
      for (const unsigned int from_face : loaded_from_face)
        if (n_blocks + 1 - from_face == block)
          load += support_load_t * 9.80665e3 /
                  (loaded_from_face.size() * 1.5 /* b (m) */);
      return load;
    }

    /** Eq. 6.12 at alpha = 0 over blocks 1..i: the all-slip chain value. */
    double
    all_slip_force(const unsigned int joint) const
    {
      double load = 0.;
      for (unsigned int block = 1; block <= joint; ++block)
        load += block_load(block);
      const double a = tan_degrees(phi_h_deg);
      const double c = tan_degrees(phi_v_deg);
      return a * load / (1. - a * c);
    }

    /**
     * tan(phi_h) tan(phi_v) >= 1 (to round-off: tan(45 deg) is
     * 0.9999999999999999): friction alone can lock the chain and the
     * all-slip value does not exist.
     */
    bool
    self_locking() const
    {
      constexpr double round_off = 1e-12;
      return tan_degrees(phi_h_deg) * tan_degrees(phi_v_deg) >= 1. - round_off;
    }
  };

  /** What one floorblock call left in its fresh output folder. */
  struct CaseOutcome
  {
    ProcessResult process;
    std::string   folder;
    double        wall_time_s = 0.;
  };

  CaseOutcome
  run_case(const std::string &command, const std::string &name)
  {
    CaseOutcome outcome;
    outcome.folder   = fresh_output_folder("hard_" + name);
    const auto start = std::chrono::steady_clock::now();
    outcome.process =
      run_floorblock(command + " tests/scenarios/hard_" + name +
                     ".prm --output " + shell_quoted(outcome.folder));
    outcome.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    std::cout << "hard_" << name << ": exit " << outcome.process.exit_code
              << ", " << outcome.wall_time_s << " s" << std::endl;
    return outcome;
  }

  /** Nulls in summary.json only in an object whose status says why. */
  void
  expect_nulls_only_with_a_status(const json &value, const std::string &path)
  {
    if (value.is_object())
      {
        bool has_null = false;
        for (const auto &[key, member] : value.items())
          has_null = has_null || member.is_null();
        if (has_null)
          EXPECT_TRUE(value.contains("status") && value["status"].is_string() &&
                      value["status"] != "ok")
            << "null without a status at " << path;
        for (const auto &[key, member] : value.items())
          expect_nulls_only_with_a_status(member, path + "/" + key);
      }
    else if (value.is_array())
      for (std::size_t k = 0; k < value.size(); ++k)
        {
          EXPECT_FALSE(value[k].is_null()) << path << "[" << k << "]";
          expect_nulls_only_with_a_status(value[k], path);
        }
  }

  /**
   * No NaN or inf in any result file (nlohmann writes them as null, fmt as
   * "nan"/"inf"): fem.json has no null at all, summary.json only next to a
   * status.
   */
  void
  expect_finite_outputs(const std::string &folder)
  {
    for (const std::string name : {"summary.json", "fem.json", "joints.csv"})
      if (std::filesystem::exists(folder + "/" + name))
        EXPECT_FALSE(has_non_finite_value(read_text(folder + "/" + name)))
          << name;
    ASSERT_TRUE(std::filesystem::exists(folder + "/fem.json"));
    EXPECT_EQ(read_text(folder + "/fem.json").find("null"), std::string::npos);
    if (std::filesystem::exists(folder + "/summary.json"))
      expect_nulls_only_with_a_status(read_json(folder + "/summary.json"), "");
  }

  std::map<std::string, json>
  joints_by_name(const json &fem)
  {
    std::map<std::string, json> joints;
    for (const auto &joint : fem["joints"])
      joints[joint["name"].get<std::string>()] = joint;
    return joints;
  }

  double
  normal_force(const json &joint)
  {
    return joint["normal_force_N_per_m"].get<double>();
  }

  double
  shear_force(const json &joint)
  {
    return joint["shear_force_N_per_m"].get<double>();
  }

  /** The checks of the top comment, on the final state in fem.json. */
  void
  expect_physical_answer(const json &fem, const SceneNumbers &scene)
  {
    ASSERT_EQ(fem["status"], "converged") << fem["status_text"];
    EXPECT_EQ(fem["force_balance_status"], "ok")
      << fem["force_balance_status_text"];
    EXPECT_LT(fem["force_balance_relative_error"].get<double>(),
              balance_tolerance);
    auto joints = joints_by_name(fem);
    ASSERT_EQ(joints.size(), 2 * scene.n_blocks);

    for (const auto &[name, joint] : joints)
      {
        const bool   bedding = joint["kind"] == "bedding";
        const double friction =
          tan_degrees(bedding ? scene.phi_h_deg : scene.phi_v_deg);
        EXPECT_GE(normal_force(joint), 0.) << name;
        EXPECT_LE(std::abs(shear_force(joint)),
                  friction * normal_force(joint) * (1. + balance_tolerance))
          << name << ": outside Coulomb";
        const double side = bedding ? scene.block_width : scene.block_height;
        EXPECT_GE(joint["contact_length_m"].get<double>(), 0.) << name;
        EXPECT_LE(joint["contact_length_m"].get<double>(), side * (1. + 1e-12))
          << name;
      }

    bool all_beddings_slide = true;
    for (unsigned int block = 1; block <= scene.n_blocks; ++block)
      {
        const std::string number  = std::to_string(block);
        const json       &bedding = joints["bedding " + number];
        const json       &joint   = joints["vertical " + number];
        const double      previous_q =
          block > 1 ?
                 normal_force(joints["vertical " + std::to_string(block - 1)]) :
                 0.;
        const double previous_shear =
          block > 1 ?
            shear_force(joints["vertical " + std::to_string(block - 1)]) :
            0.;
        const double scale =
          std::max(scene.block_load(block), std::abs(normal_force(joint)));
        EXPECT_NEAR(normal_force(bedding),
                    scene.block_load(block) + shear_force(joint) -
                      previous_shear,
                    balance_tolerance * scale)
          << "vertical balance of block " << block;
        EXPECT_NEAR(normal_force(joint) - previous_q + shear_force(bedding),
                    0.,
                    balance_tolerance * scale)
          << "horizontal balance of block " << block;

        if (scene.self_locking())
          continue; // no all-slip chain value to compare with
        const double bound = scene.all_slip_force(block);
        EXPECT_LE(normal_force(joint), bound * (1. + balance_tolerance))
          << "Q_" << block << " above the all-slip chain value";
        all_beddings_slide =
          all_beddings_slide &&
          (bedding["state"] == "slip" || bedding["state"] == "open");
        if (all_beddings_slide && joint["state"] == "slip")
          EXPECT_NEAR(normal_force(joint), bound, balance_tolerance * bound)
            << "every joint up to " << block << " slips, yet Q_" << block
            << " is not the all-slip chain value";
      }
  }

  /** Converged and physical, or a named failure with exit code 1. */
  void
  expect_physical_answer_or_named_failure(const CaseOutcome  &outcome,
                                          const SceneNumbers &scene)
  {
    expect_finite_outputs(outcome.folder);
    const json fem = read_json(outcome.folder + "/fem.json");
    if (outcome.process.exit_code == 0)
      {
        expect_physical_answer(fem, scene);
        return;
      }
    EXPECT_EQ(outcome.process.exit_code, 1) << outcome.process.output;
    EXPECT_EQ(fem["status"], "not converged");
    const std::string why = fem["status_text"].get<std::string>();
    EXPECT_NE(why.find("stage '"), std::string::npos) << why;
    EXPECT_NE(why.find("tried"), std::string::npos) << why;
  }

  /** How often @p word occurs in @p text. */
  std::size_t
  count_occurrences(const std::string &text, const std::string &word)
  {
    std::size_t count = 0;
    for (std::size_t at = text.find(word); at != std::string::npos;
         at             = text.find(word, at + word.size()))
      ++count;
    return count;
  }

  /**
   * The counters of a run that stopped: the increment that failed made
   * "after N cutbacks" (its status text) before giving up, and "cutbacks"
   * counts them with those of the converged increments kept; every failed
   * attempt is listed; counters the solver does not return for a failed
   * solve are left out, not written as 0.
   */
  void
  expect_honest_failure_counters(const json &fem)
  {
    ASSERT_TRUE(fem.contains("failure")) << fem.dump(1);
    const json       &failure = fem["failure"];
    const std::string why     = fem["status_text"].get<std::string>();
    const std::size_t after   = why.find("after ");
    ASSERT_NE(after, std::string::npos) << why;
    const unsigned int stated_cutbacks = std::stoul(why.substr(after + 6));
    EXPECT_EQ(failure["cutbacks_before_failure"].get<unsigned int>(),
              stated_cutbacks);
    unsigned int kept_cutbacks = 0;
    for (const auto &increment : fem["increments"])
      kept_cutbacks += increment["cutbacks"].get<unsigned int>();
    EXPECT_EQ(fem["cutbacks"].get<unsigned int>(),
              kept_cutbacks + stated_cutbacks);
    // Each cutback follows a failed attempt, and one more failure ends the run.
    EXPECT_GE(failure["failed_attempts"].size(), stated_cutbacks + 1);
    EXPECT_EQ(failure["n_failed_attempts"], failure["failed_attempts"].size());
    EXPECT_EQ(failure["failed_attempts"].size(),
              count_occurrences(why, "tried: "));
    // The failed attempts' Newton iterations are counted and solved.
    EXPECT_GE(fem["linear_solves"].get<unsigned int>(),
              fem["newton_iterations"].get<unsigned int>() +
                failure["failed_newton_iterations"].get<unsigned int>());
  }

  /** Every joints.csv row of @p joint, in increment order. */
  std::vector<CsvRow>
  joint_rows(const std::string &folder, const std::string &joint)
  {
    std::vector<CsvRow> rows;
    for (const CsvRow &row : read_csv(folder + "/joints.csv").rows)
      if (row.at("joint") == joint)
        rows.push_back(row);
    return rows;
  }

  /** A case that must converge: its folder and fem.json. */
  struct ConvergedCase
  {
    std::string folder;
    json        fem;
  };

  /**
   * Solves a case that must converge and checks what every converged case
   * must satisfy: exit code 0, finite outputs, the physical checks above.
   */
  ConvergedCase
  solve_converging_case(const std::string &name, const SceneNumbers &scene)
  {
    const CaseOutcome outcome = run_case("solve", name);
    EXPECT_EQ(outcome.process.exit_code, 0) << outcome.process.output;
    expect_finite_outputs(outcome.folder);
    ConvergedCase result{outcome.folder,
                         read_json(outcome.folder + "/fem.json")};
    expect_physical_answer(result.fem, scene);
    // Table 6.1's joints overlap by far less than 5 % of a block.
    EXPECT_EQ(result.fem["joint_overlap"]["status"], "ok")
      << result.fem["joint_overlap"]["text"];
    return result;
  }
} // namespace

// The tool shall stay finite and in balance as friction nears self-locking.
TEST(HardCases, FrictionNearSelfLocking)
{
  SceneNumbers scene;
  scene.phi_h_deg = 35.;
  scene.phi_v_deg = 45.;
  // 1 - tan(35) tan(45) = 0.30: the all-slip chain multiplies each block's
  // friction by 1/0.30.
  solve_converging_case("self_locking", scene);
}

// The tool shall give the support-stage forces back when the floor barely
// lifts.
TEST(HardCases, TinyFloorLiftKeepsTheSupportStageForces)
{
  const ConvergedCase outcome =
    solve_converging_case("small_lift", SceneNumbers{});
  const json &fem = outcome.fem;

  // No joint changes state during the uplift (same counts in every uplift
  // increment as at the end of the support stage), so the response to the
  // lift is linear: equal Q increments per equal lift step.
  const json       &increments = fem["increments"];
  std::vector<json> uplift;
  json              support_end;
  for (const auto &increment : increments)
    if (increment["stage"] == "uplift")
      uplift.push_back(increment);
    else
      support_end = increment;
  ASSERT_EQ(uplift.size(), 4u);
  for (const auto &increment : uplift)
    for (const std::string count : {"n_open", "n_slip", "n_stick"})
      EXPECT_EQ(increment[count], support_end[count]) << count;

  // Bound on the change: the lift imposes displacements of at most 1e-6 m,
  // and the forces this adds per metre of face are at most of order
  // E x lift (a unit-aspect elastic body; E = 9KG/(3K+G) = 16.1 GPa, so
  // 16 kN/m). Measured: 0.21 kN/m at joint 1, 0 at the open face joint.
  const double lift = 1e-6;
  for (const std::string joint : {"vertical 1", "vertical 2", "vertical 3"})
    {
      const auto rows = joint_rows(outcome.folder, joint);
      ASSERT_EQ(rows.size(), fem["increments"].size()) << joint;
      std::vector<double> q;
      for (const auto &row : rows)
        q.push_back(std::stod(row.at("normal_force_N_per_m")));
      const std::size_t first_uplift = rows.size() - uplift.size();
      const double      q_support    = q[first_uplift - 1];
      EXPECT_LE(std::abs(q.back() - q_support), youngs_modulus * lift) << joint;
      // joints.csv keeps 10 significant digits: 1e-9 |Q| per value.
      const double step = q[first_uplift] - q_support;
      for (std::size_t k = first_uplift + 1; k < q.size(); ++k)
        EXPECT_NEAR(q[k] - q[k - 1], step, 1e-8 * std::abs(q_support) + 1e-6)
          << joint << ": not linear in the lift";
    }
}

// The tool shall converge and stay in balance at a large floor lift.
TEST(HardCases, LargeFloorLift)
{
  SceneNumbers        scene;
  const ConvergedCase outcome = solve_converging_case("large_lift", scene);
  const json         &fem     = outcome.fem;
  // At 4.4 times the scene's lift friction is mobilised almost everywhere:
  // measured 98.8 % of the all-slip value at the face (the scene's own lift:
  // 98.2 %; 1e-6 m: 0 %). 5 % leaves room for the mesh, not for a stuck joint.
  const double q_face = normal_force(joints_by_name(fem)["vertical 3"]);
  EXPECT_GT(q_face, 0.95 * scene.all_slip_force(3));
}

// The tool shall converge and stay in balance under a very high support load.
TEST(HardCases, VeryHighSupportLoad)
{
  SceneNumbers scene;
  scene.support_load_t = 900.;
  solve_converging_case("heavy_support", scene);
}

// The tool shall give Q proportional to the weight when nothing else loads
// the blocks.
TEST(HardCases, NoSupportLoadGivesQFromTheWeightAlone)
{
  SceneNumbers scene;
  scene.support_load_t        = 0.;
  const ConvergedCase outcome = solve_converging_case("no_support", scene);
  const json         &fem     = outcome.fem;
  // Every joint slips, so Q_n = n W tan(phi_h) / (1 - tan(phi_h) tan(phi_v))
  // (Eq. 6.23 at alpha = 0): proportional to the weight.
  auto joints = joints_by_name(fem);
  for (const auto &[name, joint] : joints)
    EXPECT_EQ(joint["state"], "slip") << name;
  const double expected = 3. * scene.weight() * tan_degrees(30.) /
                          (1. - tan_degrees(30.) * tan_degrees(30.));
  EXPECT_NEAR(normal_force(joints["vertical 3"]),
              expected,
              balance_tolerance * expected);
}

// The tool shall handle slender blocks.
TEST(HardCases, SlenderBlocks)
{
  SceneNumbers scene;
  scene.block_height          = 5.;
  const ConvergedCase outcome = solve_converging_case("slender", scene);
  const json         &fem     = outcome.fem;
  // Measured: every joint slips, so the bound above is met with equality
  // at every joint (checked there); here only that this stays so.
  for (const auto &joint : fem["joints"])
    EXPECT_EQ(joint["state"], "slip") << joint["name"];
}

// The tool shall handle squat blocks.
TEST(HardCases, SquatBlocks)
{
  SceneNumbers scene;
  scene.block_height          = 0.5;
  const ConvergedCase outcome = solve_converging_case("squat", scene);
  const json         &fem     = outcome.fem;
  // Eq. 6.25 puts Q above the top of every squat block (they would
  // rotate); the FEM keeps them seated (HARD_CASES.md). Only the chain
  // checks above are asserted: the seating is a measurement, not a law.
  EXPECT_EQ(fem["status"], "converged");
}

// The tool shall reproduce the single-block closed form.
TEST(HardCases, OneBlockMatchesItsClosedForm)
{
  SceneNumbers scene;
  scene.n_blocks            = 1;
  scene.loaded_from_face    = {1};
  const CaseOutcome outcome = run_case("run", "one_block");
  EXPECT_EQ(outcome.process.exit_code, 0) << outcome.process.output;
  expect_finite_outputs(outcome.folder);
  const json fem = read_json(outcome.folder + "/fem.json");
  expect_physical_answer(fem, scene);

  // Both joints slip: Q = (W+P) a/(1 - a c), a = tan(phi_h), c = tan(phi_v)
  // (Eq. 6.12, one block, alpha = 0: the FEM's lifted bed is level).
  const json   summary = read_json(outcome.folder + "/summary.json");
  const json  &blocks  = summary["analytic"]["blocks"];
  const double load =
    blocks["W_N_per_m"][0].get<double>() + blocks["P_N_per_m"][0].get<double>();
  EXPECT_NEAR(load, scene.block_load(1), 1e-12 * load);
  const double q_fem = summary["comparison"]["final"][0]["Q_fem_N_per_m"];
  const double phi_h = blocks["phi_h_rad"], phi_v = blocks["phi_v_rad"];
  const auto   closed_form = [&](const double alpha) {
    const double a = std::sin(alpha) + std::tan(phi_h) * std::cos(alpha);
    const double c = std::sin(alpha) + std::tan(phi_v) * std::cos(alpha);
    return load * std::cos(alpha) * a / (1. - a * c);
  };
  EXPECT_NEAR(q_fem, closed_form(0.), balance_tolerance * q_fem);

  // The product's no-rotation closed form stands the block on the parabola
  // (alpha = L/k at its middle, 0.0025 rad), which the small-displacement
  // FEM never tilts: it must be exactly the same formula at that alpha, and
  // the FEM falls below it by that inclination alone (measured -0.86 %).
  const double alpha = blocks["alpha_rad"][0];
  const double q_closed_form =
    summary["comparison"]["final"][0]["Q_closed_form"]["no_rotation"]
           ["Q_N_per_m"];
  EXPECT_NEAR(q_closed_form, closed_form(alpha), 1e-12 * q_closed_form);
  EXPECT_NEAR(q_fem / q_closed_form,
              closed_form(0.) / closed_form(alpha),
              balance_tolerance);
}

// The tool shall solve a long chain of blocks.
TEST(HardCases, TwentyBlocks)
{
  SceneNumbers scene;
  scene.n_blocks         = 20;
  scene.loaded_from_face = {4, 5, 6};
  solve_converging_case("twenty_blocks", scene);
}

// The tool shall not write NaN or inf for badly scaled joints.
TEST(HardCases, VerySoftJoints)
{
  const CaseOutcome outcome = run_case("solve", "soft_joints");
  expect_physical_answer_or_named_failure(outcome, SceneNumbers{});
  // Measured outcome (HARD_CASES.md): it converges, so the checks below
  // always run; update both if that changes.
  ASSERT_EQ(outcome.process.exit_code, 0) << outcome.process.output;
  // The loaded blocks sink about 2 m into the bed: the answer must say that
  // it is not physical (fem.json and the terminal).
  const json overlap = read_json(outcome.folder + "/fem.json")["joint_overlap"];
  EXPECT_EQ(overlap["status"], "large");
  EXPECT_GT(overlap["largest_overlap_m"].get<double>(), 1.);
  EXPECT_NE(outcome.process.output.find("warning: the joint sides overlap"),
            std::string::npos)
    << outcome.process.output;
}

// The tool shall report joint forces that balance every block, also with
// rounded corners, and an averaged peak that never exceeds the pointwise one.
TEST(HardCases, RoundedCornersBalanceEveryBlock)
{
  // Horizontal balance of every block from the joint tables, to 1e-8 of the
  // face Q: the joint forces are the resultant's components along each
  // joint's straight part. Summed as scalars along the fillet nodes' own
  // normals they missed by 7.4 kN/m here (face Q 3748 against 3759 kN/m
  // with bedding 3 open) and by up to 2.3 kN/m on the default scene.
  // The vertical balance and the all-slip equality of the other cases do
  // not apply: the meshed blocks weigh less than W = rho g H L by their
  // polygonal fillets, and a fillet node slips along its own tangent.
  const CaseOutcome outcome = run_case("solve", "rounded_corners");
  ASSERT_EQ(outcome.process.exit_code, 0) << outcome.process.output;
  expect_finite_outputs(outcome.folder);
  const json   fem    = read_json(outcome.folder + "/fem.json");
  auto         joints = joints_by_name(fem);
  const double q_face = normal_force(joints["vertical 3"]);
  ASSERT_GT(q_face, 0.);
  for (unsigned int block = 1; block <= 3; ++block)
    {
      const std::string number = std::to_string(block);
      const double      previous_q =
        block > 1 ?
               normal_force(joints["vertical " + std::to_string(block - 1)]) :
               0.;
      EXPECT_NEAR(normal_force(joints["vertical " + number]) - previous_q +
                    shear_force(joints["bedding " + number]),
                  0.,
                  balance_tolerance * q_face)
        << "horizontal balance of block " << block;
    }
  for (const auto &joint : fem["joints"])
    EXPECT_LE(joint["sigma_max_averaged_Pa"].get<double>(),
              joint["sigma_max_Pa"].get<double>() * (1. + 1e-12))
      << joint["name"];
}

// The tool shall not write NaN or inf for stiff joints, and shall name the
// remedy.
TEST(HardCases, VeryStiffJoints)
{
  const CaseOutcome outcome = run_case("solve", "stiff_joints");
  expect_physical_answer_or_named_failure(outcome, SceneNumbers{});
  // Measured outcome (HARD_CASES.md): it fails with a named failure, so the
  // checks below always run; update both if that changes.
  ASSERT_EQ(outcome.process.exit_code, 1) << outcome.process.output;
  EXPECT_NE(outcome.process.output.find("use Joints/Law = rigid"),
            std::string::npos)
    << outcome.process.output;
  // Measured: fails in the gravity stage after its 1 cutback, 2 failed
  // attempts (HARD_CASES.md); before, fem.json said 0 cutbacks.
  expect_honest_failure_counters(read_json(outcome.folder + "/fem.json"));
}

// The remedy is named however fine a corner is meshed: the ill-conditioning
// is that of the joint's long cells (kn w / E), which a refined corner
// (critical-distance paths of L/64: cells below half a millimetre, where
// kn h / E < 3) does not shorten.
// Sized by the mesh's smallest cell instead, kn h / E fell below the
// threshold and the failure named nothing.
TEST(HardCases, VeryStiffJointsNameTheRemedyWithAFinelyMeshedCorner)
{
  const std::string folder = fresh_output_folder("hard_stiff_fine_corner");
  const auto        result = run_floorblock(
    "solve tests/scenarios/hard_stiff_joints.prm --set \"Mesh/Cells per "
           "critical distance=64\" --output " +
    shell_quoted(folder));
  ASSERT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("with h the longest pair along a joint"),
            std::string::npos)
    << result.output;
  EXPECT_NE(result.output.find("use Joints/Law = rigid"), std::string::npos)
    << result.output;
  const json fem = read_json(folder + "/fem.json");
  EXPECT_NE(fem["status_text"].get<std::string>().find(
              "use Joints/Law = rigid"),
            std::string::npos);
}

// The tool shall solve the scene with rigid joints.
TEST(HardCases, RigidJointLaw)
{
  const ConvergedCase rigid =
    solve_converging_case("rigid_law", SceneNumbers{});
  const json &fem = rigid.fem;

  // Q is set by friction, not by the joint stiffness: the compliant law
  // (kn = 9 GPa/m) gives nearly the same face Q. Measured -2.2 % on this
  // 0.1 m mesh (-0.4 % on the default scene, results/FINDINGS.md, section 12).
  const std::string compliant = fresh_output_folder("hard_rigid_compliant");
  const auto        result =
    run_floorblock("solve tests/scenarios/three_blocks.prm --output " +
                   shell_quoted(compliant));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const double q_rigid     = normal_force(joints_by_name(fem)["vertical 3"]);
  const double q_compliant = normal_force(
    joints_by_name(read_json(compliant + "/fem.json"))["vertical 3"]);
  EXPECT_NEAR(q_rigid, q_compliant, 0.05 * q_compliant);
}

// The tool shall not stop where only the exact law's complementarity
// parameter makes the semi-smooth Newton cycle: that parameter changes the
// iterates, never the answer. Without the retry with a tenth of it, the
// three-block scene at the factor 100 fails in the gravity stage after all
// cutbacks (every start cycling or over the iteration limit), and at 10 it
// converges; the default scene at vertical friction 80 deg fails the same
// way at the default 0.1 and converges at 0.01. A rescued state keeps the
// smaller parameter: restoring it after each rescue can fail this scene in
// its uplift stage.
TEST(HardCases, RigidLawRetriesWithASmallerComplementarityParameter)
{
  const std::string scene =
    "solve tests/scenarios/three_blocks.prm --set Joints/Law=rigid "
    "--set \"Solver/Error estimate=none\" --output ";
  const std::string cycling = fresh_output_folder("hard_rigid_factor_100");
  const auto        retried =
    run_floorblock(scene + shell_quoted(cycling) +
                   " --set \"Solver/Complementarity factor=100\"");
  ASSERT_EQ(retried.exit_code, 0) << retried.output;
  expect_finite_outputs(cycling);

  const std::string usual = fresh_output_folder("hard_rigid_factor_default");
  const auto        reference = run_floorblock(scene + shell_quoted(usual));
  ASSERT_EQ(reference.exit_code, 0) << reference.output;

  // The same converged state: every joint force to 1e-8 of the largest
  // (the two runs' joints.csv agree to its printed digits).
  auto a = joints_by_name(read_json(cycling + "/fem.json"));
  auto b = joints_by_name(read_json(usual + "/fem.json"));

  // fem.json says which parameter each increment converged with: the
  // retried run lowered it (so the rescue was exercised, not just a lucky
  // start) and kept it; the usual run never did.
  const auto factors = [](const nlohmann::json &fem) {
    std::vector<double> result;
    for (const auto &increment : fem.at("increments"))
      result.push_back(
        increment.at("complementarity_parameter_factor").get<double>());
    return result;
  };
  const std::vector<double> retried_factors =
    factors(read_json(cycling + "/fem.json"));
  ASSERT_FALSE(retried_factors.empty());
  EXPECT_LT(retried_factors.back(), 0.5);
  EXPECT_GT(retried_factors.back(), 0.5e-2);
  for (std::size_t k = 1; k < retried_factors.size(); ++k)
    EXPECT_LE(retried_factors[k], retried_factors[k - 1]) << "increment " << k;
  for (const double factor : factors(read_json(usual + "/fem.json")))
    EXPECT_EQ(factor, 1.);

  double largest = 0.;
  for (auto &[name, joint] : b)
    largest = std::max(largest, std::abs(normal_force(joint)));
  ASSERT_GT(largest, 0.);
  for (auto &[name, joint] : b)
    {
      EXPECT_NEAR(normal_force(a[name]), normal_force(joint), 1e-8 * largest)
        << name;
      EXPECT_NEAR(shear_force(a[name]), shear_force(joint), 1e-8 * largest)
        << name;
    }
}

// The default scene (six blocks, 650 t on blocks 4-6 from the face) with
// the rigid law at low and high friction, sharp corners, a coarse mesh: the
// scenes of the exact-contact issue, run by CI under the sanitizers too.
namespace
{
  SceneNumbers
  default_scene_at_friction(const double friction_angle_deg)
  {
    SceneNumbers scene;
    scene.n_blocks         = 6;
    scene.loaded_from_face = {4, 5, 6};
    scene.phi_h_deg        = friction_angle_deg;
    scene.phi_v_deg        = friction_angle_deg;
    return scene;
  }
} // namespace

// The tool shall solve the default scene with rigid joints at 10 deg.
TEST(HardCases, RigidLawDefaultSceneAtTenDegrees)
{
  solve_converging_case("rigid_friction_10", default_scene_at_friction(10.));
}

// The tool shall solve the default scene with rigid joints at 30 deg.
TEST(HardCases, RigidLawDefaultSceneAtThirtyDegrees)
{
  solve_converging_case("rigid_friction_30", default_scene_at_friction(30.));
}

// The tool shall solve the default scene with rigid joints at 45 deg.
TEST(HardCases, RigidLawDefaultSceneAtFortyFiveDegrees)
{
  const ConvergedCase outcome =
    solve_converging_case("rigid_friction_45", default_scene_at_friction(45.));
  // tan^2(45 deg) = 1: self-locking, no all-slip chain value (the checks
  // above skip it). Measured: the blocks lift off the bed and hang on block 1
  // (bedding 1 slips, the others open), so by the horizontal balances every
  // vertical joint carries bedding 1's friction force N_bed,1 tan(45 deg):
  // Q_i = N_bed,1 for every i.
  auto         joints    = joints_by_name(outcome.fem);
  const double bedding_1 = normal_force(joints["bedding 1"]);
  for (unsigned int joint = 1; joint <= 6; ++joint)
    EXPECT_NEAR(normal_force(joints["vertical " + std::to_string(joint)]),
                bedding_1,
                balance_tolerance * bedding_1)
      << "vertical " << joint;
}

// The tool shall report an open joint as zero force, not as NaN.
TEST(HardCases, JointThatLosesContactEntirely)
{
  const CaseOutcome outcome = run_case("run", "opening");
  EXPECT_EQ(outcome.process.exit_code, 0) << outcome.process.output;
  expect_finite_outputs(outcome.folder);
  const json fem = read_json(outcome.folder + "/fem.json");
  expect_physical_answer(fem, SceneNumbers{});

  auto        joints = joints_by_name(fem);
  const json &face   = joints["vertical 3"];
  EXPECT_EQ(normal_force(face), 0.);
  EXPECT_EQ(shear_force(face), 0.);
  EXPECT_EQ(face["contact_length_m"], 0.);
  EXPECT_EQ(face["n_stick"].get<int>() + face["n_slip"].get<int>(), 0);

  // Block 3 (material id 3) follows the base (101) away from the face
  // (x > 0 away from it); the face block (100) stays. Measured: both move
  // 0.0225 m, the block 0.1 % more (22.54 against 22.51 mm, elastic strain).
  const json  &motions = fem["body_motions_by_material_id"];
  const double block_x = motions["3"]["translation_m"][0];
  const double base_x  = motions["101"]["translation_m"][0];
  EXPECT_GT(base_x, 0.);
  EXPECT_GT(block_x, 0.9 * base_x);

  // The comparison with the closed forms: Q_fem = 0 is compared (-100 %),
  // the contact estimate has no answer and says why.
  const json  summary         = read_json(outcome.folder + "/summary.json");
  const json &face_comparison = summary["comparison"]["final"][2];
  EXPECT_EQ(face_comparison["Q_fem_N_per_m"], 0.);
  EXPECT_NE(face_comparison["contact"]["status"], "ok");
}

// The tool shall report a state without load as "no load", not as a large
// relative error or an infinite percentage.
TEST(HardCases, WeightlessUnloadedBlocks)
{
  const CaseOutcome outcome = run_case("run", "weightless");
  ASSERT_EQ(outcome.process.exit_code, 0) << outcome.process.output;
  expect_finite_outputs(outcome.folder);
  EXPECT_FALSE(has_non_finite_value(outcome.process.output))
    << outcome.process.output;
  EXPECT_FALSE(has_non_finite_value(read_text(outcome.folder + "/report.md")));

  // Nothing loads the blocks, so every force is round-off of the elastic
  // forces that the base's slide causes: about eps E |u| = 2.2e-16 x 16.1
  // GPa x 0.0225 m = 8e-8 N/m per nodal force (measured: at most 6e-7 N/m).
  // The product calls forces below 1e-10 E |u| round-off
  // (Compare::round_off_force_fraction); no force may exceed that.
  const double round_off_force = 1e-10 * youngs_modulus * 0.0225;
  const json   fem             = read_json(outcome.folder + "/fem.json");
  EXPECT_EQ(fem["status"], "converged");
  EXPECT_EQ(fem["force_balance_status"], "no load")
    << fem["force_balance_status_text"];
  // Round-off over round-off was reported as 0.52 before.
  EXPECT_EQ(fem["force_balance_relative_error"].get<double>(), 0.);
  EXPECT_LT(fem["force_balance_absolute_error_N_per_m"].get<double>(),
            round_off_force);
  for (const auto &increment : fem["increments"])
    EXPECT_EQ(increment["force_balance_status"], "no load");
  for (const auto &joint : fem["joints"])
    {
      EXPECT_LT(std::abs(normal_force(joint)), round_off_force)
        << joint["name"];
      EXPECT_LT(std::abs(shear_force(joint)), round_off_force) << joint["name"];
    }
  EXPECT_NE(outcome.process.output.find("no load"), std::string::npos)
    << outcome.process.output;

  // Every closed form with a Q gives 0 here: no relative difference (it was
  // printed as "inf %" before), and the status says why.
  const json summary = read_json(outcome.folder + "/summary.json");
  ASSERT_EQ(summary["comparison"]["final"].size(), 3u);
  for (const auto &record : summary["comparison"]["final"])
    {
      for (const auto &[mechanism, value] : record["Q_closed_form"].items())
        {
          EXPECT_TRUE(value["relative_difference"].is_null()) << mechanism;
          if (value["Q_N_per_m"].is_number())
            EXPECT_EQ(value["status"], "no_load") << mechanism;
        }
      EXPECT_EQ(record["contact"]["status"], "no_load");
    }
}

// The tool shall follow a block that starts to rotate on its bed.
TEST(HardCases, BlockStartsToRotate)
{
  SceneNumbers        scene;
  const ConvergedCase outcome = solve_converging_case("rotation", scene);
  const json         &fem     = outcome.fem;

  // Block 1's bedding: whole base at the end of the support stage, then the
  // heel lifts as the bed bends (measured 1.0 -> 0.905 -> 0.729 -> 0.604
  // -> 0.532 -> 0.487 -> 0.434 -> 0.399 -> 0.375 m over the 8 steps);
  // contact can only shrink while the tilt grows.
  const auto rows = joint_rows(outcome.folder, "bedding 1");
  ASSERT_EQ(rows.size(), fem["increments"].size());
  std::vector<double> uplift_lengths;
  double              support_length = -1.;
  for (const auto &row : rows)
    {
      const double length = std::stod(row.at("contact_length_m"));
      if (row.at("stage") == "uplift")
        uplift_lengths.push_back(length);
      else
        support_length = length;
    }
  EXPECT_DOUBLE_EQ(support_length, scene.block_width);
  ASSERT_EQ(uplift_lengths.size(), 8u);
  double previous = support_length;
  for (const double length : uplift_lengths)
    {
      EXPECT_LE(length, previous + 1e-12);
      previous = length;
    }
  EXPECT_LT(uplift_lengths.back(), 0.5 * scene.block_width);
}

// The tool shall refuse non-matching joints with a message naming the
// parameter.
TEST(HardCases, NonMatchingJointsAreRefused)
{
  const std::string folder = fresh_output_folder("hard_non_matching");
  const auto        result =
    run_floorblock("solve tests/scenarios/hard_non_matching.prm --output " +
                   shell_quoted(folder));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("Mesh/Matching joints"), std::string::npos)
    << result.output;
  EXPECT_FALSE(std::filesystem::exists(folder))
    << "a results folder was written";
}
