#include "refined_scene.h"

#include <contact/contact_assembly.h>
#include <contact/joint_pairing.h>
#include <fem/dirichlet_constraints.h>
#include <fem/rigid_body_modes.h>
#include <fem/sparsity.h>
#include <geometry/triangulation_reader.h>
#include <scene/assembly_inputs.h>
#include <scene/contact_inputs.h>
#include <scene/floor_contact_problem.h>
#include <solver/linear_solver.h>

#include <sstream>

namespace FloorBlock::Benchmark
{
  namespace
  {
    std::string
    assignment(const std::string &name, const double value)
    {
      std::ostringstream text;
      text.precision(17);
      text << name << "=" << value;
      return text.str();
    }
  } // namespace

  Parameters::ScenarioParameters
  refined_parameters(const std::string              &scene_path,
                     const std::vector<std::string> &overrides,
                     const double                    refinement,
                     const std::string              &joint_law)
  {
    const Parameters::ScenarioParameters base =
      Parameters::read_scenario(scene_path, overrides);
    std::vector<std::string> refined = overrides;
    refined.push_back(
      assignment("Mesh/Corner size", base.mesh.corner_size / refinement));
    refined.push_back(
      assignment("Mesh/Far size", base.mesh.far_size / refinement));
    refined.push_back("Joints/Law=" + joint_law);
    return Parameters::read_scenario(scene_path, refined);
  }

  Geometry::MeshStatistics
  mesh_scene(const Parameters::ScenarioParameters &scene,
             const std::string                    &msh_path,
             dealii::Triangulation<2>             &triangulation)
  {
    const Geometry::MeshStatistics statistics =
      Geometry::write_gmsh_mesh(Scene::assembly_description(scene), msh_path);
    triangulation.clear();
    Geometry::read_triangulation(msh_path, triangulation);
    return statistics;
  }

  LinearElasticSystem::LinearElasticSystem(
    const Parameters::ScenarioParameters &scene_parameters,
    const dealii::Triangulation<2>       &triangulation)
    : scene(Scene::make_floor_contact_problem(
        Scene::floor_problem_settings(scene_parameters)))
    , settings(Scene::contact_solver_settings(scene_parameters, ""))
    , space(triangulation, settings.fe_degree)
    , null_space(Fem::rigid_body_modes(space))
  {
    std::vector<Fem::DirichletCondition<2>> zero_conditions;
    for (const auto &support : scene.supports)
      zero_conditions.push_back(
        {support.boundary_id,
         support.constrained_components,
         [](const dealii::Point<2> &) { return dealii::Tensor<1, 2>(); }});
    dealii::IndexSet dirichlet_dofs;
    constraints =
      Fem::make_constraints(space, zero_conditions, true, dirichlet_dofs);

    for (unsigned int j = 0; j < scene.joints.size(); ++j)
      {
        const auto &joint = scene.joints[j];
        joint_laws.push_back(
          std::make_unique<Contact::CoulombJoint<2>>(joint.parameters));
        const auto joint_nodes =
          joint.against_rigid_plane ?
            Contact::pair_nodes_with_plane(space,
                                           joint.side_a,
                                           joint.plane_point,
                                           joint.plane_normal,
                                           joint.obstacle_curvature,
                                           j) :
            Contact::pair_joint_nodes(space, joint.side_a, joint.side_b, j);
        for (const auto &node : joint_nodes)
          {
            nodes.push_back(node);
            pair_laws.push_back(joint_laws.back().get());
          }
      }
    histories.assign(nodes.size(), Contact::JointHistory<2>());

    Fem::make_sparsity(space,
                       constraints,
                       Contact::pair_dof_groups(nodes),
                       pattern);
    matrix.reinit(pattern);
    const MPI_Comm communicator = space.dof_handler().get_communicator();
    solution.reinit(space.locally_owned_dofs(), communicator);
    residual.reinit(space.locally_owned_dofs(), communicator);
    update.reinit(space.locally_owned_dofs(), communicator);
    assemble_bulk(&warm_cache);
    assemble_joints();
  }

  void
  LinearElasticSystem::assemble_bulk(Fem::CellMatrixCache *cache)
  {
    matrix   = 0.;
    residual = 0.;
    Fem::ElasticAssemblyTargets<2> targets;
    targets.matrix   = &matrix;
    targets.residual = &residual;
    targets.cache    = cache;
    Fem::assemble_elastic_system(
      space, scene.model, solution, constraints, targets);
  }

  void
  LinearElasticSystem::reuse_bulk()
  {
    if (!stored_bulk)
      stored_bulk = std::make_unique<Fem::StoredElasticSystem<2>>(space,
                                                                  scene.model,
                                                                  constraints,
                                                                  pattern);
    matrix.copy_from(stored_bulk->condensed_stiffness());
    stored_bulk->residual(solution, 1., 1., residual);
  }

  void
  LinearElasticSystem::assemble_joints()
  {
    const auto responses =
      Contact::evaluate_contact(nodes, pair_laws, histories, solution);
    Contact::assemble_contact(
      nodes, responses, constraints, &matrix, &residual);
  }

  bool
  LinearElasticSystem::solve()
  {
    dealii::TrilinosWrappers::MPI::Vector right_hand_side(residual);
    right_hand_side *= -1.;
    update                             = 0.;
    const Solver::LinearSolveInfo info = Solver::solve_linear_system(
      settings.linear, matrix, right_hand_side, null_space, update);
    constraints.distribute(update);
    return info.success;
  }

  bool
  LinearElasticSystem::newton_iteration()
  {
    // As ContactSolver since b864195: joints evaluated, the stored bulk
    // copied and multiplied (Fem::StoredElasticSystem), joints assembled,
    // one linear solve.
    const auto responses =
      Contact::evaluate_contact(nodes, pair_laws, histories, solution);
    reuse_bulk();
    Contact::assemble_contact(
      nodes, responses, constraints, &matrix, &residual);
    return solve();
  }

  unsigned int
  LinearElasticSystem::n_dofs() const
  {
    return space.dof_handler().n_dofs();
  }

  unsigned int
  LinearElasticSystem::n_contact_pairs() const
  {
    return nodes.size();
  }

  bool
  LinearElasticSystem::uses_direct_solver() const
  {
    return settings.linear.kind == Solver::LinearSolverKind::direct ||
           (settings.linear.kind == Solver::LinearSolverKind::automatic &&
            n_dofs() <= settings.linear.max_direct_dofs);
  }

  const dealii::TrilinosWrappers::SparseMatrix &
  LinearElasticSystem::system_matrix() const
  {
    return matrix;
  }

  const dealii::TrilinosWrappers::MPI::Vector &
  LinearElasticSystem::system_residual() const
  {
    return residual;
  }
} // namespace FloorBlock::Benchmark
