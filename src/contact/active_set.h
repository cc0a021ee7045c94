#pragma once

#include <contact/joint_law.h>

#include <cstdint>
#include <vector>

namespace FloorBlock::Contact
{
  /** @brief How many pairs are in each state. */
  struct StateCounts
  {
    unsigned int n_stick = 0;
    unsigned int n_slip  = 0;
    unsigned int n_open  = 0;

    /** @brief Closed = stick + slip. */
    unsigned int
    n_closed() const
    {
      return n_stick + n_slip;
    }
  };

  /**
   * @brief The open/stick/slip state of every contact pair, as seen by
   * the semi-smooth Newton iteration.
   */
  class ActiveSet
  {
  public:
    /**
     * @brief Replaces the states.
     * @return True if any pair changed state (or the size changed).
     */
    bool
    update(const std::vector<JointState> &new_states);

    const std::vector<JointState> &
    states() const;

    StateCounts
    counts() const;

    /** @brief A hash of the states, for detecting cycling. */
    std::uint64_t
    signature() const;

  private:
    std::vector<JointState> current;
  };

  /** @brief Counts of an arbitrary state list. */
  StateCounts
  count_states(const std::vector<JointState> &states);
} // namespace FloorBlock::Contact
