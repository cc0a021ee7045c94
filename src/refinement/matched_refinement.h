#pragma once

#include <geometry/local_size_field.h>

#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <refinement/size_targets.h>

#include <utility>
#include <vector>

namespace FloorBlock::Refinement
{
  /** The boundary ids of the two sides of one joint. */
  struct JointSides
  {
    dealii::types::boundary_id side_a;
    dealii::types::boundary_id side_b;
  };

  using ActiveCell = dealii::Triangulation<2>::active_cell_iterator;

  /**
   * @brief Active cells that face each other across a joint: first the
   * coincident faces of the common part (centres equal to round-off, 1e-6
   * of a face), then, beyond it, the mirror images across the line through
   * the common part (centres within a quarter of a face once reflected,
   * lengths within a tenth): the facing top fillets. These are every face
   * whose nodes Contact::pair_joint_nodes pairs. A cell with faces on two
   * joints appears in two pairs.
   */
  std::vector<std::pair<ActiveCell, ActiveCell>>
  facing_joint_cells(const dealii::Triangulation<2> &triangulation,
                     const std::vector<JointSides>  &joints);

  /**
   * @brief Completes the refinement and coarsening flags so that both sides
   * of every joint stay matched, then leaves them ready for
   * execute_coarsening_and_refinement().
   *
   * The bodies of a joint are not neighbours for deal.II (distinct
   * vertices), so its 2:1 rule and flag smoothing act on each side alone.
   * Alternately until nothing changes: a refine flag on one cell of a
   * facing pair is set on the other; where only one of the two parents
   * would be coarsened (all its children flagged), the coarsen flags of
   * its children are cleared; then
   * Triangulation::prepare_coarsening_and_refinement(). Refine flags only
   * grow and coarsen flags only shrink, so this ends; a joint then gets the
   * same new (hanging) nodes on both sides, which keeps every node paired.
   *
   * @throws std::logic_error if the flags have not settled after many rounds.
   */
  void
  prepare_matched_refinement(dealii::Triangulation<2>      &triangulation,
                             const std::vector<JointSides> &joints);

  /**
   * Growth rate that makes a request act on the cells it touches only
   * (h_p + (g - 1) d is far above any cell size for d > 0): with hanging
   * nodes the 2:1 rule grades the mesh, and a graded request field (which
   * Gmsh needs for element quality) would refine many more cells.
   */
  constexpr double touching_cells_only = 1e6;

  /**
   * @brief Sets the refine flag of every active cell larger than sqrt(2)
   * times the size the requests ask for anywhere on it: min over requests
   * of h_p + (g - 1) d_p, d_p the distance from request p to the cell (0 on
   * or inside it), Geometry::graded_size() with growth
   * rate g = @p growth_rate. Refining halves the cell, so it then lies
   * within a factor sqrt(2) of the request. Clears the coarsen flag of a
   * cell it flags. Joint requests sit on joint nodes (cell vertices), bulk
   * requests at cell centres.
   * @return The number of cells flagged.
   */
  unsigned int
  flag_cells_above_requested_size(
    dealii::Triangulation<2>               &triangulation,
    const std::vector<Geometry::LocalSize> &requests,
    const double                            growth_rate);

  /**
   * @brief Sets the coarsen flag of the @p fraction of active cells with
   * the smallest @p indicator (indexed by active cell index) among those
   * that are refined (level > 0) and whose parent would still meet the
   * requests (twice the size at most sqrt(2) times the request). deal.II
   * coarsens a parent only if all its children are flagged.
   * @return The number of cells flagged.
   */
  unsigned int
  flag_smooth_cells_for_coarsening(
    dealii::Triangulation<2>               &triangulation,
    const dealii::Vector<float>            &indicator,
    const double                            fraction,
    const std::vector<Geometry::LocalSize> &requests,
    const double                            growth_rate);

  /** What refine_matched() did. */
  struct MatchedRefinementSummary
  {
    unsigned int n_passes          = 0; ///< refinement sweeps executed
    unsigned int n_cells_before    = 0;
    unsigned int n_cells_after     = 0;
    unsigned int n_coarsen_flagged = 0; ///< cells flagged in the first pass
    unsigned int n_cells_coarsened =
      0; ///< of those, coarsened (after the joint and 2:1 rules)
  };

  /**
   * @brief Refines the mesh until every cell meets the requests (at most
   * @p max_passes sweeps; each halves a cell once), coarsening in the first
   * sweep where @p indicator is smallest (flag_smooth_cells_for_coarsening,
   * nothing if @p coarsen_fraction is 0), with the joints kept matched
   * (prepare_matched_refinement). Manifolds attached to the triangulation
   * place the new vertices.
   */
  MatchedRefinementSummary
  refine_matched(dealii::Triangulation<2>               &triangulation,
                 const std::vector<JointSides>          &joints,
                 const std::vector<Geometry::LocalSize> &requests,
                 const double                            growth_rate,
                 const dealii::Vector<float>            &indicator,
                 const double                            coarsen_fraction,
                 const unsigned int                      max_passes);
} // namespace FloorBlock::Refinement
