// Unit tests of the Alart-Curnier complementarity function of Coulomb
// contact (contact/complementarity.h) without a mesh: generalized
// derivatives against central differences, C = 0 exactly at the solutions
// for every complementarity parameter, C != 0 where a condition is broken,
// the open/stick/slip transitions, 3D cone = 2D interval, and a semismooth
// Newton solve of one node on a spring.
#include <contact/complementarity.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <vector>

namespace
{
  using namespace FloorBlock::Contact;

  constexpr double pressure_scale       = 1e6; // Pa, contact pressure
  constexpr double friction_coefficient = 0.6; // -
  constexpr double test_cohesion        = 1e5; // Pa
  constexpr double epsilon = std::numeric_limits<double>::epsilon();
  /** Complementarity parameters spanning the brief's range (Pa/m). */
  const std::vector<double> parameter_range = {1e6, 1e8, 1e10, 1e12, 1e14};

  template <int dim>
  CoulombComplementarity<dim>
  make_law(const double normal_parameter,
           const double tangential_parameter,
           const double cohesion = 0.)
  {
    ComplementarityParameters parameters;
    parameters.friction_coefficient = friction_coefficient;
    parameters.cohesion             = cohesion;
    parameters.normal_parameter     = normal_parameter;
    parameters.tangential_parameter = tangential_parameter;
    return CoulombComplementarity<dim>(parameters);
  }

  /**
   * A unit normal off the axes and an orthonormal tangent basis of its
   * plane: 2D n = (0.6, 0.8), 3D n = (1, 2, 2)/3.
   */
  template <int dim>
  struct Frame
  {
    dealii::Tensor<1, dim>                      normal;
    std::array<dealii::Tensor<1, dim>, dim - 1> tangents;
  };

  template <int dim>
  Frame<dim>
  make_frame()
  {
    Frame<dim> frame;
    if constexpr (dim == 2)
      {
        frame.normal      = dealii::Tensor<1, 2>({0.6, 0.8});
        frame.tangents[0] = dealii::Tensor<1, 2>({0.8, -0.6});
      }
    else
      {
        frame.normal      = dealii::Tensor<1, 3>({1., 2., 2.}) / 3.;
        frame.tangents[0] = dealii::Tensor<1, 3>({2., 1., -2.}) / 3.;
        frame.tangents[1] = dealii::Tensor<1, 3>({-2., 2., -1.}) / 3.;
      }
    return frame;
  }

  /** The inputs of one evaluation. */
  template <int dim>
  struct PairInput
  {
    double                 normal_multiplier = 0.; // Pa
    dealii::Tensor<1, dim> tangential_multiplier;  // Pa
    double                 gap = 0.;               // m
    dealii::Tensor<1, dim> slip_increment;         // m
  };

  template <int dim>
  ComplementarityResponse<dim>
  evaluate(const CoulombComplementarity<dim> &law, const PairInput<dim> &input)
  {
    return law.evaluate(input.normal_multiplier,
                        input.tangential_multiplier,
                        input.gap,
                        input.slip_increment);
  }

  /** A random tangent-plane vector of length @p length. */
  template <int dim>
  dealii::Tensor<1, dim>
  random_tangent(const Frame<dim> &frame,
                 const double      length,
                 std::mt19937     &engine)
  {
    std::normal_distribution<double> gaussian;
    dealii::Tensor<1, dim>           vector;
    for (const auto &tangent : frame.tangents)
      vector += gaussian(engine) * tangent;
    return length * vector / vector.norm();
  }

  /**
   * A random input in @p state whose augmented multipliers lie at least
   * 20 % of their scale away from every kink (xi_n = 0, |xi_t| = R):
   * xi_n and xi_t are drawn first, then g and Delta s solved for.
   */
  template <int dim>
  PairInput<dim>
  random_input(const JointState                   state,
               const CoulombComplementarity<dim> &law,
               const Frame<dim>                  &frame,
               std::mt19937                      &engine)
  {
    const ComplementarityParameters       &constants = law.parameters();
    std::uniform_real_distribution<double> unit(0., 1.);
    auto between = [&](const double low, const double high) {
      return low + (high - low) * unit(engine);
    };
    PairInput<dim> input;
    input.normal_multiplier = between(-1., 1.) * pressure_scale;
    input.tangential_multiplier =
      random_tangent(frame, between(0., 1.) * pressure_scale, engine);
    const double augmented_normal = (state == JointState::open ? -1. : 1.) *
                                    between(0.2, 1.) * pressure_scale;
    input.gap =
      (input.normal_multiplier - augmented_normal) / constants.normal_parameter;
    const double radius =
      constants.cohesion + constants.friction_coefficient * augmented_normal;
    const double augmented_magnitude =
      state == JointState::open  ? between(0., 1.) * pressure_scale :
      state == JointState::stick ? between(0.1, 0.8) * radius :
                                   between(1.25, 3.) * radius;
    const dealii::Tensor<1, dim> augmented_tangential =
      random_tangent(frame, augmented_magnitude, engine);
    input.slip_increment =
      (augmented_tangential - input.tangential_multiplier) /
      constants.tangential_parameter;
    return input;
  }

  /** (C_n, C_t) as one vector of dim + 1 entries: [C_n, C_t[0], ...]. */
  template <int dim>
  std::array<double, dim + 1>
  stacked(const ComplementarityResponse<dim> &response)
  {
    std::array<double, dim + 1> values;
    values[0] = response.normal_residual;
    for (unsigned int i = 0; i < dim; ++i)
      values[i + 1] = response.tangential_residual[i];
    return values;
  }

  /**
   * Largest central-difference error of the derivative columns at @p input,
   * each column divided by its natural scale (1 for the multipliers, c_n for
   * g, c_t for Delta s), over all inputs: lambda_n, every component of
   * lambda_t, g, every component of Delta s.
   */
  template <int dim>
  double
  largest_difference_error(const CoulombComplementarity<dim> &law,
                           const PairInput<dim>              &input)
  {
    const ComplementarityParameters       &constants   = law.parameters();
    const ComplementarityResponse<dim>     response    = evaluate(law, input);
    const ComplementarityDerivatives<dim> &derivatives = response.derivatives;
    // Steps that move an augmented multiplier by 1 Pa, below 5e-5 of the
    // distance to the nearest kink (>= 0.2 xi_n >= 2e5 Pa, >= 0.2 R >=
    // 2.4e4 Pa): both sides stay on one smooth branch. Truncation ~
    // (step / |xi_t|)^2 <= 1e-10 on the slip branch (the only curved one);
    // round-off ~ eps |C| / (1 Pa) ~ 1e-9 with |C| <~ 4e6 Pa.
    const double multiplier_step = 1.;                                  // Pa
    const double gap_step        = 1. / constants.normal_parameter;     // m
    const double slip_step       = 1. / constants.tangential_parameter; // m

    double largest_error = 0.;
    auto   check_column  = [&](const auto                        &perturb,
                            const double                       step,
                            const double                       scale,
                            const std::array<double, dim + 1> &expected) {
      PairInput<dim> plus = input, minus = input;
      perturb(plus, step);
      perturb(minus, -step);
      const auto plus_response  = evaluate(law, plus);
      const auto minus_response = evaluate(law, minus);
      EXPECT_EQ(plus_response.state, response.state);
      EXPECT_EQ(minus_response.state, response.state);
      const auto plus_values  = stacked(plus_response);
      const auto minus_values = stacked(minus_response);
      for (unsigned int row = 0; row < dim + 1; ++row)
        largest_error =
          std::max(largest_error,
                   std::abs((plus_values[row] - minus_values[row]) /
                              (2. * step) -
                            expected[row]) /
                     scale);
    };

    std::array<double, dim + 1> expected;
    expected[0] = derivatives.normal_by_normal_multiplier;
    for (unsigned int i = 0; i < dim; ++i)
      expected[i + 1] = derivatives.tangential_by_normal_multiplier[i];
    check_column([](PairInput<dim> &point,
                    const double    step) { point.normal_multiplier += step; },
                 multiplier_step,
                 1.,
                 expected);

    expected[0] = derivatives.normal_by_gap;
    for (unsigned int i = 0; i < dim; ++i)
      expected[i + 1] = derivatives.tangential_by_gap[i];
    check_column([](PairInput<dim> &point,
                    const double    step) { point.gap += step; },
                 gap_step,
                 constants.normal_parameter,
                 expected);

    for (unsigned int column = 0; column < dim; ++column)
      {
        expected[0] = 0.; // C_n depends on lambda_n and g only
        for (unsigned int i = 0; i < dim; ++i)
          expected[i + 1] =
            derivatives.tangential_by_tangential_multiplier[i][column];
        check_column(
          [column](PairInput<dim> &point, const double step) {
            point.tangential_multiplier[column] += step;
          },
          multiplier_step,
          1.,
          expected);

        for (unsigned int i = 0; i < dim; ++i)
          expected[i + 1] = derivatives.tangential_by_slip_increment[i][column];
        check_column(
          [column](PairInput<dim> &point, const double step) {
            point.slip_increment[column] += step;
          },
          slip_step,
          constants.tangential_parameter,
          expected);
      }
    return largest_error;
  }

  template <int dim>
  void
  check_derivatives_against_differences()
  {
    // 1e-6 relative to the column's scale; the step choice above predicts
    // 1e-9 or better (measured 1.6e-10), and a wrong or missing term is of
    // order mu rho or more (0.6 x 0.33 on the slip branch), far above.
    constexpr double                tolerance = 1e-6;
    constexpr unsigned int          n_points  = 20;
    const Frame<dim>                frame     = make_frame<dim>();
    std::mt19937                    engine(2008 + dim);
    const std::array<JointState, 3> states = {
      {JointState::open, JointState::stick, JointState::slip}};
    std::array<double, 3> largest_by_state{};
    for (const double parameter : {1e6, 1e10, 1e14}) // Pa/m
      for (const double cohesion : {0., test_cohesion})
        {
          // c_t a decade below c_n: the two parameters enter separately.
          const auto law = make_law<dim>(parameter, 0.1 * parameter, cohesion);
          for (unsigned int s = 0; s < states.size(); ++s)
            for (unsigned int point = 0; point < n_points; ++point)
              {
                const PairInput<dim> input =
                  random_input(states[s], law, frame, engine);
                ASSERT_EQ(evaluate(law, input).state, states[s]);
                const double error = largest_difference_error(law, input);
                EXPECT_LE(error, tolerance)
                  << "dim " << dim << " c_n " << parameter << " cohesion "
                  << cohesion << " state " << int(states[s]);
                largest_by_state[s] = std::max(largest_by_state[s], error);
              }
        }
    std::cout << "dim " << dim
              << ": largest scaled difference error open/stick/slip "
              << largest_by_state[0] << " / " << largest_by_state[1] << " / "
              << largest_by_state[2] << '\n';
  }

  TEST(Complementarity, DerivativesMatchCentralDifferences)
  {
    check_derivatives_against_differences<2>();
    check_derivatives_against_differences<3>();
  }

  template <int dim>
  void
  check_zero_at_solutions()
  {
    const Frame<dim>                       frame = make_frame<dim>();
    std::mt19937                           engine(13 + dim);
    std::uniform_real_distribution<double> unit(0., 1.);
    // Open and stick are exact: C is lambda, c_n * 0 or c_t * 0. Slip
    // computes lambda_t - R e with e = Delta s/|Delta s| rounded: a few
    // eps of R.
    const double slip_tolerance = 4. * epsilon;
    for (const double normal_parameter : parameter_range)
      for (const double tangential_parameter : parameter_range)
        for (const double cohesion : {0., test_cohesion})
          {
            const auto law =
              make_law<dim>(normal_parameter, tangential_parameter, cohesion);
            for (unsigned int sample = 0; sample < 5; ++sample)
              {
                const double pressure = (0.1 + unit(engine)) * pressure_scale;
                const double radius =
                  cohesion + friction_coefficient * pressure;

                PairInput<dim> open;
                open.gap = (0.01 + unit(engine)) * 1e-3; // m
                open.slip_increment =
                  random_tangent(frame, unit(engine) * 1e-3, engine);
                const auto open_response = evaluate(law, open);
                EXPECT_EQ(open_response.state, JointState::open);
                EXPECT_EQ(open_response.normal_residual, 0.);
                EXPECT_EQ(open_response.tangential_residual.norm(), 0.);

                PairInput<dim> stick;
                stick.normal_multiplier = pressure;
                stick.tangential_multiplier =
                  random_tangent(frame, 0.99 * unit(engine) * radius, engine);
                const auto stick_response = evaluate(law, stick);
                EXPECT_EQ(stick_response.state, JointState::stick);
                EXPECT_EQ(stick_response.normal_residual, 0.);
                EXPECT_EQ(stick_response.tangential_residual.norm(), 0.);

                // Slip: the multiplier, the traction on side A, points
                // along the slip of B; the traction on B, -lambda_t,
                // opposes it.
                PairInput<dim> slip;
                slip.normal_multiplier = pressure;
                slip.slip_increment =
                  random_tangent(frame, (0.01 + unit(engine)) * 1e-3, engine);
                slip.tangential_multiplier =
                  radius * slip.slip_increment / slip.slip_increment.norm();
                const auto slip_response = evaluate(law, slip);
                EXPECT_EQ(slip_response.state, JointState::slip);
                EXPECT_EQ(slip_response.normal_residual, 0.);
                EXPECT_LE(slip_response.tangential_residual.norm(),
                          slip_tolerance * radius)
                  << "c_n " << normal_parameter << " c_t "
                  << tangential_parameter;
              }
          }
  }

  TEST(Complementarity, ZeroAtSolutionsForEveryParameter)
  {
    check_zero_at_solutions<2>();
    check_zero_at_solutions<3>();
  }

  template <int dim>
  void
  check_nonzero_at_violations()
  {
    const Frame<dim>             frame        = make_frame<dim>();
    const dealii::Tensor<1, dim> tangent      = frame.tangents[0];
    constexpr double             pressure     = pressure_scale;
    constexpr double             small_length = 1e-6; // m
    // The violations below are exact expressions of the branch taken; the
    // relative bound 1e-14 is round-off of one product or projection.
    constexpr double relative = 1e-14;
    for (const double normal_parameter : parameter_range)
      for (const double tangential_parameter : parameter_range)
        {
          const auto   law    = make_law<dim>(normal_parameter,
                                         tangential_parameter,
                                         test_cohesion);
          const double radius = test_cohesion + friction_coefficient * pressure;

          PairInput<dim> penetration; // g < 0, lambda_n = 0
          penetration.gap       = -small_length;
          const auto penetrated = evaluate(law, penetration);
          EXPECT_NEAR(penetrated.normal_residual,
                      -normal_parameter * small_length,
                      relative * normal_parameter * small_length);

          PairInput<dim> tension; // lambda_n < 0 at g = 0
          tension.normal_multiplier = -pressure;
          const auto pulled         = evaluate(law, tension);
          EXPECT_EQ(pulled.state, JointState::open);
          EXPECT_EQ(pulled.normal_residual, -pressure);

          PairInput<dim> open_with_shear; // g > 0 carrying shear
          open_with_shear.gap                   = small_length;
          open_with_shear.tangential_multiplier = pressure * tangent;
          EXPECT_EQ(evaluate(law, open_with_shear).tangential_residual.norm(),
                    pressure);

          PairInput<dim> beyond_cone; // |lambda_t| > R, Delta s = 0
          beyond_cone.normal_multiplier     = pressure;
          beyond_cone.tangential_multiplier = 1.5 * radius * tangent;
          const auto beyond                 = evaluate(law, beyond_cone);
          EXPECT_EQ(beyond.state, JointState::slip);
          EXPECT_NEAR(beyond.tangential_residual * tangent,
                      0.5 * radius,
                      relative * radius);

          // Slip while the shear is inside the cone: either the stick
          // branch (|C_t| = c_t |Delta s|) or the slip branch
          // (|C_t| >= R - |lambda_t|) sees it.
          PairInput<dim> slipping_inside;
          slipping_inside.normal_multiplier     = pressure;
          slipping_inside.tangential_multiplier = 0.5 * radius * tangent;
          slipping_inside.slip_increment        = small_length * tangent;
          EXPECT_GE(evaluate(law, slipping_inside).tangential_residual.norm(),
                    (1. - relative) *
                      std::min(tangential_parameter * small_length,
                               0.5 * radius));

          // Wrong sign: multiplier on the cone but against the slip.
          PairInput<dim> wrong_sign        = slipping_inside;
          wrong_sign.tangential_multiplier = -radius * tangent;
          EXPECT_GE(evaluate(law, wrong_sign).tangential_residual.norm(),
                    (1. - relative) *
                      std::min(tangential_parameter * small_length,
                               2. * radius));
        }
  }

  TEST(Complementarity, NonzeroWhereAConditionIsViolated)
  {
    check_nonzero_at_violations<2>();
    check_nonzero_at_violations<3>();
  }

  template <int dim>
  void
  check_gap_sweep()
  {
    // lambda_n = 0: closed iff c_n g <= 0, i.e. at g = 0 for every c_n;
    // C_n = c_n g on the closed side and 0 (= lambda_n) on the open side,
    // continuous through the switch.
    const auto       law       = make_law<dim>(1e10, 1e10);
    constexpr double gap_scale = 1e-4; // m
    constexpr int    n_steps   = 10;
    for (int step = -n_steps; step <= n_steps; ++step)
      {
        PairInput<dim> input;
        input.gap           = gap_scale * step / n_steps;
        const auto response = evaluate(law, input);
        EXPECT_EQ(response.state == JointState::open, step > 0)
          << "g = " << input.gap;
        EXPECT_EQ(response.normal_residual, step > 0 ? 0. : 1e10 * input.gap);
      }
  }

  template <int dim>
  void
  check_shear_sweep()
  {
    // g = 0, Delta s = 0, lambda_n = P: stick iff |lambda_t| <= R; C_t = 0
    // up to R and grows as |lambda_t| - R beyond (continuous).
    const Frame<dim> frame = make_frame<dim>();
    const auto       law   = make_law<dim>(1e10, 1e10, test_cohesion);
    const double radius = test_cohesion + friction_coefficient * pressure_scale;
    std::mt19937 engine(7);
    const dealii::Tensor<1, dim> direction = random_tangent(frame, 1., engine);
    constexpr int                n_steps   = 10;
    for (int step = 0; step <= 2 * n_steps; ++step)
      {
        const double   ratio = double(step) / n_steps; // |lambda_t| / R
        PairInput<dim> input;
        input.normal_multiplier     = pressure_scale;
        input.tangential_multiplier = ratio * radius * direction;
        const auto response         = evaluate(law, input);
        EXPECT_EQ(response.state,
                  ratio <= 1. ? JointState::stick : JointState::slip)
          << "|lambda_t|/R = " << ratio;
        EXPECT_NEAR(response.tangential_residual.norm(),
                    std::max(0., ratio - 1.) * radius,
                    1e-14 * radius);
      }
  }

  TEST(Complementarity, StateTransitions)
  {
    check_gap_sweep<2>();
    check_gap_sweep<3>();
    check_shear_sweep<2>();
    check_shear_sweep<3>();
  }

  TEST(Complementarity, ConeReducesToIntervalIn2D)
  {
    // A 3D input whose tangential vectors lie along one tangent axis gives
    // the 2D answer on that axis (and nothing on the other), in every
    // state and for both signs.
    const Frame<2> frame_2d = make_frame<2>();
    const Frame<3> frame_3d = make_frame<3>();
    const auto     law_2d   = make_law<2>(1e10, 1e9, test_cohesion);
    const auto     law_3d   = make_law<3>(1e10, 1e9, test_cohesion);
    std::mt19937   engine(3);
    std::uniform_real_distribution<double> symmetric(-1., 1.);
    for (unsigned int sample = 0; sample < 200; ++sample)
      {
        const double normal_multiplier = symmetric(engine) * pressure_scale;
        const double gap               = symmetric(engine) * 1e-4;
        const double shear             = symmetric(engine) * pressure_scale;
        const double slip              = symmetric(engine) * 1e-3;
        const auto   response_2d       = law_2d.evaluate(normal_multiplier,
                                                 shear * frame_2d.tangents[0],
                                                 gap,
                                                 slip * frame_2d.tangents[0]);
        const auto   response_3d       = law_3d.evaluate(normal_multiplier,
                                                 shear * frame_3d.tangents[0],
                                                 gap,
                                                 slip * frame_3d.tangents[0]);
        const auto  &tangent_2d        = frame_2d.tangents[0];
        const auto  &tangent_3d        = frame_3d.tangents[0];
        const auto  &other_3d          = frame_3d.tangents[1];
        const auto  &derivatives_2d    = response_2d.derivatives;
        const auto  &derivatives_3d    = response_3d.derivatives;
        // Same formulas, other rounding of the rotated components.
        const double tolerance = 1e-14;
        ASSERT_EQ(response_2d.state, response_3d.state);
        EXPECT_EQ(response_2d.normal_residual, response_3d.normal_residual);
        EXPECT_NEAR(response_2d.tangential_residual * tangent_2d,
                    response_3d.tangential_residual * tangent_3d,
                    tolerance * pressure_scale);
        EXPECT_NEAR(response_3d.tangential_residual * other_3d,
                    0.,
                    tolerance * pressure_scale);
        EXPECT_EQ(derivatives_2d.normal_by_normal_multiplier,
                  derivatives_3d.normal_by_normal_multiplier);
        EXPECT_EQ(derivatives_2d.normal_by_gap, derivatives_3d.normal_by_gap);
        EXPECT_NEAR(tangent_2d *
                      derivatives_2d.tangential_by_tangential_multiplier *
                      tangent_2d,
                    tangent_3d *
                      derivatives_3d.tangential_by_tangential_multiplier *
                      tangent_3d,
                    tolerance);
        EXPECT_NEAR(tangent_2d * derivatives_2d.tangential_by_slip_increment *
                      tangent_2d,
                    tangent_3d * derivatives_3d.tangential_by_slip_increment *
                      tangent_3d,
                    tolerance * 1e9);
        EXPECT_NEAR(derivatives_2d.tangential_by_normal_multiplier * tangent_2d,
                    derivatives_3d.tangential_by_normal_multiplier * tangent_3d,
                    tolerance);
        EXPECT_NEAR(derivatives_2d.tangential_by_gap * tangent_2d,
                    derivatives_3d.tangential_by_gap * tangent_3d,
                    tolerance * 1e10);
      }
  }

  TEST(Complementarity, KinkChoices)
  {
    const Frame<2> frame = make_frame<2>();
    const auto     law   = make_law<2>(1e10, 1e10, test_cohesion);
    // xi_n = 0 (touching, no pressure) and xi_t = 0: closed and stuck, with
    // the stick derivative (a regular first Newton matrix).
    const auto touching = law.evaluate(0., {}, 0., {});
    EXPECT_EQ(touching.state, JointState::stick);
    EXPECT_EQ(touching.derivatives.normal_by_gap, 1e10);
    EXPECT_EQ(touching.derivatives.tangential_by_slip_increment[0][0], -1e10);
    // Frictionless and cohesionless: the same point is still stuck (R = 0).
    ComplementarityParameters frictionless;
    frictionless.normal_parameter = frictionless.tangential_parameter = 1e10;
    EXPECT_EQ(
      CoulombComplementarity<2>(frictionless).evaluate(0., {}, 0., {}).state,
      JointState::stick);
    // |xi_t| = R exactly: stick.
    const double radius = test_cohesion + friction_coefficient * pressure_scale;
    EXPECT_EQ(
      law.evaluate(pressure_scale, radius * frame.tangents[0], 0., {}).state,
      JointState::stick);
    // Cohesion binds closed pairs only: an open pair with shear below c is
    // not stuck, C_t = lambda_t.
    const auto open =
      law.evaluate(0., 0.5 * test_cohesion * frame.tangents[0], 1e-6, {});
    EXPECT_EQ(open.state, JointState::open);
    EXPECT_EQ(open.tangential_residual.norm(), 0.5 * test_cohesion);
  }

  TEST(Complementarity, InvalidParametersThrow)
  {
    ComplementarityParameters parameters;
    parameters.normal_parameter = parameters.tangential_parameter = 1e10;
    EXPECT_NO_THROW(CoulombComplementarity<2>{parameters});
    ComplementarityParameters zero_parameter = parameters;
    zero_parameter.tangential_parameter      = 0.;
    EXPECT_ANY_THROW(CoulombComplementarity<2>{zero_parameter});
    ComplementarityParameters negative_friction = parameters;
    negative_friction.friction_coefficient      = -0.1;
    EXPECT_ANY_THROW(CoulombComplementarity<3>{negative_friction});
  }

  /**
   * One block node B on an isotropic spring (stiffness k per unit area,
   * Pa/m) whose far end is driven to w = -w_n n + w_t (m), above a rigid
   * plane (side A, fixed) with initial gap g0. Unknowns: displacement u
   * (dim), lambda_n, and lambda_t = sum_k alpha_k tau_k (dim - 1).
   * Equations: equilibrium k (u - w) - lambda_n n + lambda_t = 0 (the
   * internal force density of B, as CoulombJoint), C_n = 0, tau_j . C_t = 0,
   * with g = g0 + u.n and Delta s = u - (u.n) n (no previous slip).
   */
  template <int dim>
  struct SpringBlock
  {
    double                 stiffness   = 1e9;  // Pa/m
    double                 initial_gap = 2e-4; // m
    double                 pressing    = 1e-3; // m, w_n
    dealii::Tensor<1, dim> push;               // m, w_t (tangent)
  };

  template <int dim>
  struct NewtonOutcome
  {
    dealii::Tensor<1, dim> displacement;           // m
    double                 normal_multiplier = 0.; // Pa
    dealii::Tensor<1, dim> tangential_multiplier;  // Pa
    JointState             state        = JointState::open;
    unsigned int           n_iterations = 0;
    bool                   converged    = false;
  };

  template <int dim>
  NewtonOutcome<dim>
  solve_spring_block(const SpringBlock<dim>            &block,
                     const CoulombComplementarity<dim> &law,
                     const Frame<dim>                  &frame)
  {
    constexpr unsigned int n_unknowns     = 2 * dim;
    constexpr unsigned int max_iterations = 20;
    // Stop: state unchanged and every equation below 1e-12 of its scale:
    // force k |w| for equilibrium; for C the larger of the pressure k w_n
    // and c |w|, since a closed row is c_n g (or c_t Delta s), whose
    // round-off is c eps |u| (at c = 1e14 Pa/m alone 3e-7 of k w_n).
    constexpr double              relative_tolerance = 1e-12;
    const dealii::Tensor<1, dim> &normal             = frame.normal;
    const dealii::Tensor<1, dim> driver = -block.pressing * normal + block.push;
    const double                 force_scale = block.stiffness * driver.norm();
    const double                 pressure =
      std::max({block.stiffness * block.pressing,
                law.parameters().normal_parameter * driver.norm(),
                law.parameters().tangential_parameter * driver.norm()});
    const dealii::Tensor<2, dim> tangent_projector =
      dealii::Tensor<2, dim>(dealii::unit_symmetric_tensor<dim>()) -
      dealii::outer_product(normal, normal);

    dealii::Vector<double> unknowns(n_unknowns), update(n_unknowns),
      residual(n_unknowns);
    NewtonOutcome<dim> outcome;
    JointState         previous_state = JointState::open;
    for (unsigned int iteration = 0; iteration <= max_iterations; ++iteration)
      {
        dealii::Tensor<1, dim> displacement, tangential_multiplier;
        for (unsigned int i = 0; i < dim; ++i)
          displacement[i] = unknowns[i];
        const double normal_multiplier = unknowns[dim];
        for (unsigned int k = 0; k < dim - 1; ++k)
          tangential_multiplier += unknowns[dim + 1 + k] * frame.tangents[k];
        const double gap = block.initial_gap + displacement * normal;
        const dealii::Tensor<1, dim> slip_increment =
          tangent_projector * displacement;
        const ComplementarityResponse<dim> response = law.evaluate(
          normal_multiplier, tangential_multiplier, gap, slip_increment);
        const ComplementarityDerivatives<dim> &derivatives =
          response.derivatives;

        const dealii::Tensor<1, dim> equilibrium =
          block.stiffness * (displacement - driver) -
          normal_multiplier * normal + tangential_multiplier;
        double largest = 0.;
        for (unsigned int i = 0; i < dim; ++i)
          {
            residual[i] = equilibrium[i];
            largest = std::max(largest, std::abs(equilibrium[i]) / force_scale);
          }
        residual[dim] = response.normal_residual;
        largest       = std::max(largest, std::abs(residual[dim]) / pressure);
        for (unsigned int j = 0; j < dim - 1; ++j)
          {
            residual[dim + 1 + j] =
              frame.tangents[j] * response.tangential_residual;
            largest =
              std::max(largest, std::abs(residual[dim + 1 + j]) / pressure);
          }

        outcome.displacement          = displacement;
        outcome.normal_multiplier     = normal_multiplier;
        outcome.tangential_multiplier = tangential_multiplier;
        outcome.state                 = response.state;
        outcome.n_iterations          = iteration;
        if (iteration > 0 && response.state == previous_state &&
            largest <= relative_tolerance)
          {
            outcome.converged = true;
            return outcome;
          }
        previous_state = response.state;

        // Jacobian, chained with dg/du = n and dDelta s/du = I - n n.
        dealii::FullMatrix<double> jacobian(n_unknowns, n_unknowns);
        for (unsigned int i = 0; i < dim; ++i)
          {
            jacobian(i, i)   = block.stiffness;
            jacobian(i, dim) = -normal[i];
            for (unsigned int k = 0; k < dim - 1; ++k)
              jacobian(i, dim + 1 + k) = frame.tangents[k][i];
          }
        for (unsigned int i = 0; i < dim; ++i)
          jacobian(dim, i) = derivatives.normal_by_gap * normal[i];
        jacobian(dim, dim) = derivatives.normal_by_normal_multiplier;
        const dealii::Tensor<2, dim> tangential_by_displacement =
          dealii::outer_product(derivatives.tangential_by_gap, normal) +
          derivatives.tangential_by_slip_increment * tangent_projector;
        for (unsigned int j = 0; j < dim - 1; ++j)
          {
            const dealii::Tensor<1, dim> &row_tangent = frame.tangents[j];
            const dealii::Tensor<1, dim>  by_displacement =
              row_tangent * tangential_by_displacement;
            for (unsigned int i = 0; i < dim; ++i)
              jacobian(dim + 1 + j, i) = by_displacement[i];
            jacobian(dim + 1 + j, dim) =
              row_tangent * derivatives.tangential_by_normal_multiplier;
            for (unsigned int k = 0; k < dim - 1; ++k)
              jacobian(dim + 1 + j, dim + 1 + k) =
                row_tangent * derivatives.tangential_by_tangential_multiplier *
                frame.tangents[k];
          }
        jacobian.gauss_jordan();
        jacobian.vmult(update, residual);
        unknowns -= update;
      }
    return outcome;
  }

  /**
   * Newton from u = 0, lambda = 0 (an open start: g0 > 0) against the
   * closed form: lambda_n = k (w_n - g0), u.n = -g0; stick iff k |w_t| <=
   * R = c + mu lambda_n, then u_t = 0, lambda_t = k w_t; else
   * lambda_t = R w_t/|w_t|, u_t = w_t - lambda_t/k.
   */
  template <int dim>
  void
  check_spring_block(const double push_length, const JointState expected)
  {
    const Frame<dim> frame = make_frame<dim>();
    SpringBlock<dim> block;
    // In 3D the push is off both tangent axes.
    block.push = frame.tangents[0];
    if constexpr (dim == 3)
      block.push = 0.6 * frame.tangents[0] + 0.8 * frame.tangents[1];
    block.push *= push_length;
    const double normal_multiplier =
      block.stiffness * (block.pressing - block.initial_gap);
    const double radius =
      test_cohesion + friction_coefficient * normal_multiplier;
    const dealii::Tensor<1, dim> push_direction =
      block.push / block.push.norm();
    const bool sticks = block.stiffness * push_length <= radius;
    const dealii::Tensor<1, dim> tangential_multiplier =
      sticks ? block.stiffness * block.push : radius * push_direction;
    const dealii::Tensor<1, dim> displacement =
      -block.initial_gap * frame.normal +
      (sticks ? dealii::Tensor<1, dim>() :
                block.push - tangential_multiplier / block.stiffness);
    ASSERT_EQ(sticks, expected == JointState::stick);

    // The answer must not depend on the parameters; the iterates may. The
    // system is piecewise linear along the fixed push direction, so once
    // the state is right one step lands on the answer up to round-off of a
    // 2 dim x 2 dim solve whose rows differ in scale by up to c/k = 1e5.
    constexpr unsigned int iteration_bound = 6;
    constexpr double       relative        = 1e-9;
    for (const double parameter : parameter_range)
      {
        const auto law = make_law<dim>(parameter, parameter, test_cohesion);
        const NewtonOutcome<dim> outcome =
          solve_spring_block(block, law, frame);
        ASSERT_TRUE(outcome.converged) << "c = " << parameter;
        std::cout
          << "dim " << dim << " state " << int(expected) << " c " << parameter
          << ": " << outcome.n_iterations << " Newton iterations, errors u "
          << (outcome.displacement - displacement).norm() / displacement.norm()
          << " lambda_n "
          << std::abs(outcome.normal_multiplier - normal_multiplier) /
               normal_multiplier
          << " lambda_t "
          << (outcome.tangential_multiplier - tangential_multiplier).norm() /
               tangential_multiplier.norm()
          << '\n';
        EXPECT_LE(outcome.n_iterations, iteration_bound) << "c = " << parameter;
        EXPECT_EQ(outcome.state, expected);
        EXPECT_LE((outcome.displacement - displacement).norm(),
                  relative * displacement.norm());
        EXPECT_NEAR(outcome.normal_multiplier,
                    normal_multiplier,
                    relative * normal_multiplier);
        EXPECT_LE(
          (outcome.tangential_multiplier - tangential_multiplier).norm(),
          relative * tangential_multiplier.norm());
      }
  }

  TEST(Complementarity, NewtonSpringBlockSticks)
  {
    // k |w_t| = 2e5 Pa < R = 1e5 + 0.6 * 8e5 = 5.8e5 Pa.
    check_spring_block<2>(2e-4, JointState::stick);
    check_spring_block<3>(2e-4, JointState::stick);
  }

  TEST(Complementarity, NewtonSpringBlockSlips)
  {
    // k |w_t| = 1e6 Pa > R = 5.8e5 Pa: slides by 4.2e-4 m.
    check_spring_block<2>(1e-3, JointState::slip);
    check_spring_block<3>(1e-3, JointState::slip);
  }
} // namespace
