#include <output/gnuplot.h>

#include <fmt/format.h>
#include <studies/corner_report.h>

#include <cmath>

namespace FloorBlock::Studies
{
  using nlohmann::json;

  namespace
  {
    /** JSON number, or null for a value that is not finite. */
    json
    number(const double value)
    {
      return std::isfinite(value) ? json(value) : json(nullptr);
    }

    double
    two_term_value(const Analytic::AsymptoticFit &fit, const double d)
    {
      return fit.k1 * std::pow(d, fit.lambda1 - 1.) +
             fit.k2 * std::pow(d, fit.lambda2 - 1.);
    }

    json
    modes_json(const Corner::CornerTheory &theory)
    {
      json modes = json::array();
      for (const auto &mode : theory.modes)
        modes.push_back({{"exponent_real", mode.exponent.real()},
                         {"exponent_imag", mode.exponent.imag()},
                         {"symmetry", Analytic::to_string(mode.symmetry)}});
      return modes;
    }

    /** Every zoom level's figures. */
    json
    levels_json(const CornerAnalysis &analysis)
    {
      json levels = json::array();
      for (std::size_t k = 0; k < analysis.levels.size(); ++k)
        {
          const ZoomLevel    &level   = analysis.levels[k];
          const LevelFigures &figures = analysis.figures[k];
          levels.push_back(
            {{"level", level.level},
             {"n_dofs", level.n_dofs},
             {"cell_size_m", level.requested_size},
             {"wall_time_s", level.wall_time},
             {"contact_kind", Corner::to_string(level.profile.kind)},
             {"edge_beyond_corner_m", level.profile.edge_beyond_corner},
             {"edge_node_spacing_m", level.profile.edge_spacing},
             {"edge_state", Contact::state_name(level.profile.edge_state)},
             {"sigma_max_Pa", level.profile.peak_traction},
             {"peak_distance_from_edge_m", level.profile.peak_distance},
             {"sigma_max_change", figures.peak_change},
             {"K1", figures.intensity.first},
             {"K1_change", figures.intensity_change},
             {"exponent", figures.exponent},
             {"averaged_peak_Pa", level.averaged_peak_stress},
             {"contact_length_m", level.closed_length},
             {"Q_N_per_m", level.normal_force}});
        }
      return levels;
    }

    json
    rounding_study_json(const RoundingStudy &rounding)
    {
      json study = json::array();
      for (const auto &point : rounding.points)
        study.push_back({{"radius_m", point.radius},
                         {"sigma_max_Pa", point.peak},
                         {"averaged_peak_Pa", point.averaged_peak},
                         {"contact_length_m", point.contact_length},
                         {"edge_beyond_corner_m", point.edge_beyond_corner},
                         {"sigma_max_last_change", point.last_change},
                         {"converged", point.converged},
                         {"levels", point.n_levels},
                         {"n_dofs", point.n_dofs},
                         {"cell_size_m", point.smallest_size},
                         {"wall_time_s", point.wall_time}});
      return study;
    }

    json
    theory_json(const Corner::CornerTheory &theory)
    {
      return {{"configuration", theory.configuration},
              {"covered", theory.covered},
              {"why_not", theory.why_not},
              {"wedge_angles_rad",
               {theory.pair.first_angle, theory.pair.second_angle}},
              {"interface_state", Corner::to_string(theory.pair.state)},
              {"friction_coefficient", theory.pair.friction_coefficient},
              {"modes", modes_json(theory)},
              {"exponent", theory.exponent},
              {"next_exponent", theory.next_exponent},
              {"traction_exponent", theory.exponent - 1.}};
    }

    /** The fits of the last level over their range. */
    json
    fit_json(const Parameters::ScenarioParameters &scene,
             const CornerAnalysis                 &analysis)
    {
      const Corner::CornerFit    &fit    = analysis.fit;
      const Corner::CornerTheory &theory = analysis.theory;
      return {
        {"range_from_m", fit.range.from},
        {"range_to_m", fit.range.to},
        {"range_rule",
         fmt::format("the traction of the last level within {} of the level "
                     "before, from {} node spacings at the contact's end to "
                     "{} of the peak's distance from it",
                     scene.corner.converged_change,
                     fit_from_spacings,
                     fit_to_peak_fraction)},
        {"n_samples", fit.expansion.n_samples},
        {"terms", theory.third_exponent > theory.next_exponent ? 3 : 2},
        {"exponent", fit.expansion.lambda1},
        {"exponent_difference", fit.expansion.lambda1 - theory.exponent},
        {"expansion_K1", fit.expansion.k1},
        {"expansion_rms_relative_residual",
         fit.expansion.rms_relative_residual},
        {"exponent_two_term", fit.two_terms.lambda1},
        {"exponent_one_term", fit.one_term.lambda1},
        {"two_term_K1", fit.two_terms.k1},
        {"two_term_K2", fit.two_terms.k2},
        {"two_term_rms_relative_residual", fit.two_terms.rms_relative_residual},
        {"K1_theory_exponents", fit.intensity.first},
        {"K2_theory_exponents", fit.intensity.second},
        {"K_units", fmt::format("Pa m^{:.4g}", 1. - theory.exponent)},
        {"one_term_validity_m", number(fit.validity_distance)}};
    }

    json
    invariant_fit_json(const CornerAnalysis &analysis)
    {
      const Corner::CornerTheory &theory = analysis.theory;
      return {{"invariant",
               "mean pressure -(sigma_xx + sigma_yy + sigma_zz) / 3 at "
               "the joint side's nodes"},
              {"range_from_m", analysis.invariant_range.from},
              {"range_to_m", analysis.invariant_range.to},
              {"n_samples", analysis.invariant_fit.n_samples},
              {"exponent", analysis.invariant_fit.lambda1},
              {"exponent_difference",
               analysis.invariant_fit.n_samples > 0 ?
                 analysis.invariant_fit.lambda1 - theory.exponent :
                 0.},
              {"rms_relative_residual",
               number(analysis.invariant_fit.rms_relative_residual)}};
    }
  } // namespace

  double
  sharp_corner_exponent(const CornerAnalysis &analysis)
  {
    if (analysis.levels.empty())
      return 0.;
    Corner::CornerProfile sharp = analysis.levels.back().profile;
    sharp.kind                  = Corner::CornerContactKind::reaches_corner;
    const Corner::CornerTheory theory =
      Corner::corner_theory(sharp, analysis.materials, 0.);
    return theory.covered ? theory.exponent : 0.;
  }

  double
  predicted_rounding_power(const double sharp_exponent)
  {
    return sharp_exponent < 1. ? sharp_exponent - 1. : 0.;
  }

  json
  corner_json(const Parameters::ScenarioParameters &scene,
              const CornerAnalysis                 &analysis,
              const RoundingStudy                  &rounding)
  {
    const Corner::CornerTheory &theory = analysis.theory;
    const double                kn     = scene.joints.normal_stiffness;
    const double     sharp_exponent    = sharp_corner_exponent(analysis);
    const ZoomLevel *last =
      analysis.levels.empty() ? nullptr : &analysis.levels.back();
    return {
      {"scene", scene.scene_name},
      {"joint", analysis.site.joint_name},
      {"joint_law",
       scene.joints.law == Contact::JointLawKind::rigid ? "rigid" :
                                                          "compliant"},
      {"site",
       {{"corner_x_m", analysis.site.corner.x},
        {"corner_y_m", analysis.site.corner.y},
        {"rounding_radius_m", analysis.site.rounding_radius}}},
      {"state",
       {{"contact_kind", last ? Corner::to_string(last->profile.kind) : ""},
        {"edge_beyond_corner_m", last ? last->profile.edge_beyond_corner : 0.},
        {"edge_state",
         last ? Contact::state_name(last->profile.edge_state) : ""},
        {"edge_shear_over_normal",
         last ? last->profile.edge_traction_ratio : 0.},
        {"relative_rotation_rad", last ? last->relative_rotation : 0.}}},
      {"theory", theory_json(theory)},
      {"fit", fit_json(scene, analysis)},
      {"invariant_fit", invariant_fit_json(analysis)},
      {"converged", analysis.converged},
      {"stop_reason", analysis.stop_reason},
      {"levels", levels_json(analysis)},
      {"closed_form",
       {{"sigma_max_Pa", analysis.closed_form_peak},
        {"contact_length_m", last ? last->closed_form_contact_length : 0.},
        {"field_sigma_max_Pa", last ? last->profile.peak_traction : 0.},
        {"matching_averaging_length_m",
         analysis.matching_averaging_length > 0. ?
           json(analysis.matching_averaging_length) :
           json(nullptr)}}},
      {"compliant_length_E_over_kn_m",
       kn > 0. ? scene.material.youngs_modulus() / kn : 0.},
      {"rounding_study", rounding_study_json(rounding)},
      {"rounding_power_fitted", rounding.fitted_power},
      {"sharp_corner_exponent", sharp_exponent},
      {"rounding_power_predicted", predicted_rounding_power(sharp_exponent)},
      {"sigma_max_falls_with_radius", rounding.falls_with_radius}};
  }

  namespace
  {
    /** corner_traction.csv and corner_traction.png: the last level's
     * traction, the fitted nodes and the fits. */
    void
    write_traction(const Output::ResultFolder &folder,
                   const CornerAnalysis       &analysis)
    {
      const Corner::CornerFit &fit = analysis.fit;
      std::string              traction =
        "distance_from_edge_m,normal_traction_Pa,fitted,two_term_fit_Pa,"
        "leading_term_Pa\n";
      const Analytic::AsymptoticFit &leading = fit.expansion;
      std::string                    fitted_points, other_points, fit_line;
      if (!analysis.levels.empty())
        for (const auto &sample : analysis.levels.back().profile.samples)
          {
            const bool inside = sample.distance >= fit.range.from &&
                                sample.distance <= fit.range.to;
            const double two = two_term_value(fit.two_terms, sample.distance);
            const double lead =
              leading.k1 * std::pow(sample.distance, leading.lambda1 - 1.);
            traction += fmt::format("{:.9e},{:.9e},{},{:.9e},{:.9e}\n",
                                    sample.distance,
                                    sample.traction,
                                    inside ? 1 : 0,
                                    two,
                                    lead);
            (inside ? fitted_points : other_points) +=
              fmt::format("{:.6e} {:.6e}\n", sample.distance, sample.traction);
            if (inside)
              fit_line += fmt::format("{:.6e} {:.6e} {:.6e}\n",
                                      sample.distance,
                                      two,
                                      lead);
          }
      folder.write("corner_traction.csv", traction);
      if (!fitted_points.empty() || !other_points.empty())
        Output::render_png(
          fmt::format(
            "set logscale xy\nset grid\nset key top left\n"
            "set format x '%.0e'\nset format y '%.0e'\n"
            "set title 'Corner traction ({}): fit {:.2g}-{:.2g} m, lambda "
            "{:.4f}, theory {:.4f}'\n"
            "set xlabel 'distance from the contact end (m)'\n"
            "set ylabel 'normal traction (Pa)'\n"
            "plot '-' with points pt 7 ps 0.4 lc rgb 'gray' title 'FEM nodes', "
            "'-' with points pt 7 ps 0.6 lc rgb 'blue' title 'fitted nodes', "
            "'-' using 1:2 with lines lw 2 lc rgb 'red' title 'two-term fit', "
            "'-' using 1:3 with lines dt 2 lw 2 lc rgb 'black' title "
            "'leading term of the expansion fit'\n"
            "{}e\n{}e\n{}e\n{}e\n",
            Corner::to_string(analysis.levels.back().profile.kind),
            fit.range.from,
            fit.range.to,
            fit.expansion.lambda1,
            analysis.theory.exponent,
            other_points.empty() ? "NaN NaN\n" : other_points,
            fitted_points.empty() ? "NaN NaN\n" : fitted_points,
            fit_line.empty() ? "NaN NaN NaN\n" : fit_line,
            fit_line.empty() ? "NaN NaN NaN\n" : fit_line),
          folder.path_of("corner_traction.png"));
    }

    /** corner_mean_pressure.csv: the invariant along the joint side. */
    void
    write_mean_pressure(const Output::ResultFolder &folder,
                        const CornerAnalysis       &analysis)
    {
      std::string pressure = "distance_from_edge_m,mean_pressure_Pa,fitted\n";
      if (!analysis.levels.empty())
        for (const auto &sample : analysis.levels.back().invariant_samples)
          pressure +=
            fmt::format("{:.9e},{:.9e},{}\n",
                        sample.distance,
                        sample.traction,
                        sample.distance >= analysis.invariant_range.from &&
                            sample.distance <= analysis.invariant_range.to ?
                          1 :
                          0);
      folder.write("corner_mean_pressure.csv", pressure);
    }

    /** corner_levels.csv: every zoom level's figures. */
    void
    write_level_table(const Output::ResultFolder &folder,
                      const CornerAnalysis       &analysis)
    {
      std::string level_table =
        "level,n_dofs,cell_size_m,sigma_max_Pa,sigma_max_change,K1,K1_change,"
        "edge_beyond_corner_m,contact_length_m,Q_N_per_m,wall_time_s\n";
      for (std::size_t k = 0; k < analysis.levels.size(); ++k)
        {
          const auto &level   = analysis.levels[k];
          const auto &figures = analysis.figures[k];
          level_table += fmt::format(
            "{},{},{:.6e},{:.9e},{:.3e},{:.9e},{:.3e},{:.9e},{:.9e},{:.9e},{:.2f}\n",
            level.level,
            level.n_dofs,
            level.requested_size,
            level.profile.peak_traction,
            figures.peak_change,
            figures.intensity.first,
            figures.intensity_change,
            level.profile.edge_beyond_corner,
            level.closed_length,
            level.normal_force,
            level.wall_time);
        }
      folder.write("corner_levels.csv", level_table);
    }

    /** rounding_study.csv and rounding_study.png. */
    void
    write_rounding_study(const Output::ResultFolder &folder,
                         const CornerAnalysis       &analysis,
                         const RoundingStudy        &rounding)
    {
      std::string study =
        "radius_m,sigma_max_Pa,averaged_peak_Pa,contact_length_m,"
        "edge_beyond_corner_m,sigma_max_last_change,converged,levels,n_dofs,"
        "cell_size_m,wall_time_s\n";
      std::string study_points;
      for (const auto &point : rounding.points)
        {
          study += fmt::format(
            "{:.6e},{:.9e},{:.9e},{:.9e},{:.9e},{:.3e},{},{},{},{:.3e},{:.1f}\n",
            point.radius,
            point.peak,
            point.averaged_peak,
            point.contact_length,
            point.edge_beyond_corner,
            point.last_change,
            point.converged ? 1 : 0,
            point.n_levels,
            point.n_dofs,
            point.smallest_size,
            point.wall_time);
          study_points += fmt::format("{:.6e} {:.6e}\n",
                                      point.radius * 1e3,
                                      point.peak / 1e6);
        }
      folder.write("rounding_study.csv", study);
      if (!study_points.empty())
        Output::render_png(
          fmt::format("set logscale xy\nset grid\nset key top right\n"
                      "set title 'Peak corner traction against the rounding "
                      "radius (fitted power {:.3f}, predicted {:.3f})'\n"
                      "set xlabel 'corner rounding radius (mm)'\n"
                      "set ylabel 'sigma_max (MPa)'\n"
                      "plot '-' with linespoints pt 7 lw 2 title 'FEM, zoomed "
                      "to convergence'\n{}e\n",
                      rounding.fitted_power,
                      predicted_rounding_power(sharp_corner_exponent(analysis)),
                      study_points),
          folder.path_of("rounding_study.png"));
    }
  } // namespace

  void
  write_corner_tables_and_plots(const Output::ResultFolder &folder,
                                const CornerAnalysis       &analysis,
                                const RoundingStudy        &rounding)
  {
    write_traction(folder, analysis);
    write_mean_pressure(folder, analysis);
    write_level_table(folder, analysis);
    write_rounding_study(folder, analysis, rounding);
  }

  void
  write_corner_report(const Output::ResultFolder           &folder,
                      const Parameters::ScenarioParameters &scene,
                      const CornerAnalysis                 &analysis,
                      const RoundingStudy                  &rounding,
                      const double                          wall_time)
  {
    json report           = corner_json(scene, analysis, rounding);
    report["wall_time_s"] = wall_time;
    folder.write_json("corner.json", report);
    write_corner_tables_and_plots(folder, analysis, rounding);
    folder.write_summary({{"command", "corner"},
                          {"converged", analysis.converged},
                          {"wall_time_s", wall_time}});
  }

  std::string
  corner_summary_lines(const CornerAnalysis &analysis,
                       const RoundingStudy  &rounding)
  {
    std::string text;
    if (analysis.levels.empty())
      return "no level solved: " + analysis.stop_reason + "\n";
    const ZoomLevel &last = analysis.levels.back();
    text += fmt::format("corner of {}: {} ({} at the end), {}\n",
                        analysis.site.joint_name,
                        Corner::to_string(last.profile.kind),
                        Contact::state_name(last.profile.edge_state),
                        analysis.theory.configuration);
    text += fmt::format("zoom: {} levels, {} ({})\n",
                        analysis.levels.size(),
                        analysis.converged ? "converged" : "NOT converged",
                        analysis.stop_reason);
    text += fmt::format("peak traction {:.4e} Pa, {:.3e} m from the contact "
                        "end; Eq. 6.53 sigma_max {:.4e} Pa; {}\n",
                        last.profile.peak_traction,
                        last.profile.peak_distance,
                        analysis.closed_form_peak,
                        analysis.matching_averaging_length > 0. ?
                          fmt::format("the field's mean over {:.3e} m from "
                                      "the end equals it",
                                      analysis.matching_averaging_length) :
                          std::string("no averaging length makes the field's "
                                      "mean equal it"));
    if (analysis.theory.covered)
      text += fmt::format(
        "exponent: theory {:.4f} ({}), fitted {:.4f} (expansion), {:.4f} "
        "(two terms), {:.4f} (one term) over {:.3e}-{:.3e} m; K1 {:.4e} Pa "
        "m^{:.3g} (last change {:.2e})\n",
        analysis.theory.exponent,
        Corner::to_string(analysis.theory.pair.state),
        analysis.fit.expansion.lambda1,
        analysis.fit.two_terms.lambda1,
        analysis.fit.one_term.lambda1,
        analysis.fit.range.from,
        analysis.fit.range.to,
        analysis.fit.intensity.first,
        1. - analysis.theory.exponent,
        analysis.figures.back().intensity_change);
    if (analysis.theory.covered && analysis.invariant_fit.n_samples > 0)
      text += fmt::format("mean pressure: fitted exponent {:.4f} over "
                          "{:.3e}-{:.3e} m\n",
                          analysis.invariant_fit.lambda1,
                          analysis.invariant_range.from,
                          analysis.invariant_range.to);
    else
      text += "theory: " + analysis.theory.why_not + "\n";
    for (const auto &point : rounding.points)
      text += fmt::format("rounding {:.4g} m: sigma_max {:.4e} Pa ({}, last "
                          "change {:.2e}, {} levels)\n",
                          point.radius,
                          point.peak,
                          point.converged ? "converged" : "NOT converged",
                          point.last_change,
                          point.n_levels);
    if (!rounding.points.empty())
      text +=
        fmt::format("rounding: fitted power {:.3f}; sigma_max {} with "
                    "the radius\n",
                    rounding.fitted_power,
                    rounding.falls_with_radius ? "falls" : "does NOT fall");
    return text;
  }
} // namespace FloorBlock::Studies
