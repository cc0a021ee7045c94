#pragma once

#include <contact/contact_node.h>
#include <contact/contact_problem.h>
#include <contact/joint_law.h>
#include <contact/results.h>
#include <fem/elastic_assembly.h>
#include <fem/fe_space.h>
#include <loading/load_factors.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <utility>
#include <vector>

namespace FloorBlock::Contact
{
  /**
   * @brief What ContactSolver reports about a converged increment beyond
   * its Newton statistics: the global force balance, the joint reports,
   * the blocks' rigid-body fits, and the optional VTU series.
   *
   * Reads the solver's mesh, problem and contact nodes; changes nothing
   * of the solver's state.
   */
  template <int dim>
  class IncrementPostProcessor
  {
  public:
    /**
     * @param[in] fe_space, problem, nodes The solver's; must outlive this.
     * @param[in] dirichlet_dofs DoFs held by the supports; must outlive this.
     * @param[in] averaging_length Length of the averaged peak normal
     *   stress (m).
     */
    IncrementPostProcessor(const Fem::FeSpace<dim>             &fe_space,
                           const ContactProblem<dim>           &problem,
                           const std::vector<ContactNode<dim>> &nodes,
                           const dealii::IndexSet              &dirichlet_dofs,
                           const double averaging_length);

    /**
     * @brief Fills the balance, joint reports and rigid motions of
     * @p increment.
     * @param[in] factors Load factors of the increment (-).
     * @param[in] responses Every pair's law at @p solution.
     * @param[in] solution Converged displacement (m).
     */
    void
    describe(const Loading::LoadFactors                  &factors,
             const std::vector<JointResponse<dim>>       &responses,
             const dealii::TrilinosWrappers::MPI::Vector &solution,
             IncrementResult                             &increment);

    /**
     * @brief Appends the increment to the .pvd/.vtu series in
     * @p directory, with the pairs' states as a debug field.
     */
    void
    write_vtu(const std::vector<JointResponse<dim>>       &responses,
              const dealii::TrilinosWrappers::MPI::Vector &solution,
              const std::string                           &directory);

  private:
    ForceBalance
    force_balance(const Loading::LoadFactors                  &factors,
                  const std::vector<JointResponse<dim>>       &responses,
                  const dealii::TrilinosWrappers::MPI::Vector &solution);

    const Fem::FeSpace<dim>             &fe_space;
    const ContactProblem<dim>           &problem;
    const std::vector<ContactNode<dim>> &nodes;
    const dealii::IndexSet              &dirichlet_dofs;
    const double                         averaging_length;
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
} // namespace FloorBlock::Contact
