#pragma once

#include <contact/joint_law_kind.h>
#include <fem/elastic_model.h>
#include <fem/fe_space.h>
#include <fem/point_stress.h>
#include <parameters/scenario_parameters.h>

#include <deal.II/lac/trilinos_vector.h>

#include <safety/corner_paths.h>
#include <safety/corner_sampling.h>
#include <strength/critical_distance.h>
#include <strength/strength_factor.h>

#include <vector>

namespace FloorBlock::Safety
{
  /** @brief The FEM's stress at a point as Strength:: reads it. */
  Strength::PlaneStrainStress
  plane_strain(const Fem::PointStress &stress);

  /** The critical-distance measures a corner's factor is read from. */
  enum class SafetyMethod
  {
    point, ///< the stress at L/2 along the path
    line,  ///< the mean stress over L along the path
    area   ///< the mean stress over the block's material within L
  };

  /** @brief "point", "line", "area". */
  const char *
  to_string(SafetyMethod method);

  /**
   * @brief The measure a corner's verdict (holds, fails) and the governing
   * corner go by under the joint law @p law: the one that depends on
   * neither the mesh nor a rounding radius much smaller than L under it
   * (results/FINDINGS.md, section 13, with L = 20 mm on the default
   * scene).
   *
   * Compliant joints: the line method (0.7 % over three nested levels,
   * 1.1 % over radii of 1-5 mm). The joint spreads the contact pressure
   * down the face; the point method's stress at L/2 sits where sigma_3
   * turns from compression to tension and moves 2.6 % and 14 %; the area
   * method counts the top r of the joint, which a fillet takes out of
   * contact, and moves 25 % over the radii.
   *
   * Exact contact: the area method (0.6 % over the levels, 0.6 % over the
   * radii). The corner carries a concentrated load, applied where the
   * fillet's normal meets the contact force, up to about r from the
   * path's start: every stress within L of the corner follows r (the
   * point method moves 42 % over the radii, the line method 22 %), but the
   * mean over the region is set by the tractions on its boundary, which r
   * hardly moves (Strength::area_method_stress()).
   */
  SafetyMethod
  verdict_method(Contact::JointLawKind law);

  /**
   * @brief The floor's safety factor at one block corner by the theory of
   * critical distances (Strength/Critical distance L): the Hoek-Brown
   * strength factor (Strength::strength_factor) of the stress at L/2 along
   * the corner's path (point method), of the mean stress over L along it
   * (line method) and of the mean stress over the block's material within
   * L of the hot spot (area method, Strength::area_method_stress()). None
   * depends on the pointwise peak at the corner, which the mesh and the
   * rounding radius decide.
   */
  struct CornerSafety
  {
    CornerPath                  path;
    double                      critical_distance = 0.; ///< L (m)
    Strength::PrincipalStresses point_stresses;         ///< at L/2 (Pa)
    Strength::PrincipalStresses line_stresses;          ///< mean over L (Pa)
    /** Mean over the block's material within L of the hot spot (Pa). */
    Strength::PrincipalStresses area_stresses;
    double                      point_factor = 0.; ///< FS, point method
    double                      line_factor  = 0.; ///< FS, line method
    double                      area_factor  = 0.; ///< FS, area method
    /** The method the verdict goes by (verdict_method() of the law). */
    SafetyMethod verdict_method = SafetyMethod::line;
    /** The stress along the path over [0, L], and its strength factor
     * (resolved paths only; else empty). */
    std::vector<Strength::PathSample> samples;
    std::vector<double>               sample_factors;
    /** Largest cell along the path over [0, L] (m). */
    double largest_cell = 0.;
    /** Largest cell the area method's rays cross (m). Its mean is an
     * integral of the field, so it asks less of the mesh than the stress
     * at one point; resolved() goes by the path. */
    double largest_cell_within_L = 0.;

    /** @brief Whether the mesh resolves L: cells along the path at most
     * L / min_cells_per_critical_distance. Elsewhere the stress at L/2 is
     * a cell's value, not the field's, and the factors are no answer. */
    bool
    resolved() const;
  };

  /** @brief @p corner's factor by @p method. */
  double
  factor(const CornerSafety &corner, SafetyMethod method);

  /** @brief The factor @p corner's verdict goes by: its verdict_method's. */
  double
  verdict_factor(const CornerSafety &corner);

  /** Cells across L along a path for its factors to count (resolved()). */
  constexpr double min_cells_per_critical_distance = 4.;

  /**
   * @brief CornerSafety at every floor-level corner of @p scene's vertical
   * joints (floor_corner_paths()) from the displacement @p solution of a
   * 2D solve on @p space. One process only (Fem::stresses_at_points()).
   */
  std::vector<CornerSafety>
  corner_safety(const Parameters::ScenarioParameters        &scene,
                const Fem::FeSpace<2>                       &space,
                const Fem::ElasticModel<2>                  &model,
                const dealii::TrilinosWrappers::MPI::Vector &solution);

  /** @brief The same, at sample points already located in @p space's
   * mesh (locate_corner_samples(): once per mesh, for every increment of
   * a load path on it). */
  std::vector<CornerSafety>
  corner_safety(const Parameters::ScenarioParameters        &scene,
                const std::vector<CornerSamplePoints>       &sample_points,
                const Fem::FeSpace<2>                       &space,
                const Fem::ElasticModel<2>                  &model,
                const dealii::TrilinosWrappers::MPI::Vector &solution);

  /** @brief The corner with the smallest verdict_factor() when every
   * corner is resolved, else the least resolved corner (the floor then has
   * no verdict); @p corners must not be empty. */
  const CornerSafety &
  governing_corner(const std::vector<CornerSafety> &corners);
} // namespace FloorBlock::Safety
