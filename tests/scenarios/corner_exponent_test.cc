// Issue 15, the corner field under exact contact: `floorblock corner` must
// zoom until the peak and the intensity settle, find the face corner's
// state, and fit an exponent that agrees with the theory for that state.
// Release only (scenario label): about 20 s, 14 zoom levels down to cells
// of 1.5 um, too slow under the sanitizers' debug deal.II. Further scenes
// (2 cm fillets and 20 deg friction, the default scene) are measured in
// README.md, "Corner stress": each takes 1-3 minutes.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

#include "process.h"

using namespace FloorBlockTest;
using nlohmann::json;

namespace
{
  /** Issue 15: fitted exponent within 0.05 of the theory. */
  constexpr double exponent_tolerance = 0.05;
  /** Issue 15: K within 2 % over the last two levels. */
  constexpr double intensity_tolerance = 0.02;

  void
  expect_exponent_of_the_state(const std::string &settings)
  {
    const std::string folder = fresh_output_folder("corner_exponent");
    const auto        result = run_floorblock(
      "corner tests/scenarios/hard_rounded_corners.prm --output " +
      shell_quoted(folder) +
      " --set Joints/Law=rigid --set "
             "'Corner/Rounding radii=' " +
      settings);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const json report = read_json(folder + "/corner.json");
    ASSERT_TRUE(report["converged"].get<bool>()) << report["stop_reason"];
    // Rounded corners under exact contact: the zone ends in the fillets
    // with a smooth edge, t ~ d^(1/2).
    EXPECT_EQ(report["state"]["contact_kind"], "edge in fillet");
    ASSERT_TRUE(report["theory"]["covered"].get<bool>());
    EXPECT_NEAR(report["theory"]["exponent"].get<double>(), 1.5, 1e-6);

    const json &fit = report["fit"];
    EXPECT_GE(fit["range_to_m"].get<double>(),
              10. * fit["range_from_m"].get<double>());
    EXPECT_NEAR(fit["exponent"].get<double>(),
                report["theory"]["exponent"].get<double>(),
                exponent_tolerance)
      << fit;
    // The mean pressure's own fit (a constant under the edge's terms).
    EXPECT_NEAR(report["invariant_fit"]["exponent"].get<double>(),
                report["theory"]["exponent"].get<double>(),
                exponent_tolerance)
      << report["invariant_fit"];
    const json &last = report["levels"].back();
    EXPECT_LE(last["K1_change"].get<double>(), intensity_tolerance);
    EXPECT_GT(last["K1"].get<double>(), 0.);
  }
} // namespace

// The tool shall fit the smooth edge's exponent on the 3-block scene with
// 5 cm fillets (Coulomb 30 deg).
TEST(CornerExponent, FiveCentimetreFilletsMeetTheSmoothEdgeExponent)
{
  expect_exponent_of_the_state("");
}
