#include <rigid/force_balance.h>
#include <rigid/joint_report.h>
#include <rigid/model.h>
#include <rigid/motion_predictor.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <utility>

namespace FloorBlock::RigidBlocks
{
  namespace
  {
    /** Fraction of a stage treated as its end (-). */
    constexpr double stage_end_tolerance = 1e-12;

    /** Factors at fraction @p target of @p stage (earlier stages complete). */
    LoadFactors
    stage_factors(const Loading::LoadStage stage, const double target)
    {
      switch (stage)
        {
          case Loading::LoadStage::gravity:
            return {target, 0., 0.};
          case Loading::LoadStage::support_pressure:
            return {1., target, 0.};
          case Loading::LoadStage::uplift:
            return {1., 1., target};
        }
      return {};
    }

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
      double      uplift = 0.;
      RigidSolveResult result;
    };
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
                             const double                    uplift_factor) const
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
    path.histories = joints.virgin_histories();
    const RigidSolverSettings &settings = description.solver;

    const std::vector<std::pair<Loading::LoadStage, unsigned int>> stages = {
      {Loading::LoadStage::gravity, description.steps.n_gravity},
      {Loading::LoadStage::support_pressure, description.steps.n_pressure},
      {Loading::LoadStage::uplift, description.steps.n_uplift}};

    for (const auto &[stage, n_increments] : stages)
      {
        if (n_increments == 0)
          continue;
        const double nominal_step = 1. / n_increments;
        double       reached      = 0.;
        double       step         = nominal_step;
        unsigned int n_failed     = 0;
        while (reached < 1.)
          {
            // A remainder below stage_end_tolerance is round-off of the
            // summed steps, not an increment of its own.
            const double target = reached + step >= 1. - stage_end_tolerance ?
                                    1. :
                                    reached + step;
            const auto   clock   = std::chrono::steady_clock::now();
            const LoadFactors factors = stage_factors(stage, target);
            const IncrementOutcome outcome =
              solve_load_state(joints,
                               block_load_list,
                               settings,
                               description.assembly.block_width,
                               factors,
                               predict_motions(joints,
                                               path.motions,
                                               path.uplift,
                                               factors.uplift),
                               path.histories);
            if (outcome.newton.converged)
              {
                IncrementReport increment;
                increment.stage             = stage;
                increment.gravity_factor    = factors.gravity;
                increment.support_factor    = factors.support;
                increment.uplift_factor     = factors.uplift;
                increment.n_iterations      = outcome.newton.n_iterations;
                increment.n_cutbacks        = n_failed;
                increment.relative_residual = outcome.newton.relative_residual;
                increment.counts            = outcome.newton.counts;
                increment.motions           = outcome.motions;
                increment.joints =
                  make_joint_reports(joints, outcome.responses, true);
                increment.relative_imbalance =
                  relative_imbalance(joints,
                                     increment.joints,
                                     block_load_list,
                                     factors.gravity,
                                     factors.support,
                                     description.assembly.block_width);
                path.motions   = outcome.motions;
                path.uplift    = factors.uplift;
                path.histories =
                  committed_histories(path.histories, outcome.responses);
                reached  = target;
                n_failed = 0;
                // Grow back after a cutback, never beyond the nominal step.
                step = std::min(nominal_step, 2. * step);
                increment.wall_time = seconds_since(clock);
                // Profiles only for the last increment unless asked:
                // drop the previous.
                if (!settings.profiles_of_every_increment &&
                    !path.result.increments.empty())
                  for (RigidJointReport &joint : path.result.increments.back().joints)
                    joint.profile.clear();
                path.result.increments.push_back(std::move(increment));
                continue;
              }
            std::ostringstream attempt;
            attempt << Loading::stage_name(stage) << " factor " << target << " (step "
                    << step << "): " << outcome.newton.failure_reason
                    << " (relative residual "
                    << outcome.newton.relative_residual << " after "
                    << outcome.newton.n_iterations << " iterations)";
            path.result.failed_attempts.push_back(attempt.str());
            if (++n_failed > settings.max_cutbacks)
              {
                path.result.status        = outcome.failure;
                path.result.failing_block = outcome.failing_block;
                path.result.message =
                  std::string("stage '") + Loading::stage_name(stage) + "' failed after " +
                  std::to_string(settings.max_cutbacks) +
                  " cutbacks: " + outcome.newton.failure_reason;
                path.result.wall_time = seconds_since(start);
                return path.result;
              }
            step /= 2.;
          }
      }
    path.result.wall_time = seconds_since(start);
    return path.result;
  }
} // namespace FloorBlock::RigidBlocks
