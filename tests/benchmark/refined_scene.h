#pragma once

#include <contact/contact_node.h>
#include <contact/contact_problem.h>
#include <contact/joint_law.h>
#include <fem/elastic_assembly.h>
#include <fem/fe_space.h>
#include <fem/stored_elastic_system.h>
#include <geometry/assembly_mesher.h>
#include <parameters/scenario_parameters.h>
#include <solver/near_null_space.h>

#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>
#include <vector>

namespace FloorBlock::Benchmark
{
  /**
   * @brief A scene read with the project's parameter reader and
   * @p overrides ("Subsection/Entry=value"), its Mesh/Corner
   * size and Mesh/Far size divided by @p refinement and its Joints/Law set
   * to @p joint_law ("compliant" or "rigid").
   */
  Parameters::ScenarioParameters
  refined_parameters(const std::string              &scene_path,
                     const std::vector<std::string> &overrides,
                     const double                    refinement,
                     const std::string              &joint_law);

  /**
   * @brief Meshes @p scene with Gmsh into @p msh_path and reads it back,
   * exactly as the solve pipeline does (src/app/fem_pipeline.cc).
   */
  Geometry::MeshStatistics
  mesh_scene(const Parameters::ScenarioParameters &scene,
             const std::string                    &msh_path,
             dealii::Triangulation<2>             &triangulation);

  /**
   * @brief The linear system the contact solver starts every loading path
   * from, built from the same library calls as Contact::ContactSolver: bulk
   * elasticity with full loads, the supports as homogeneous constraints,
   * and every joint node pair closed and stuck (zero displacement), so the
   * joints act as their kn, ks springs and glue the bodies together. Same
   * sparsity (bulk + pair couplings) and the same linear-solver settings as
   * the contact solver (Scene::contact_solver_settings).
   *
   * The springs are the scene's kn, ks for either joint law (the rigid law
   * would use its augmentation stiffness instead: same sparsity, hence the
   * same cost for KLU up to pivoting).
   */
  class LinearElasticSystem
  {
  public:
    /** @param[in] triangulation Must outlive this object. */
    LinearElasticSystem(const Parameters::ScenarioParameters &scene,
                        const dealii::Triangulation<2>       &triangulation);

    /** @brief Bulk assembly of matrix and residual; @p cache may be null. */
    void
    assemble_bulk(Fem::CellMatrixCache *cache);

    /**
     * @brief The bulk as the contact solver gets it in every Newton
     * iteration instead of assemble_bulk(): the stored condensed stiffness
     * copied (values only) and the residual \f$K u - f\f$ from one
     * product (Fem::StoredElasticSystem). The first call builds the stored
     * system; only later calls are representative.
     */
    void
    reuse_bulk();

    /** @brief Joint law evaluation and assembly of the pair terms. */
    void
    assemble_joints();

    /** @brief update = solution of matrix update = -residual; false on failure. */
    bool
    solve();

    /**
     * @brief One Newton iteration as the contact solver does it: joint
     * evaluation, stored bulk copied and multiplied (reuse_bulk()), pair
     * assembly, linear solve, constraint distribution.
     */
    bool
    newton_iteration();

    unsigned int
    n_dofs() const;
    unsigned int
    n_contact_pairs() const;
    /** @brief Whether the contact solver's settings pick a direct solver here. */
    bool
    uses_direct_solver() const;

    const dealii::TrilinosWrappers::SparseMatrix &
    system_matrix() const;
    const dealii::TrilinosWrappers::MPI::Vector &
    system_residual() const;

  private:
    const Contact::ContactProblem<2>     scene;
    const Contact::ContactSolverSettings settings;
    const Fem::FeSpace<2>                space;
    /** ML's near-null space, for the solves that go iterative. */
    const Solver::NearNullSpace                            null_space;
    dealii::AffineConstraints<double>                      constraints;
    std::vector<Contact::ContactNode<2>>                   nodes;
    std::vector<std::unique_ptr<Contact::CoulombJoint<2>>> joint_laws;
    std::vector<const Contact::CoulombJoint<2> *>          pair_laws;
    std::vector<Contact::JointHistory<2>>                  histories;
    Fem::CellMatrixCache                                   warm_cache;
    dealii::TrilinosWrappers::SparsityPattern              pattern;
    dealii::TrilinosWrappers::SparseMatrix                 matrix;
    std::unique_ptr<Fem::StoredElasticSystem<2>>           stored_bulk;
    dealii::TrilinosWrappers::MPI::Vector                  solution;
    dealii::TrilinosWrappers::MPI::Vector                  residual;
    dealii::TrilinosWrappers::MPI::Vector                  update;
  };
} // namespace FloorBlock::Benchmark
