// Size requests of the adaptive re-meshing on synthetic states: a joint
// whose closed zone ends mid-way with a quadratic pressure peak, and a
// displacement field whose gradient jumps grow in one direction.
#include <geometry/local_size_field.h>

#include <deal.II/base/function.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/numerics/vector_tools.h>

#include <gtest/gtest.h>
#include <refinement/size_targets.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace
{
  using namespace FloorBlock;
  using Contact::JointNodeSample;
  using Contact::JointReport;
  using Contact::JointState;

  constexpr double spacing    = 0.1; // m between joint nodes
  constexpr double zone_start = 1.5; // m: closed above, open below
  constexpr double peak       = 1e6; // Pa at the top (y = 2 m)

  /**
   * A vertical joint, nodes every 0.1 m from y = 0 to 2 m; closed for
   * y > 1.5 m with t = peak ((y - 1.5)/0.5)^2, so the jumps between
   * neighbours from y = 1.5 up are 0.04, 0.12, 0.20, 0.28, 0.36 x peak.
   */
  JointReport
  vertical_joint()
  {
    JointReport joint;
    joint.name = "vertical 3";
    for (unsigned int k = 0; k <= 20; ++k)
      {
        JointNodeSample sample;
        sample.arc_position    = k * spacing;
        sample.position        = dealii::Point<2>(0., k * spacing);
        const double rise      = (sample.position[1] - zone_start) / 0.5;
        const bool   closed    = sample.position[1] > zone_start + 1e-9;
        sample.state           = closed ? JointState::stick : JointState::open;
        sample.normal_traction = closed ? peak * rise * rise : 0.;
        joint.profile.push_back(sample);
      }
    return joint;
  }

  /** An open joint without traction: nothing to refine. */
  JointReport
  open_joint()
  {
    JointReport joint;
    joint.name = "bedding 1";
    for (unsigned int k = 0; k <= 10; ++k)
      {
        JointNodeSample sample;
        sample.arc_position = k * spacing;
        sample.position     = dealii::Point<2>(k * spacing, -1.);
        joint.profile.push_back(sample);
      }
    return joint;
  }

  std::set<long>
  heights_in_mm(const std::vector<Geometry::LocalSize> &targets)
  {
    std::set<long> heights;
    for (const auto &target : targets)
      heights.insert(std::lround(target.position.y * 1e3));
    return heights;
  }

  TEST(JointSizeTargets, MarkZoneEndAndSteepTraction)
  {
    Refinement::RefinementSettings settings;
    // Threshold 0.5 x 0.36 = 0.18 x peak: the three segments nearest the
    // top are steep; 1.5-1.6 m is the state change, which also marks its
    // neighbours 1.4-1.5 and 1.6-1.7 m; below 1.4 m nothing.
    settings.traction_jump_fraction = 0.5;
    settings.smallest_size          = 1e-3;
    const auto targets =
      Refinement::joint_size_targets({vertical_joint(), open_joint()},
                                     settings);
    // Two nodes per marked segment, six segments from 1.4 to 2.0 m.
    EXPECT_EQ(targets.size(), 12u);
    EXPECT_EQ(heights_in_mm(targets),
              (std::set<long>{1400, 1500, 1600, 1700, 1800, 1900, 2000}));
    // Requests come in pairs, one pair per marked segment.
    for (std::size_t k = 0; k + 1 < targets.size(); k += 2)
      {
        EXPECT_DOUBLE_EQ(targets[k].position.x, 0.); // none on the open joint
        // The zone end (segments 1.4-1.5, 1.5-1.6, 1.6-1.7 m) asks for the
        // spacing / zone_end_refinement, the steep segments above for half.
        const double lower =
          std::min(targets[k].position.y, targets[k + 1].position.y);
        const double divisor = lower < 1.65 ? settings.zone_end_refinement : 2.;
        EXPECT_NEAR(targets[k].size, spacing / divisor, 1e-15) << lower;
        EXPECT_NEAR(targets[k + 1].size, spacing / divisor, 1e-15) << lower;
      }
  }

  TEST(JointSizeTargets, RequestsStopAtTheSmallestSize)
  {
    Refinement::RefinementSettings settings;
    settings.traction_jump_fraction = 0.5;
    settings.smallest_size          = 0.08; // above half the spacing
    for (const auto &target :
         Refinement::joint_size_targets({vertical_joint()}, settings))
      EXPECT_DOUBLE_EQ(target.size, 0.08);
  }

  TEST(JointSizeTargets, JointsWithoutTractionOrStateChangeAreNotRefined)
  {
    Refinement::RefinementSettings settings;
    settings.traction_jump_fraction = 0.; // even a zero threshold
    EXPECT_TRUE(
      Refinement::joint_size_targets({open_joint()}, settings).empty());
  }

  /** u = (exp(4x), 0): second derivative, hence Kelly jumps, grow with x. */
  class SteepField : public dealii::Function<2>
  {
  public:
    SteepField()
      : dealii::Function<2>(2)
    {}
    double
    value(const dealii::Point<2> &point,
          const unsigned int      component) const override
    {
      return component == 0 ? std::exp(4. * point[0]) : 0.;
    }
  };

  TEST(BulkSizeTargets, LargestKellyIndicatorsAskForHalfTheirSize)
  {
    constexpr unsigned int   n_per_side = 8;
    dealii::Triangulation<2> triangulation;
    dealii::GridGenerator::subdivided_hyper_cube(triangulation, n_per_side);
    const Fem::FeSpace<2>                 space(triangulation, 1);
    dealii::TrilinosWrappers::MPI::Vector solution(space.locally_owned_dofs(),
                                                   MPI_COMM_SELF);
    dealii::VectorTools::interpolate(space.mapping(),
                                     space.dof_handler(),
                                     SteepField(),
                                     solution);
    Refinement::RefinementSettings settings;
    settings.bulk_fraction = 0.1;
    const auto targets     = Refinement::bulk_size_targets(
      triangulation, Refinement::kelly_indicator(space, solution), settings);
    // ceil(0.1 x 64) = 7 cells, each 1/8 wide: requests of 1/16 m.
    ASSERT_EQ(targets.size(), 7u);
    for (const auto &target : targets)
      {
        EXPECT_NEAR(target.size, 1. / (2. * n_per_side), 1e-14);
        // du/dx of the interpolant is constant per cell, so the jumps sit
        // on the vertical faces and grow like exp(4x). Kelly sums the
        // jumps over a cell's faces (boundary faces add nothing): the
        // column x in [6/8, 7/8] (centre 0.8125) has the two largest,
        // e^3.5 and e^3 (the last column only one), and 8 equal cells.
        EXPECT_NEAR(target.position.x, 0.8125, 1e-12);
      }
  }

  TEST(MergeSizeRequests, OnlyRequestsThatRefineAreKept)
  {
    constexpr double                 growth   = 1.3;
    std::vector<Geometry::LocalSize> requests = {{{0., 0.}, 0.01}};
    Refinement::merge_size_requests(
      requests,
      {{{0., 0.}, 0.01},   // repeated: adds nothing
       {{0.1, 0.}, 0.05},  // existing gives 0.01 + 0.3 x 0.1 = 0.04 < 0.05
       {{0.1, 0.}, 0.02},  // smaller than 0.04: kept
       {{0.11, 0.}, 0.02}, // the one above gives 0.023 here: kept
       {{0.1, 0.}, 0.02}}, // duplicate of a kept one: dropped
      growth);
    ASSERT_EQ(requests.size(), 3u);
    EXPECT_DOUBLE_EQ(requests[1].size, 0.02);
    EXPECT_DOUBLE_EQ(requests[2].position.x, 0.11);
  }

  TEST(LocalSizeField, GradedMinimumOverRequests)
  {
    const std::vector<Geometry::LocalSize> requests = {{{0., 0.}, 0.01},
                                                       {{1., 0.}, 0.002}};
    constexpr double                       growth   = 1.3;
    // At (0.5, 0): 0.01 + 0.3 x 0.5 = 0.16 vs 0.002 + 0.3 x 0.5 = 0.152.
    EXPECT_NEAR(Geometry::local_size_at(requests, growth, {0.5, 0.}),
                0.152,
                1e-15);
    EXPECT_NEAR(Geometry::local_size_at(requests, growth, {0., 0.}),
                0.01,
                1e-15);
    EXPECT_GT(Geometry::local_size_at({}, growth, {0., 0.}), 1e300);
  }

  TEST(LocalSizeField, ClassesRoundDownByAtMostAQuarterOctave)
  {
    for (const double size : {1e-3, 0.0037, 0.01, 0.02, 0.25, 0.7})
      {
        const double rounded = Geometry::local_size_class(size);
        EXPECT_LE(rounded, size * (1. + 1e-15));
        EXPECT_GT(rounded, size / std::pow(2., 0.25) * (1. - 1e-15));
      }
    // Powers of two are their own class.
    EXPECT_DOUBLE_EQ(Geometry::local_size_class(0.125), 0.125);
  }
} // namespace
