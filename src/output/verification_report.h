#pragma once

#include <nlohmann/json.hpp>

#include <map>
#include <string>

namespace FloorBlock::Output
{
  /** One computed quantity of a verification case against its closed form. */
  struct CheckedQuantity
  {
    double computed    = 0.; ///< in the quantity's SI unit
    double closed_form = 0.; ///< same unit
    /** |computed - closed_form| over the quantity's scale (see the case). */
    double relative_error = 0.;
    double tolerance      = 0.; ///< on relative_error
    bool   passed         = false;
  };

  /**
   * What a verification case (`floorblock verify <case>`) found: the
   * checked quantities and, for information, figures and counts; names
   * carry the unit where there is one ("contact_cell_size_m").
   */
  struct VerificationResult
  {
    std::map<std::string, CheckedQuantity> checks;
    std::map<std::string, double>          figures;
    std::map<std::string, unsigned int>    counts;

    /** @brief Whether every checked quantity is within its tolerance. */
    bool
    passed() const;
  };

  /**
   * @brief verify.json: {"case", "passed", "quantities"}, the quantities
   * by name (checked ones as {computed, closed_form, relative_error,
   * tolerance, passed}, figures and counts as numbers).
   */
  nlohmann::json
  verification_json(const std::string        &case_name,
                    const VerificationResult &result);

  /** @brief One terminal line per checked quantity, with ok/FAILED. */
  std::string
  verification_lines(const VerificationResult &result);
} // namespace FloorBlock::Output
