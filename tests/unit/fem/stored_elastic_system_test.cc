// The stored bulk of the Newton system must give exactly what the cell loop
// gives: same condensed stiffness, same residual, also with non-zero
// prescribed displacements (floor uplift), which condensation alone would
// drop from the residual.
#include <fem/dirichlet_constraints.h>
#include <fem/elastic_assembly.h>
#include <fem/sparsity.h>
#include <fem/stored_elastic_system.h>

#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "block_mesh.h"
#include "test_scenes.h"

namespace
{
  using namespace FloorBlock;
  using dealii::TrilinosWrappers::SparseMatrix;
  using dealii::TrilinosWrappers::MPI::Vector;

  constexpr dealii::types::boundary_id sides = 10, bottom = 11, top = 12;

  /** @p refine_corner: one refined cell, so hanging-node lines with entries. */
  void
  expect_cell_loop_result(const bool refine_corner)
  {
    dealii::Triangulation<2> mesh;
    Testing::make_block_assembly(
      {{0., 1., 0., 0.5, 4, 3, 1, sides, sides, bottom, top}}, mesh);
    if (refine_corner)
      {
        mesh.begin_active()->set_refine_flag();
        mesh.execute_coarsening_and_refinement();
      }
    const Fem::FeSpace<2> space(mesh, 1);

    Fem::ElasticModel<2> model;
    model.laws.emplace(1, Testing::table_rock());
    model.densities[1]   = 2500.; // kg/m^3
    model.gravity[1]     = -9.81; // m/s^2
    model.pressures[top] = 2e6;   // Pa

    dealii::IndexSet                        fixed;
    std::vector<Fem::DirichletCondition<2>> zero{
      {bottom, {{true, true}}, [](const dealii::Point<2> &) {
         return dealii::Tensor<1, 2>();
       }}};
    const auto constraints = Fem::make_constraints(space, zero, true, fixed);
    bool       has_entries = false;
    for (const auto &line : constraints.get_lines())
      has_entries = has_entries || !line.entries.empty();
    ASSERT_EQ(has_entries, refine_corner);
    dealii::TrilinosWrappers::SparsityPattern pattern;
    Fem::make_sparsity(space, constraints, {}, pattern);

    const Fem::StoredElasticSystem<2> stored(space,
                                             model,
                                             constraints,
                                             pattern);

    // A displacement that is non-zero everywhere, also on the support
    // (as during uplift), smooth so that every cell is strained.
    const MPI_Comm communicator = space.dof_handler().get_communicator();
    Vector         solution(space.locally_owned_dofs(), communicator);
    for (unsigned int i = 0; i < solution.size(); ++i)
      solution(i) = 1e-3 * std::sin(0.7 * i + 0.3);
    solution.compress(dealii::VectorOperation::insert);
    dealii::AffineConstraints<double> hanging_only;
    for (const auto &line : constraints.get_lines())
      if (!line.entries.empty())
        {
          hanging_only.add_line(line.index);
          hanging_only.add_entries(line.index, line.entries);
        }
    hanging_only.close();
    hanging_only.distribute(solution); // a conforming field, as in Newton

    const double         gravity_factor = 0.3, pressure_factor = 0.7;
    Fem::ElasticModel<2> scaled = model;
    scaled.gravity *= gravity_factor;
    scaled.pressures[top] *= pressure_factor;
    SparseMatrix reference_matrix(pattern);
    Vector       reference_residual(solution);
    reference_residual = 0.;
    Fem::ElasticAssemblyTargets<2> targets;
    targets.matrix   = &reference_matrix;
    targets.residual = &reference_residual;
    Fem::assemble_elastic_system(space, scaled, solution, constraints, targets);

    Vector residual(solution);
    stored.residual(solution, gravity_factor, pressure_factor, residual);
    Vector difference(residual);
    difference -= reference_residual;
    // Same cell matrices and loads summed in another order: round-off only.
    EXPECT_LT(difference.l2_norm(), 1e-12 * reference_residual.l2_norm());
    EXPECT_GT(reference_residual.l2_norm(), 0.);
    for (const auto &line : constraints.get_lines())
      EXPECT_EQ(residual(line.index), 0.);

    // The round-off scale bounds the residual entry by entry (triangle
    // inequality), and the floor is (longest row + 2) eps times it: rows
    // of the unconstrained Q1 plane-strain stiffness have 8 to 18 entries,
    // up to about 26 next to a refined cell (hanging-node neighbours;
    // measured 22).
    const double magnitude =
      stored.residual_magnitude(solution, gravity_factor, pressure_factor);
    EXPECT_GE(magnitude, residual.l2_norm());
    const double eps = std::numeric_limits<double>::epsilon();
    const double floor =
      stored.round_off_floor(solution, gravity_factor, pressure_factor);
    EXPECT_GE(floor, 10. * eps * magnitude);
    EXPECT_LE(floor, (refine_corner ? 28. : 20.) * eps * magnitude);

    SparseMatrix matrix_difference(pattern);
    matrix_difference.copy_from(stored.condensed_stiffness());
    matrix_difference.add(-1., reference_matrix);
    EXPECT_LT(matrix_difference.frobenius_norm(),
              1e-13 * reference_matrix.frobenius_norm());
  }

  TEST(StoredElasticSystem, MatchesTheCellLoopWithUpliftedSupport)
  {
    expect_cell_loop_result(false);
  }

  TEST(StoredElasticSystem, MatchesTheCellLoopWithHangingNodes)
  {
    expect_cell_loop_result(true);
  }
} // namespace
