#pragma once

namespace FloorBlock::Loading
{
  /** @brief Increments per loading stage; 0 skips a stage. */
  struct LoadSteps
  {
    unsigned int n_gravity  = 1;
    unsigned int n_pressure = 1;
    unsigned int n_uplift   = 1;
    /**
     * Gravity rises with the support load over the n_pressure increments
     * of stage 2 (n_gravity is then not used): the path "gravity and load
     * together" of the six-block benchmark scene.
     */
    bool gravity_with_pressure = false;
  };
} // namespace FloorBlock::Loading
