#include <fmt/format.h>
#include <studies/corner_analysis.h>

#include <cmath>

namespace FloorBlock::Studies
{
  namespace
  {
    double
    relative_change(const double now, const double before)
    {
      return before != 0. ? std::abs(now / before - 1.) : 1.;
    }

    /** The fit range of @p fine against the level before. */
    Corner::DistanceRange
    fit_range(const Corner::CornerProfile &fine,
              const Corner::CornerProfile &coarse,
              const double                 tolerance)
    {
      return Corner::converged_range(fine.samples,
                                     coarse.samples,
                                     tolerance,
                                     fit_from_spacings * fine.edge_spacing,
                                     fit_to_peak_fraction * fine.peak_distance);
    }

    /**
     * The length l from the contact's end over which the mean traction
     * equals @p target: trapezoid integral of the samples, the traction
     * taken as 0 at the end itself (zones that end between nodes).
     */
    double
    averaging_length_for(const std::vector<Analytic::RadialSample> &samples,
                         const double                               target)
    {
      double integral = 0., d_before = 0., t_before = 0., best = 0.;
      for (const auto &sample : samples)
        {
          integral +=
            0.5 * (t_before + sample.traction) * (sample.distance - d_before);
          d_before          = sample.distance;
          t_before          = sample.traction;
          const double mean = integral / sample.distance;
          // The mean rises to its largest near the peak and then falls:
          // the length wanted is where it falls through the target.
          if (mean >= target)
            best = sample.distance;
        }
      return best;
    }

    /** The rock and joint of @p scene as the corner theory needs them. */
    Corner::CornerMaterials
    corner_materials(const Parameters::ScenarioParameters &scene)
    {
      Corner::CornerMaterials materials;
      materials.rock = {scene.material.shear_modulus,
                        scene.material.poissons_ratio()};
      materials.friction_coefficient =
        std::tan(scene.joints.vertical_friction_angle);
      materials.exact_contact =
        scene.joints.law == Contact::JointLawKind::rigid;
      materials.compliant_length =
        scene.material.youngs_modulus() / scene.joints.normal_stiffness;
      return materials;
    }

    /**
     * K1, its change and the fitted exponent of the newest level against
     * the one before, over the newest level's converged range; the span of
     * that range (to / from), 0 if it has no samples.
     */
    double
    fit_newest_level(const double tolerance, CornerAnalysis &analysis)
    {
      const std::size_t           level  = analysis.levels.size() - 1;
      const ZoomLevel            &record = analysis.levels[level];
      const Corner::DistanceRange range =
        fit_range(record.profile,
                  analysis.levels[level - 1].profile,
                  tolerance);
      if (range.n_samples == 0)
        return 0.;
      const auto now = Corner::theory_intensities(
        Corner::samples_within(record.profile.samples, range), analysis.theory);
      const auto before = Corner::theory_intensities(
        Corner::samples_within(analysis.levels[level - 1].profile.samples,
                               range),
        analysis.theory);
      LevelFigures &figures    = analysis.figures.back();
      figures.intensity        = now;
      figures.intensity_change = relative_change(now.first, before.first);
      figures.exponent =
        Corner::fit_corner(record.profile.samples, range, analysis.theory)
          .expansion.lambda1;
      return range.to / range.from;
    }

    /** The fit and the invariant's fit on the last two levels, and the
     * averaging length that matches the closed form's peak. */
    void
    fit_last_levels(const double tolerance, CornerAnalysis &analysis)
    {
      const std::size_t n = analysis.levels.size();
      if (n >= 2 && analysis.theory.covered)
        {
          const ZoomLevel &last   = analysis.levels[n - 1];
          const ZoomLevel &before = analysis.levels[n - 2];
          analysis.fit            = Corner::fit_corner(last.profile.samples,
                                            fit_range(last.profile,
                                                      before.profile,
                                                      tolerance),
                                            analysis.theory);
          // The invariant over its own converged range.
          analysis.invariant_range = Corner::converged_range(
            last.invariant_samples,
            before.invariant_samples,
            tolerance,
            fit_from_spacings * last.profile.edge_spacing,
            invariant_to_peak_fraction * last.profile.peak_distance);
          analysis.invariant_fit =
            Corner::fit_invariant(last.invariant_samples,
                                  analysis.invariant_range,
                                  analysis.theory);
        }
      if (n >= 1)
        {
          analysis.closed_form_peak = analysis.levels.back().closed_form_peak;
          analysis.matching_averaging_length =
            averaging_length_for(analysis.levels.back().profile.samples,
                                 analysis.closed_form_peak);
        }
    }

    /** Why no further zoom level is solved, or "" if one is. */
    std::string
    reason_not_to_zoom(const unsigned int             level,
                       const CornerZoom              &zoom,
                       const CornerAnalysis          &analysis,
                       const std::function<double()> &seconds_left)
    {
      if (level > 0 && !zoom.can_refine())
        return "the smallest zoom cell (3e-7 of the block side) is reached";
      if (level > 0 && !analysis.levels.empty() &&
          seconds_left() < 2. * analysis.levels.back().wall_time)
        return "time budget (Corner/Time budget) spent";
      return "";
    }

    /** The progress line of zoom level @p level, with the change of K1
     * the convergence test used (1 where there is no fit, 0 on level 0). */
    std::string
    level_line(const unsigned int    level,
               const double          intensity_change,
               const CornerAnalysis &analysis)
    {
      const ZoomLevel    &record  = analysis.levels[level];
      const LevelFigures &figures = analysis.figures[level];
      return fmt::format(
        "level {:2d}: {:6d} DoFs, cells {:.2e} m, {}, peak {:.4e} Pa "
        "(change {:.2e}), K1 change {:.2e}, exponent {:.4f}, {:.1f} s",
        level,
        record.n_dofs,
        record.requested_size,
        Corner::to_string(record.profile.kind),
        record.profile.peak_traction,
        figures.peak_change,
        level > 0 ? intensity_change : 0.,
        figures.exponent,
        record.wall_time);
    }
  } // namespace

  CornerAnalysis
  analyse_corner(const Parameters::ScenarioParameters &scene,
                 const Output::ResultFolder           &folder,
                 const std::function<double()>        &seconds_left,
                 const Progress                       &progress)
  {
    CornerAnalysis analysis;
    analysis.site      = Corner::floor_corner_site(scene, scene.corner.joint);
    analysis.materials = corner_materials(scene);
    const double tolerance   = scene.corner.converged_change;
    const double k_tolerance = scene.corner.intensity_change;

    CornerZoom zoom(scene, analysis.site);
    for (unsigned int level = 0; level <= scene.corner.max_zoom_levels; ++level)
      {
        analysis.stop_reason =
          reason_not_to_zoom(level, zoom, analysis, seconds_left);
        if (!analysis.stop_reason.empty())
          break;
        const auto record = zoom.next(Output::ResultFolder(
          folder.path_of("level_" + std::to_string(level))));
        if (!record)
          {
            analysis.stop_reason = fmt::format(
              "the solve of zoom level {} did not converge (see its fem.json)",
              level);
            break;
          }
        analysis.levels.push_back(*record);
        LevelFigures figures;
        if (level > 0)
          figures.peak_change = peak_change(analysis.levels, level);
        analysis.figures.push_back(figures);

        analysis.theory = Corner::corner_theory(record->profile,
                                                analysis.materials,
                                                analysis.site.rounding_radius);
        double fit_span = 0.;
        if (level > 0 && analysis.theory.covered)
          fit_span = fit_newest_level(tolerance, analysis);
        const double intensity_change =
          level > 0 && fit_span > 0. ?
            analysis.figures.back().intensity_change :
            1.;
        progress(level_line(level, intensity_change, analysis));
        // Without a theory there is no K1: the peak alone decides.
        const double exponent_change =
          level > 1 && analysis.figures[level - 1].exponent > 0. ?
            std::abs(analysis.figures[level].exponent -
                     analysis.figures[level - 1].exponent) :
            1.;
        if (peak_settled(analysis.levels, tolerance) &&
            (!analysis.theory.covered ||
             (intensity_change <= k_tolerance &&
              fit_span >= smallest_fit_span &&
              exponent_change <= converged_exponent_change)))
          {
            analysis.converged = true;
            analysis.stop_reason =
              analysis.theory.covered ?
                fmt::format("the peak changed by at most {} twice in a row, "
                            "K1 by at most {} and the fitted exponent by at "
                            "most {}, over a fit range of a decade",
                            tolerance,
                            k_tolerance,
                            converged_exponent_change) :
                fmt::format("the peak changed by at most {} twice in a row",
                            tolerance);
            break;
          }
      }
    if (analysis.stop_reason.empty())
      analysis.stop_reason = "zoom levels (Corner/Zoom levels) used up";
    fit_last_levels(tolerance, analysis);
    return analysis;
  }
} // namespace FloorBlock::Studies
