#pragma once

namespace FloorBlock
{
  /**
   * @brief Starts the command's wall clock; main() calls it first, so that
   * seconds_since_start() and a solve deadline count the whole command.
   */
  void
  start_wall_clock();

  /** @brief Wall time (s) since start_wall_clock(), or since its first use. */
  double
  seconds_since_start();

  /**
   * @brief From now on, a long solve stops at its next safe point once the
   * command's wall clock passes @p seconds (stop_if_interrupted() throws
   * DeadlineReached). A time budget is kept this way even where a forecast
   * of a solve's duration was too low.
   */
  void
  set_solve_deadline(double seconds);

  /** @brief Long solves run to their end again. */
  void
  clear_solve_deadline();

  /** @brief Whether a deadline is set and the wall clock has passed it. */
  bool
  solve_deadline_passed();

  /** @brief Thrown at a safe point once the solve deadline has passed. */
  struct DeadlineReached
  {};

  /**
   * @brief Sets the solve deadline for its own lifetime and clears it
   * after, also when a solve throws.
   */
  class ScopedSolveDeadline
  {
  public:
    explicit ScopedSolveDeadline(const double seconds)
    {
      set_solve_deadline(seconds);
    }
    ~ScopedSolveDeadline()
    {
      clear_solve_deadline();
    }
    ScopedSolveDeadline(const ScopedSolveDeadline &) = delete;
    ScopedSolveDeadline &
    operator=(const ScopedSolveDeadline &) = delete;
  };
} // namespace FloorBlock
