#pragma once

#include <string>

namespace FloorBlock
{
  /**
   * @brief A session directory of this process's own for Open MPI, when the
   * process starts MPI by itself (a singleton, not launched by mpirun);
   * removed again when the object is destroyed. Construct it before MPI
   * starts and destroy it after MPI has finished.
   *
   * Open MPI 4.1.4 creates its shared session directory
   * /tmp/ompi.<host>.<uid> by checking for it and then calling mkdir, and
   * removes it when its last process leaves. Two processes that start MPI
   * at the same moment (ctest -j2, two floorblock runs side by side) can
   * therefore fail in MPI_Init ("A call to mkdir was unable to create the
   * desired directory ... File exists", orte_init failed; seen in a CI
   * rehearsal). Pointing OMPI_MCA_orte_tmpdir_base at a private directory
   * takes the process out of that race.
   *
   * Left alone: a process started by mpirun (its session directory comes
   * from the launcher), and an OMPI_MCA_orte_tmpdir_base the user set. If
   * the directory cannot be made, Open MPI keeps its default.
   */
  class PrivateMpiSessionDirectory
  {
  public:
    PrivateMpiSessionDirectory();
    ~PrivateMpiSessionDirectory();
    PrivateMpiSessionDirectory(const PrivateMpiSessionDirectory &) = delete;
    PrivateMpiSessionDirectory &
    operator=(const PrivateMpiSessionDirectory &) = delete;

    /** @brief The directory made, or "" if none was. */
    const std::string &
    path() const;

  private:
    std::string directory;
  };
} // namespace FloorBlock
