#include <geometry/ids.h>
#include <scene/swept_contact_problem.h>

#include <algorithm>

namespace FloorBlock::Scene
{
  namespace
  {
    /** (x, y, 0) from (x, y). */
    dealii::Tensor<1, 3>
    with_zero_z(const dealii::Tensor<1, 2> &vector)
    {
      dealii::Tensor<1, 3> result;
      result[0] = vector[0];
      result[1] = vector[1];
      return result;
    }

    Fem::ElasticModel<3>
    swept_model(const Fem::ElasticModel<2> &plane)
    {
      Fem::ElasticModel<3> model;
      for (const auto &[material, law] : plane.laws)
        model.laws.emplace(material,
                           Material::ElasticLaw<3>::same_material_as(law));
      model.densities          = plane.densities;
      model.gravity            = with_zero_z(plane.gravity);
      model.pressures          = plane.pressures;
      model.vertical_pressures = plane.vertical_pressures;
      model.down               = with_zero_z(plane.down);
      return model;
    }

    Contact::JointDefinition<3>
    swept_joint(const Contact::JointDefinition<2> &plane)
    {
      Contact::JointDefinition<3> joint;
      joint.name                = plane.name;
      joint.side_a              = plane.side_a;
      joint.side_b              = plane.side_b;
      joint.law                 = plane.law;
      joint.parameters          = plane.parameters;
      joint.against_rigid_plane = plane.against_rigid_plane;
      joint.plane_point  = dealii::Point<3>(with_zero_z(plane.plane_point));
      joint.plane_normal = with_zero_z(plane.plane_normal);
      joint.obstacle_curvature      = plane.obstacle_curvature;
      joint.plane_moves_with_uplift = plane.plane_moves_with_uplift;
      return joint;
    }

    Contact::SupportDefinition<3>
    swept_support(const Contact::SupportDefinition<2> &plane)
    {
      Contact::SupportDefinition<3> support;
      support.boundary_id               = plane.boundary_id;
      support.constrained_components[0] = plane.constrained_components[0];
      support.constrained_components[1] = plane.constrained_components[1];
      support.constrained_components[2] =
        plane.constrained_components[0] && plane.constrained_components[1];
      support.moves_with_uplift = plane.moves_with_uplift;
      return support;
    }
  } // namespace

  Contact::ContactProblem<3>
  swept_contact_problem(const Contact::ContactProblem<2> &plane,
                        const Geometry::EndFaces          end_faces)
  {
    Contact::ContactProblem<3> problem;
    problem.model = swept_model(plane.model);
    for (const auto &joint : plane.joints)
      problem.joints.push_back(swept_joint(joint));
    for (const auto &support : plane.supports)
      problem.supports.push_back(swept_support(support));
    if (end_faces == Geometry::EndFaces::plane_strain)
      for (const auto end :
           {Geometry::Ids::end_face_near, Geometry::Ids::end_face_far})
        {
          Contact::SupportDefinition<3> support;
          support.boundary_id            = end;
          support.constrained_components = {{false, false, true}};
          problem.supports.push_back(support);
        }
    problem.uplift = plane.uplift;
    problem.steps  = plane.steps;
    return problem;
  }
} // namespace FloorBlock::Scene
