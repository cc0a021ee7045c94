#include <rigid/results.h>

namespace FloorBlock::RigidBlocks
{
  std::string
  to_string(const SolveStatus status)
  {
    switch (status)
      {
        case SolveStatus::converged:
          return "converged";
        case SolveStatus::floating_block:
          return "floating_block";
        case SolveStatus::no_equilibrium:
          return "no_equilibrium";
        case SolveStatus::not_converged:
          return "not_converged";
      }
    return "unknown";
  }
} // namespace FloorBlock::RigidBlocks
