// Unit tests of the exact (rigid) contact law as Newton equations
// (contact/exact_contact.h) on hand-built 2D node pairs, without a mesh:
// the assembled rows dE/d(u, mu) against central differences of E in the
// open, stick and slip states (two-sided pair and pair against a rigid
// obstacle), the force block B^T mu against the residual of
// assemble_contact, the open/stick/slip transitions, directions held by
// Dirichlet DoFs on both sides, zero_open_multipliers and the
// set_multipliers / evaluate round trip.
#include <contact/contact_assembly.h>
#include <contact/exact_contact.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace
{
  using namespace FloorBlock::Contact;
  using Vector = dealii::TrilinosWrappers::MPI::Vector;
  using Matrix = dealii::TrilinosWrappers::SparseMatrix;
  using dealii::types::global_dof_index;

  constexpr double normal_parameter     = 1e9; // c_n (Pa/m)
  constexpr double tangential_parameter = 4e8; // c_t (Pa/m)
  constexpr double friction_coefficient = 0.6; // -
  constexpr double test_cohesion        = 2e4; // Pa
  constexpr double surface_stiffness    = 3e9; // Pa/m

  ExactPairLaw
  make_law(const double cohesion = test_cohesion)
  {
    ExactPairLaw law;
    law.complementarity.friction_coefficient = friction_coefficient;
    law.complementarity.cohesion             = cohesion;
    law.complementarity.normal_parameter     = normal_parameter;
    law.complementarity.tangential_parameter = tangential_parameter;
    law.surface_stiffness                    = surface_stiffness;
    return law;
  }

  /** The tangent ExactContact<2> uses: the normal turned by +90 degrees. */
  dealii::Tensor<1, 2>
  tangent_of(const dealii::Tensor<1, 2> &normal)
  {
    return dealii::Tensor<1, 2>({-normal[1], normal[0]});
  }

  ContactNode<2>
  two_sided_pair(const unsigned int                   joint,
                 const dealii::Point<2>              &position,
                 const double                         weight,
                 const dealii::Tensor<1, 2>          &normal,
                 const std::vector<global_dof_index> &dofs_a,
                 const std::vector<global_dof_index> &dofs_b,
                 const double                         initial_gap = 0.)
  {
    ContactNode<2> node;
    node.joint       = joint;
    node.position    = position;
    node.weight      = weight;
    node.normal      = normal;
    node.initial_gap = initial_gap;
    for (unsigned int c = 0; c < 2; ++c)
      {
        node.dofs_a[c] = dofs_a[c];
        node.dofs_b[c] = dofs_b[c];
      }
    return node;
  }

  ContactNode<2>
  obstacle_pair(const unsigned int                   joint,
                const dealii::Point<2>              &position,
                const double                         weight,
                const dealii::Tensor<1, 2>          &normal,
                const std::vector<global_dof_index> &dofs_a,
                const dealii::Tensor<1, 2>          &obstacle_displacement,
                const double                         initial_gap = 0.)
  {
    ContactNode<2> node        = two_sided_pair(joint,
                                         position,
                                         weight,
                                         normal,
                                         dofs_a,
                                         {dealii::numbers::invalid_dof_index,
                                                 dealii::numbers::invalid_dof_index},
                                         initial_gap);
    node.obstacle_displacement = obstacle_displacement;
    return node;
  }

  /**
   * Pairs, laws, constraints and an ExactContact over them, with the
   * displacement vector (size n_u), the Newton matrix and residual (size
   * n_u + n_multipliers). ExactContact keeps references to the nodes and
   * constraints, so a System is neither copied nor moved.
   */
  struct System
  {
    System(std::vector<ContactNode<2>>              pairs,
           std::vector<std::optional<ExactPairLaw>> pair_laws,
           const unsigned int                       n_displacement_dofs,
           const dealii::AffineConstraints<double> &given_constraints =
             dealii::AffineConstraints<double>())
      : nodes(std::move(pairs))
      , laws(std::move(pair_laws))
      , n_u(n_displacement_dofs)
      , histories(nodes.size())
      , responses(nodes.size())
    {
      constraints.copy_from(given_constraints);
      if (!constraints.is_closed())
        constraints.close();
      contact =
        std::make_unique<ExactContact<2>>(nodes, laws, constraints, n_u);
      n_total = n_u + contact->n_multipliers();
      dealii::DynamicSparsityPattern pattern(n_total, n_total);
      for (unsigned int i = 0; i < n_total; ++i)
        pattern.add(i, i);
      contact->add_couplings(pattern);
      matrix.reinit(pattern);
      u.reinit(dealii::complete_index_set(n_u), MPI_COMM_SELF);
      residual.reinit(dealii::complete_index_set(n_total), MPI_COMM_SELF);
    }

    System(const System &) = delete;
    System &
    operator=(const System &) = delete;

    /** evaluate() at u and the current multipliers, then assemble. */
    void
    assemble()
    {
      contact->evaluate(u, histories, responses);
      matrix   = 0.;
      residual = 0.;
      contact->assemble_equations(matrix, residual);
    }

    /** The equations E (rows n_u..) at u and the current multipliers. */
    std::vector<double>
    equations()
    {
      assemble();
      std::vector<double> values(n_total - n_u);
      for (unsigned int r = n_u; r < n_total; ++r)
        values[r - n_u] = residual(r);
      return values;
    }

    /** Unknown j of (u, mu): a displacement or a multiplier. */
    double
    unknown(const unsigned int j)
    {
      return j < n_u ? static_cast<double>(u(j)) :
                       contact->multipliers()(j - n_u);
    }

    void
    set_unknown(const unsigned int j, const double value)
    {
      if (j < n_u)
        u(j) = value;
      else
        contact->multipliers()(j - n_u) = value;
    }

    std::vector<ContactNode<2>>              nodes;
    std::vector<std::optional<ExactPairLaw>> laws;
    dealii::AffineConstraints<double>        constraints;
    unsigned int                             n_u;
    unsigned int                             n_total = 0;
    std::vector<JointHistory<2>>             histories;
    std::vector<JointResponse<2>>            responses;
    std::unique_ptr<ExactContact<2>>         contact;
    Matrix                                   matrix;
    Vector                                   u;
    Vector                                   residual;
  };

  /**
   * A state of one pair, given by what the law sees: gap g, slip
   * increment s (along the pair's tangent) and the multipliers
   * mu = lambda / c_n (m).
   */
  struct PairState
  {
    JointState state;
    double     gap;
    double     slip_increment;
    double     normal_multiplier;
    double     tangential_multiplier;
  };

  /**
   * States clearly inside one branch (c_n = 1e9, c_t = 4e8 Pa/m,
   * mu = 0.6, c = 2e4 Pa, with or without cohesion):
   * - open: xi_n = 5e3 - 2e4 = -1.5e4 Pa, 1.5e-5 m of gap from the kink;
   * - stick: xi_n = 1.01e5 Pa, R >= 6.06e4 Pa, |xi_t| = 2.2e4 Pa;
   * - slip: xi_n = 1.01e5 Pa, R <= 8.06e4 Pa, |xi_t| = 1.08e5 Pa.
   * The finite-difference steps below (1e-10 m) are 1e-5 of the margins.
   */
  PairState
  state_of(const JointState state, const double sign)
  {
    switch (state)
      {
        case JointState::open:
          return {state, 2e-5, sign * 1e-5, 0.5e-5, sign * 3e-6};
        case JointState::stick:
          return {state, -1e-6, sign * 5e-6, 1e-4, sign * 2e-5};
        case JointState::slip:
        default:
          return {state, -1e-6, sign * 2e-5, 1e-4, sign * 1e-4};
      }
  }

  /**
   * Sets the displacements of pair k (node p) and its multipliers so that
   * the law sees @p state; @p side_a is the side-A displacement of a
   * two-sided pair (the jump fixes side B).
   */
  void
  impose(System                     &system,
         const unsigned int          p,
         const unsigned int          k,
         const PairState            &state,
         const dealii::Tensor<1, 2> &side_a)
  {
    const ContactNode<2>      &node    = system.nodes[p];
    const dealii::Tensor<1, 2> tangent = tangent_of(node.normal);
    const dealii::Tensor<1, 2> jump =
      state.gap * node.normal +
      (state.slip_increment * tangent + system.histories[p].reference_slip);
    // jump = g0 n + u_B - u_A (two-sided) or g0 n + d_obstacle - u_A.
    dealii::Tensor<1, 2> u_a = side_a;
    if (node.against_rigid_obstacle())
      u_a = node.initial_gap * node.normal + node.obstacle_displacement - jump;
    for (unsigned int c = 0; c < 2; ++c)
      {
        system.u(node.dofs_a[c]) = u_a[c];
        if (!node.against_rigid_obstacle())
          system.u(node.dofs_b[c]) =
            jump[c] + u_a[c] - node.initial_gap * node.normal[c];
      }
    system.contact->multipliers()(2 * k)     = state.normal_multiplier;
    system.contact->multipliers()(2 * k + 1) = state.tangential_multiplier;
  }

  /**
   * Three node pairs with off-axis normals: two-sided (DoFs 0-3),
   * two-sided (DoFs 4-7), and one against a moved rigid obstacle with an
   * initial gap (DoFs 8-9).
   */
  std::vector<ContactNode<2>>
  three_pairs()
  {
    std::vector<ContactNode<2>> nodes;
    nodes.push_back(two_sided_pair(0,
                                   dealii::Point<2>(0., 0.),
                                   0.3,
                                   dealii::Tensor<1, 2>({0.6, 0.8}),
                                   {0, 1},
                                   {2, 3}));
    nodes.push_back(two_sided_pair(1,
                                   dealii::Point<2>(1., 0.),
                                   0.4,
                                   dealii::Tensor<1, 2>({0., 1.}),
                                   {4, 5},
                                   {6, 7}));
    nodes.push_back(obstacle_pair(2,
                                  dealii::Point<2>(2., 0.),
                                  0.7,
                                  dealii::Tensor<1, 2>({-0.8, 0.6}),
                                  {8, 9},
                                  dealii::Tensor<1, 2>({1e-5, -2e-5}),
                                  1e-5));
    return nodes;
  }

  /**
   * Two exact pairs with off-axis normals and a compliant pair between
   * them (no multipliers, so pair k != node index): pair 0 two-sided
   * (DoFs 0-3), node 1 compliant (DoFs 4-7), pair 1 (node 2) against a
   * moved rigid obstacle with an initial gap (DoFs 8-9); n_u = 10.
   */
  std::unique_ptr<System>
  make_two_pair_system(const dealii::AffineConstraints<double> &constraints =
                         dealii::AffineConstraints<double>())
  {
    const std::vector<ContactNode<2>>        nodes = three_pairs();
    std::vector<std::optional<ExactPairLaw>> laws  = {make_law(),
                                                      std::nullopt,
                                                      make_law()};
    auto system = std::make_unique<System>(nodes, laws, 10, constraints);
    // A slip before this increment on pair 0: Delta s = s - s_ref.
    system->histories[0].reference_slip =
      3e-6 * tangent_of(system->nodes[0].normal);
    return system;
  }

  /**
   * make_two_pair_system() with the given multipliers and the
   * displacement u_d = 1e-6 cos(2 + d) m, evaluated there.
   */
  std::unique_ptr<System>
  evaluated_two_pair_system(const std::vector<double> &multipliers)
  {
    auto system = make_two_pair_system();
    for (unsigned int i = 0; i < multipliers.size(); ++i)
      system->contact->multipliers()(i) = multipliers[i];
    for (unsigned int d = 0; d < system->n_u; ++d)
      system->u(d) = 1e-6 * std::cos(2. + d);
    system->contact->evaluate(system->u, system->histories, system->responses);
    return system;
  }

  /**
   * Pins down: every entry the Newton matrix gets in the multiplier rows
   * (by all displacements and all multipliers, including the zeros) is
   * the derivative of the residual rows E, for a two-sided pair and a
   * pair against a rigid obstacle, in the open, stick and slip states,
   * with and without cohesion (JointHistory::intact). Wrong signs of the
   * jump, a missing tangent projector, the lambda = c_n mu scaling or a
   * row written to the wrong pair all fail. Central differences with
   * step 1e-10 m are exact up to round-off on these piecewise linear
   * (2D) branches; tolerance 1e-6 of the row's largest entry (round-off
   * is ~1e-10 of it).
   */
  TEST(ExactContact, RowsAreDerivativesOfTheEquations)
  {
    constexpr double step      = 1e-10; // m, displacement and multiplier
    constexpr double tolerance = 1e-6;  // relative to the row's maximum
    for (const bool intact : {true, false})
      for (const JointState state :
           {JointState::open, JointState::stick, JointState::slip})
        {
          SCOPED_TRACE("intact " + std::to_string(intact) + ", state " +
                       std::to_string(static_cast<int>(state)));
          auto system = make_two_pair_system();
          for (auto &history : system->histories)
            history.intact = intact;
          impose(*system,
                 0,
                 0,
                 state_of(state, +1.),
                 dealii::Tensor<1, 2>({3e-5, -2e-5}));
          impose(*system, 2, 1, state_of(state, -1.), {});
          system->assemble();
          ASSERT_EQ(system->responses[0].state, state);
          ASSERT_EQ(system->responses[2].state, state);

          const unsigned int n_u     = system->n_u;
          const unsigned int n_total = system->n_total;
          // The analytic rows, read before the matrix is reassembled.
          std::vector<std::vector<double>> rows(n_total - n_u,
                                                std::vector<double>(n_total));
          for (unsigned int r = n_u; r < n_total; ++r)
            for (unsigned int j = 0; j < n_total; ++j)
              rows[r - n_u][j] = system->matrix.el(r, j);

          std::vector<std::vector<double>> differences(
            n_total - n_u, std::vector<double>(n_total));
          for (unsigned int j = 0; j < n_total; ++j)
            {
              const double base = system->unknown(j);
              system->set_unknown(j, base + step);
              const std::vector<double> plus = system->equations();
              system->set_unknown(j, base - step);
              const std::vector<double> minus = system->equations();
              system->set_unknown(j, base);
              for (unsigned int r = 0; r < n_total - n_u; ++r)
                differences[r][j] = (plus[r] - minus[r]) / (2. * step);
            }

          for (unsigned int r = 0; r < n_total - n_u; ++r)
            {
              double largest = 0.;
              for (const double entry : rows[r])
                largest = std::max(largest, std::abs(entry));
              // Every row has at least w c_t |tau_c| >= 0.3 * 4e8 / sqrt(2)
              // Pa somewhere (the stick tangent row: 9.6e7 Pa).
              ASSERT_GT(largest, 5e7) << "row " << r;
              for (unsigned int j = 0; j < n_total; ++j)
                EXPECT_NEAR(rows[r][j], differences[r][j], tolerance * largest)
                  << "row n_u + " << r << ", column " << j;
            }
          // Closed pairs depend on the displacement: not only on mu.
          if (state != JointState::open)
            for (unsigned int r = 0; r < n_total - n_u; ++r)
              {
                double by_displacement = 0.;
                for (unsigned int j = 0; j < n_u; ++j)
                  by_displacement =
                    std::max(by_displacement, std::abs(rows[r][j]));
                EXPECT_GT(by_displacement, 0.) << "row n_u + " << r;
              }
        }
  }

  /**
   * Pins down: the u-rows of the constant block B^T times the multipliers
   * (add_force_block) are the forces assemble_contact adds for the
   * responses evaluate() returns (w force_density on side B, minus on
   * side A, force_density = -lambda_n n + lambda_t), also where a
   * Dirichlet DoF drops a row and a constrained DoF (u_9 = (u_10 +
   * u_11)/2) moves it to its masters; and B^T has nothing in the
   * multiplier rows. Relative tolerance 1e-12 of the largest force.
   */
  TEST(ExactContact, ForceBlockMatchesContactResidual)
  {
    dealii::AffineConstraints<double> constraints;
    constraints.add_line(1);
    constraints.add_line(9);
    constraints.add_entry(9, 10, 0.5);
    constraints.add_entry(9, 11, 0.5);
    constraints.close();
    const std::vector<ContactNode<2>> nodes = three_pairs();
    System                            system(nodes,
                  {make_law(), std::nullopt, make_law()},
                  12,
                  constraints);
    const std::vector<double> multipliers = {1.3e-4, -0.4e-4, 0.7e-4, 2.1e-4};
    for (unsigned int i = 0; i < multipliers.size(); ++i)
      system.contact->multipliers()(i) = multipliers[i];
    for (unsigned int d = 0; d < system.n_u; ++d)
      system.u(d) = 1e-6 * std::sin(1. + d);
    system.contact->evaluate(system.u, system.histories, system.responses);

    Vector contact_residual;
    contact_residual.reinit(dealii::complete_index_set(system.n_u),
                            MPI_COMM_SELF);
    assemble_contact(system.nodes,
                     system.responses,
                     system.constraints,
                     nullptr,
                     &contact_residual);

    system.matrix = 0.;
    system.contact->add_force_block(system.matrix);
    double largest = 0.;
    for (unsigned int d = 0; d < system.n_u; ++d)
      largest = std::max(largest, std::abs(contact_residual(d)));
    ASSERT_GT(largest, 1e4); // w c_n mu ~ 0.3 * 1e9 * 1e-4 N/m
    for (unsigned int r = 0; r < system.n_total; ++r)
      {
        double product = 0.;
        for (unsigned int m = 0; m < multipliers.size(); ++m)
          product += system.matrix.el(r, system.n_u + m) * multipliers[m];
        const double expected = r < system.n_u ? contact_residual(r) : 0.;
        EXPECT_NEAR(product, expected, 1e-12 * largest) << "row " << r;
      }
    // The Dirichlet row is dropped, the constrained row moved on.
    EXPECT_EQ(contact_residual(1), 0.);
    EXPECT_EQ(contact_residual(9), 0.);
    EXPECT_NE(contact_residual(10), 0.);
  }

  /**
   * Pins down the state logic and the tractions of one horizontal pair
   * (normal (0, 1), w = 0.5 m, tangent (-1, 0)):
   * - touching, unloaded (g = 0, mu = 0): stick (the kink choice of the
   *   complementarity function), E = 0;
   * - pulled apart (g = 1e-5 m, mu_n = 0): open, the rows are w c_n mu
   *   with no displacement column, so one Newton step sets mu to zero;
   * - compressed (mu_n = 1e-4 m, g = 0) with c_n mu_t = 1e5 Pa beyond
   *   c + mu lambda_n = 8e4 Pa and a slip increment: slip; at c_n mu_t
   *   = R along the slip E_t = 0 (lambda_t points along Delta s), the
   *   opposite traction sticks with E_t = -w c_t Delta s;
   * - the responses' tractions are c_n mu, force_density = -lambda_n n +
   *   lambda_t. Tolerances: 1e-12 relative.
   */
  TEST(ExactContact, OpenStickSlipTransitions)
  {
    const dealii::Tensor<1, 2> normal({0., 1.});
    const dealii::Tensor<1, 2> tangent = tangent_of(normal);
    const double               weight  = 0.5;
    const double               scale   = weight * normal_parameter;
    System                     system(
      {two_sided_pair(0, dealii::Point<2>(), weight, normal, {0, 1}, {2, 3})},
      {make_law()},
      4);
    auto &mu = system.contact->multipliers();

    // Touching, unloaded.
    std::vector<double> e = system.equations();
    EXPECT_EQ(system.responses[0].state, JointState::stick);
    EXPECT_EQ(e[0], 0.);
    EXPECT_EQ(e[1], 0.);

    // Pulled apart, with a leftover tangential multiplier.
    system.u(3) = 1e-5;
    mu(0)       = 0.;
    mu(1)       = 3e-6;
    e           = system.equations();
    EXPECT_EQ(system.responses[0].state, JointState::open);
    EXPECT_NEAR(system.responses[0].gap, 1e-5, 1e-17);
    EXPECT_NEAR(e[0], 0., 1e-12 * scale * 3e-6);
    EXPECT_NEAR(e[1], scale * 3e-6, 1e-12 * scale * 3e-6);
    for (unsigned int r = 4; r < 6; ++r)
      {
        for (unsigned int j = 0; j < 4; ++j)
          EXPECT_EQ(system.matrix.el(r, j), 0.) << r << ", " << j;
        EXPECT_NEAR(system.matrix.el(r, r), scale, 1e-12 * scale);
        EXPECT_EQ(system.matrix.el(r, r == 4 ? 5 : 4), 0.);
        // One Newton step of the (decoupled) row: mu - E / (w c_n).
        EXPECT_NEAR(mu(r - 4) - e[r - 4] / system.matrix.el(r, r),
                    0.,
                    1e-14 * 3e-6);
      }
    EXPECT_NEAR(system.responses[0].tangential_traction * tangent,
                normal_parameter * 3e-6,
                1e-12 * normal_parameter * 3e-6);

    // Compressed, sheared beyond the Coulomb radius, slipping along +tau.
    system.u(3) = 0.;
    system.u(2) = -1e-6; // slip increment 1e-6 m along tau = (-1, 0)
    mu(0)       = 1e-4;
    mu(1)       = 1e-4;
    e           = system.equations();
    const JointResponse<2> &response = system.responses[0];
    EXPECT_EQ(response.state, JointState::slip);
    EXPECT_NEAR(response.slip * tangent, 1e-6, 1e-18);
    EXPECT_NEAR(response.normal_traction, normal_parameter * 1e-4, 1e-7);
    for (unsigned int c = 0; c < 2; ++c)
      {
        EXPECT_NEAR(response.tangential_traction[c],
                    normal_parameter * 1e-4 * tangent[c],
                    1e-7);
        EXPECT_NEAR(response.force_density[c],
                    normal_parameter * 1e-4 * (tangent[c] - normal[c]),
                    1e-7);
      }
    EXPECT_DOUBLE_EQ(response.closure_stiffness, surface_stiffness);
    const double radius = test_cohesion + friction_coefficient * 1e5; // Pa
    EXPECT_NEAR(e[0], 0., 1e-12 * scale * 1e-4);
    EXPECT_NEAR(e[1], weight * (1e5 - radius), 1e-12 * weight * 1e5);

    // At the Coulomb limit along the slip: the equations hold.
    mu(1) = radius / normal_parameter;
    e     = system.equations();
    EXPECT_EQ(system.responses[0].state, JointState::slip);
    EXPECT_NEAR(e[1], 0., 1e-12 * weight * radius);
    // The same traction against the slip is inside the radius, |xi_t| =
    // R - c_t |Delta s|: stick, with C_t = -c_t Delta s != 0.
    mu(1) = -radius / normal_parameter;
    e     = system.equations();
    EXPECT_EQ(system.responses[0].state, JointState::stick);
    EXPECT_NEAR(e[1],
                -weight * tangential_parameter * 1e-6,
                1e-9 * weight * tangential_parameter * 1e-6);
  }

  /**
   * Pins down the directions held on both sides: a vertical pair (normal
   * (1, 0)) whose two x DoFs are Dirichlet DoFs has a fixed normal
   * direction, counted by n_fixed_directions(), with the row w c_n mu_n
   * (diagonal only, no displacement column) and no force column; its
   * tangent row stays an equation. One side held is not fixed; both y
   * DoFs held fix the tangent; an obstacle pair is fixed by its one
   * side. set_multipliers gives the fixed direction zero. Tolerance
   * 1e-12 relative.
   */
  TEST(ExactContact, DirectionHeldOnBothSidesIsFixed)
  {
    const dealii::Tensor<1, 2> normal({1., 0.});
    const double               weight     = 0.25;
    const double               scale      = weight * normal_parameter;
    const auto                 make_pairs = [&]() {
      return std::vector<ContactNode<2>>{
        two_sided_pair(0, dealii::Point<2>(), weight, normal, {0, 1}, {2, 3})};
    };
    const auto constrained = [](const std::vector<unsigned int> &dofs) {
      dealii::AffineConstraints<double> constraints;
      for (const unsigned int d : dofs)
        constraints.add_line(d);
      constraints.close();
      return constraints;
    };

    {
      System system(make_pairs(), {make_law()}, 4, constrained({0, 2}));
      EXPECT_EQ(system.contact->n_fixed_directions(), 1u);
      system.u(1)                      = 2e-6; // some slip
      system.contact->multipliers()(0) = 3e-5;
      system.contact->multipliers()(1) = 1e-5;
      system.assemble();
      EXPECT_NEAR(system.residual(4), scale * 3e-5, 1e-12 * scale * 3e-5);
      EXPECT_NEAR(system.matrix.el(4, 4), scale, 1e-12 * scale);
      for (unsigned int j = 0; j < 6; ++j)
        {
          if (j != 4)
            {
              EXPECT_EQ(system.matrix.el(4, j), 0.) << "column " << j;
            }
        }
      // The tangent row is an equation of the y DoFs.
      EXPECT_NE(system.matrix.el(5, 1), 0.);
      EXPECT_NE(system.matrix.el(5, 3), 0.);
      // The force block has no entry for the fixed normal multiplier.
      system.matrix = 0.;
      system.contact->add_force_block(system.matrix);
      for (unsigned int d = 0; d < 4; ++d)
        EXPECT_EQ(system.matrix.el(d, 4), 0.) << "row " << d;
      EXPECT_NE(system.matrix.el(1, 5), 0.);
      // set_multipliers leaves the fixed direction at zero.
      std::vector<JointResponse<2>> responses(1);
      responses[0].normal_traction        = 1e5;
      responses[0].tangential_traction[1] = 2e4;
      system.contact->set_multipliers(responses);
      EXPECT_EQ(system.contact->multipliers()(0), 0.);
      EXPECT_NEAR(system.contact->multipliers()(1),
                  2e4 / normal_parameter,
                  1e-14 * 2e4 / normal_parameter);
    }
    {
      // One side held: the gap still changes with u_B.
      System system(make_pairs(), {make_law()}, 4, constrained({0}));
      EXPECT_EQ(system.contact->n_fixed_directions(), 0u);
      system.assemble();
      EXPECT_NE(system.matrix.el(4, 2), 0.);
    }
    {
      // Both y DoFs held: the tangent is fixed.
      System system(make_pairs(), {make_law()}, 4, constrained({1, 3}));
      EXPECT_EQ(system.contact->n_fixed_directions(), 1u);
      system.contact->multipliers()(1) = 1e-5;
      system.assemble();
      EXPECT_NEAR(system.residual(5), scale * 1e-5, 1e-12 * scale * 1e-5);
      for (unsigned int j = 0; j < 6; ++j)
        {
          if (j != 5)
            {
              EXPECT_EQ(system.matrix.el(5, j), 0.) << "column " << j;
            }
        }
    }
    {
      // An obstacle pair is held on its one side.
      System system(
        {obstacle_pair(0, dealii::Point<2>(), weight, normal, {0, 1}, {})},
        {make_law()},
        2,
        constrained({0}));
      EXPECT_EQ(system.contact->n_fixed_directions(), 1u);
    }
  }

  /**
   * Pins down: zero_open_multipliers zeroes the multipliers of exactly the
   * pairs open at the last evaluate() and leaves the others bit for bit;
   * set_multipliers(responses of evaluate) gives back the multipliers
   * (mu -> lambda = c_n mu -> mu), relative 1e-14, with a compliant pair
   * between the exact ones (responses indexed by node, multipliers by
   * pair).
   */
  TEST(ExactContact, ZeroOpenMultipliersAndRoundTrip)
  {
    for (const JointState first : {JointState::open, JointState::slip})
      {
        // Pair 0 open, pair 1 stick; then pair 0 slip, pair 1 open.
        const JointState other =
          first == JointState::open ? JointState::stick : JointState::open;
        auto system = make_two_pair_system();
        impose(*system,
               0,
               0,
               state_of(first, 1.),
               dealii::Tensor<1, 2>({1e-5, 2e-5}));
        impose(*system, 2, 1, state_of(other, -1.), {});
        system->assemble();
        ASSERT_EQ(system->responses[0].state, first);
        ASSERT_EQ(system->responses[2].state, other);
        const dealii::Vector<double> before = system->contact->multipliers();
        for (unsigned int i = 0; i < before.size(); ++i)
          ASSERT_NE(before(i), 0.);
        system->contact->zero_open_multipliers();
        const dealii::Vector<double> &after = system->contact->multipliers();
        for (unsigned int k = 0; k < 2; ++k)
          {
            const bool open = (k == 0 ? first : other) == JointState::open;
            for (unsigned int i = 0; i < 2; ++i)
              EXPECT_EQ(after(2 * k + i), open ? 0. : before(2 * k + i))
                << "pair " << k << ", direction " << i;
          }
      }

    const std::vector<double> multipliers = {1.3e-4, -0.4e-4, 0.7e-4, 2.1e-4};
    auto                      system = evaluated_two_pair_system(multipliers);
    // The compliant pair's response is not the exact law's.
    EXPECT_EQ(system->responses[1].normal_traction, 0.);
    for (unsigned int i = 0; i < multipliers.size(); ++i)
      system->contact->multipliers()(i) = 1.;
    system->contact->set_multipliers(system->responses);
    for (unsigned int i = 0; i < multipliers.size(); ++i)
      EXPECT_NEAR(system->contact->multipliers()(i),
                  multipliers[i],
                  1e-14 * std::abs(multipliers[i]))
        << "multiplier " << i;
  }

  /**
   * scale_complementarity(f) keeps the tractions the multipliers stand for
   * (responses before and after agree to 1e-12 relative) and divides the
   * multipliers by f; the force block brought along with weight 1 - 1/f
   * equals a block written fresh at the new parameters (1e-12 of its
   * largest entry); scaling back by 1/f restores the multipliers.
   */
  TEST(ExactContact, ScaledComplementarityKeepsTheTractions)
  {
    const std::vector<double> multipliers = {1.3e-4, -0.4e-4, 0.7e-4, 2.1e-4};
    auto                      system = evaluated_two_pair_system(multipliers);
    const std::vector<JointResponse<2>> before = system->responses;
    system->matrix                             = 0.;
    system->contact->add_force_block(system->matrix);

    constexpr double factor = 0.1;
    system->contact->scale_complementarity(factor);
    system->contact->add_force_block(system->matrix, 1. - 1. / factor);
    for (unsigned int i = 0; i < multipliers.size(); ++i)
      EXPECT_NEAR(system->contact->multipliers()(i),
                  multipliers[i] / factor,
                  1e-14 * std::abs(multipliers[i] / factor));
    system->contact->evaluate(system->u, system->histories, system->responses);
    for (unsigned int p : {0u, 2u})
      {
        const double scale = std::abs(before[p].normal_traction) +
                             before[p].tangential_traction.norm();
        ASSERT_GT(scale, 0.);
        EXPECT_NEAR(system->responses[p].normal_traction,
                    before[p].normal_traction,
                    1e-12 * scale);
        EXPECT_NEAR((system->responses[p].tangential_traction -
                     before[p].tangential_traction)
                      .norm(),
                    0.,
                    1e-12 * scale);
      }

    Matrix fresh;
    fresh.reinit(system->matrix);
    fresh = 0.;
    system->contact->add_force_block(fresh);
    double largest = 0.;
    for (unsigned int r = 0; r < system->n_total; ++r)
      for (unsigned int c = 0; c < system->n_total; ++c)
        largest = std::max(largest, std::abs(fresh.el(r, c)));
    ASSERT_GT(largest, 0.);
    for (unsigned int r = 0; r < system->n_total; ++r)
      for (unsigned int c = 0; c < system->n_total; ++c)
        EXPECT_NEAR(system->matrix.el(r, c), fresh.el(r, c), 1e-12 * largest)
          << "entry " << r << ", " << c;

    system->contact->scale_complementarity(1. / factor);
    for (unsigned int i = 0; i < multipliers.size(); ++i)
      EXPECT_NEAR(system->contact->multipliers()(i),
                  multipliers[i],
                  1e-14 * std::abs(multipliers[i]));
  }
} // namespace
