#pragma once

#include <string>

namespace FloorBlock
{
  /**
   * @brief The Open MPI environment of a process that starts MPI by itself
   * (a singleton, not launched by mpirun): a session directory of its own,
   * removed again when the object is destroyed, and start-up settings that
   * suit one process. Construct it before MPI starts and destroy it after
   * MPI has finished.
   *
   * **Session directory.** Open MPI 4.1.4 creates its shared session
   * directory /tmp/ompi.<host>.<uid> by checking for it and then calling
   * mkdir, and removes it when its last process leaves. Two processes that
   * start MPI at the same moment (ctest -j2, two floorblock runs side by
   * side) can therefore fail in MPI_Init ("A call to mkdir was unable to
   * create the desired directory ... File exists", orte_init failed; seen
   * in a CI rehearsal). Pointing OMPI_MCA_orte_tmpdir_base at a private
   * directory takes the process out of that race. If the directory cannot
   * be made, Open MPI keeps its default.
   *
   * **Start-up settings** (singleton_start_up_settings()). Measured on
   * Debian 12 (Open MPI 4.1.4), `verify hertz` took 0.64 s as a whole
   * process, of which MPI_Init was about 0.37 s:
   * - about 0.2 s is the InfiniPath PSM library, which Open MPI's `cm`
   *   messaging layer loads to probe for InfiniBand and which calibrates
   *   a timer by sleeping in 125 us steps. One process sends no message to
   *   another, so the `ob1` layer (shared memory and TCP) is chosen
   *   directly: OMPI_MCA_pml = ob1.
   * - about 0.1 s is the helper daemon a singleton starts so that it could
   *   later spawn processes (MPI_Comm_spawn, never used here):
   *   OMPI_MCA_ess_singleton_isolated = 1.
   * With both, the same `verify hertz` takes 0.27 s.
   *
   * Left alone: a process started by mpirun (its settings come from the
   * launcher), and every variable the user set.
   */
  class SingletonMpiEnvironment
  {
  public:
    SingletonMpiEnvironment();
    ~SingletonMpiEnvironment();
    SingletonMpiEnvironment(const SingletonMpiEnvironment &) = delete;
    SingletonMpiEnvironment &
    operator=(const SingletonMpiEnvironment &) = delete;

    /** @brief The session directory made, or "" if none was. */
    const std::string &
    path() const;

  private:
    std::string directory;
  };

  /** @brief One Open MPI setting: environment variable and value. */
  struct MpiSetting
  {
    const char *variable;
    const char *value;
  };

  /**
   * @brief The start-up settings SingletonMpiEnvironment gives a singleton
   * (see there for why and what each one saves).
   */
  constexpr MpiSetting singleton_start_up_settings[] =
    {{"OMPI_MCA_pml", "ob1"}, {"OMPI_MCA_ess_singleton_isolated", "1"}};
} // namespace FloorBlock
