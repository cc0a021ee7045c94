#pragma once

#include <contact/complementarity.h>
#include <contact/contact_node.h>
#include <contact/joint_law.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <optional>
#include <vector>

namespace FloorBlock::Contact
{
  /**
   * @brief The exact (rigid) contact law as equations of the Newton
   * iteration: nodal multipliers, one set per node pair, and the
   * Alart–Curnier complementarity function of each pair
   * (CoulombComplementarity).
   *
   * The displacement unknowns keep their DoF numbers 0..n_u-1; pair k's
   * multipliers follow them at n_u + dim k (normal) and n_u + dim k + j,
   * j = 1..dim-1 (along the pair's tangent basis). The unknowns are the
   * tractions in units of length, \f$\mu = \lambda/c_n\f$ (m), and the
   * equations are \f$E = w\,C\f$ (N/m in 2D, w the pair's lumped
   * weight): then every entry of the Newton matrix is of the order of the
   * stiffness, \f$w c_n \sim E\f$ (the multipliers' forces \f$w c_n
   * \mu\f$, \f$\partial E/\partial g = w c_n\f$, \f$\partial
   * E/\partial\mu = w c_n \partial C/\partial\lambda\f$). With the
   * tractions themselves as unknowns the columns differed by E ~ 1e10
   * and KLU missed the linear tolerance at every solve. The Newton
   * system is
   * \f[ \begin{pmatrix} K & B^T \\ \partial E/\partial u &
   *     \partial E/\partial\mu \end{pmatrix}
   *     \begin{pmatrix}\delta u \\ \delta\mu\end{pmatrix} =
   *     -\begin{pmatrix} r_u \\ E \end{pmatrix}, \f]
   * with \f$B^T\mu\f$ the pairs' forces on their nodes: constant, so
   * add_force_block() writes it once. Each pair's equations involve its
   * own multipliers and its own two nodes only (a local, nodal basis), so
   * a pair's constraint never spreads to its neighbours.
   *
   * Where neither node of a pair can move along one of its directions
   * (every DoF coupled to it a Dirichlet DoF), the gap or slip along it
   * cannot change and no equation would determine that multiplier: it
   * is set to zero, and the traction along that direction becomes part of
   * the support reaction. Such directions are counted by
   * n_fixed_directions().
   */
  /** @brief The exact law at one pair. */
  struct ExactPairLaw
  {
    /** Coulomb constants and complementarity parameters (intact pair). */
    ComplementarityParameters complementarity;
    /**
     * The surface's own stiffness, Young's modulus over the local cell
     * size (Pa/m): the scale of the contact indicator
     * (JointResponse::closure_stiffness), deliberately not the
     * complementarity parameter, which must not change any result.
     */
    double surface_stiffness = 0.;
  };

  template <int dim>
  class ExactContact
  {
  public:
    /**
     * @param[in] nodes All contact pairs of the problem.
     * @param[in] laws For each pair, the complementarity constants while
     *   the pair is intact (cohesion) if it follows the exact law, empty
     *   for a compliant pair. Cohesion is dropped once the pair has
     *   slipped or opened (JointHistory::intact).
     * @param[in] constraints Homogeneous constraints of the displacement
     *   (Dirichlet and hanging nodes), over DoFs 0..n_u-1.
     * @param[in] n_displacement_dofs n_u.
     * @p nodes and @p constraints are kept by reference: they must outlive
     * this object and keep their addresses (ContactSolver owns them).
     */
    ExactContact(const std::vector<ContactNode<dim>>            &nodes,
                 const std::vector<std::optional<ExactPairLaw>> &laws,
                 const dealii::AffineConstraints<double>        &constraints,
                 const unsigned int n_displacement_dofs);

    /** @brief Number of pairs with multipliers. */
    unsigned int
    n_pairs() const;

    /** @brief dim times n_pairs(). */
    unsigned int
    n_multipliers() const;

    /** @brief Pair directions held by supports on both sides. */
    unsigned int
    n_fixed_directions() const;

    /**
     * @brief Adds the couplings of the multipliers (rows and columns
     * n_u..n_u + n_multipliers() - 1) to @p pattern, which has n_u +
     * n_multipliers() rows.
     */
    void
    add_couplings(dealii::DynamicSparsityPattern &pattern) const;

    /**
     * @brief Adds @p weight times the constant block \f$B^T\f$ to
     * @p matrix (weight 1 writes it into a matrix without it; after
     * scale_complementarity(f), weight 1 - 1/f brings a matrix that holds
     * the old block to the new one).
     */
    void
    add_force_block(dealii::TrilinosWrappers::SparseMatrix &matrix,
                    const double                            weight = 1.) const;

    /**
     * @brief Evaluates every exact pair at the displacement @p solution
     * and the current multipliers; writes their responses into
     * @p responses (indexed like the nodes; other entries untouched) and
     * keeps the complementarity values for assemble_equations().
     */
    void
    evaluate(const dealii::TrilinosWrappers::MPI::Vector &solution,
             const std::vector<JointHistory<dim>>        &histories,
             std::vector<JointResponse<dim>>             &responses);

    /**
     * @brief Adds the scaled equations E of the last evaluate() to rows
     * n_u.. of @p residual and their derivatives to @p matrix (both of
     * size n_u + n_multipliers()).
     */
    void
    assemble_equations(dealii::TrilinosWrappers::SparseMatrix &matrix,
                       dealii::TrilinosWrappers::MPI::Vector  &residual) const;

    /**
     * @brief What round-off alone can leave in E (N/m): the l2 norm over
     * the pairs of \f$w c_n \epsilon (|u_A| + |u_B| + |g_0|)\f$, the
     * error of forming the gap of a closed pair.
     */
    double
    round_off_floor(
      const dealii::TrilinosWrappers::MPI::Vector &solution) const;

    /**
     * @brief Sets the multipliers of the pairs open at the last
     * evaluate() to exactly zero. Their equation is \f$\mu = 0\f$, met
     * to round-off by the linear solve; at a converged state the
     * round-off (1e-85 N/m was seen) is removed so that an open joint
     * reports zero force, not a negative one.
     */
    void
    zero_open_multipliers();

    /**
     * @brief Sets the multipliers from given tractions (a penalty
     * solution): \f$\mu = \lambda / c_n\f$ of each exact pair's normal
     * and tangential traction in @p responses.
     */
    void
    set_multipliers(const std::vector<JointResponse<dim>> &responses);

    /**
     * @brief Multiplies every pair's complementarity parameters
     * \f$c_n, c_t\f$ by @p factor (> 0) and divides the multipliers by
     * it, so that the tractions \f$\lambda = c_n \mu\f$ they stand for
     * do not change. The converged answer does not depend on the
     * parameters; the semi-smooth Newton iterates do.
     */
    void
    scale_complementarity(const double factor);

    /** @brief The multipliers \f$\mu = \lambda/c_n\f$ (m), working values. */
    dealii::Vector<double> &
    multipliers();

    const dealii::Vector<double> &
    multipliers() const;

  private:
    struct ExactPair
    {
      /** Index into the node list. */
      unsigned int node = 0;
      /** Unit tangents completing the pair's normal to a basis. */
      std::array<dealii::Tensor<1, dim>, dim - 1> tangents;
      /** Normal, then tangents: may the jump along it change? */
      std::array<bool, dim>       free_direction;
      double                      surface_stiffness;
      CoulombComplementarity<dim> intact_law;
      CoulombComplementarity<dim> broken_law;
    };

    /** Value and derivatives of the last evaluate(), per exact pair. */
    struct Evaluation
    {
      ComplementarityResponse<dim> response;
      double                       weight = 0.;
    };

    /**
     * Adds one equation's derivatives to @p matrix: by the pair's
     * multipliers, and by the displacements through the jump \f$[u] =
     * u_B - u_A\f$, each displacement column moved to its masters (or
     * dropped for a Dirichlet DoF) as the constraints say.
     */
    void
    add_row(const unsigned int                      row,
            const ExactPair                        &pair,
            const std::array<double, dim>          &by_multipliers,
            const dealii::Tensor<1, dim>           &by_jump,
            dealii::TrilinosWrappers::SparseMatrix &matrix) const;

    /** The equation mu = 0 of a direction held on both sides. */
    void
    add_fixed_direction_row(
      const unsigned int                      row,
      const ExactPair                        &pair,
      dealii::TrilinosWrappers::SparseMatrix &matrix,
      dealii::TrilinosWrappers::MPI::Vector  &residual) const;

    /** \f$w c_n\f$ of the pair (Pa): force per unit multiplier. */
    double
    force_scale(const ExactPair &pair) const;

    /** @p dof as a combination of unconstrained DoFs (empty if fixed). */
    std::vector<std::pair<dealii::types::global_dof_index, double>>
    distributed(const dealii::types::global_dof_index dof) const;

    /** The signed displacement DoFs of a pair: (+1, side B), (-1, side A). */
    std::vector<std::pair<double, dealii::types::global_dof_index>>
    side_dofs(const ContactNode<dim> &node, const unsigned int component) const;

    const std::vector<ContactNode<dim>>     &nodes;
    const dealii::AffineConstraints<double> &constraints;
    const unsigned int                       n_displacement_dofs;
    std::vector<ExactPair>                   pairs;
    std::vector<Evaluation>                  evaluations;
    unsigned int                             fixed_directions = 0;
    dealii::Vector<double>                   values;
  };
} // namespace FloorBlock::Contact
