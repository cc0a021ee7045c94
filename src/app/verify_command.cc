#include <app/command_options.h>
#include <common/input_error.h>
#include <output/result_folder.h>
#include <output/verification_report.h>
#include <pipeline/verification_runs.h>

#include <iostream>

namespace FloorBlock::App
{
  int
  verify_command(const CommandOptions &options)
  {
    const auto &cases = Pipeline::verification_cases();
    const auto  found = cases.find(options.verification_case);
    if (found == cases.end())
      throw InputError(
        "verify: unknown case '" + options.verification_case +
        "'; available: hertz, patch, punch, incline, two-blocks");
    std::vector<std::string> overrides = found->second.base_overrides;
    overrides.insert(overrides.end(),
                     options.overrides.begin(),
                     options.overrides.end());
    const auto scene =
      Parameters::read_defaults("verify_" + options.verification_case,
                                overrides);

    const Output::VerificationResult result = found->second.run(scene);
    std::cout << Output::verification_lines(result);
    const Output::ResultFolder folder(output_directory(options, scene));
    folder.write_inputs(scene);
    folder.write_json("verify.json",
                      Output::verification_json(options.verification_case,
                                                result));
    std::cout << "wrote " << folder.path_of("verify.json") << std::endl;
    return result.passed() ? exit_code::success : exit_code::failure;
  }
} // namespace FloorBlock::App
