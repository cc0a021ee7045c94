// Cost of one application of the 3D elasticity operator per unknown, as the
// mesh grows out of the caches: the assembled matrix (Epetra, what GMRES and
// ML's fine level multiply by today) against deal.II's matrix-free operator
// (the design issue 16 names for a fine level whose cost per unknown does not
// grow). A measurement program, not a test: CTest never runs it.
//
// The mesh is a box of hexahedra with a smooth interior distortion, so that
// every cell is non-affine as the swept Gmsh meshes are and the matrix-free
// operator keeps a full Jacobian per quadrature point (its most expensive
// storage). One process, one thread.

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  constexpr int dim = 3;

  // Lame constants of the default scene's rock (E = 10 GPa, nu = 0.25).
  constexpr double lambda = 4e9;
  constexpr double mu     = 4e9;

  // Smallest wall time of `repeats` calls, per call: the least disturbed one
  // on a shared machine.
  template <typename Function>
  double
  best_time_s(const Function &function, const unsigned int repeats)
  {
    double best = 1e300;
    for (unsigned int r = 0; r < repeats; ++r)
      {
        const auto start = std::chrono::steady_clock::now();
        function();
        const std::chrono::duration<double> took =
          std::chrono::steady_clock::now() - start;
        best = std::min(best, took.count());
      }
    return best;
  }

  void
  make_distorted_box(Triangulation<dim> &mesh, const unsigned int cells)
  {
    GridGenerator::subdivided_hyper_cube(mesh, cells, 0., 1.);
    GridTools::transform(
      [](const Point<dim> &p) {
        Point<dim> q = p;
        for (unsigned int d = 0; d < dim; ++d)
          q[d] += 0.03 * std::sin(3. * p[(d + 1) % dim]) *
                  std::sin(2. * p[(d + 2) % dim]);
        return q;
      },
      mesh);
  }

  template <int degree>
  class MatrixFreeElasticity
  {
  public:
    using Vector = LinearAlgebra::distributed::Vector<double>;

    MatrixFreeElasticity(const DoFHandler<dim>           &dofs,
                         const AffineConstraints<double> &constraints)
    {
      typename MatrixFree<dim, double>::AdditionalData data;
      data.tasks_parallel_scheme =
        MatrixFree<dim, double>::AdditionalData::none;
      data.mapping_update_flags = update_gradients | update_JxW_values;
      matrix_free.reinit(MappingQ<dim>(1),
                         dofs,
                         constraints,
                         QGauss<1>(degree + 1),
                         data);
    }

    void
    initialize_vector(Vector &vector) const
    {
      matrix_free.initialize_dof_vector(vector);
    }

    void
    vmult(Vector &dst, const Vector &src) const
    {
      matrix_free.cell_loop(&MatrixFreeElasticity::apply_cells,
                            this,
                            dst,
                            src,
                            true);
    }

    std::size_t
    memory_bytes() const
    {
      return matrix_free.memory_consumption();
    }

  private:
    void
    apply_cells(const MatrixFree<dim, double>               &data,
                Vector                                      &dst,
                const Vector                                &src,
                const std::pair<unsigned int, unsigned int> &cells) const
    {
      FEEvaluation<dim, degree, degree + 1, dim, double> phi(data);
      for (unsigned int cell = cells.first; cell < cells.second; ++cell)
        {
          phi.reinit(cell);
          phi.gather_evaluate(src, EvaluationFlags::gradients);
          for (unsigned int q = 0; q < phi.n_q_points; ++q)
            {
              const auto strain = phi.get_symmetric_gradient(q);
              auto       stress = (2. * mu) * strain;
              const auto volume = trace(strain) * lambda;
              for (unsigned int d = 0; d < dim; ++d)
                stress[d][d] += volume;
              phi.submit_symmetric_gradient(stress, q);
            }
          phi.integrate_scatter(EvaluationFlags::gradients, dst);
        }
    }

    MatrixFree<dim, double> matrix_free;
  };

  void
  assemble_matrix(const DoFHandler<dim>             &dofs,
                  const AffineConstraints<double>   &constraints,
                  const unsigned int                 degree,
                  TrilinosWrappers::SparseMatrix    &matrix)
  {
    DynamicSparsityPattern pattern(dofs.n_dofs());
    DoFTools::make_sparsity_pattern(dofs, pattern, constraints, false);
    matrix.reinit(pattern);

    const FiniteElement<dim> &fe = dofs.get_fe();
    FEValues<dim>             values(fe,
                         QGauss<dim>(degree + 1),
                         update_gradients | update_JxW_values);
    const unsigned int        n = fe.n_dofs_per_cell();
    FullMatrix<double>        cell_matrix(n, n);
    std::vector<types::global_dof_index> indices(n);
    for (const auto &cell : dofs.active_cell_iterators())
      {
        values.reinit(cell);
        cell_matrix = 0;
        for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int ci = fe.system_to_component_index(i).first;
              const auto        &gi = values.shape_grad(i, q);
              for (unsigned int j = 0; j < n; ++j)
                {
                  const unsigned int cj =
                    fe.system_to_component_index(j).first;
                  const auto &gj = values.shape_grad(j, q);
                  double      k  = lambda * gi[ci] * gj[cj] +
                             mu * gi[cj] * gj[ci];
                  if (ci == cj)
                    k += mu * (gi * gj);
                  cell_matrix(i, j) += k * values.JxW(q);
                }
            }
        cell->get_dof_indices(indices);
        constraints.distribute_local_to_global(cell_matrix, indices, matrix);
      }
    matrix.compress(VectorOperation::add);
  }

  // Sizes: cells per edge of the box, from about 1e4 to about 2e6 unknowns
  // at degree 1.
  template <int degree>
  void
  measure(const unsigned int cells_per_edge, const unsigned int repeats)
  {
    Triangulation<dim> mesh;
    make_distorted_box(mesh, cells_per_edge);
    const FESystem<dim> fe{FE_Q<dim>(degree), dim};
    DoFHandler<dim>     dofs(mesh);
    dofs.distribute_dofs(fe);
    AffineConstraints<double> constraints; // none: the products alone
    constraints.close();
    const double n_dofs = dofs.n_dofs();

    // Assembled matrix, as Epetra multiplies it.
    double crs_s = 0., crs_mb = 0., nonzeros_per_row = 0.;
    {
      TrilinosWrappers::SparseMatrix matrix;
      assemble_matrix(dofs, constraints, degree, matrix);
      TrilinosWrappers::MPI::Vector x(matrix.locally_owned_domain_indices(),
                                      MPI_COMM_WORLD);
      TrilinosWrappers::MPI::Vector y(x);
      for (unsigned int i = 0; i < n_dofs; ++i)
        x[i] = std::sin(0.001 * i);
      crs_s = best_time_s([&] { matrix.vmult(y, x); }, repeats);
      crs_mb           = matrix.memory_consumption() / 1e6;
      nonzeros_per_row = double(matrix.n_nonzero_elements()) / n_dofs;
    }

    // Matrix-free.
    MatrixFreeElasticity<degree>                   op(dofs, constraints);
    LinearAlgebra::distributed::Vector<double> x, y;
    op.initialize_vector(x);
    op.initialize_vector(y);
    for (unsigned int i = 0; i < x.locally_owned_size(); ++i)
      x.local_element(i) = std::sin(0.001 * i);
    const double mf_s = best_time_s([&] { op.vmult(y, x); }, repeats);

    std::printf("| %d | %.0f | %.1f | %.1f | %.3f | %.3f | %.1f | %.3f |\n",
                degree,
                n_dofs,
                nonzeros_per_row,
                crs_mb,
                1e3 * crs_s,
                1e9 * crs_s / n_dofs,
                op.memory_bytes() / 1e6,
                1e9 * mf_s / n_dofs);
    std::fflush(stdout);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Usage: floorblock_operator_cost [largest cells per edge, default 64]
  const unsigned int largest = argc > 1 ? std::atoi(argv[1]) : 64;
  std::printf("| degree | DoFs | nonzeros per row | matrix (MB) | matrix "
              "product (ms) | matrix product per DoF (ns) | matrix-free "
              "data (MB) | matrix-free product per DoF (ns) |\n"
              "|---|---|---|---|---|---|---|---|\n");
  for (const unsigned int cells : {15u, 22u, 32u, 45u, 64u, 80u, 96u})
    if (cells <= largest)
      measure<1>(cells, cells < 40 ? 20 : 5);
  for (const unsigned int cells : {8u, 11u, 16u, 22u, 32u, 40u})
    if (2 * cells <= largest)
      measure<2>(cells, cells < 20 ? 20 : 5);
  return 0;
}
