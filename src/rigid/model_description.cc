#include <common/input_error.h>
#include <rigid/model_description.h>

#include <cmath>
#include <string>

namespace FloorBlock::RigidBlocks
{
  namespace
  {
    std::string
    text(const double value)
    {
      return std::to_string(value);
    }

    void
    require(const bool         condition,
            const std::string &parameter,
            const double       value,
            const std::string &allowed)
    {
      if (!condition)
        throw InputError(parameter, text(value), allowed);
    }

    /** Joint constants: kn, ks > 0 (a rigid body needs springs), phi in [0, 90
     * deg). */
    void
    validate_joint(const Contact::JointConstants &joint,
                   const std::string             &section)
    {
      require(std::isfinite(joint.normal_stiffness) &&
                joint.normal_stiffness > 0.,
              section + "/Normal stiffness",
              joint.normal_stiffness,
              "finite and > 0 Pa/m");
      require(std::isfinite(joint.shear_stiffness) &&
                joint.shear_stiffness > 0.,
              section + "/Shear stiffness",
              joint.shear_stiffness,
              "finite and > 0 Pa/m");
      require(std::isfinite(joint.friction_angle) &&
                joint.friction_angle >= 0. && joint.friction_angle < M_PI / 2.,
              section + "/Friction angle",
              joint.friction_angle,
              "0 <= phi < pi/2 rad");
      require(std::isfinite(joint.cohesion) && joint.cohesion >= 0.,
              section + "/Cohesion",
              joint.cohesion,
              "finite and >= 0 Pa");
      require(std::isfinite(joint.tensile_strength) &&
                joint.tensile_strength >= 0.,
              section + "/Tensile strength",
              joint.tensile_strength,
              "finite and >= 0 Pa");
    }
  } // namespace

  void
  validate(const ModelDescription &description)
  {
    Geometry::validate(description.assembly);
    require(std::isfinite(description.density) && description.density >= 0.,
            "Material/Density",
            description.density,
            "finite and >= 0 kg/m^3");
    require(std::isfinite(description.gravity) && description.gravity >= 0.,
            "Loading/Gravity",
            description.gravity,
            "finite and >= 0 m/s^2");
    const unsigned int n_blocks = description.assembly.n_blocks;
    if (!description.support_line_loads.empty() &&
        description.support_line_loads.size() != n_blocks)
      throw InputError("Loading/Support line loads",
                       std::to_string(description.support_line_loads.size()) +
                         " entries",
                       "none or one per block (" + std::to_string(n_blocks) +
                         ")");
    for (const double load : description.support_line_loads)
      require(std::isfinite(load) && load >= 0.,
              "Loading/Support line loads",
              load,
              "finite and >= 0 N/m");
    require(description.support_load_position >= 0. &&
              description.support_load_position <= 1.,
            "Loading/Support load position",
            description.support_load_position,
            "0 <= r <= 1 (fraction of L from the side away from the face)");
    validate_joint(description.bedding_joint, "Joints/Bedding");
    validate_joint(description.vertical_joint, "Joints/Vertical");
    require(std::isfinite(description.uplift.magnitude) &&
              std::isfinite(description.uplift.dip_angle) &&
              std::isfinite(description.uplift.pivot_x) &&
              std::isfinite(description.uplift.pivot_y),
            "Loading/Floor uplift",
            description.uplift.magnitude,
            "finite magnitude, dip angle and pivot");
    require(description.solver.n_points_per_joint >= 2,
            "Rigid blocks/Points per joint",
            description.solver.n_points_per_joint,
            ">= 2 (trapezoid rule with both end points)");
  }
} // namespace FloorBlock::RigidBlocks
