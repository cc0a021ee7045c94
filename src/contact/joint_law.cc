#include <contact/joint_law.h>

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>

namespace FloorBlock::Contact
{
  const char *
  state_name(const JointState state)
  {
    switch (state)
      {
        case JointState::open:
          return "open";
        case JointState::stick:
          return "stick";
        case JointState::slip:
          return "slip";
      }
    return "unknown";
  }

  template <int dim>
  CoulombJoint<dim>::CoulombJoint(const JointConstants &parameters)
    : constants(parameters)
  {}

  template <int dim>
  const JointConstants &
  CoulombJoint<dim>::parameters() const
  {
    return constants;
  }

  template <int dim>
  JointResponse<dim>
  CoulombJoint<dim>::evaluate(const dealii::Tensor<1, dim> &jump,
                              const dealii::Tensor<1, dim> &normal,
                              const JointHistory<dim>      &history) const
  {
    using dealii::outer_product;
    JointResponse<dim> response;
    response.gap  = jump * normal;
    response.slip = jump - response.gap * normal;

    const double tensile_limit =
      history.intact ? constants.tensile_strength : 0.;
    const double normal_trial =
      history.normal_base - constants.normal_stiffness * response.gap;
    if (normal_trial < -tensile_limit)
      return response;

    const dealii::Tensor<2, dim> identity =
      dealii::unit_symmetric_tensor<dim>();
    const dealii::Tensor<2, dim> normal_projector =
      outer_product(normal, normal);
    response.normal_traction   = normal_trial;
    response.tangent           = constants.normal_stiffness * normal_projector;
    response.closure_stiffness = constants.normal_stiffness;

    const double friction_coefficient = std::tan(constants.friction_angle);
    const double cohesion = history.intact ? constants.cohesion : 0.;
    // A tensile normal traction cannot produce a negative shear strength.
    const double shear_limit =
      std::max(0., cohesion + friction_coefficient * normal_trial);
    const dealii::Tensor<1, dim> tangential_trial =
      history.tangential_base +
      constants.shear_stiffness * (response.slip - history.reference_slip);
    const double trial_magnitude = tangential_trial.norm();

    if (trial_magnitude <= shear_limit)
      {
        response.state               = JointState::stick;
        response.tangential_traction = tangential_trial;
        response.tangent +=
          constants.shear_stiffness * (identity - normal_projector);
      }
    else
      {
        response.state = JointState::slip;
        const dealii::Tensor<1, dim> direction =
          tangential_trial / trial_magnitude;
        response.tangential_traction = shear_limit * direction;
        // d t_t / d jump = (limit/|trial|) ks (I - n n - e e)
        //                + e (d limit / d jump), non-symmetric.
        response.tangent +=
          shear_limit / trial_magnitude * constants.shear_stiffness *
          (identity - normal_projector - outer_product(direction, direction));
        if (shear_limit > 0.)
          response.tangent -= friction_coefficient *
                              constants.normal_stiffness *
                              outer_product(direction, normal);
      }
    response.force_density =
      -response.normal_traction * normal + response.tangential_traction;
    return response;
  }

  template class CoulombJoint<2>;
  template class CoulombJoint<3>;
} // namespace FloorBlock::Contact
