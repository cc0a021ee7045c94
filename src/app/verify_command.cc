#include <app/command_options.h>
#include <common/input_error.h>
#include <contact/hertz_verification.h>
#include <output/result_folder.h>

#include <fmt/format.h>

#include <cmath>
#include <iostream>

namespace FloorBlock::App
{
  using nlohmann::json;

  namespace
  {
    // Tolerances of the Hertz check: the half-width is resolved to
    // one contact cell, the peak pressure is a nodal value of a smooth field.
    constexpr double half_width_tolerance    = 0.02;
    constexpr double peak_pressure_tolerance = 0.05;

    /**
     * A verification case starts from exact contact (rigid law; stiff
     * springs if the user asks for the compliant law), then the user's
     * --set overrides apply on top.
     */
    const std::vector<std::string> verification_base = {
      "Joints/Law=rigid", "Joints/Normal stiffness=1e14",
      "Joints/Shear stiffness=1e14"};

    json
    quantity(const double computed, const double closed_form,
             const double tolerance)
    {
      const double error = std::abs(computed / closed_form - 1.);
      return {{"computed", computed},
              {"closed_form", closed_form},
              {"relative_error", error},
              {"tolerance", tolerance},
              {"passed", error <= tolerance}};
    }

    json
    verify_hertz(const Parameters::ScenarioParameters &scene)
    {
      Contact::HertzSettings settings;
      settings.radius         = scene.verify.hertz_radius;
      settings.line_load      = scene.verify.hertz_line_load;
      settings.youngs_modulus = scene.verify.hertz_youngs_modulus;
      settings.poissons_ratio = scene.verify.hertz_poissons_ratio;
      settings.mesh_level     = scene.verify.hertz_mesh_level;
      settings.law = scene.joints.law == Parameters::JointLaw::rigid ?
                       Contact::JointLawKind::rigid :
                       Contact::JointLawKind::compliant;
      settings.compliant_stiffness = scene.joints.normal_stiffness;
      settings.fe_degree           = scene.solver.fe_degree;

      const Contact::HertzResult result = Contact::run_hertz_verification(settings);
      return {{"contact_half_width",
               quantity(result.half_width_computed, result.half_width_exact,
                        half_width_tolerance)},
              {"peak_pressure",
               quantity(result.peak_pressure_computed,
                        result.peak_pressure_exact, peak_pressure_tolerance)},
              {"n_dofs", result.n_dofs},
              {"contact_cell_size_m", result.contact_cell_size}};
    }
  } // namespace

  int
  verify_command(const CommandOptions &options)
  {
    if (options.verification_case != "hertz")
      throw InputError("verify: unknown case '" + options.verification_case +
                       "'; available: hertz");
    std::vector<std::string> overrides = verification_base;
    overrides.insert(overrides.end(), options.overrides.begin(),
                     options.overrides.end());
    const auto scene = Parameters::read_defaults("verify_hertz", overrides);

    json quantities = verify_hertz(scene);
    bool passed     = true;
    for (const char *name : {"contact_half_width", "peak_pressure"})
      {
        const auto &q = quantities[name];
        passed        = passed && q["passed"].get<bool>();
        std::cout << fmt::format(
          "{:<20} computed {:.6e}  closed form {:.6e}  error {:.2f} % "
          "(tolerance {:.0f} %) {}\n",
          name, q["computed"].get<double>(), q["closed_form"].get<double>(),
          100 * q["relative_error"].get<double>(),
          100 * q["tolerance"].get<double>(),
          q["passed"].get<bool>() ? "ok" : "FAILED");
      }
    const Output::ResultFolder folder(output_directory(options, scene));
    folder.write_inputs(scene);
    folder.write_json("verify.json", {{"case", options.verification_case},
                                      {"passed", passed},
                                      {"quantities", quantities}});
    std::cout << "wrote " << folder.path_of("verify.json") << std::endl;
    return passed ? exit_code::success : exit_code::failure;
  }
} // namespace FloorBlock::App
