#include <contact/active_set.h>

namespace FloorBlock::Contact
{
  namespace
  {
    /** FNV-1a 64-bit offset basis and prime (public-domain constants). */
    constexpr std::uint64_t fnv_offset_basis = 14695981039346656037ULL;
    constexpr std::uint64_t fnv_prime        = 1099511628211ULL;
  } // namespace

  bool
  ActiveSet::update(const std::vector<JointState> &new_states)
  {
    const bool changed = new_states != current;
    current            = new_states;
    return changed;
  }

  const std::vector<JointState> &
  ActiveSet::states() const
  {
    return current;
  }

  StateCounts
  ActiveSet::counts() const
  {
    return count_states(current);
  }

  std::uint64_t
  ActiveSet::signature() const
  {
    std::uint64_t hash = fnv_offset_basis;
    for (const JointState state : current)
      {
        hash ^= static_cast<std::uint64_t>(state);
        hash *= fnv_prime;
      }
    return hash;
  }

  StateCounts
  count_states(const std::vector<JointState> &states)
  {
    StateCounts counts;
    for (const JointState state : states)
      switch (state)
        {
          case JointState::open:
            ++counts.n_open;
            break;
          case JointState::stick:
            ++counts.n_stick;
            break;
          case JointState::slip:
            ++counts.n_slip;
            break;
        }
    return counts;
  }
} // namespace FloorBlock::Contact
