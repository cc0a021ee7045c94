// Randomized robustness test of the closed-form library on its own: hostile
// block chains straight into every public function, bypassing the
// parameter patterns that normally keep inputs in range.

#include <analytic/analytic.h>
#include <common/input_error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>

#include "fuzz_settings.h"
#include "output_checks.h"
#include "random_values.h"

using namespace FloorBlock;
using namespace FloorBlock::Fuzz;

namespace
{
  constexpr std::uint64_t default_seed     = 61;
  constexpr std::uint64_t default_n_inputs = 20000;
  // Longest chain tried; the scene files allow up to 99 blocks.
  constexpr std::size_t longest_chain    = 120;
  constexpr std::size_t n_failures_shown = 10;

  /** A hostile value most of the time, a plausible one otherwise. */
  double
  maybe_hostile(RandomEngine &engine, const double plausible)
  {
    return random_chance(engine, 0.15) ? random_double(engine) : plausible;
  }

  std::vector<double>
  values(RandomEngine &engine, const std::size_t n, const double plausible_max)
  {
    std::vector<double> result;
    for (std::size_t i = 0; i < n; ++i)
      result.push_back(maybe_hostile(
        engine,
        std::uniform_real_distribution<double>(0., plausible_max)(engine)));
    return result;
  }

  /** Mostly well-formed chains near the valid region, some broken ones. */
  Analytic::BlockChain
  random_chain(RandomEngine &engine)
  {
    const auto angle = [&](const double largest) {
      return std::uniform_real_distribution<double>(-largest, largest)(engine);
    };
    std::size_t          n = random_index(engine, longest_chain + 1);
    Analytic::BlockChain chain;
    chain.weight       = values(engine, n, 1e6);
    chain.support_load = values(engine, n, 1e7);
    chain.inclination  = values(engine, n, 0.);
    for (double &alpha : chain.inclination)
      alpha += angle(1.6);
    // Length mismatches must give invalid_input, not out-of-bounds reads.
    if (random_chance(engine, 0.05))
      chain.support_load.resize(random_index(engine, n + 2));
    chain.block_width  = maybe_hostile(engine, 0.01 + angle(5.) * angle(5.));
    chain.block_height = maybe_hostile(engine, 0.01 + angle(5.) * angle(5.));
    chain.bedding_friction  = maybe_hostile(engine, std::abs(angle(1.6)));
    chain.vertical_friction = maybe_hostile(engine, std::abs(angle(1.6)));
    chain.support_load_position =
      maybe_hostile(engine,
                    std::uniform_real_distribution<double>(0., 1.)(engine));
    return chain;
  }

  void
  check_forces(const Analytic::ChainForces &forces,
               const Analytic::BlockChain  &chain,
               const std::string           &name,
               std::vector<std::string>    &defects)
  {
    if (!is_known_status(Analytic::to_string(forces.status)))
      defects.push_back(name + ": unknown status");
    for (const auto &[label, vector] :
         {std::pair{"Q", &forces.lateral_force},
          {"N", &forces.normal_force},
          {"V", &forces.joint_shear},
          {"offset", &forces.normal_force_offset}})
      {
        for (const double value : *vector)
          if (!std::isfinite(value))
            {
              defects.push_back(name + ": non-finite " + label);
              break;
            }
        if (!vector->empty() && vector->size() != chain.n_blocks())
          defects.push_back(name + ": " + label + " has the wrong length");
      }
    if (forces.status == Analytic::Status::ok &&
        forces.lateral_force.size() != chain.n_blocks())
      defects.push_back(name + ": ok but Q is not one value per block");
    if (forces.failing_block > chain.n_blocks())
      defects.push_back(name + ": failing_block beyond the chain");
  }

  void
  check_contact(const Analytic::CornerContact &contact,
                std::vector<std::string>      &defects)
  {
    if (!is_known_status(Analytic::to_string(contact.status)))
      defects.push_back("corner_contact: unknown status");
    for (const double value : {contact.contact_area,
                               contact.contact_length,
                               contact.average_stress,
                               contact.max_stress})
      if (!std::isfinite(value))
        defects.push_back("corner_contact: non-finite output");
  }

  /** Calls a helper that may reject its input only through InputError. */
  void
  expect_finite_or_input_error(const std::function<double()> &helper,
                               const std::string             &name,
                               std::vector<std::string>      &defects)
  {
    try
      {
        if (!std::isfinite(helper()))
          defects.push_back(name + ": non-finite result");
      }
    catch (const InputError &)
      {}
  }

  /**
   * One hostile chain through every public function. With @p helpers false
   * only the mechanisms and centroid heights; with true also corner_contact
   * and the floor-shape helpers, whose overflow on huge finite inputs is a
   * known defect (see HelpersStayFiniteOnHugeInputs).
   */
  std::vector<std::string>
  defects_of_one_input(RandomEngine &engine, const bool helpers)
  {
    std::vector<std::string>    defects;
    const Analytic::BlockChain  chain = random_chain(engine);
    const Analytic::ChainForces slip  = Analytic::slip_no_rotation(chain);
    check_forces(slip, chain, "slip_no_rotation", defects);
    check_forces(Analytic::rotation_no_vertical_slip(chain),
                 chain,
                 "rotation_no_vertical_slip",
                 defects);
    check_forces(Analytic::rotation_vertical_slip(chain),
                 chain,
                 "rotation_vertical_slip",
                 defects);

    // Heights from the mechanism's own Q, or from hostile Q values.
    const auto heights = Analytic::centroid_heights(
      chain,
      random_chance(engine, 0.7) ?
        slip.lateral_force :
        values(engine, random_index(engine, chain.n_blocks() + 2), 1e7));
    if (!is_known_status(Analytic::to_string(heights.status)))
      defects.push_back("centroid_heights: unknown status");
    for (const auto *vector :
         {&heights.centroid_height, &heights.rotation_margin})
      for (const double value : *vector)
        if (!std::isfinite(value))
          defects.push_back("centroid_heights: non-finite output");

    if (!helpers)
      return defects;

    const double face_force = slip.lateral_force.empty() ?
                                random_double(engine) :
                                slip.lateral_force.back() * 1.5;
    check_contact(Analytic::corner_contact(maybe_hostile(engine, face_force),
                                           maybe_hostile(engine, 0.05),
                                           maybe_hostile(engine, 2e10),
                                           maybe_hostile(engine, 1.5),
                                           chain.block_width,
                                           chain.block_height),
                  defects);

    expect_finite_or_input_error(
      [&] {
        double largest = 0.;
        for (const double alpha :
             Analytic::parabolic_inclinations(chain.n_blocks(),
                                              chain.block_width,
                                              maybe_hostile(engine, 400.)))
          largest =
            std::isfinite(alpha) ? std::max(largest, std::abs(alpha)) : alpha;
        return largest;
      },
      "parabolic_inclinations",
      defects);
    expect_finite_or_input_error(
      [&] {
        return Analytic::joint_floor_lift(random_double(engine),
                                          random_double(engine),
                                          chain.block_width);
      },
      "joint_floor_lift",
      defects);
    expect_finite_or_input_error(
      [&] {
        return Analytic::youngs_modulus_from_bulk_shear(random_double(engine),
                                                        random_double(engine));
      },
      "youngs_modulus_from_bulk_shear",
      defects);
    expect_finite_or_input_error(
      [&] {
        return Analytic::poisson_ratio_from_bulk_shear(random_double(engine),
                                                       random_double(engine));
      },
      "poisson_ratio_from_bulk_shear",
      defects);
    return defects;
  }

  /** Runs the randomized loop; returns the number of failing inputs. */
  std::uint64_t
  run_hostile_inputs(const bool helpers)
  {
    const FuzzSettings settings = fuzz_settings(default_seed, default_n_inputs);
    RandomEngine       engine(settings.seed);
    std::uint64_t      n_failures = 0;
    std::map<std::string, std::uint64_t> n_by_defect;
    for (std::uint64_t index = 0; index < settings.n_inputs; ++index)
      {
        std::vector<std::string> defects;
        try
          {
            defects = defects_of_one_input(engine, helpers);
          }
        catch (const std::exception &error)
          {
            defects.push_back(std::string("escaped exception: ") +
                              error.what());
          }
        if (defects.empty())
          continue;
        for (const std::string &defect : defects)
          ++n_by_defect[defect];
        if (++n_failures <= n_failures_shown)
          ADD_FAILURE() << "seed " << settings.seed << " input " << index
                        << ": " << defects.front() << " (and "
                        << defects.size() - 1 << " more)";
      }
    for (const auto &[defect, count] : n_by_defect)
      std::cout << "[fuzz] " << count << " x " << defect << '\n';
    std::cout << "[fuzz] seed " << settings.seed << ": " << settings.n_inputs
              << " analytic inputs tried, " << n_failures << " failures\n";
    return n_failures;
  }
} // namespace

// The closed-form mechanisms shall answer any block chain, however hostile,
// with a known status and finite numbers.
TEST(AnalyticFuzz, HostileChainsGiveStatusAndFiniteNumbers)
{
  EXPECT_EQ(run_hostile_inputs(false), 0u);
}

// corner_contact and the floor-shape helpers shall return finite numbers, a
// status or InputError for any input, also huge finite ones (this found
// youngs_modulus_from_bulk_shear(1e308, 1e308) = NaN,
// corner_contact(1e300, 1e300, 1e300, 1, 1, 1) = inf and
// joint_floor_lift(1.5, 0, 1e308) = inf, now fixed).
TEST(AnalyticFuzz, HelpersStayFiniteOnHugeInputs)
{
  EXPECT_EQ(run_hostile_inputs(true), 0u);
}
