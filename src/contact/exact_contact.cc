#include <contact/exact_contact.h>

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>
#include <limits>

namespace FloorBlock::Contact
{
  namespace
  {
    /** Orthonormal tangents of a unit normal (2D: the normal turned by
     *  +90 degrees; 3D: any right-handed pair). */
    template <int dim>
    std::array<dealii::Tensor<1, dim>, dim - 1>
    tangent_basis(const dealii::Tensor<1, dim> &normal)
    {
      std::array<dealii::Tensor<1, dim>, dim - 1> tangents;
      if constexpr (dim == 2)
        {
          tangents[0][0] = -normal[1];
          tangents[0][1] = normal[0];
        }
      else
        {
          // Cross with the axis least aligned with the normal.
          unsigned int axis = 0;
          for (unsigned int c = 1; c < dim; ++c)
            if (std::abs(normal[c]) < std::abs(normal[axis]))
              axis = c;
          dealii::Tensor<1, dim> unit;
          unit[axis]  = 1.;
          tangents[0] = dealii::cross_product_3d(normal, unit);
          tangents[0] /= tangents[0].norm();
          tangents[1] = dealii::cross_product_3d(normal, tangents[0]);
        }
      return tangents;
    }

    /** A direction component below this (-) does not couple a DoF. */
    constexpr double direction_tolerance = 1e-12;

    ComplementarityParameters
    without_cohesion(ComplementarityParameters parameters)
    {
      parameters.cohesion = 0.;
      return parameters;
    }
  } // namespace

  template <int dim>
  ExactContact<dim>::ExactContact(
    const std::vector<ContactNode<dim>>            &nodes,
    const std::vector<std::optional<ExactPairLaw>> &laws,
    const dealii::AffineConstraints<double>        &constraints,
    const unsigned int                              n_displacement_dofs)
    : nodes(nodes)
    , constraints(constraints)
    , n_displacement_dofs(n_displacement_dofs)
  {
    for (unsigned int p = 0; p < nodes.size(); ++p)
      {
        if (!laws[p])
          continue;
        ExactPair pair{p,
                       tangent_basis(nodes[p].normal),
                       {},
                       laws[p]->surface_stiffness,
                       CoulombComplementarity<dim>(laws[p]->complementarity),
                       CoulombComplementarity<dim>(
                         without_cohesion(laws[p]->complementarity))};
        // Can the relative displacement along each direction change?
        for (unsigned int i = 0; i < dim; ++i)
          {
            const dealii::Tensor<1, dim> direction =
              i == 0 ? nodes[p].normal : pair.tangents[i - 1];
            pair.free_direction[i] = false;
            for (unsigned int c = 0; c < dim; ++c)
              for (const auto &[sign, dof] : side_dofs(nodes[p], c))
                if (std::abs(direction[c]) > direction_tolerance &&
                    !distributed(dof).empty())
                  pair.free_direction[i] = true;
            if (!pair.free_direction[i])
              ++fixed_directions;
          }
        pairs.push_back(pair);
      }
    evaluations.resize(pairs.size());
    values.reinit(n_multipliers());
  }

  template <int dim>
  unsigned int
  ExactContact<dim>::n_pairs() const
  {
    return pairs.size();
  }

  template <int dim>
  unsigned int
  ExactContact<dim>::n_multipliers() const
  {
    return dim * pairs.size();
  }

  template <int dim>
  unsigned int
  ExactContact<dim>::n_fixed_directions() const
  {
    return fixed_directions;
  }

  template <int dim>
  dealii::Vector<double> &
  ExactContact<dim>::multipliers()
  {
    return values;
  }

  template <int dim>
  const dealii::Vector<double> &
  ExactContact<dim>::multipliers() const
  {
    return values;
  }

  template <int dim>
  std::vector<std::pair<double, dealii::types::global_dof_index>>
  ExactContact<dim>::side_dofs(const ContactNode<dim> &node,
                               const unsigned int      component) const
  {
    std::vector<std::pair<double, dealii::types::global_dof_index>> dofs;
    if (!node.against_rigid_obstacle())
      dofs.emplace_back(1., node.dofs_b[component]);
    dofs.emplace_back(-1., node.dofs_a[component]);
    return dofs;
  }

  template <int dim>
  std::vector<std::pair<dealii::types::global_dof_index, double>>
  ExactContact<dim>::distributed(
    const dealii::types::global_dof_index dof) const
  {
    if (!constraints.is_constrained(dof))
      return {{dof, 1.}};
    // A Dirichlet DoF has no entries: its column or row is dropped.
    const auto *entries = constraints.get_constraint_entries(dof);
    if (entries == nullptr)
      return {};
    return *entries;
  }

  template <int dim>
  void
  ExactContact<dim>::add_couplings(
    dealii::DynamicSparsityPattern &pattern) const
  {
    for (unsigned int k = 0; k < pairs.size(); ++k)
      for (unsigned int i = 0; i < dim; ++i)
        {
          const unsigned int multiplier = n_displacement_dofs + dim * k + i;
          for (unsigned int j = 0; j < dim; ++j)
            pattern.add(multiplier, n_displacement_dofs + dim * k + j);
          for (unsigned int c = 0; c < dim; ++c)
            for (const auto &[sign, dof] : side_dofs(nodes[pairs[k].node], c))
              for (const auto &[column, weight] : distributed(dof))
                {
                  pattern.add(multiplier, column);
                  pattern.add(column, multiplier);
                }
        }
  }

  template <int dim>
  void
  ExactContact<dim>::add_force_block(
    dealii::TrilinosWrappers::SparseMatrix &matrix,
    const double                            weight) const
  {
    // Force on side B per unit multiplier: w c_n (-n) (normal), w c_n
    // tau_j (tangent j),
    // from the traction -t_A = lambda_n n - lambda_t acting on B and the
    // residual convention internal - external (JointResponse::
    // force_density); side A receives the opposite.
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        const ExactPair        &pair = pairs[k];
        const ContactNode<dim> &node = nodes[pair.node];
        for (unsigned int i = 0; i < dim; ++i)
          {
            const dealii::Tensor<1, dim> direction =
              force_scale(pair) *
              (i == 0 ? -node.normal : pair.tangents[i - 1]);
            const unsigned int column = n_displacement_dofs + dim * k + i;
            for (unsigned int c = 0; c < dim; ++c)
              for (const auto &[sign, dof] : side_dofs(node, c))
                for (const auto &[row, share] : distributed(dof))
                  matrix.add(row, column, weight * sign * share * direction[c]);
          }
      }
    matrix.compress(dealii::VectorOperation::add);
  }

  template <int dim>
  void
  ExactContact<dim>::evaluate(
    const dealii::TrilinosWrappers::MPI::Vector &solution,
    const std::vector<JointHistory<dim>>        &histories,
    std::vector<JointResponse<dim>>             &responses)
  {
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        const ExactPair        &pair = pairs[k];
        const ContactNode<dim> &node = nodes[pair.node];
        dealii::Tensor<1, dim>  jump =
          node.initial_gap * node.normal + node.obstacle_displacement;
        for (unsigned int c = 0; c < dim; ++c)
          for (const auto &[sign, dof] : side_dofs(node, c))
            jump[c] += sign * solution(dof);
        const double                 weight  = node.weight;
        const double                 gap     = jump * node.normal;
        const dealii::Tensor<1, dim> slip    = jump - gap * node.normal;
        const JointHistory<dim>     &history = histories[pair.node];

        const double scale = pair.intact_law.parameters().normal_parameter;
        const double normal_multiplier = scale * values(dim * k);
        dealii::Tensor<1, dim> tangential_multiplier;
        for (unsigned int j = 1; j < dim; ++j)
          tangential_multiplier +=
            scale * values(dim * k + j) * pair.tangents[j - 1];

        const CoulombComplementarity<dim> &law =
          history.intact ? pair.intact_law : pair.broken_law;
        evaluations[k].response = law.evaluate(normal_multiplier,
                                               tangential_multiplier,
                                               gap,
                                               slip - history.reference_slip);
        evaluations[k].weight   = weight;

        JointResponse<dim> &response = responses[pair.node];
        response                     = JointResponse<dim>();
        response.state               = evaluations[k].response.state;
        response.normal_traction     = normal_multiplier;
        response.tangential_traction = tangential_multiplier;
        response.force_density =
          -normal_multiplier * node.normal + tangential_multiplier;
        response.gap  = gap;
        response.slip = slip;
        // The tangent stays zero: the multipliers' Jacobian is assembled
        // here, not through the pair's law.
        response.closure_stiffness = pair.surface_stiffness;
        response.exact_traction    = true;
      }
  }

  template <int dim>
  void
  ExactContact<dim>::set_multipliers(
    const std::vector<JointResponse<dim>> &responses)
  {
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        const ExactPair          &pair     = pairs[k];
        const JointResponse<dim> &response = responses[pair.node];
        const double scale = pair.intact_law.parameters().normal_parameter;
        values(dim * k) =
          pair.free_direction[0] ? response.normal_traction / scale : 0.;
        for (unsigned int j = 1; j < dim; ++j)
          values(dim * k + j) =
            pair.free_direction[j] ?
              (response.tangential_traction * pair.tangents[j - 1]) / scale :
              0.;
      }
  }

  template <int dim>
  void
  ExactContact<dim>::scale_complementarity(const double factor)
  {
    AssertThrow(factor > 0. && std::isfinite(factor),
                dealii::ExcMessage("complementarity scale must be > 0"));
    for (ExactPair &pair : pairs)
      {
        ComplementarityParameters intact = pair.intact_law.parameters();
        intact.normal_parameter *= factor;
        intact.tangential_parameter *= factor;
        pair.intact_law = CoulombComplementarity<dim>(intact);
        pair.broken_law = CoulombComplementarity<dim>(without_cohesion(intact));
      }
    values /= factor;
  }

  template <int dim>
  void
  ExactContact<dim>::zero_open_multipliers()
  {
    for (unsigned int k = 0; k < pairs.size(); ++k)
      if (evaluations[k].response.state == JointState::open)
        for (unsigned int i = 0; i < dim; ++i)
          values(dim * k + i) = 0.;
  }

  template <int dim>
  double
  ExactContact<dim>::force_scale(const ExactPair &pair) const
  {
    return nodes[pair.node].weight *
           pair.intact_law.parameters().normal_parameter;
  }

  template <int dim>
  void
  ExactContact<dim>::add_row(
    const unsigned int                      row,
    const ExactPair                        &pair,
    const std::array<double, dim>          &by_multipliers,
    const dealii::Tensor<1, dim>           &by_jump,
    dealii::TrilinosWrappers::SparseMatrix &matrix) const
  {
    // dE/dmu = w c_n dC/dlambda, since lambda = c_n mu.
    const unsigned int k = (row - n_displacement_dofs) / dim;
    for (unsigned int j = 0; j < dim; ++j)
      matrix.add(row,
                 n_displacement_dofs + dim * k + j,
                 force_scale(pair) * by_multipliers[j]);
    const ContactNode<dim> &node = nodes[pair.node];
    for (unsigned int c = 0; c < dim; ++c)
      if (by_jump[c] != 0.)
        for (const auto &[sign, dof] : side_dofs(node, c))
          for (const auto &[column, weight] : distributed(dof))
            matrix.add(row, column, sign * weight * by_jump[c]);
  }

  template <int dim>
  void
  ExactContact<dim>::add_fixed_direction_row(
    const unsigned int                      row,
    const ExactPair                        &pair,
    dealii::TrilinosWrappers::SparseMatrix &matrix,
    dealii::TrilinosWrappers::MPI::Vector  &residual) const
  {
    // Both nodes held along this direction: the traction along it is a
    // support reaction, so the multiplier is set to zero (E = w c_n mu).
    const double scale = force_scale(pair);
    residual(row) += scale * values(row - n_displacement_dofs);
    matrix.add(row, row, scale);
  }

  template <int dim>
  void
  ExactContact<dim>::assemble_equations(
    dealii::TrilinosWrappers::SparseMatrix &matrix,
    dealii::TrilinosWrappers::MPI::Vector  &residual) const
  {
    const dealii::Tensor<2, dim> identity =
      dealii::unit_symmetric_tensor<dim>();
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        const ExactPair              &pair     = pairs[k];
        const dealii::Tensor<1, dim> &normal   = nodes[pair.node].normal;
        const double                  weight   = evaluations[k].weight;
        const auto                   &response = evaluations[k].response;
        const auto                   &d        = response.derivatives;
        const unsigned int            first    = n_displacement_dofs + dim * k;

        // E_n = w C_n; C_n depends on lambda_n = c_n mu_n and g.
        std::array<double, dim> by_multipliers{};
        if (pair.free_direction[0])
          {
            residual(first) += weight * response.normal_residual;
            by_multipliers[0] = d.normal_by_normal_multiplier;
            add_row(first,
                    pair,
                    by_multipliers,
                    weight * d.normal_by_gap * normal,
                    matrix);
          }
        else
          add_fixed_direction_row(first, pair, matrix, residual);

        // E_j = w tau_j . C_t, with Delta s = (I - n n) [u] - s_ref.
        const dealii::Tensor<2, dim> tangent_projector =
          identity - dealii::outer_product(normal, normal);
        for (unsigned int j = 1; j < dim; ++j)
          {
            if (!pair.free_direction[j])
              {
                add_fixed_direction_row(first + j, pair, matrix, residual);
                continue;
              }
            by_multipliers                        = {};
            const dealii::Tensor<1, dim> &tangent = pair.tangents[j - 1];
            residual(first + j) +=
              weight * (tangent * response.tangential_residual);
            by_multipliers[0] = tangent * d.tangential_by_normal_multiplier;
            for (unsigned int m = 1; m < dim; ++m)
              by_multipliers[m] =
                tangent *
                (d.tangential_by_tangential_multiplier * pair.tangents[m - 1]);
            const dealii::Tensor<1, dim> by_jump =
              weight *
              ((tangent * d.tangential_by_gap) * normal +
               tangent * d.tangential_by_slip_increment * tangent_projector);
            add_row(first + j, pair, by_multipliers, by_jump, matrix);
          }
      }
    matrix.compress(dealii::VectorOperation::add);
    residual.compress(dealii::VectorOperation::add);
  }

  template <int dim>
  double
  ExactContact<dim>::round_off_floor(
    const dealii::TrilinosWrappers::MPI::Vector &solution) const
  {
    double sum = 0.;
    for (const ExactPair &pair : pairs)
      {
        const ContactNode<dim> &node = nodes[pair.node];
        double                  size =
          std::abs(node.initial_gap) + node.obstacle_displacement.norm();
        for (unsigned int c = 0; c < dim; ++c)
          for (const auto &[sign, dof] : side_dofs(node, c))
            size += std::abs(solution(dof));
        const double term = node.weight *
                            pair.intact_law.parameters().normal_parameter *
                            std::numeric_limits<double>::epsilon() * size;
        sum += term * term;
      }
    return std::sqrt(sum);
  }

  template class ExactContact<2>;
  template class ExactContact<3>;
} // namespace FloorBlock::Contact
