#pragma once

namespace FloorBlock
{
  /**
   * @brief Installs SIGINT and SIGTERM handlers that only set a flag, so long
   * jobs can stop at a safe point (between cases, between load increments)
   * and leave no half-written file behind.
   */
  void
  install_interrupt_handlers();

  /** @brief Whether SIGINT or SIGTERM has arrived since the handlers were installed. */
  bool
  interrupt_requested();

  /** @brief Thrown at a safe point once an interrupt was requested. */
  struct Interrupted
  {};

  /**
   * @brief Throws Interrupted if an interrupt was requested, and
   * DeadlineReached (common/wall_clock.h) if a solve deadline has passed:
   * the one check long solves make at their safe points.
   */
  void
  stop_if_interrupted();
} // namespace FloorBlock
