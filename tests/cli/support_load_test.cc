// The FEM must apply the whole support load P_i of the closed forms, also
// with rounded corners, where the pressure acts only on the straight part
// of the block top between the two fillets (found by the hard-case runs:
// dividing by L applied (L - 2r)/L of P). Checked through equilibrium at the
// end of the support stage on the lifted (level) bed: the bedding joints
// carry every block's weight and support load, the face joint no shear yet.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "process.h"

using namespace FloorBlockTest;

TEST(SupportLoad, RoundedBlocksReceiveTheWholeSupportLoad)
{
  const std::string folder = fresh_output_folder("support_load_rounded");
  const auto        result =
    run_floorblock("solve tests/scenarios/three_blocks.prm"
                   " --set \"Geometry/Corner rounding radius=0.05\""
                   " --set \"Mesh/Corner size=0.05\" --output " +
                   shell_quoted(folder));
  ASSERT_EQ(result.exit_code, 0) << result.output;

  // Sum the bedding normal forces and the face-joint shear of the last
  // support-stage increment (stage_factor 1) in joints.csv.
  double bedding_normal = 0., face_shear = 0.;
  for (const CsvRow &row : read_csv(folder + "/joints.csv").rows)
    {
      if (row.at("stage") != "support_load" ||
          number_in(row, "stage_factor") != 1.)
        continue;
      if (row.at("kind") == "bedding")
        bedding_normal += number_in(row, "normal_force_N_per_m");
      else if (row.at("joint") == "vertical 3")
        face_shear += number_in(row, "shear_force_N_per_m");
    }

  // Scene: 3 blocks 1 m x 2 m, rho 2500 kg/m^3, g 9.81 m/s^2, four fillets
  // of r = 0.05 m per block (each removes (1 - pi/4) r^2), 650 t over b =
  // 1.5 m shared by the loaded blocks.
  const double r       = 0.05;
  const double area    = 1. * 2. - 4. * (1. - M_PI / 4.) * r * r;
  const double weight  = 3. * 2500. * 9.81 * area;
  const double support = 650. * 1000. * 9.80665 / 1.5;
  // Tolerance: the fillet arcs are meshed by straight-edged cells, which
  // lose a few 1e-6 of the weight (measured 3e-6); the former shortfall
  // (L - 2r)/L was 1e-1 of P here.
  EXPECT_NEAR((bedding_normal + face_shear) / (weight + support), 1., 1e-5);
}
