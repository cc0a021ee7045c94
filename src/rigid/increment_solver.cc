#include <contact/active_set.h>
#include <rigid/dense_system.h>
#include <rigid/increment_solver.h>
#include <rigid/system_assembly.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace FloorBlock::RigidBlocks
{
  namespace
  {
    constexpr unsigned int dofs_per_block = 3;

    /** l2 norm with moment rows divided by L (N/m). */
    double
    force_norm(const std::vector<double> &values, const double block_width)
    {
      double sum = 0.;
      for (unsigned int row = 0; row < values.size(); ++row)
        {
          const double value = (row % dofs_per_block == 2) ?
                                 values[row] / block_width :
                                 values[row];
          sum += value * value;
        }
      return std::sqrt(sum);
    }

    /** Number of closed points of every block's joints. */
    std::vector<unsigned int>
    closed_points_per_block(const JointSet       &joint_set,
                            const JointResponses &responses)
    {
      std::vector<unsigned int>         closed(joint_set.n_blocks(), 0);
      const std::vector<JointGeometry> &joints = joint_set.joints();
      for (unsigned int j = 0; j < joints.size(); ++j)
        for (const Contact::JointResponse<2> &response : responses[j])
          if (response.state != Contact::JointState::open)
            for (const BodyRef &body : {joints[j].side_a, joints[j].side_b})
              if (body.kind == BodyKind::block)
                ++closed[body.index];
      return closed;
    }

    /**
     * A point whose normal trial traction, or whose distance to the Coulomb
     * limit, is below this fraction of the largest normal traction sits on
     * a branch boundary of the law (-). Both branches give the same
     * traction there, so round-off flips between them (seen at points that
     * slipped in the previous increment and did not move since) must not
     * count as a change of the active set; the residual test still has to
     * pass. Round-off in the tractions is about 1e-13 of this scale.
     */
    constexpr double borderline_fraction = 1e-9;

    /** Set codes for the signature: branch boundaries get their own code. */
    enum class SetCode : std::uint8_t
    {
      open,
      stick,
      slip_positive,
      slip_negative,
      borderline
    };

    /**
     * @brief Hash of the stick/slip/open set in which points on a branch
     * boundary share one code (see borderline_fraction).
     */
    std::uint64_t
    set_signature(const JointSet       &joint_set,
                  const JointResponses &responses,
                  const JointHistories &histories)
    {
      double largest_traction = 0.;
      for (const auto &joint : responses)
        for (const Contact::JointResponse<2> &response : joint)
          largest_traction =
            std::max(largest_traction, std::abs(response.normal_traction));
      const double margin = borderline_fraction * largest_traction;

      constexpr std::uint64_t fnv_offset_basis = 14695981039346656037ull;
      constexpr std::uint64_t fnv_prime        = 1099511628211ull;
      std::uint64_t           hash             = fnv_offset_basis;
      const std::vector<JointGeometry> &joints = joint_set.joints();
      for (unsigned int j = 0; j < joints.size(); ++j)
        {
          const Contact::JointConstants &constants =
            joint_set.law(joints[j]).parameters();
          const double friction = std::tan(constants.friction_angle);
          for (unsigned int p = 0; p < responses[j].size(); ++p)
            {
              const Contact::JointResponse<2> &response = responses[j][p];
              const double                     normal_trial =
                -constants.normal_stiffness * response.gap;
              const double shear =
                response.tangential_traction * joints[j].points[p].tangent;
              const double cohesion =
                histories[j][p].intact ? constants.cohesion : 0.;
              const double limit =
                cohesion + friction * response.normal_traction;
              SetCode code = SetCode::stick;
              if (std::abs(normal_trial) <= margin)
                code = SetCode::borderline;
              else if (response.state == Contact::JointState::open)
                code = SetCode::open;
              else if (limit - std::abs(shear) <= margin)
                code =
                  shear > 0. ? SetCode::slip_positive : SetCode::slip_negative;
              hash = (hash ^ static_cast<std::uint64_t>(code)) * fnv_prime;
            }
        }
      return hash;
    }

    /**
     * Safety factor on the estimated round-off of the residual (-): the
     * estimate below is a root-sum-square, the true accumulation can be a
     * few times larger.
     */
    constexpr double roundoff_safety = 10.;

    /**
     * @brief Estimated round-off floor of the residual norm (N/m): every
     * gap is the difference of two displacements of size |u_A| + |u_B|, so
     * it carries an error of about eps (|u_A| + |u_B|), i.e. a force error
     * of eps w kn (|u_A| + |u_B|) per point, summed as random errors.
     * With 1 cm of common base and block travel at kn = 1e14 Pa/m this is
     * 1e-10 of the default loads, above a fixed 1e-10 tolerance.
     */
    double
    residual_roundoff(const JointSet                 &joint_set,
                      const std::vector<BlockMotion> &motions,
                      const double                    uplift_factor)
    {
      double sum_of_squares = 0.;
      for (const JointGeometry &joint : joint_set.joints())
        {
          const double stiffness =
            std::max(joint_set.law(joint).parameters().normal_stiffness,
                     joint_set.law(joint).parameters().shear_stiffness);
          for (const JointPoint &point : joint.points)
            {
              const double travel = joint_set
                                      .side_displacement(joint.side_a,
                                                         point.position,
                                                         motions,
                                                         uplift_factor)
                                      .norm() +
                                    joint_set
                                      .side_displacement(joint.side_b,
                                                         point.position,
                                                         motions,
                                                         uplift_factor)
                                      .norm();
              const double force = point.weight * stiffness * travel;
              sum_of_squares += force * force;
            }
        }
      return std::numeric_limits<double>::epsilon() * std::sqrt(sum_of_squares);
    }

    std::vector<Contact::JointState>
    all_states(const JointResponses &responses)
    {
      std::vector<Contact::JointState> states;
      for (const auto &joint : responses)
        for (const Contact::JointResponse<2> &response : joint)
          states.push_back(response.state);
      return states;
    }

    /** Forces applied to every block at @p factors, dofs_per_block each. */
    std::vector<double>
    applied_forces(const std::vector<BlockLoads> &loads,
                   const Loading::LoadFactors    &factors)
    {
      std::vector<double> applied(dofs_per_block * loads.size());
      for (unsigned int index = 0; index < loads.size(); ++index)
        {
          const auto force =
            applied_force(loads[index], factors.gravity, factors.support);
          for (unsigned int r = 0; r < dofs_per_block; ++r)
            applied[dofs_per_block * index + r] = force[r];
        }
      return applied;
    }

    /**
     * One increment's Newton iteration: the callbacks of
     * Contact::solve_newton() over the block motions in @p outcome.
     */
    class IncrementIteration
    {
    public:
      IncrementIteration(const JointSet                &joint_set,
                         const std::vector<BlockLoads> &loads,
                         const RigidSolverSettings     &settings,
                         const double                   block_width,
                         const Loading::LoadFactors    &factors,
                         const JointHistories          &histories,
                         IncrementOutcome              &outcome)
        : joint_set(joint_set)
        , loads(loads)
        , settings(settings)
        , block_width(block_width)
        , factors(factors)
        , histories(histories)
        , outcome(outcome)
        , motions_at_solve(outcome.motions)
      {}

      Contact::NewtonIterate
      assemble()
      {
        outcome.responses =
          joint_set.evaluate(outcome.motions, factors.uplift, histories);
        assemble_system(joint_set,
                        outcome.responses,
                        loads,
                        factors.gravity,
                        factors.support,
                        {&residual, &tangent});
        Contact::NewtonIterate iterate;
        iterate.residual_norm = force_norm(residual, block_width);
        iterate.set_signature =
          set_signature(joint_set, outcome.responses, histories);
        iterate.counts = Contact::count_states(all_states(outcome.responses));
        return iterate;
      }

      /** A small dense system solved exactly: no forcing term applies. */
      bool
      solve_update(std::string &message)
      {
        const std::vector<unsigned int> closed =
          closed_points_per_block(joint_set, outcome.responses);
        for (unsigned int index = 0; index < closed.size(); ++index)
          if (closed[index] == 0)
            {
              outcome.failure       = SolveStatus::floating_block;
              outcome.failing_block = index + 1;
              message               = "block " + std::to_string(index + 1) +
                        " is floating: all points of its joints are open";
              return false;
            }
        update = residual;
        DenseSolveResult solved =
          solve_dense(tangent, update, settings.singular_pivot_tolerance);
        singular_in_last_solve = !solved.success;
        if (!solved.success && settings.slip_stabilisation > 0.)
          {
            outcome.failing_block = solved.singular_row / dofs_per_block + 1;
            assemble_system(joint_set,
                            outcome.responses,
                            loads,
                            factors.gravity,
                            factors.support,
                            {nullptr, &tangent, settings.slip_stabilisation});
            update = residual;
            solved =
              solve_dense(tangent, update, settings.singular_pivot_tolerance);
          }
        if (!solved.success)
          {
            outcome.failure       = SolveStatus::no_equilibrium;
            outcome.failing_block = solved.singular_row / dofs_per_block + 1;
            message               = "singular tangent at block " +
                      std::to_string(outcome.failing_block) +
                      ": its closed joint points slip and nothing resists the "
                      "motion, no static equilibrium";
            return false;
          }
        motions_at_solve = outcome.motions;
        return true;
      }

      /** Newton: q_new = q - step K^{-1} R. */
      void
      set_step(const double step)
      {
        for (unsigned int index = 0; index < outcome.motions.size(); ++index)
          {
            const unsigned int first = dofs_per_block * index;
            outcome.motions[index].translation[0] =
              motions_at_solve[index].translation[0] - step * update[first];
            outcome.motions[index].translation[1] =
              motions_at_solve[index].translation[1] - step * update[first + 1];
            outcome.motions[index].rotation =
              motions_at_solve[index].rotation - step * update[first + 2];
          }
      }

      /**
       * The consistent tangent of the last Newton step was singular (a
       * mechanism in the tangent): if Newton fails, that is the reason.
       */
      bool singular_in_last_solve = false;

    private:
      const JointSet                &joint_set;
      const std::vector<BlockLoads> &loads;
      const RigidSolverSettings     &settings;
      const double                   block_width;
      const Loading::LoadFactors    &factors;
      const JointHistories          &histories;
      IncrementOutcome              &outcome;
      std::vector<BlockMotion>       motions_at_solve;
      std::vector<double>            residual;
      std::vector<double>            update;
      DenseMatrix                    tangent;
    };
  } // namespace

  IncrementOutcome
  solve_load_state(const JointSet                 &joint_set,
                   const std::vector<BlockLoads>  &loads,
                   const RigidSolverSettings      &settings,
                   const double                    block_width,
                   const Loading::LoadFactors     &factors,
                   const std::vector<BlockMotion> &start_motions,
                   const JointHistories           &histories)
  {
    IncrementOutcome outcome;
    outcome.motions = start_motions;
    IncrementIteration iteration(
      joint_set, loads, settings, block_width, factors, histories, outcome);
    Contact::NewtonCallbacks callbacks;
    callbacks.assemble     = [&]() { return iteration.assemble(); };
    callbacks.solve_update = [&](double /*forcing*/, std::string &message) {
      return iteration.solve_update(message);
    };
    callbacks.set_step = [&](const double step) { iteration.set_step(step); };

    // The residual cannot be driven below the round-off of the gaps: if
    // that floor is above the requested tolerance, ask for the floor (the
    // increment's force balance is still checked and reported separately).
    const double load_norm =
      force_norm(applied_forces(loads, factors), block_width);
    Contact::NewtonSettings newton = settings.newton;
    if (load_norm > 0.)
      newton.relative_tolerance =
        std::max(newton.relative_tolerance,
                 roundoff_safety *
                   residual_roundoff(joint_set, start_motions, factors.uplift) /
                   load_norm);
    outcome.newton = Contact::solve_newton(newton, load_norm, callbacks);
    if (!outcome.newton.converged &&
        outcome.failure != SolveStatus::floating_block)
      {
        if (iteration.singular_in_last_solve)
          outcome.failure = SolveStatus::no_equilibrium;
        else
          {
            outcome.failure       = SolveStatus::not_converged;
            outcome.failing_block = 0;
          }
      }
    return outcome;
  }
} // namespace FloorBlock::RigidBlocks
