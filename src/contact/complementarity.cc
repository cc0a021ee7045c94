#include <contact/complementarity.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/symmetric_tensor.h>

namespace FloorBlock::Contact
{
  template <int dim>
  CoulombComplementarity<dim>::CoulombComplementarity(
    const ComplementarityParameters &parameters)
    : constants(parameters)
  {
    AssertThrow(constants.friction_coefficient >= 0.,
                dealii::ExcMessage("friction coefficient must be >= 0"));
    AssertThrow(constants.cohesion >= 0.,
                dealii::ExcMessage("cohesion must be >= 0 Pa"));
    AssertThrow(
      constants.normal_parameter > 0. && constants.tangential_parameter > 0.,
      dealii::ExcMessage("complementarity parameters must be > 0 Pa/m"));
  }

  template <int dim>
  const ComplementarityParameters &
  CoulombComplementarity<dim>::parameters() const
  {
    return constants;
  }

  template <int dim>
  ComplementarityResponse<dim>
  CoulombComplementarity<dim>::evaluate(
    const double                  normal_multiplier,
    const dealii::Tensor<1, dim> &tangential_multiplier,
    const double                  gap,
    const dealii::Tensor<1, dim> &slip_increment) const
  {
    const dealii::Tensor<2, dim> identity =
      dealii::unit_symmetric_tensor<dim>();
    ComplementarityResponse<dim>     response;
    ComplementarityDerivatives<dim> &derivatives = response.derivatives;

    const double augmented_normal =
      normal_multiplier - constants.normal_parameter * gap;
    // xi_n = 0 counts as closed (see the class doc: kink choices).
    if (augmented_normal < 0.)
      {
        response.state                                  = JointState::open;
        response.normal_residual                        = normal_multiplier;
        response.tangential_residual                    = tangential_multiplier;
        derivatives.normal_by_normal_multiplier         = 1.;
        derivatives.tangential_by_tangential_multiplier = identity;
        return response;
      }

    response.normal_residual  = constants.normal_parameter * gap;
    derivatives.normal_by_gap = constants.normal_parameter;

    const double shear_strength =
      constants.cohesion + constants.friction_coefficient * augmented_normal;
    const dealii::Tensor<1, dim> augmented_tangential =
      tangential_multiplier + constants.tangential_parameter * slip_increment;
    const double augmented_magnitude = augmented_tangential.norm();

    // |xi_t| = R (also 0 = 0) counts as stick (see the class doc).
    if (augmented_magnitude <= shear_strength)
      {
        response.state = JointState::stick;
        response.tangential_residual =
          -constants.tangential_parameter * slip_increment;
        derivatives.tangential_by_slip_increment =
          -constants.tangential_parameter * identity;
        return response;
      }

    // Slip: |xi_t| > R >= 0, so the direction is defined.
    response.state = JointState::slip;
    const dealii::Tensor<1, dim> direction =
      augmented_tangential / augmented_magnitude;
    response.tangential_residual =
      tangential_multiplier - shear_strength * direction;
    const double strength_ratio = shear_strength / augmented_magnitude;
    const dealii::Tensor<2, dim> across_direction =
      identity - dealii::outer_product(direction, direction);
    derivatives.tangential_by_tangential_multiplier =
      identity - strength_ratio * across_direction;
    derivatives.tangential_by_slip_increment =
      -constants.tangential_parameter * strength_ratio * across_direction;
    derivatives.tangential_by_normal_multiplier =
      -constants.friction_coefficient * direction;
    derivatives.tangential_by_gap =
      constants.friction_coefficient * constants.normal_parameter * direction;
    return response;
  }

  template class CoulombComplementarity<2>;
  template class CoulombComplementarity<3>;
} // namespace FloorBlock::Contact
