// Issue 16: the bulk assembly in 3D. A box under a uniform pressure on its
// top, on rollers on three orthogonal faces, is in uniaxial stress; Q1
// reproduces the linear displacement exactly (a patch test), which checks
// the 3D stiffness, the pressure load and the constraints together.
#include <fem/dirichlet_constraints.h>
#include <fem/elastic_assembly.h>
#include <fem/sparsity.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/trilinos_solver.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "test_scenes.h"

namespace
{
  using namespace FloorBlock;

  // colorize: x = 0 -> 0, y = 0 -> 2, y = top -> 3, z = 0 -> 4.
  constexpr dealii::types::boundary_id left = 0, bottom = 2, top = 3, back = 4;

  TEST(ElasticAssembly3d, UniaxialPressureIsReproducedExactly)
  {
    dealii::Triangulation<3> mesh;
    const dealii::Point<3>   far(1.0, 0.5, 0.6); // m
    dealii::GridGenerator::subdivided_hyper_rectangle(
      mesh, {3, 2, 2}, dealii::Point<3>(), far, true);
    // colorize also numbers the cells by octant: one material here.
    for (auto &cell : mesh.active_cell_iterators())
      cell->set_material_id(0);
    // Distorted interior vertices: the patch test must not rely on boxes.
    std::vector<bool> moved(mesh.n_vertices(), false);
    for (auto &cell : mesh.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          if (moved[cell->vertex_index(v)])
            continue;
          moved[cell->vertex_index(v)] = true;
          dealii::Point<3> &x          = cell->vertex(v);
          const bool        interior   = x[0] > 1e-9 && x[0] < far[0] - 1e-9 &&
                                x[1] > 1e-9 && x[1] < far[1] - 1e-9 &&
                                x[2] > 1e-9 && x[2] < far[2] - 1e-9;
          if (interior)
            x += dealii::Point<3>(0.03, -0.02, 0.025);
        }
    const Fem::FeSpace<3> space(mesh, 1);

    const double youngs = 16.1e9, poisson = 0.2, pressure = 2e6; // Pa, -, Pa
    Fem::ElasticModel<3> model;
    model.laws.emplace(0,
                       Material::ElasticLaw<3>::from_youngs_poisson(youngs,
                                                                    poisson));
    model.densities[0]   = 0.;
    model.pressures[top] = pressure;

    const auto roller = [](const unsigned int               component,
                           const dealii::types::boundary_id id) {
      std::array<bool, 3> mask{{false, false, false}};
      mask[component] = true;
      return Fem::DirichletCondition<3>{id, mask, [](const dealii::Point<3> &) {
                                          return dealii::Tensor<1, 3>();
                                        }};
    };
    dealii::IndexSet fixed;
    const auto       constraints = Fem::make_constraints(space,
                                                   {roller(0, left),
                                                          roller(1, bottom),
                                                          roller(2, back)},
                                                   true,
                                                   fixed);
    dealii::TrilinosWrappers::SparsityPattern pattern;
    Fem::make_sparsity(space, constraints, {}, pattern);

    const MPI_Comm communicator = space.dof_handler().get_communicator();
    dealii::TrilinosWrappers::MPI::Vector  solution(space.locally_owned_dofs(),
                                                   communicator);
    dealii::TrilinosWrappers::MPI::Vector  residual(solution);
    dealii::TrilinosWrappers::SparseMatrix matrix(pattern);
    dealii::Tensor<1, 3>                   applied;
    Fem::ElasticAssemblyTargets<3>         targets;
    targets.matrix             = &matrix;
    targets.residual           = &residual;
    targets.applied_load_total = &applied;
    Fem::assemble_elastic_system(space, model, solution, constraints, targets);
    // The total load is the pressure times the top area, straight down.
    EXPECT_NEAR(applied[1], -pressure * far[0] * far[2], 1e-6 * pressure);
    EXPECT_NEAR(applied[0], 0., 1e-9 * pressure);
    EXPECT_NEAR(applied[2], 0., 1e-9 * pressure);

    residual *= -1.;
    dealii::TrilinosWrappers::MPI::Vector  increment(solution);
    dealii::SolverControl                  control;
    dealii::TrilinosWrappers::SolverDirect direct(control);
    direct.solve(matrix, increment, residual);
    constraints.distribute(increment);

    // sigma_yy = -p: eps_yy = -p/E, eps_xx = eps_zz = nu p/E.
    const double strain = pressure / youngs;
    for (const auto &cell : space.dof_handler().active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          const dealii::Point<3> &x           = cell->vertex(v);
          const double            expected[3] = {poisson * strain * x[0],
                                                 -strain * x[1],
                                                 poisson * strain * x[2]};
          for (unsigned int c = 0; c < 3; ++c)
            EXPECT_NEAR(increment(cell->vertex_dof_index(v, c)),
                        expected[c],
                        1e-10 * strain)
              << "component " << c << " at " << x;
        }
  }
} // namespace
