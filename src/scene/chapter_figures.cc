#include <common/units.h>
#include <scene/chapter_figures.h>

#include <fmt/format.h>

#include <cmath>

namespace FloorBlock::Scene
{
  namespace
  {
    // The chapter's grids (section 6.6 and 6.7), in the chapter's units.
    const std::vector<double> bedding_friction_degrees{10, 15, 20, 25, 30, 35};
    const std::vector<double> vertical_friction_degrees{15, 25, 35, 45};
    const std::vector<double> support_load_tonnes{400, 500, 600, 700, 800, 900};
    const std::vector<double> stress_figure_curvatures{400, 200, 100, 50};

    /**
     * A scene whose flat bedding is lifted into its floor profile (the
     * default reading) must be lifted into each figure's floor: u_y = x^2/k
     * for the parabolic figures, the planar slope for Figure 6.5, reaching
     * the profile's height at the free end x = nL. Without this every FEM
     * point would be lifted into the scene's own parabola whatever the
     * figure. Other uplift modes are the user's explicit choice and stay.
     */
    void
    follow_figure_floor(Parameters::ScenarioParameters &variant)
    {
      const bool follows_profile =
        variant.loading.uplift_mode == Parameters::UpliftMode::parabola ||
        variant.loading.uplift_mode == Parameters::UpliftMode::slope;
      if (variant.bedding.floor_uplift !=
            Geometry::FloorUplift::lifted_flat_bedding ||
          !follows_profile)
        return;
      variant.loading.uplift_mode =
        variant.bedding.shape == Geometry::BeddingShape::parabolic ?
          Parameters::UpliftMode::parabola :
          Parameters::UpliftMode::slope;
      variant.loading.floor_lift =
        variant.bedding.rise_at_free_end(variant.geometry.n_blocks,
                                         variant.geometry.block_width);
      variant.loading.floor_lift_origin = "the figure's bedding rise";
    }

    FigurePoint
    evaluate(const std::string             &figure,
             Parameters::ScenarioParameters variant,
             const double                   curvature,
             const double                   bedding_friction_degree,
             const double                   vertical_friction_degree)
    {
      variant.bedding.shape = curvature > 0 ?
                                Geometry::BeddingShape::parabolic :
                                Geometry::BeddingShape::planar;
      if (curvature > 0)
        variant.bedding.curvature = curvature;
      follow_figure_floor(variant);
      variant.joints.bedding_friction_angle =
        Units::degrees_to_radians(bedding_friction_degree);
      variant.joints.vertical_friction_angle =
        Units::degrees_to_radians(vertical_friction_degree);
      return {figure,
              curvature,
              variant.joints.bedding_friction_angle,
              variant.joints.vertical_friction_angle,
              variant.loading.support_load,
              evaluate_closed_forms(variant),
              variant};
    }
  } // namespace

  std::string
  FigurePoint::id() const
  {
    return fmt::format("{}_k{:.0f}_phih{:.0f}_phiv{:.0f}_load{:.0f}t",
                       figure,
                       curvature,
                       Units::radians_to_degrees(bedding_friction),
                       Units::radians_to_degrees(vertical_friction),
                       support_load / Units::tonnes_force_to_newtons(1.));
  }

  std::vector<FigurePoint>
  lateral_force_figures(const Parameters::ScenarioParameters &scene)
  {
    const std::vector<std::pair<std::string, double>> figures{
      {"fig6_5", 0.0}, {"fig6_6", 400.0}, {"fig6_7", 200.0}};
    std::vector<FigurePoint> points;
    for (const auto &[figure, curvature] : figures)
      for (const double vertical : vertical_friction_degrees)
        for (const double bedding : bedding_friction_degrees)
          points.push_back(
            evaluate(figure, scene, curvature, bedding, vertical));
    return points;
  }

  std::vector<FigurePoint>
  floor_stress_figures(const Parameters::ScenarioParameters &scene)
  {
    const double vertical_degrees =
      Units::radians_to_degrees(scene.joints.vertical_friction_angle);
    std::vector<FigurePoint> points;
    for (const double curvature : stress_figure_curvatures)
      for (const double load : support_load_tonnes)
        for (const double bedding : bedding_friction_degrees)
          {
            Parameters::ScenarioParameters variant = scene;
            variant.loading.support_load = Units::tonnes_force_to_newtons(load);
            points.push_back(evaluate(
              "fig6_10_11", variant, curvature, bedding, vertical_degrees));
          }
    return points;
  }
} // namespace FloorBlock::Scene
