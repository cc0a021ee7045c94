// Which refinement converges the face joint's contact length under the
// exact (rigid) joint law (results/FINDINGS.md, section 7). A measurement
// program, not a test: CTest never runs it.
//
// From the scene's level-0 mesh (Studies::AdaptiveLevels, as `run`), each
// step refines toward size requests that are halved from step to step
// (AdaptiveLevels::solve_refined_toward, no coarsening, joints matched):
//  - the face joint's peak (the loaded corner's fillet) asks for h_c;
//  - points every h_j / 2 along the face joint's closed zone and a margin
//    of half its length beyond each end ask for h_j;
//  - cells farther away may grow by g per unit of distance,
//    h(x) = min_p (h_p + (g - 1)|x - x_p|).
// By default all three are halved per step (g - 1 too), so each step is a
// nested refinement of the whole neighbourhood of the zone with a gentler
// grading; --fixed-growth keeps g, --fixed-corner keeps h_c, which
// separates the three effects. The requests of a step come from the
// previous step's solution (peak and zone ends move).
//
// Usage:
//   floorblock_graded_zone_sequence <scene.prm> <h_c mm> <g> <h_j mm> <steps>
//       [--fixed-growth] [--fixed-corner] [--check] [--halvings N]
//       [--from-halving K] [--all-peaks] [--all-ends] [--set
//       "Section/Name=value"]...
// --check solves the last step once more with every cell halved and prints
// `run`'s two-grid estimate of the last step from it
// (Studies::refined_solve_error: 6 times the difference plus the ends'
// location uncertainty), i.e. what `run` would report for that step.
// --halvings N solves the last step with every cell halved 1..N times (the
// first is --check's solve when both are given): a nested uniform ladder
// on the graded mesh; --from-halving K skips the halvings below K (a ladder
// whose coarser levels are known is extended by its next level alone).
// --all-ends adds both ends of every joint (the blocks' corners, where the
// elastic field is singular) with size h_c. --all-peaks adds the
// peak of every other closed joint (vertical and bedding) with size h_c.
// The solves' files go to a folder under the system's temporary directory.

#include <compare/joint_name.h>
#include <parameters/scenario_parameters.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <studies/adaptive_levels.h>
#include <studies/error_estimate.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace
{
  using namespace FloorBlock;

  struct Options
  {
    std::string              scene_file;
    double                   corner_size   = 0.; // m
    double                   growth_rate   = 0.;
    double                   line_size     = 0.; // m
    int                      steps         = 0;
    bool                     fixed_growth  = false;
    bool                     fixed_corner  = false;
    bool                     check         = false;
    unsigned int             halvings      = 0;
    unsigned int             first_halving = 1;
    bool                     all_peaks     = false;
    bool                     all_ends      = false;
    std::vector<std::string> overrides;
  };

  Options
  parse(const int argc, char **argv)
  {
    if (argc < 6)
      {
        std::fprintf(
          stderr,
          "usage: %s <scene.prm> <h_c mm> <g> <h_j mm> <steps> "
          "[--fixed-growth] [--fixed-corner] [--check] [--halvings N] [--from-halving K] [--all-peaks] [--all-ends] [--set "
          "\"Section/Name=value\"]...\n",
          argv[0]);
        std::exit(2);
      }
    Options options;
    options.scene_file  = argv[1];
    options.corner_size = std::atof(argv[2]) * 1e-3;
    options.growth_rate = std::atof(argv[3]);
    options.line_size   = std::atof(argv[4]) * 1e-3;
    options.steps       = std::atoi(argv[5]);
    for (int k = 6; k < argc; ++k)
      {
        const std::string argument = argv[k];
        if (argument == "--fixed-growth")
          options.fixed_growth = true;
        else if (argument == "--fixed-corner")
          options.fixed_corner = true;
        else if (argument == "--check")
          options.check = true;
        else if (argument == "--all-peaks")
          options.all_peaks = true;
        else if (argument == "--all-ends")
          options.all_ends = true;
        else if (argument == "--halvings" && k + 1 < argc)
          options.halvings = static_cast<unsigned int>(std::atoi(argv[++k]));
        else if (argument == "--from-halving" && k + 1 < argc)
          options.first_halving =
            static_cast<unsigned int>(std::max(1, std::atoi(argv[++k])));
        else if (argument == "--set" && k + 1 < argc)
          options.overrides.push_back(argv[++k]);
        else
          {
            std::fprintf(stderr, "unknown argument '%s'\n", argument.c_str());
            std::exit(2);
          }
      }
    if (!(options.corner_size > 0. && options.growth_rate > 1. &&
          options.line_size > 0. && options.steps >= 0))
      {
        std::fprintf(stderr, "need h_c > 0, g > 1, h_j > 0, steps >= 0\n");
        std::exit(2);
      }
    return options;
  }

  const Contact::JointReport *
  face_joint(const Pipeline::FemOutcome &outcome, const std::string &name)
  {
    if (outcome.result.increments.empty())
      return nullptr;
    for (const auto &joint : outcome.result.increments.back().joints)
      if (joint.name == name)
        return &joint;
    return nullptr;
  }

  /** The requests of one step, from the face joint of the step before. */
  std::vector<Geometry::LocalSize>
  zone_requests(const Contact::JointReport &joint,
                const double                corner_size,
                const double                line_size)
  {
    std::vector<Geometry::LocalSize> requests{
      {{joint.peak_position[0], joint.peak_position[1]}, corner_size}};
    std::vector<Contact::JointNodeSample> nodes = joint.profile;
    std::sort(nodes.begin(), nodes.end(), [](const auto &a, const auto &b) {
      return a.arc_position < b.arc_position;
    });
    double first = 1e300, last = -1e300; // arc positions of the closed zone
    for (const auto &node : nodes)
      if (node.state != Contact::JointState::open)
        {
          first = std::min(first, node.arc_position);
          last  = std::max(last, node.arc_position);
        }
    if (first > last)
      return requests;
    const double margin = 0.5 * (last - first);
    for (std::size_t k = 1; k < nodes.size(); ++k)
      {
        const auto &a = nodes[k - 1], &b = nodes[k];
        if (b.arc_position < first - margin || a.arc_position > last + margin)
          continue;
        const int n = 1 + static_cast<int>(a.position.distance(b.position) /
                                           (0.5 * line_size));
        for (int i = 0; i <= n; ++i)
          {
            const double w = double(i) / n;
            requests.push_back(
              {{a.position[0] + w * (b.position[0] - a.position[0]),
                a.position[1] + w * (b.position[1] - a.position[1])},
               line_size});
          }
      }
    return requests;
  }

  void
  print_step(const int                   step,
             const double                corner_size,
             const double                growth_rate,
             const double                line_size,
             const Pipeline::FemOutcome &outcome,
             const std::string          &face,
             const double                wall_time)
  {
    const Contact::JointReport *joint = face_joint(outcome, face);
    std::printf("%4d %10.4g %8.4g %10.4g %9u %8.1f %9s %16.4f %14.4f %12.1f\n",
                step,
                corner_size * 1e3,
                growth_rate,
                line_size * 1e3,
                static_cast<unsigned int>(outcome.result.n_dofs),
                wall_time,
                outcome.converged ? "yes" : "no",
                joint ? joint->closed_length * 1e3 : 0.,
                joint ? joint->closed_length_uncertainty * 1e3 : 0.,
                joint ? joint->normal_force * 1e-3 : 0.);
    std::fflush(stdout);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Options                            options = parse(argc, argv);
  const auto                               scene =
    Parameters::read_scenario(options.scene_file, options.overrides);
  const std::string face = Compare::face_joint_name(scene.geometry.n_blocks);
  const std::filesystem::path folder =
    std::filesystem::temp_directory_path() /
    ("floorblock_graded_zone_sequence_" + std::to_string(::getpid()));

  Studies::AdaptiveLevels levels(scene,
                                 Studies::bounded_refinement({}, scene),
                                 0.);
  std::printf("step  h_c (mm)        g   h_j (mm)      DoFs  solve_s converged "
              "contact_length_mm uncertainty_mm  Q_kN_per_m\n");
  dealii::Timer        timer;
  Pipeline::FemOutcome outcome =
    levels.solve_next(Output::ResultFolder((folder / "step_0").string()),
                      false);
  print_step(0, 0., 0., 0., outcome, face, timer.wall_time());
  for (int step = 1; step <= options.steps && outcome.converged; ++step)
    {
      const Contact::JointReport *joint = face_joint(outcome, face);
      if (joint == nullptr)
        break;
      const double halving = std::exp2(-double(step - 1));
      const double corner_size =
        options.corner_size * (options.fixed_corner ? 1. : halving);
      const double                     growth_rate = options.fixed_growth ?
                                                       options.growth_rate :
                                                       1. + (options.growth_rate - 1.) * halving;
      const double                     line_size = options.line_size * halving;
      std::vector<Geometry::LocalSize> requests =
        zone_requests(*joint, corner_size, line_size);
      if (options.all_peaks)
        for (const auto &other : outcome.result.increments.back().joints)
          if (other.name != face && other.counts.n_closed() > 0)
            requests.push_back(
              {{other.peak_position[0], other.peak_position[1]}, corner_size});
      if (options.all_ends)
        for (const auto &other : outcome.result.increments.back().joints)
          if (!other.profile.empty())
            {
              const auto [first, last] =
                std::minmax_element(other.profile.begin(),
                                    other.profile.end(),
                                    [](const auto &a, const auto &b) {
                                      return a.arc_position < b.arc_position;
                                    });
              for (const auto *end : {&*first, &*last})
                requests.push_back(
                  {{end->position[0], end->position[1]}, corner_size});
            }
      timer.restart();
      outcome = levels.solve_refined_toward(
        requests,
        growth_rate,
        Output::ResultFolder(
          (folder / ("step_" + std::to_string(step))).string()),
        false);
      print_step(step,
                 corner_size,
                 growth_rate,
                 line_size,
                 outcome,
                 face,
                 timer.wall_time());
    }
  if (options.check && outcome.converged)
    {
      timer.restart();
      const Pipeline::FemOutcome halved =
        levels.solve_halved(Output::ResultFolder((folder / "check").string()));
      print_step(-1, 0., 0., 0., halved, face, timer.wall_time());
      const Output::FemErrorEstimate estimate =
        Studies::refined_solve_error(outcome, halved);
      if (estimate.available && estimate.joints.count(face) > 0)
        {
          const Output::FigureError &length =
            estimate.joints.at(face).contact_length;
          std::printf("check: contact length %.4f mm +- %.4f mm (%.3g %%), "
                      "halved %.4f mm\n",
                      length.value * 1e3,
                      length.absolute_error * 1e3,
                      100. * length.relative_error.value_or(0.),
                      length.refined_value * 1e3);
        }
      else
        std::printf("check: no estimate: %s\n", estimate.status_text.c_str());
    }
  // --check already solved the mesh halved once.
  for (unsigned int times =
         std::max(options.first_halving, options.check ? 2u : 1u);
       times <= options.halvings && outcome.converged;
       ++times)
    {
      timer.restart();
      const Pipeline::FemOutcome halved = levels.solve_halved(
        Output::ResultFolder(
          (folder / ("halved_" + std::to_string(times))).string()),
        times);
      print_step(
        -static_cast<int>(times), 0., 0., 0., halved, face, timer.wall_time());
    }
  std::printf("files: %s\n", folder.c_str());
  return outcome.converged ? 0 : 1;
}
