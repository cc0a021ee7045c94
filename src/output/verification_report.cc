#include <output/verification_report.h>

#include <fmt/format.h>

namespace FloorBlock::Output
{
  using nlohmann::json;

  bool
  VerificationResult::passed() const
  {
    for (const auto &[name, check] : checks)
      if (!check.passed)
        return false;
    return true;
  }

  json
  verification_json(const std::string        &case_name,
                    const VerificationResult &result)
  {
    json quantities = json::object();
    for (const auto &[name, check] : result.checks)
      quantities[name] = {{"computed", check.computed},
                          {"closed_form", check.closed_form},
                          {"relative_error", check.relative_error},
                          {"tolerance", check.tolerance},
                          {"passed", check.passed}};
    for (const auto &[name, value] : result.figures)
      quantities[name] = value;
    for (const auto &[name, count] : result.counts)
      quantities[name] = count;
    return {{"case", case_name},
            {"passed", result.passed()},
            {"quantities", quantities}};
  }

  std::string
  verification_lines(const VerificationResult &result)
  {
    std::string text;
    for (const auto &[name, check] : result.checks)
      text +=
        fmt::format("{:<30} computed {:.6e}  closed form {:.6e}  error {:.2e} "
                    "(tolerance {:.0e}) {}\n",
                    name,
                    check.computed,
                    check.closed_form,
                    check.relative_error,
                    check.tolerance,
                    check.passed ? "ok" : "FAILED");
    return text;
  }
} // namespace FloorBlock::Output
