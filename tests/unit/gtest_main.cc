#include <common/blas_threads.h>
#include <common/singleton_mpi_environment.h>

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

int
main(int argc, char **argv)
{
  // Test executables start side by side under ctest -j: a private Open MPI
  // session directory each and the quick singleton start-up (see the class),
  // declared first to outlive MPI.
  const FloorBlock::SingletonMpiEnvironment mpi_environment;
  // One thread: tests must give the same answer on a loaded CI machine.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // As in floorblock's main: small dense fronts, no spinning BLAS threads.
  FloorBlock::limit_blas_to_one_thread();
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
