#pragma once

#include <contact/results.h>
#include <fem/fe_space.h>
#include <geometry/local_size_field.h>

#include <deal.II/grid/tria.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace FloorBlock::Refinement
{
  /**
   * @brief What adaptive refinement refines, and how much.
   *
   * Each marked place asks for half its current cell size (a zone end for
   * a quarter). `converge --mode remesh` keeps the requests of all levels
   * (each level is a new Gmsh mesh); `--mode adaptive` applies each level's
   * requests to the previous level's deal.II mesh, which keeps its cells.
   */
  /**
   * Fraction of the cells flagged for coarsening per adaptive level
   * (`converge --coarsen-fraction`'s default, and `run`'s).
   */
  constexpr double default_coarsen_fraction = 0.03;

  struct RefinementSettings
  {
    /**
     * A joint segment (two neighbouring joint nodes) is refined where the
     * normal traction jumps across it by at least this fraction of the
     * largest jump on any joint. Units: 1.
     */
    double traction_jump_fraction = 0.25;
    /**
     * The ends of the closed zones ask for their segment length divided by
     * this, not by 2: the contact length is resolved to one node spacing
     * there (an error of up to half a spacing at each end, first order and
     * not improved by anything else), and refining a point of a line costs
     * few cells. Units: 1.
     */
    double zone_end_refinement = 4.;
    /** Fraction of all cells, those with the largest Kelly indicator, refined
     * in the bulk. Units: 1. */
    double bulk_fraction = 0.1;
    /** No request goes below this size (m); see
     * Geometry::validate_local_sizes(). */
    double smallest_size = 1e-3;
  };

  /**
   * @brief Size requests along the joints, from the converged joint state.
   *
   * Along each joint (nodes sorted along it, JointReport::profile), a
   * segment between neighbouring nodes is marked
   *  - where the contact state changes (open on one node, closed on the
   *    other), and the segment on either side: the ends of the closed
   *    zones, which decide the contact length to one cell and move by up
   *    to a segment from one mesh to the next; and
   *  - where the normal traction jump \f$|t_{n,k+1} - t_{n,k}|\f$ is at
   *    least RefinementSettings::traction_jump_fraction of the largest jump
   *    on any joint: the jump is the size of the traction gradient times the
   *    spacing, i.e. the local interpolation error of the linear traction.
   * Both nodes of a marked segment ask for half its length, at a zone end
   * for its length / RefinementSettings::zone_end_refinement (never below
   * RefinementSettings::smallest_size). Positions are those of side A;
   * side B has the same nodes.
   */
  std::vector<Geometry::LocalSize>
  joint_size_targets(const std::vector<Contact::JointReport> &joints,
                     const RefinementSettings                &settings);

  /**
   * @brief The size of a cell that requests are made for and compared
   * with: the square root of its area. Units: m.
   */
  double
  cell_size(const dealii::TriaAccessor<2, 2, 2> &cell);

  /**
   * @brief The Kelly indicator of the displacement per active cell (by
   * active cell index): the jump of the normal derivative, i.e. of the
   * traction, across interior faces; joint faces are boundaries and add
   * nothing (joint_size_targets() covers them).
   */
  dealii::Vector<float>
  kelly_indicator(const Fem::FeSpace<2>                       &space,
                  const dealii::TrilinosWrappers::MPI::Vector &solution);

  /**
   * @brief Size requests in the bodies: the
   * RefinementSettings::bulk_fraction of cells with the largest @p
   * indicator (kelly_indicator(), by active cell index) ask at their centre
   * for half their size (square root of the area).
   */
  std::vector<Geometry::LocalSize>
  bulk_size_targets(const dealii::Triangulation<2> &triangulation,
                    const dealii::Vector<float>    &indicator,
                    const RefinementSettings       &settings);

  /**
   * @brief Adds to @p requests those @p candidates that ask for less than
   * the requests already give at their position
   * (Geometry::local_size_at() with @p growth_rate), smallest first, so
   * that repeated and overlapping requests (neighbouring cells, both ends
   * of a segment, earlier levels) do not pile up in the mesher.
   */
  void
  merge_size_requests(std::vector<Geometry::LocalSize> &requests,
                      std::vector<Geometry::LocalSize>  candidates,
                      const double                      growth_rate);
} // namespace FloorBlock::Refinement
