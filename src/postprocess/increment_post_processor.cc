#include <contact/contact_assembly.h>
#include <contact/swept_sections.h>
#include <fem/rigid_motion.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <postprocess/increment_post_processor.h>
#include <postprocess/joint_report.h>
#include <postprocess/swept_joint_report.h>
#include <postprocess/vtu_writer.h>

#include <cmath>
#include <utility>

namespace FloorBlock::Postprocess
{
  using namespace Contact;

  template <int dim>
  IncrementPostProcessor<dim>::IncrementPostProcessor(
    const ContactSolver<dim> &solver,
    const double              averaging_length,
    const std::string        &vtu_directory,
    IncrementExtras           extras)
    : fe_space(solver.space())
    , problem(solver.contact_problem())
    , nodes(solver.contact_nodes())
    , dirichlet_dofs(solver.supported_dofs())
    , averaging_length(averaging_length)
    , vtu_directory(vtu_directory)
    , extras(std::move(extras))
    , face_length(face_length_of(fe_space.dof_handler().get_triangulation()))
  {
    for (const auto &joint : problem.joints)
      joint_names.push_back(joint.name);
    const auto &fe = fe_space.fe();
    dof_component.assign(fe_space.dof_handler().n_dofs(), 0);
    std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : fe_space.dof_handler().active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          dof_component[dofs[i]] = fe.system_to_component_index(i).first;
      }
  }

  template <int dim>
  void
  IncrementPostProcessor<dim>::describe(
    const Loading::LoadFactors                  &factors,
    const std::vector<JointResponse<dim>>       &responses,
    const dealii::TrilinosWrappers::MPI::Vector &solution,
    IncrementResult                             &increment)
  {
    increment.balance = force_balance(factors, responses, solution);
    if constexpr (dim == 2)
      {
        increment.joints =
          make_joint_reports(nodes, responses, joint_names, averaging_length);
        increment.motions = Fem::fit_rigid_motions(fe_space, solution);
      }
    else
      {
        increment.joints = make_swept_joint_reports(
          nodes, responses, joint_names, averaging_length, face_length);
        for (const auto &[material, motion] :
             Fem::fit_rigid_motions(fe_space, solution))
          {
            Fem::RigidMotion<2> in_plane;
            in_plane.translation[0]     = motion.translation[0];
            in_plane.translation[1]     = motion.translation[1];
            in_plane.rotation           = motion.rotation;
            increment.motions[material] = in_plane;
          }
      }
    if (extras.describe)
      extras.describe(solution, increment);
  }

  template <int dim>
  ForceBalance
  IncrementPostProcessor<dim>::force_balance(
    const Loading::LoadFactors                  &factors,
    const std::vector<JointResponse<dim>>       &responses,
    const dealii::TrilinosWrappers::MPI::Vector &solution)
  {
    Fem::ElasticModel<dim> model = problem.model;
    model.gravity *= factors.gravity;
    for (auto &entry : model.pressures)
      entry.second *= factors.support;

    dealii::AffineConstraints<double> no_constraints;
    no_constraints.close();
    dealii::TrilinosWrappers::MPI::Vector raw(
      fe_space.locally_owned_dofs(), fe_space.dof_handler().get_communicator());
    ForceBalance                     balance;
    dealii::Tensor<1, dim>           applied_load;
    dealii::Tensor<1, dim>           support_reaction;
    Fem::ElasticAssemblyTargets<dim> targets;
    targets.cache              = &cell_matrices;
    targets.residual           = &raw;
    targets.applied_load_total = &applied_load;
    Fem::assemble_elastic_system(
      fe_space, model, solution, no_constraints, targets);
    assemble_contact(nodes, responses, no_constraints, nullptr, &raw);
    // The equations solved are the condensed ones: a hanging node's
    // residual is carried by its masters, and where a master is a support
    // DoF that share is part of the support's reaction. Without it the
    // check reported 2e-3 imbalance on adaptively refined meshes whose
    // hanging nodes touch a support (the solution itself was balanced).
    dealii::Vector<double> condensed(raw);
    for (const auto &line : fe_space.hanging_node_constraints().get_lines())
      if (!dirichlet_dofs.is_element(line.index))
        {
          for (const auto &[master, weight] : line.entries)
            condensed(master) += weight * condensed(line.index);
          condensed(line.index) = 0.;
        }
    // Each process sums the DoFs and pairs it owns; the sums are added
    // over the processes below (on one process it owns them all).
    const dealii::IndexSet &owned              = fe_space.locally_owned_dofs();
    double                  reaction_magnitude = 0.;
    for (const auto dof : dirichlet_dofs)
      if (owned.is_element(dof))
        {
          support_reaction[dof_component[dof]] += condensed(dof);
          reaction_magnitude += std::abs(condensed(dof));
        }
    // A rigid obstacle is a support too: it receives +w f (the force
    // density on side B) from each of its pairs.
    for (unsigned int p = 0; p < nodes.size(); ++p)
      if (nodes[p].against_rigid_obstacle() &&
          owned.is_element(nodes[p].dofs_a[0]))
        {
          const dealii::Tensor<1, dim> force =
            nodes[p].weight * responses[p].force_density;
          support_reaction += force;
          double magnitude = 0.;
          for (unsigned int c = 0; c < dim; ++c)
            magnitude += std::abs(force[c]);
          reaction_magnitude += magnitude;
        }
    const MPI_Comm communicator = fe_space.dof_handler().get_communicator();
    applied_load = dealii::Utilities::MPI::sum(applied_load, communicator);
    support_reaction =
      dealii::Utilities::MPI::sum(support_reaction, communicator);
    reaction_magnitude =
      dealii::Utilities::MPI::sum(reaction_magnitude, communicator);
    const double scale = applied_load.norm() + reaction_magnitude;
    balance.relative_imbalance =
      scale > 0. ? (applied_load + support_reaction).norm() / scale : 0.;
    // Per metre of face, as every force of the reports (3D: the totals
    // over the face length).
    for (unsigned int c = 0; c < dim; ++c)
      {
        balance.applied_load[c]     = applied_load[c] / face_length;
        balance.support_reaction[c] = support_reaction[c] / face_length;
      }
    return balance;
  }

  template <int dim>
  bool
  IncrementPostProcessor<dim>::records() const
  {
    return !vtu_directory.empty();
  }

  template <int dim>
  void
  IncrementPostProcessor<dim>::record(
    const std::vector<JointResponse<dim>>       &responses,
    const dealii::TrilinosWrappers::MPI::Vector &solution)
  {
    std::vector<double> node_states(nodes.size());
    for (unsigned int p = 0; p < nodes.size(); ++p)
      node_states[p] = static_cast<double>(responses[p].state);
    std::vector<dealii::types::global_dof_index> state_dofs;
    for (const auto &node : nodes)
      state_dofs.push_back(node.dofs_a[0]);
    write_vtu_increment(fe_space,
                        problem.model,
                        solution,
                        state_dofs,
                        node_states,
                        vtu_directory,
                        output_records,
                        extras.cell_fields ? extras.cell_fields(solution) :
                                             CellFields());
  }

  template <int dim>
  SolveResult
  solve_with_reports(ContactSolver<dim>          &solver,
                     const ContactSolverSettings &settings,
                     const IncrementExtras       &extras)
  {
    IncrementPostProcessor<dim> reports(solver,
                                        settings.averaging_length,
                                        settings.output_directory,
                                        extras);
    return solver.run(reports);
  }

  template class IncrementPostProcessor<2>;
  template class IncrementPostProcessor<3>;
  template SolveResult
  solve_with_reports(ContactSolver<2> &,
                     const ContactSolverSettings &,
                     const IncrementExtras &);
  template SolveResult
  solve_with_reports(ContactSolver<3> &,
                     const ContactSolverSettings &,
                     const IncrementExtras &);
} // namespace FloorBlock::Postprocess
