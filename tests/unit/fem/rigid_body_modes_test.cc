// The near-null space handed to ML: every rigid-body mode is strain-free,
// so the unconstrained stiffness maps it to zero, in 2D (3 modes) and 3D
// (6 modes), for degree 1 and 2 (the mid-side support points too).
#include <fem/elastic_assembly.h>
#include <fem/rigid_body_modes.h>
#include <fem/sparsity.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using namespace FloorBlock;
  using dealii::TrilinosWrappers::MPI::Vector;

  template <int dim>
  void
  expect_modes_strain_free(const unsigned int degree)
  {
    dealii::Triangulation<dim> mesh;
    dealii::Point<dim>         far;
    for (unsigned int d = 0; d < dim; ++d)
      far[d] = 0.5 + 0.25 * d; // m
    dealii::GridGenerator::hyper_rectangle(mesh, dealii::Point<dim>(), far);
    mesh.refine_global(2);
    // Shifted off the origin: rotations about it are not centred here.
    dealii::GridTools::shift(dealii::Point<dim>::unit_vector(0) * 3., mesh);
    const Fem::FeSpace<dim> space(mesh, degree);

    Fem::ElasticModel<dim> model;
    model.laws.emplace(
      0, Material::ElasticLaw<dim>::from_youngs_poisson(16.1e9, 0.2)); // Pa, -
    model.densities[0] = 0.;
    const dealii::AffineConstraints<double>   no_constraints;
    dealii::TrilinosWrappers::SparsityPattern pattern;
    Fem::make_sparsity(space, no_constraints, {}, pattern);
    dealii::TrilinosWrappers::SparseMatrix stiffness(pattern);
    const MPI_Comm communicator = space.dof_handler().get_communicator();
    Vector         zero(space.locally_owned_dofs(), communicator);
    Vector         residual(zero);
    Fem::ElasticAssemblyTargets<dim> targets;
    targets.matrix   = &stiffness;
    targets.residual = &residual;
    Fem::assemble_elastic_system(space, model, zero, no_constraints, targets);

    const Solver::NearNullSpace null_space = Fem::rigid_body_modes(space);
    EXPECT_EQ(null_space.n_components, static_cast<unsigned int>(dim));
    ASSERT_EQ(null_space.modes.size(), dim == 2 ? 3u : 6u);
    for (std::size_t k = 0; k < null_space.modes.size(); ++k)
      {
        ASSERT_EQ(null_space.modes[k].size(), space.dof_handler().n_dofs());
        Vector mode(zero);
        for (unsigned int i = 0; i < mode.size(); ++i)
          mode(i) = null_space.modes[k][i];
        mode.compress(dealii::VectorOperation::insert);
        Vector force(zero);
        stiffness.vmult(force, mode);
        // Round-off of rows with entries of about E = 1.6e10 and mode
        // entries up to 4: a strained mode would give forces of order E h.
        EXPECT_LT(force.l2_norm(),
                  1e-12 * stiffness.frobenius_norm() * mode.l2_norm())
          << "mode " << k;
        EXPECT_GT(mode.l2_norm(), 0.) << "mode " << k;
      }
  }

  TEST(RigidBodyModes, AreStrainFreeIn2d)
  {
    expect_modes_strain_free<2>(1);
    expect_modes_strain_free<2>(2);
  }

  TEST(RigidBodyModes, AreStrainFreeIn3d)
  {
    expect_modes_strain_free<3>(1);
    expect_modes_strain_free<3>(2);
  }

  // A mode that is not rigid must show: the test above can fail.
  TEST(RigidBodyModes, AStretchIsNotStrainFree)
  {
    dealii::Triangulation<2> mesh;
    dealii::GridGenerator::hyper_cube(mesh, 0., 1.);
    mesh.refine_global(2);
    const Fem::FeSpace<2> space(mesh, 1);
    Fem::ElasticModel<2>  model;
    model.laws.emplace(0,
                       Material::ElasticLaw<2>::from_youngs_poisson(16.1e9,
                                                                    0.2));
    model.densities[0] = 0.;
    const dealii::AffineConstraints<double>   no_constraints;
    dealii::TrilinosWrappers::SparsityPattern pattern;
    Fem::make_sparsity(space, no_constraints, {}, pattern);
    dealii::TrilinosWrappers::SparseMatrix stiffness(pattern);
    Vector                                 zero(space.locally_owned_dofs(),
                space.dof_handler().get_communicator());
    Vector                                 residual(zero);
    Fem::ElasticAssemblyTargets<2>         targets;
    targets.matrix   = &stiffness;
    targets.residual = &residual;
    Fem::assemble_elastic_system(space, model, zero, no_constraints, targets);

    const Solver::NearNullSpace null_space = Fem::rigid_body_modes(space);
    // u = (x, 0): translation x mode times the rotation mode's y entries
    // gives (x, 0) on x-DoFs (rotation about z has x-entries -y, y-entries x).
    Vector stretch(zero);
    for (unsigned int i = 0; i < stretch.size(); ++i)
      stretch(i) =
        null_space.modes[0][i] != 0. ? null_space.modes[2][i + 1] : 0.;
    stretch.compress(dealii::VectorOperation::insert);
    Vector force(zero);
    stiffness.vmult(force, stretch);
    EXPECT_GT(force.l2_norm(),
              1e-3 * stiffness.frobenius_norm() * stretch.l2_norm());
  }
} // namespace
