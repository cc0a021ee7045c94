#include <compare/joint_comparison.h>
#include <compare/joint_name.h>
#include <geometry/ids.h>

#include <cmath>
#include <map>

namespace FloorBlock::Compare
{
  namespace
  {
    double
    rotation_of(const Contact::IncrementResult  &increment,
                const dealii::types::material_id material)
    {
      const auto motion = increment.motions.find(material);
      return motion == increment.motions.end() ? 0. : motion->second.rotation;
    }

    ForceComparison
    compare_force(const Scene::MechanismResult &entry,
                  const unsigned int            joint,
                  const double                  fem_force,
                  const bool                    fem_carries_load,
                  const bool                    same_scene)
    {
      ForceComparison comparison;
      comparison.mechanism          = Scene::to_string(entry.mechanism);
      comparison.closed_form_status = entry.forces.status;
      comparison.status             = Analytic::to_string(entry.forces.status);
      const auto &values            = entry.forces.lateral_force;
      if (joint == 0 || joint > values.size())
        return comparison;
      comparison.has_value   = true;
      comparison.closed_form = values[joint - 1];
      if (!fem_carries_load)
        comparison.difference_status = DifferenceStatus::no_load;
      else if (!same_scene)
        comparison.difference_status = DifferenceStatus::other_scene;
      else if (comparison.closed_form == 0.)
        comparison.difference_status = DifferenceStatus::zero_closed_form;
      else
        {
          comparison.difference_status = DifferenceStatus::defined;
          comparison.relative_difference =
            (fem_force - comparison.closed_form) /
            std::abs(comparison.closed_form);
        }
      return comparison;
    }
  } // namespace

  std::string
  to_string(const DifferenceStatus status)
  {
    switch (status)
      {
        case DifferenceStatus::defined:
          return "ok";
        case DifferenceStatus::no_closed_form:
          return "no_closed_form";
        case DifferenceStatus::no_load:
          return "no_load";
        case DifferenceStatus::zero_closed_form:
          return "zero_closed_form";
        case DifferenceStatus::other_scene:
          return "other_scene";
      }
    return "unknown";
  }

  ClosedFormInputs
  closed_form_inputs(const Scene::ClosedForms &closed_forms)
  {
    return {closed_forms.chain.inclination,
            closed_forms.chain.weight,
            closed_forms.chain.support_load,
            closed_forms.floor_lift,
            closed_forms.scene_differences};
  }

  std::vector<JointComparison>
  compare_vertical_joints(const Contact::IncrementResult &increment,
                          const Scene::ClosedForms       &closed_forms,
                          const ContactConstants         &constants)
  {
    const unsigned int n_blocks = closed_forms.chain.n_blocks();
    const LoadCheck    load = check_load(increment, constants.youngs_modulus);
    std::vector<JointComparison> comparisons;
    for (const Contact::JointReport &report : increment.joints)
      {
        const JointName name = parse_joint_name(report.name);
        if (name.kind != "vertical" || name.number == 0)
          continue;
        const unsigned int joint = name.number;

        JointComparison comparison{joint, report.normal_force, {}, {}, load};
        for (const auto &entry : closed_forms.mechanisms)
          comparison.forces.push_back(
            compare_force(entry,
                          joint,
                          report.normal_force,
                          load.carries_load(),
                          closed_forms.scene_differences.empty()));

        const auto face_side_material =
          joint == n_blocks ? Geometry::Ids::face_block_material :
                              Geometry::Ids::block_material(joint + 1);
        ContactComparison &contact = comparison.contact;
        contact.relative_rotation =
          rotation_of(increment, Geometry::Ids::block_material(joint)) -
          rotation_of(increment, face_side_material);
        contact.floor_lift =
          constants.block_width * std::tan(contact.relative_rotation);
        contact.force_over_width =
          std::max(report.normal_force, 0.) * constants.support_width;
        contact.closed_form = Analytic::corner_contact(contact.force_over_width,
                                                       contact.floor_lift,
                                                       constants.youngs_modulus,
                                                       constants.support_width,
                                                       constants.block_width,
                                                       constants.block_height);
        contact.fem_area    = report.closed_length * constants.support_width;
        contact.fem_mean_stress          = report.mean_normal_stress;
        contact.fem_peak_stress          = report.peak_normal_stress;
        contact.fem_averaged_peak_stress = report.averaged_peak_normal_stress;
        contact.fem_carries_load         = load.carries_load();
        comparisons.push_back(comparison);
      }
    return comparisons;
  }
} // namespace FloorBlock::Compare
