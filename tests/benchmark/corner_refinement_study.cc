// Study (not a test): peak normal stress at the top corner of the face joint
// under mesh refinement, sharp vs rounded corners, on the lifted level
// floor (the UDEC loading path). Prints one line per mesh.
// Usage: corner_refinement_study <rigid|compliant> <n blocks> <support 0|1>
//          <averaging length m> <rounding m> <corner size m>...
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "lifted_floor_case.h"

int
main(int argc, char **argv)
{
  using namespace FloorBlock;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 7)
    {
      std::fprintf(stderr,
                   "usage: %s <rigid|compliant> <n blocks> <support 0|1> "
                   "<averaging length m> <rounding m> <corner size m>...\n",
                   argv[0]);
      return 2;
    }
  Testing::LiftedFloorCase floor_case;
  floor_case.law              = std::string(argv[1]) == "rigid" ?
                                  Contact::JointLawKind::rigid :
                                  Contact::JointLawKind::compliant;
  floor_case.n_blocks         = std::atoi(argv[2]);
  floor_case.support_load     = std::atoi(argv[3]) != 0;
  floor_case.averaging_length = std::atof(argv[4]);
  floor_case.rounding         = std::atof(argv[5]);
  std::printf("%-9s %-8s %7s %6s %13s %13s %13s %9s %7s\n",
              "rounding",
              "corner",
              "cells",
              "pairs",
              "Q (N/m)",
              "peak (Pa)",
              "avg peak",
              "peak y",
              "time s");
  for (int arg = 6; arg < argc; ++arg)
    {
      floor_case.corner_size = std::atof(argv[arg]);
      dealii::Timer clock;
      try
        {
          const Testing::LiftedFloorOutcome outcome =
            Testing::run_lifted_floor(floor_case);
          const Contact::JointReport &face_joint =
            outcome.last.joints.at(floor_case.n_blocks - 1);
          std::printf("%-9g %-8g %7u %6u %13.6e %13.6e %13.6e %9.5f %7.1f\n",
                      floor_case.rounding,
                      floor_case.corner_size,
                      outcome.n_cells,
                      outcome.n_pairs,
                      face_joint.normal_force,
                      face_joint.peak_normal_stress,
                      face_joint.averaged_peak_normal_stress,
                      face_joint.peak_position[1],
                      clock.wall_time());
        }
      catch (const std::exception &error)
        {
          std::printf("%-9g %-8g failed: %s\n",
                      floor_case.rounding,
                      floor_case.corner_size,
                      error.what());
        }
      std::fflush(stdout);
    }
  return 0;
}
