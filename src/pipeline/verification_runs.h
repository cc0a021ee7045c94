#pragma once

#include <output/verification_report.h>
#include <parameters/scenario_parameters.h>

#include <map>
#include <string>
#include <vector>

namespace FloorBlock::Pipeline
{
  /** A verification case: the parameters it starts from, and its run. */
  struct VerificationCase
  {
    /** "Subsection/Entry=value" applied before the user's --set. */
    std::vector<std::string> base_overrides;
    /** Runs the case on the scene and checks it against its closed form. */
    Output::VerificationResult (*run)(
      const Parameters::ScenarioParameters &scene);
  };

  /**
   * @brief The cases of `floorblock verify` by name: "hertz", "patch"
   * (exact contact: rigid law, or stiff springs for the compliant law),
   * "incline" and "two-blocks" (the chapter's compliant joints).
   */
  const std::map<std::string, VerificationCase> &
  verification_cases();
} // namespace FloorBlock::Pipeline
