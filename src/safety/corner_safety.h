#pragma once

#include <fem/elastic_model.h>
#include <fem/fe_space.h>
#include <fem/point_stress.h>
#include <parameters/scenario_parameters.h>
#include <safety/corner_paths.h>
#include <strength/critical_distance.h>
#include <strength/strength_factor.h>

#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace FloorBlock::Safety
{
  /** @brief The FEM's stress at a point as Strength:: reads it. */
  Strength::PlaneStrainStress
  plane_strain(const Fem::PointStress &stress);

  /** Samples of the stress along [0, L] of each path: the FE field is
   * smooth within cells, so this many points resolve cells down to L/32
   * with linear interpolation between them. */
  constexpr unsigned int samples_per_critical_distance = 128;

  /**
   * @brief The floor's safety factor at one block corner by the theory of
   * critical distances (Strength/Critical distance L): the Hoek-Brown
   * strength factor (Strength::strength_factor) of the stress at L/2 along
   * the corner's path (point method) and of the mean stress over L (line
   * method). Neither depends on the pointwise peak at the corner, which
   * the mesh and the rounding radius decide.
   */
  struct CornerSafety
  {
    CornerPath                   path;
    double                       critical_distance = 0.; ///< L (m)
    Strength::PrincipalStresses  point_stresses;          ///< at L/2 (Pa)
    Strength::PrincipalStresses  line_stresses;           ///< mean over L (Pa)
    double                       point_factor = 0.;       ///< FS, point method
    double                       line_factor  = 0.;       ///< FS, line method
    /** The stress along the path over [0, L], and its strength factor
     * (resolved paths only; else empty). */
    std::vector<Strength::PathSample> samples;
    std::vector<double>               sample_factors;
    /** Largest cell along the path over [0, L] (m). */
    double largest_cell = 0.;

    /** @brief Whether the mesh resolves L: cells along the path at most
     * L / min_cells_per_critical_distance. Elsewhere the stress at L/2 is
     * a cell's value, not the field's, and the factors are no answer. */
    bool
    resolved() const;
  };

  /**
   * @brief The factor a corner's verdict (holds, fails) and the governing
   * corner go by: the line method's. On the default scene with L = 20 mm
   * it changes by less than 0.2 % over three nested refinement levels and
   * by 1.1 % over corner radii of 1-5 mm, where the point method's changes
   * by 2.9 % and 13 %: the stress at L/2 sits where sigma_3 turns from
   * compression to a tension close to the rock mass's tensile strength,
   * and the factor follows sigma_3 there (results/FINDINGS.md, section 13).
   */
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

  /** @brief The corner with the smallest verdict_factor() when every
   * corner is resolved, else the least resolved corner (the floor then has
   * no verdict); @p corners must not be empty. */
  const CornerSafety &
  governing_corner(const std::vector<CornerSafety> &corners);
} // namespace FloorBlock::Safety
