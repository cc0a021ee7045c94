#pragma once

#include <analytic/block_chain.h>

#include <cmath>
#include <vector>

namespace FloorBlock::AnalyticTest
{
  /** Degrees to radians, for readable test inputs. */
  inline double
  degrees(const double angle_in_degrees)
  {
    return angle_in_degrees * M_PI / 180.;
  }

  /**
   * A deliberately irregular chain: unequal weights and support loads,
   * inclinations that vary from block to block (curved bedding), L != H.
   */
  inline Analytic::BlockChain
  irregular_chain()
  {
    Analytic::BlockChain chain;
    chain.weight       = {41.e3, 55.e3, 47.e3, 60.e3, 52.e3};
    chain.support_load = {300.e3, 0., 150.e3, 0., 80.e3};
    chain.inclination  = {
       degrees(9.), degrees(7.5), degrees(5.), degrees(3.), degrees(1.)};
    chain.block_width           = 1.2;
    chain.block_height          = 2.;
    chain.bedding_friction      = degrees(12.);
    chain.vertical_friction     = degrees(30.);
    chain.support_load_position = 0.3;
    return chain;
  }

  /** Relative difference, safe for a zero reference. */
  inline double
  relative_difference(const double value, const double reference)
  {
    const double scale = std::max(std::abs(reference), 1e-300);
    return std::abs(value - reference) / scale;
  }

  /** Relative agreement tolerance for a closed form against an LU solve of
   * a well-conditioned system of 10-20 equations in double precision. */
  constexpr double solve_tolerance = 1e-12;
} // namespace FloorBlock::AnalyticTest
