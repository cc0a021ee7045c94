#pragma once

#include <analytic/block_chain.h>

namespace FloorBlock::Analytic
{
  namespace Internal
  {
    /**
     * Denominators (1 - a c, 1 - tan phi_h tan phi_v, (L - H tan phi_h)/L)
     * at or below this dimensionless value count as vanished: closer to
     * zero, Q exceeds 1e12 times the block weight and carries no meaning.
     */
    constexpr double singular_denominator = 1e-12;

    /**
     * @brief A result with empty vectors and @p status, for a closed form
     * that has no finite value.
     * @param[in] block_number Chapter (1-based) number of the block where
     * it fails, or 0 when no single block is to blame (bad input).
     */
    ChainForces
    no_finite_answer(const Status status, const std::size_t block_number);

    /**
     * @brief Admissibility checks shared by all mechanisms: every Q_i >= 0
     * (joints carry no tension) and every N_i >= 0 (bases carry no
     * tension). Sets status and failing_block of @p forces on the first
     * offending block and keeps the values. Leaves a non-ok status alone.
     */
    void
    check_no_tension(ChainForces &forces);

    /** @brief True if every entry of every vector of @p forces is finite. */
    bool
    all_finite(const ChainForces &forces);
  } // namespace Internal
} // namespace FloorBlock::Analytic
