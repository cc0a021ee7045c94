#pragma once

#include <contact/contact_node.h>
#include <contact/contact_problem.h>
#include <contact/exact_contact.h>
#include <contact/joint_law.h>
#include <fem/dirichlet_constraints.h>
#include <fem/fe_space.h>

#include <deal.II/base/index_set.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Contact
{
  /**
   * @brief Checks every joint's law and pairs its nodes.
   * @return The pairs, joint by joint.
   * Throws InputError for a compliant joint without positive stiffnesses
   * or sides that do not match.
   */
  template <int dim>
  std::vector<ContactNode<dim>>
  pair_all_joints(const Fem::FeSpace<dim>   &fe_space,
                  const ContactProblem<dim> &problem);

  /** @brief Every pair's law, for both formulations. */
  template <int dim>
  struct PairLaws
  {
    /** The laws the pointers below point to. */
    std::vector<std::unique_ptr<CoulombJoint<dim>>> owned;
    /** Per pair: its spring law, null for an exact pair. */
    std::vector<const CoulombJoint<dim> *> laws;
    /**
     * laws with springs of the complementarity parameter's stiffness
     * (kn = ks = c_n) for the exact pairs (the penalty start).
     */
    std::vector<const CoulombJoint<dim> *> penalty_laws;
    /** Per pair: the exact law, empty for a spring. */
    std::vector<std::optional<ExactPairLaw>> exact_laws;
    /** Rigid-law pairs at crosspoints, which follow springs of E/h. */
    unsigned int n_crosspoint_pairs = 0;

    /** Whether some pair has the exact law. */
    bool
    any_exact() const;
  };

  /**
   * @brief The law of every pair of @p nodes: its joint's compliant law,
   * or for a rigid-law joint the exact law with a complementarity
   * parameter of @p complementarity_factor times the surface stiffness
   * E / (pair length), or at a crosspoint springs of that stiffness.
   * @param[in] held_dofs DoFs held by the supports (ground for the
   *   crosspoints).
   */
  template <int dim>
  PairLaws<dim>
  make_pair_laws(const Fem::FeSpace<dim>             &fe_space,
                 const ContactProblem<dim>           &problem,
                 const std::vector<ContactNode<dim>> &nodes,
                 const dealii::IndexSet              &held_dofs,
                 const double                         complementarity_factor);

  /**
   * @brief What a failure message adds when the compliant joints are
   * much stiffer than the cells they join (empty otherwise): kn w / E
   * above 3 for a compliant pair of @p nodes, w its length along its
   * joint (weights_along_joint) and E the largest Young's modulus.
   */
  template <int dim>
  std::string
  stiffness_hint(const Fem::FeSpace<dim>             &fe_space,
                 const ContactProblem<dim>           &problem,
                 const std::vector<ContactNode<dim>> &nodes);

  /**
   * @brief The supports' Dirichlet conditions: zero, or with
   * @p uplift_factor the supports that move with the uplift displaced.
   */
  template <int dim>
  std::vector<Fem::DirichletCondition<dim>>
  support_conditions(const ContactProblem<dim>  &problem,
                     const std::optional<double> uplift_factor);

  /** @brief The pairs' states of @p responses. */
  template <int dim>
  std::vector<JointState>
  states_of(const std::vector<JointResponse<dim>> &responses);

  /**
   * @brief Makes @p responses the converged state of the pairs'
   * @p histories.
   */
  template <int dim>
  void
  commit_histories(const std::vector<JointResponse<dim>> &responses,
                   std::vector<JointHistory<dim>>        &histories);
} // namespace FloorBlock::Contact
