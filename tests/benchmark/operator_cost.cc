// Cost of one application of the 3D elasticity operator per unknown, as the
// mesh grows out of the caches: the assembled matrix (Epetra, what GMRES and
// ML's fine level multiply by today) against deal.II's matrix-free operator
// (a fine level whose cost per unknown does not grow; results/FINDINGS.md,
// section 11, has what this program measures). A measurement
// program, not a test: CTest never runs it.
//
// The mesh is a box of hexahedra with a smooth interior distortion, so that
// every cell is non-affine as the swept Gmsh meshes are and the matrix-free
// operator keeps a full Jacobian per quadrature point (its most expensive
// storage). One process, one thread.

#include <fem/elastic_assembly.h>
#include <fem/elastic_model.h>
#include <fem/fe_space.h>
#include <fem/sparsity.h>
#include <material/elastic_law.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
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

  // The default scene's rock; one law serves both operators.
  const FloorBlock::Material::ElasticLaw<dim> rock =
    FloorBlock::Material::ElasticLaw<dim>::from_youngs_poisson(10e9, 0.25);

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

    MatrixFreeElasticity(const FloorBlock::Fem::FeSpace<dim> &space,
                         const AffineConstraints<double>     &constraints)
    {
      typename MatrixFree<dim, double>::AdditionalData data;
      data.tasks_parallel_scheme =
        MatrixFree<dim, double>::AdditionalData::none;
      data.mapping_update_flags = update_gradients | update_JxW_values;
      matrix_free.reinit(space.mapping(),
                         space.dof_handler(),
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
      matrix_free.cell_loop(
        &MatrixFreeElasticity::apply_cells, this, dst, src, true);
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
              auto       stress = (2. * rock.shear_modulus()) * strain;
              const auto volume = trace(strain) * rock.lame_lambda();
              for (unsigned int d = 0; d < dim; ++d)
                stress[d][d] += volume;
              phi.submit_symmetric_gradient(stress, q);
            }
          phi.integrate_scatter(EvaluationFlags::gradients, dst);
        }
    }

    MatrixFree<dim, double> matrix_free;
  };

  // The assembled stiffness exactly as the contact solver builds its bulk:
  // the project's sparsity and single cell loop.
  void
  assemble_matrix(const FloorBlock::Fem::FeSpace<dim> &space,
                  const AffineConstraints<double>     &constraints,
                  TrilinosWrappers::SparseMatrix      &matrix)
  {
    TrilinosWrappers::SparsityPattern pattern;
    FloorBlock::Fem::make_sparsity(space, constraints, {}, pattern);
    matrix.reinit(pattern);
    FloorBlock::Fem::ElasticModel<dim> model;
    model.laws.emplace(types::material_id(0), rock);
    model.densities[0] = 0.;
    TrilinosWrappers::MPI::Vector solution(space.locally_owned_dofs(),
                                           MPI_COMM_WORLD);
    FloorBlock::Fem::ElasticAssemblyTargets<dim> targets;
    targets.matrix = &matrix;
    FloorBlock::Fem::assemble_elastic_system(
      space, model, solution, constraints, targets);
  }

  // Sizes: cells per edge of the box, from about 1e4 to about 2e6 unknowns
  // at degree 1.
  template <int degree>
  void
  measure(const unsigned int cells_per_edge, const unsigned int repeats)
  {
    Triangulation<dim> mesh;
    make_distorted_box(mesh, cells_per_edge);
    const FloorBlock::Fem::FeSpace<dim> space(mesh, degree);
    AffineConstraints<double>           constraints; // none: the products alone
    constraints.close();
    const double n_dofs = space.dof_handler().n_dofs();

    // Assembled matrix, as Epetra multiplies it. Its product is kept to
    // check that both operators compute the same thing.
    double              crs_s = 0., crs_mb = 0., nonzeros_per_row = 0.;
    std::vector<double> crs_product(space.dof_handler().n_dofs());
    {
      TrilinosWrappers::SparseMatrix matrix;
      assemble_matrix(space, constraints, matrix);
      TrilinosWrappers::MPI::Vector x(matrix.locally_owned_domain_indices(),
                                      MPI_COMM_WORLD);
      TrilinosWrappers::MPI::Vector y(x);
      for (unsigned int i = 0; i < n_dofs; ++i)
        x[i] = std::sin(0.001 * i);
      crs_s = best_time_s([&] { matrix.vmult(y, x); }, repeats);
      for (unsigned int i = 0; i < n_dofs; ++i)
        crs_product[i] = y[i];
      crs_mb           = matrix.memory_consumption() / 1e6;
      nonzeros_per_row = double(matrix.n_nonzero_elements()) / n_dofs;
    }

    // Matrix-free.
    MatrixFreeElasticity<degree>               op(space, constraints);
    LinearAlgebra::distributed::Vector<double> x, y;
    op.initialize_vector(x);
    op.initialize_vector(y);
    for (unsigned int i = 0; i < x.locally_owned_size(); ++i)
      x.local_element(i) = std::sin(0.001 * i);
    const double mf_s    = best_time_s([&] { op.vmult(y, x); }, repeats);
    double       largest = 0., difference = 0.;
    for (unsigned int i = 0; i < n_dofs; ++i)
      {
        largest    = std::max(largest, std::abs(crs_product[i]));
        difference = std::max(difference, std::abs(crs_product[i] - y(i)));
      }

    std::printf("| %d | %.0f | %.1f | %.1f | %.3f | %.3f | %.1f | %.3f | "
                "%.1e |\n",
                degree,
                n_dofs,
                nonzeros_per_row,
                crs_mb,
                1e3 * crs_s,
                1e9 * crs_s / n_dofs,
                op.memory_bytes() / 1e6,
                1e9 * mf_s / n_dofs,
                difference / largest);
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
              "data (MB) | matrix-free product per DoF (ns) | products "
              "differ by (of the largest entry) |\n"
              "|---|---|---|---|---|---|---|---|---|\n");
  for (const unsigned int cells : {15u, 22u, 32u, 45u, 64u, 80u, 96u})
    if (cells <= largest)
      measure<1>(cells, cells < 40 ? 20 : 5);
  for (const unsigned int cells : {8u, 11u, 16u, 22u, 32u, 40u})
    if (2 * cells <= largest)
      measure<2>(cells, cells < 20 ? 20 : 5);
  return 0;
}
