#pragma once

#include <parameters/scenario_parameters.h>

#include <deal.II/grid/tria.h>

#include <refinement/matched_refinement.h>

#include <vector>

namespace FloorBlock::Pipeline
{
  /**
   * @brief The boundary ids of both sides of every joint between two
   * meshed bodies (joints against the rigid plane have one side only):
   * what Refinement::refine_matched keeps matched.
   */
  std::vector<Refinement::JointSides>
  matched_joint_sides(const Parameters::ScenarioParameters &scene);

  /**
   * @brief Halves the cells along the floor safety's corner paths
   * (Scene::critical_distance_sizes) until each is within sqrt(2) of the
   * requested L / N, both sides of every joint alike.
   *
   * Gmsh's size field grades towards the requests but leaves cells up to
   * about twice them where many requests crowd a corner, and with a small
   * L (a strong rock: L = (K_Ic / sigma_t)^2 / pi) a path could stay
   * coarser than Safety::min_cells_per_critical_distance allows. deal.II's
   * hanging nodes refine exactly the cells the path crosses. Nothing is
   * done when the scene asks for no corner sizes (2D only, Mesh/Cells per
   * critical distance > 0).
   * @return The number of cells added.
   */
  unsigned int
  refine_corner_paths(const Parameters::ScenarioParameters &scene,
                      dealii::Triangulation<2>             &triangulation);
} // namespace FloorBlock::Pipeline
