#include <loading/load_path.h>
#include <rigid/force_balance.h>
#include <rigid/joint_report.h>
#include <rigid/model.h>
#include <rigid/motion_predictor.h>

#include <chrono>
#include <sstream>
#include <utility>

namespace FloorBlock::RigidBlocks
{
  namespace
  {
    double
    seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                           start)
        .count();
    }

    /** The loading path as it runs: committed state and result so far. */
    struct PathState
    {
      std::vector<BlockMotion> motions;
      JointHistories           histories;
      /** Uplift factor of the committed state (-). */
      double           uplift = 0.;
      RigidSolveResult result;
    };

    /** The report of a converged increment, before its wall time. */
    IncrementReport
    increment_report(const JointSet                &joints,
                     const std::vector<BlockLoads> &loads,
                     const double                   block_width,
                     const Loading::LoadState      &state,
                     const IncrementOutcome        &outcome)
    {
      IncrementReport increment;
      increment.stage             = state.stage;
      increment.gravity_factor    = state.factors.gravity;
      increment.support_factor    = state.factors.support;
      increment.uplift_factor     = state.factors.uplift;
      increment.n_iterations      = outcome.newton.n_iterations;
      increment.n_cutbacks        = state.n_cutbacks;
      increment.relative_residual = outcome.newton.relative_residual;
      increment.counts            = outcome.newton.counts;
      increment.motions           = outcome.motions;
      increment.joints = make_joint_reports(joints, outcome.responses, true);
      increment.relative_imbalance = relative_imbalance(joints,
                                                        increment.joints,
                                                        loads,
                                                        state.factors.gravity,
                                                        state.factors.support,
                                                        block_width);
      return increment;
    }
  } // namespace

  Model::Model(const ModelDescription &description_in)
    : description((validate(description_in), description_in))
    , joints(description)
    , block_load_list(block_loads(description))
  {}

  const JointSet &
  Model::joint_set() const
  {
    return joints;
  }

  const std::vector<BlockLoads> &
  Model::loads() const
  {
    return block_load_list;
  }

  std::vector<RigidJointReport>
  Model::evaluate_prescribed(const std::vector<BlockMotion> &motions,
                             const double uplift_factor) const
  {
    const JointResponses responses =
      joints.evaluate(motions, uplift_factor, joints.virgin_histories());
    return make_joint_reports(joints, responses, true);
  }

  RigidSolveResult
  Model::solve() const
  {
    const auto start = std::chrono::steady_clock::now();
    PathState  path;
    path.motions.resize(joints.n_blocks());
    path.histories                      = joints.virgin_histories();
    const RigidSolverSettings &settings = description.solver;

    IncrementOutcome                      outcome;
    std::chrono::steady_clock::time_point clock;
    Loading::LoadPathCallbacks            callbacks;
    callbacks.solve = [&](const Loading::LoadState &state,
                          const Loading::FailedStartRecorder &,
                          std::string &reason) {
      clock   = std::chrono::steady_clock::now();
      outcome = solve_load_state(joints,
                                 block_load_list,
                                 settings,
                                 description.assembly.block_width,
                                 state.factors,
                                 predict_motions(joints,
                                                 path.motions,
                                                 path.uplift,
                                                 state.factors.uplift),
                                 path.histories);
      if (outcome.newton.converged)
        return true;
      std::ostringstream why;
      why << outcome.newton.failure_reason << " (relative residual "
          << outcome.newton.relative_residual << " after "
          << outcome.newton.n_iterations << " iterations)";
      reason = why.str();
      return false;
    };
    callbacks.commit = [&](const Loading::LoadState &state) {
      IncrementReport increment =
        increment_report(joints,
                         block_load_list,
                         description.assembly.block_width,
                         state,
                         outcome);
      path.motions   = outcome.motions;
      path.uplift    = state.factors.uplift;
      path.histories = committed_histories(path.histories, outcome.responses);
      increment.wall_time = seconds_since(clock);
      // Profiles only for the last increment unless asked: drop the
      // previous.
      if (!settings.profiles_of_every_increment &&
          !path.result.increments.empty())
        for (RigidJointReport &joint : path.result.increments.back().joints)
          joint.profile.clear();
      path.result.increments.push_back(std::move(increment));
    };
    // solve_load_state works on copies of the committed state.
    callbacks.discard = [](const std::string &) {};
    // No interrupt check: a rigid solve is short, and sweeps check
    // between cases.

    // Gravity always has its own stage in the rigid model (README.md);
    // raising it with the support load is the FE model's path only.
    Loading::LoadSteps steps    = description.steps;
    steps.gravity_with_pressure = false;
    const Loading::LoadPathOutcome path_outcome =
      Loading::follow_load_path(steps, settings.max_cutbacks, callbacks);
    path.result.failed_attempts = path_outcome.failed_attempts;
    if (!path_outcome.completed)
      {
        path.result.status        = outcome.failure;
        path.result.failing_block = outcome.failing_block;
        path.result.message       = std::string("stage '") +
                              Loading::stage_name(path_outcome.failed_stage) +
                              "' failed after " +
                              std::to_string(settings.max_cutbacks) +
                              " cutbacks: " + outcome.newton.failure_reason;
      }
    path.result.wall_time = seconds_since(start);
    return path.result;
  }
} // namespace FloorBlock::RigidBlocks
