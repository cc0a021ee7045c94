#include "scene_fixture.h"

#include <cmath>
#include <stdexcept>

namespace FloorBlock::RigidBlocks::Testing
{
  double
  radians(const double degrees)
  {
    return degrees * M_PI / 180.;
  }

  Contact::JointConstants
  table_joint(const double friction_angle)
  {
    Contact::JointConstants joint;
    joint.normal_stiffness = table_normal_stiffness;
    joint.shear_stiffness  = table_shear_stiffness;
    joint.friction_angle   = friction_angle;
    return joint;
  }

  ModelDescription
  planar_scene(const unsigned int n_blocks,
               const double       inclination,
               const double       bedding_friction,
               const double       vertical_friction)
  {
    ModelDescription description;
    description.assembly.n_blocks      = n_blocks;
    description.assembly.bedding_shape = Geometry::BeddingShape::planar;
    description.assembly.inclination   = inclination;
    description.density                = rock_density;
    description.gravity                = standard_gravity;
    description.bedding_joint          = table_joint(bedding_friction);
    description.vertical_joint         = table_joint(vertical_friction);
    description.steps                  = {1, 0, 0};
    return description;
  }

  ModelDescription
  default_scene(const unsigned int n_uplift)
  {
    constexpr double       support_tonnes = 650.;
    constexpr double       tonne          = 1000.;
    constexpr double       support_width  = 1.5;
    constexpr unsigned int n_loaded       = 3;
    constexpr double       floor_lift     = 0.05;
    ModelDescription       description;
    description.density        = rock_density;
    description.gravity        = standard_gravity;
    description.bedding_joint  = table_joint(radians(30.));
    description.vertical_joint = table_joint(radians(30.));
    description.support_line_loads.assign(description.assembly.n_blocks, 0.);
    for (unsigned int index = 0; index < n_loaded; ++index)
      description.support_line_loads[index] =
        support_tonnes * tonne * standard_gravity / (n_loaded * support_width);
    description.uplift.mode      = Contact::UpliftMotion::vertical_translation;
    description.uplift.magnitude = floor_lift;
    description.steps            = {1, 1, n_uplift};
    return description;
  }

  ModelDescription
  lifted_parabola_scene(const unsigned int n_uplift)
  {
    ModelDescription description = default_scene(n_uplift);
    description.assembly.floor_uplift =
      Geometry::FloorUplift::lifted_flat_bedding;
    description.uplift.mode      = Contact::UpliftMotion::parabola;
    description.uplift.magnitude = description.assembly.curvature;
    return description;
  }

  const RigidJointReport &
  find_joint(const IncrementReport &increment,
             const JointKind        kind,
             const unsigned int     number)
  {
    for (const RigidJointReport &joint : increment.joints)
      if (joint.kind == kind && joint.number == number)
        return joint;
    throw std::logic_error("no such joint in the increment");
  }
} // namespace FloorBlock::RigidBlocks::Testing
