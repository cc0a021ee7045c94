#include <scene/analytic_inputs.h>
#include <scene/closed_forms.h>

namespace FloorBlock::Scene
{
  std::string
  to_string(const Mechanism mechanism)
  {
    switch (mechanism)
      {
        case Mechanism::no_rotation:
          return "no_rotation";
        case Mechanism::rotation_no_vertical_slip:
          return "rotation_no_vertical_slip";
        case Mechanism::rotation_vertical_slip:
          return "rotation_vertical_slip";
      }
    return "unknown";
  }

  namespace
  {
    Analytic::ChainForces
    solve(const Mechanism mechanism, const Analytic::BlockChain &chain)
    {
      switch (mechanism)
        {
          case Mechanism::no_rotation:
            return Analytic::slip_no_rotation(chain);
          case Mechanism::rotation_no_vertical_slip:
            return Analytic::rotation_no_vertical_slip(chain);
          case Mechanism::rotation_vertical_slip:
            break;
        }
      return Analytic::rotation_vertical_slip(chain);
    }
  } // namespace

  ClosedForms
  evaluate_closed_forms(const Parameters::ScenarioParameters &scene)
  {
    ClosedForms result;
    result.chain          = block_chain(scene);
    result.support_width  = scene.geometry.support_width;
    result.youngs_modulus = scene.material.youngs_modulus();
    result.floor_lift     = face_joint_floor_lift(scene, result.chain);

    for (const Mechanism mechanism : {Mechanism::no_rotation,
                                      Mechanism::rotation_no_vertical_slip,
                                      Mechanism::rotation_vertical_slip})
      {
        MechanismResult entry{mechanism,
                              solve(mechanism, result.chain),
                              0.,
                              {}};
        if (!entry.forces.lateral_force.empty())
          {
            entry.face_force_over_width =
              entry.forces.lateral_force.back() * result.support_width;
            entry.contact =
              Analytic::corner_contact(entry.face_force_over_width,
                                       result.floor_lift,
                                       result.youngs_modulus,
                                       result.support_width,
                                       scene.geometry.block_width,
                                       scene.geometry.block_height);
          }
        else
          entry.contact.status = entry.forces.status;
        result.mechanisms.push_back(entry);
      }

    const auto &no_rotation = result.mechanisms.front().forces;
    if (!no_rotation.lateral_force.empty())
      result.no_rotation_heights =
        Analytic::centroid_heights(result.chain, no_rotation.lateral_force);
    else
      result.no_rotation_heights.status = no_rotation.status;
    return result;
  }
} // namespace FloorBlock::Scene
