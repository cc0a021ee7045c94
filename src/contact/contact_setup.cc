#include <common/input_error.h>
#include <contact/contact_setup.h>
#include <contact/crosspoints.h>
#include <contact/joint_pairing.h>
#include <contact/swept_sections.h>
#include <contact/uplift.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace FloorBlock::Contact
{
  namespace
  {
    /** kn h / E above which a failure suggests the rigid law (-). */
    constexpr double ill_conditioned_joint_ratio = 3.;

    template <int dim>
    double
    largest_youngs_modulus(const ContactProblem<dim> &problem)
    {
      double largest_modulus = 0.;
      for (const auto &entry : problem.model.laws)
        largest_modulus =
          std::max(largest_modulus, entry.second.youngs_modulus());
      return largest_modulus;
    }

    template <int dim>
    void
    check_joint(const JointDefinition<dim> &joint)
    {
      if (joint.obstacle_curvature != 0. &&
          (!(joint.obstacle_curvature > 0.) || !joint.against_rigid_plane ||
           joint.plane_moves_with_uplift))
        throw std::logic_error(
          "joint '" + joint.name +
          "': an obstacle curvature needs a fixed rigid plane and must be "
          "positive");
      if (joint.law == JointLawKind::compliant &&
          (!(joint.parameters.normal_stiffness > 0.) ||
           !(joint.parameters.shear_stiffness > 0.)))
        throw InputError("joint '" + joint.name +
                         "': compliant law needs kn > 0 and ks > 0 Pa/m");
    }
  } // namespace

  template <int dim>
  std::vector<ContactNode<dim>>
  pair_all_joints(const Fem::FeSpace<dim>   &fe_space,
                  const ContactProblem<dim> &problem)
  {
    std::vector<ContactNode<dim>> nodes;
    for (unsigned int j = 0; j < problem.joints.size(); ++j)
      {
        const JointDefinition<dim> &joint = problem.joints[j];
        check_joint(joint);
        const std::vector<ContactNode<dim>> joint_nodes =
          joint.against_rigid_plane ?
            pair_nodes_with_plane(fe_space,
                                  joint.side_a,
                                  joint.plane_point,
                                  joint.plane_normal,
                                  joint.obstacle_curvature,
                                  j) :
            pair_joint_nodes(fe_space, joint.side_a, joint.side_b, j);
        nodes.insert(nodes.end(), joint_nodes.begin(), joint_nodes.end());
      }
    return nodes;
  }

  template <int dim>
  bool
  PairLaws<dim>::any_exact() const
  {
    return std::any_of(exact_laws.begin(),
                       exact_laws.end(),
                       [](const auto &law) { return law.has_value(); });
  }

  template <int dim>
  PairLaws<dim>
  make_pair_laws(const Fem::FeSpace<dim>             &fe_space,
                 const ContactProblem<dim>           &problem,
                 const std::vector<ContactNode<dim>> &nodes,
                 const dealii::IndexSet              &held_dofs,
                 const double                         complementarity_factor)
  {
    PairLaws<dim> result;
    // The joints' own laws come first: result.owned[j] is joint j's.
    for (const auto &joint : problem.joints)
      result.owned.push_back(
        std::make_unique<CoulombJoint<dim>>(joint.parameters));
    std::vector<bool> joint_is_exact;
    for (const auto &joint : problem.joints)
      joint_is_exact.push_back(joint.law == JointLawKind::rigid);
    const std::vector<bool> yields_at_crosspoint =
      crosspoint_pairs(nodes, joint_is_exact, held_dofs);
    result.n_crosspoint_pairs = std::count(yields_at_crosspoint.begin(),
                                           yields_at_crosspoint.end(),
                                           true);
    // The pairs' scales are lengths along the joint line, as in 2D: in 3D
    // a pair's weight is an area, and the joint's contact ends run along
    // the face, resolved by the in-plane cells (swept_sections.h).
    const auto  &triangulation   = fe_space.dof_handler().get_triangulation();
    const double smallest_cell   = smallest_in_plane_cell(triangulation);
    const double largest_modulus = largest_youngs_modulus(problem);
    const std::vector<double> pair_lengths =
      weights_along_joint(nodes,
                          problem.joints.size(),
                          face_length_of(triangulation));
    for (unsigned int p = 0; p < nodes.size(); ++p)
      {
        const JointDefinition<dim> &joint = problem.joints[nodes[p].joint];
        if (joint.law == JointLawKind::compliant)
          {
            result.laws.push_back(result.owned[nodes[p].joint].get());
            result.penalty_laws.push_back(result.laws.back());
            result.exact_laws.emplace_back();
            continue;
          }
        // Exact law: the complementarity parameter per pair is a multiple
        // of the surface's own stiffness E / w, so that the multiplier and
        // gap terms of the augmented multipliers weigh alike at every pair
        // whatever its cell size. It changes the Newton iterates, never
        // the converged answer.
        const double length = std::max(pair_lengths[p], smallest_cell);
        ExactPairLaw law;
        law.surface_stiffness = largest_modulus / length;
        law.complementarity.friction_coefficient =
          std::tan(joint.parameters.friction_angle);
        law.complementarity.cohesion = joint.parameters.cohesion;
        law.complementarity.normal_parameter =
          complementarity_factor * law.surface_stiffness;
        law.complementarity.tangential_parameter =
          law.complementarity.normal_parameter;
        JointConstants springs   = joint.parameters;
        springs.normal_stiffness = law.complementarity.normal_parameter;
        springs.shear_stiffness  = law.complementarity.tangential_parameter;
        springs.tensile_strength = 0.;
        if (yields_at_crosspoint[p])
          {
            // Springs of the surface stiffness E / h itself (not of the
            // complementarity parameter, which must not change a result).
            springs.normal_stiffness = law.surface_stiffness;
            springs.shear_stiffness  = law.surface_stiffness;
            result.owned.push_back(
              std::make_unique<CoulombJoint<dim>>(springs));
            result.laws.push_back(result.owned.back().get());
            result.penalty_laws.push_back(result.laws.back());
            result.exact_laws.emplace_back();
            continue;
          }
        result.exact_laws.push_back(law);
        result.laws.push_back(nullptr);
        result.owned.push_back(std::make_unique<CoulombJoint<dim>>(springs));
        result.penalty_laws.push_back(result.owned.back().get());
      }
    return result;
  }

  template <int dim>
  std::string
  stiffness_hint(const Fem::FeSpace<dim>             &fe_space,
                 const ContactProblem<dim>           &problem,
                 const std::vector<ContactNode<dim>> &nodes)
  {
    // Compliant joints much stiffer than the cells they join make the
    // Newton matrix ill-conditioned and the contact set flip (bug 3 of
    // tests/scenarios/HARD_CASES.md: kn h / E = 9 cycles, 0.9 converges);
    // a failure then names the remedy. The worst pair is the one whose
    // spring kn w is largest against the bulk's E: the longest pair along
    // its joint, not the smallest cell of the mesh, which a refined corner
    // (the critical-distance paths, a fillet) makes tiny while the
    // joint's other cells stay long.
    const std::vector<double> lengths =
      weights_along_joint(nodes,
                          problem.joints.size(),
                          face_length_of(
                            fe_space.dof_handler().get_triangulation()));
    double ratio = 0., longest = 0.;
    for (unsigned int p = 0; p < nodes.size(); ++p)
      {
        const JointDefinition<dim> &joint = problem.joints[nodes[p].joint];
        if (joint.law != JointLawKind::compliant)
          continue;
        const double stiffness = std::max(joint.parameters.normal_stiffness,
                                          joint.parameters.shear_stiffness);
        if (stiffness * lengths[p] > ratio)
          {
            ratio   = stiffness * lengths[p];
            longest = lengths[p];
          }
      }
    ratio /= largest_youngs_modulus(problem);
    if (!(ratio > ill_conditioned_joint_ratio))
      return "";
    std::ostringstream hint;
    hint << "; note: the compliant joints are stiff against the "
            "blocks (kn h / E = "
         << ratio << " with h the longest pair along a joint, " << longest
         << " m): use Joints/Law = rigid for joints this stiff";
    return hint.str();
  }

  template <int dim>
  std::vector<Fem::DirichletCondition<dim>>
  support_conditions(const ContactProblem<dim>  &problem,
                     const std::optional<double> uplift_factor)
  {
    std::vector<Fem::DirichletCondition<dim>> conditions;
    const UpliftSettings                      uplift = problem.uplift;
    for (const auto &support : problem.supports)
      {
        const bool   moves  = uplift_factor && support.moves_with_uplift;
        const double factor = uplift_factor.value_or(0.);
        conditions.push_back(
          {support.boundary_id,
           support.constrained_components,
           [uplift, factor, moves](const dealii::Point<dim> &point) {
             return moves ? uplift_displacement(uplift, factor, point) :
                            dealii::Tensor<1, dim>();
           }});
      }
    return conditions;
  }

  template <int dim>
  std::vector<JointState>
  states_of(const std::vector<JointResponse<dim>> &responses)
  {
    std::vector<JointState> states;
    states.reserve(responses.size());
    for (const auto &response : responses)
      states.push_back(response.state);
    return states;
  }

  template <int dim>
  void
  commit_histories(const std::vector<JointResponse<dim>> &responses,
                   std::vector<JointHistory<dim>>        &histories)
  {
    for (unsigned int p = 0; p < histories.size(); ++p)
      {
        const JointResponse<dim> &response = responses[p];
        JointHistory<dim>        &history  = histories[p];
        history.tangential_base            = response.tangential_traction;
        history.reference_slip             = response.slip;
        // UDEC convention: cohesion and tensile strength are lost for good
        // once the pair slips or opens.
        history.intact = history.intact && response.state == JointState::stick;
      }
  }

#define FLOORBLOCK_INSTANTIATE(dim)                                             \
  template std::vector<ContactNode<dim>> pair_all_joints(                       \
    const Fem::FeSpace<dim> &, const ContactProblem<dim> &);                    \
  template struct PairLaws<dim>;                                                \
  template PairLaws<dim> make_pair_laws(const Fem::FeSpace<dim> &,              \
                                        const ContactProblem<dim> &,            \
                                        const std::vector<ContactNode<dim>> &,  \
                                        const dealii::IndexSet &,               \
                                        const double);                          \
  template std::string   stiffness_hint(const Fem::FeSpace<dim> &,              \
                                        const ContactProblem<dim> &,            \
                                        const std::vector<ContactNode<dim>> &); \
  template std::vector<Fem::DirichletCondition<dim>> support_conditions(        \
    const ContactProblem<dim> &, const std::optional<double>);                  \
  template std::vector<JointState> states_of(                                   \
    const std::vector<JointResponse<dim>> &);                                   \
  template void commit_histories(const std::vector<JointResponse<dim>> &,       \
                                 std::vector<JointHistory<dim>> &);
  FLOORBLOCK_INSTANTIATE(2)
  FLOORBLOCK_INSTANTIATE(3)
#undef FLOORBLOCK_INSTANTIATE
} // namespace FloorBlock::Contact
