#pragma once

#include <map>
#include <string>
#include <vector>

namespace FloorBlock::Benchmark
{
  /**
   * @brief Wall and process CPU time since construction (s). CPU time is
   * what one core would need on an otherwise idle machine; the wall time
   * also holds the waits for the other jobs of a shared machine.
   */
  class Stopwatch
  {
  public:
    Stopwatch();
    double
    wall_seconds() const;
    double
    cpu_seconds() const;

  private:
    double wall_start;
    double cpu_start;
  };

  /** @brief Mean wall and CPU time of one repetition of a stage (s). */
  struct StageTime
  {
    double wall = 0.;
    double cpu  = 0.;
  };

  /** @brief What the whole contact solve of one scene reported. */
  struct ContactSolveRecord
  {
    bool         converged = false;
    std::string  failure;
    StageTime    time; ///< ContactSolver construction + run()
    unsigned int n_dofs              = 0;
    unsigned int n_increments        = 0;
    unsigned int n_newton_iterations = 0;
    unsigned int n_cutbacks          = 0;
    /** Closed length of the face joint at the end of the loading path (m). */
    double face_contact_length = 0.;
    /** The solver's TimerOutput sections (wall, s). */
    std::map<std::string, double> sections;
  };

  /** @brief Everything measured on one mesh of the default scene. */
  struct LevelRecord
  {
    double       refinement      = 1.; ///< mesh sizes divided by this
    unsigned int n_cells         = 0;
    unsigned int n_dofs          = 0;
    unsigned int n_contact_pairs = 0;
    bool         direct_solver   = true;
    std::map<std::string, StageTime> stages; ///< by stage name
    /** CPU time (s) per phase, per direct solver ("KLU", "UMFPACK"). */
    std::map<std::string, std::map<std::string, double>> direct_phases;
    std::map<std::string, ContactSolveRecord> solves; ///< by joint law
  };

  /** @brief One Hertz verification run. */
  struct HertzRecord
  {
    unsigned int cells_per_half_width = 0;
    unsigned int n_dofs               = 0;
    unsigned int n_newton_iterations  = 0;
    StageTime    time;
    double       half_width_error    = 0.; ///< relative (-)
    double       peak_pressure_error = 0.; ///< relative (-)
    std::string  failure;
  };

  /** @brief All records of this process, filled by the benchmarks. */
  struct Records
  {
    std::map<double, LevelRecord>       levels; ///< by refinement
    std::map<unsigned int, HertzRecord> hertz;  ///< by cells per half-width
  };

  /** @brief The process-wide records (benchmarks run one after another). */
  Records &
  records();
} // namespace FloorBlock::Benchmark
