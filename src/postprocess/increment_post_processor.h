#pragma once

#include <contact/contact_node.h>
#include <contact/contact_problem.h>
#include <contact/contact_solver.h>
#include <contact/increment_observer.h>
#include <contact/joint_law.h>
#include <contact/results.h>
#include <fem/elastic_assembly.h>
#include <fem/fe_space.h>
#include <loading/load_factors.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>

#include <string>
#include <utility>
#include <vector>

namespace FloorBlock::Postprocess
{
  /**
   * @brief What a ContactSolver reports about a converged increment
   * beyond its Newton statistics: the global force balance, the joint
   * reports, the blocks' rigid-body fits, and the optional VTU series.
   *
   * Reads the solver's mesh, problem and contact nodes; changes nothing
   * of the solver's state.
   */
  /**
   * What a caller adds to each increment from its solution: to its record
   * (describe) and, when a VTU series is written, cell fields by name, one
   * value per active cell (cell_fields). The pipeline adds the floor's
   * safety factors and the strength-factor field.
   */
  struct IncrementExtras
  {
    std::function<void(const dealii::TrilinosWrappers::MPI::Vector &solution,
                       Contact::IncrementResult                    &increment)>
      describe;
    std::function<std::vector<std::pair<std::string, std::vector<double>>>(
      const dealii::TrilinosWrappers::MPI::Vector &solution)>
      cell_fields;
  };

  template <int dim>
  class IncrementPostProcessor : public Contact::IncrementObserver<dim>
  {
  public:
    /**
     * @param[in] solver The solver observed; must outlive this.
     * @param[in] averaging_length Length of the averaged peak normal
     *   stress (m).
     * @param[in] vtu_directory If not empty, a .pvd/.vtu series is
     *   written here per increment.
     * @param[in] extras What the caller adds to every increment's record
     *   (called last by describe()) and VTU file.
     */
    IncrementPostProcessor(const Contact::ContactSolver<dim> &solver,
                           const double                       averaging_length,
                           const std::string                 &vtu_directory,
                           IncrementExtras extras = {});

    /**
     * @brief Fills the balance, joint reports and rigid motions of
     * @p increment.
     * @param[in] factors Load factors of the increment (-).
     * @param[in] responses Every pair's law at @p solution.
     * @param[in] solution Converged displacement (m).
     */
    void
    describe(const Loading::LoadFactors                     &factors,
             const std::vector<Contact::JointResponse<dim>> &responses,
             const dealii::TrilinosWrappers::MPI::Vector    &solution,
             Contact::IncrementResult &increment) override;

    /** @brief Whether a VTU directory was given. */
    bool
    records() const override;

    /**
     * @brief Appends the increment to the .pvd/.vtu series in the VTU
     * directory, with the pairs' states as a debug field.
     */
    void
    record(const std::vector<Contact::JointResponse<dim>> &responses,
           const dealii::TrilinosWrappers::MPI::Vector    &solution) override;

  private:
    Contact::ForceBalance
    force_balance(const Loading::LoadFactors                     &factors,
                  const std::vector<Contact::JointResponse<dim>> &responses,
                  const dealii::TrilinosWrappers::MPI::Vector    &solution);

    const Fem::FeSpace<dim>                      &fe_space;
    const Contact::ContactProblem<dim>           &problem;
    const std::vector<Contact::ContactNode<dim>> &nodes;
    const dealii::IndexSet                       &dirichlet_dofs;
    const double                                  averaging_length;
    const std::string                             vtu_directory;
    const IncrementExtras                         extras;
    /**
     * Length of face the mesh stands for (m): 1 in 2D, the extent along
     * z in 3D; the reports give forces per metre of it.
     */
    const double             face_length;
    std::vector<std::string> joint_names;
    /** Vector component (x 0, y 1, z 2) of every DoF. */
    std::vector<unsigned int> dof_component;
    Fem::CellMatrixCache      cell_matrices;
    /** Time and file of every .vtu written, for the .pvd. */
    std::vector<std::pair<double, std::string>> output_records;
  };

  /**
   * @brief Runs @p solver with an IncrementPostProcessor of the averaging
   * length and VTU directory of @p settings, and @p extras.
   * @return Every converged increment with its joint reports; throws as
   *   ContactSolver::run().
   */
  template <int dim>
  Contact::SolveResult
  solve_with_reports(Contact::ContactSolver<dim>          &solver,
                     const Contact::ContactSolverSettings &settings,
                     const IncrementExtras                &extras = {});
} // namespace FloorBlock::Postprocess
