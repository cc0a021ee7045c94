#pragma once

#include <contact/contact_problem.h>
#include <parameters/scenario_parameters.h>

#include <deal.II/grid/tria.h>

#include <optional>
#include <vector>

namespace FloorBlock::Scene
{
  /** The support's footprint on the face of a 3D scene, z in [start, end]. */
  struct SupportFootprint
  {
    double start = 0.; ///< m
    double end   = 0.; ///< m

    double
    length() const
    {
      return end - start;
    }
  };

  /**
   * @brief The footprint of Loading/Footprint length and offset (centred
   * when the offset is not given); empty for a 2D scene or a Footprint
   * length of 0 (the per-metre load along the whole face).
   */
  std::optional<SupportFootprint>
  support_footprint(const Parameters::ScenarioParameters &scene);

  /**
   * @brief Slice positions of the 3D scene's sweep along the face:
   * Geometry::uniform_slices() of Mesh/Slice size, or with a footprint
   * Geometry::footprint_slices(), whose ends are then slice positions.
   */
  std::vector<double>
  swept_slices(const Parameters::ScenarioParameters &scene);

  /**
   * @brief The 3D scene's mesh made ready for the footprint load: the
   * loaded blocks' tops within the footprint get Ids::footprint_surface
   * (Geometry::tag_footprint()); nothing without a footprint. @p solid
   * must have been swept through swept_slices().
   */
  void
  tag_support_footprint(const Parameters::ScenarioParameters &scene,
                        dealii::Triangulation<3>             &solid);

  /**
   * @brief Moves the support load of the swept problem onto the footprint.
   *
   * The 2D scene's support pressure p acts on the loaded blocks' tops
   * (Ids::floor_surface) and is per metre of face: Support load over the
   * support width b (Geometry/Support width) and the loaded blocks' tops,
   * so swept along the whole face it stands for supports side by side,
   * Support load every b metres. With a footprint of length \f$\ell\f$
   * the pressure \f$p\,b/\ell\f$ acts on the tops within it
   * (Ids::footprint_surface) and none elsewhere: the footprint carries
   * the whole Support load of one support, and for \f$\ell = b\f$ (the
   * shield's own width) its pressure is the 2D one.
   *
   * @param[in] footprint Where the support stands.
   * @param[in] support_width b (m), > 0.
   * @param[in,out] problem Swept from the 2D problem
   *   (swept_contact_problem()); its mesh tagged by tag_support_footprint().
   */
  void
  load_support_footprint(const SupportFootprint     &footprint,
                         const double                support_width,
                         Contact::ContactProblem<3> &problem);
} // namespace FloorBlock::Scene
