#include <scene/analytic_inputs.h>
#include <scene/closed_forms.h>
#include <strength/hoek_brown.h>

#include <fmt/format.h>

#include <cmath>

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

  std::vector<std::string>
  scene_differences(const Parameters::ScenarioParameters &scene)
  {
    std::vector<std::string> differences;
    const auto              &bedding = scene.bedding;
    const auto              &loading = scene.loading;
    const bool               loaded =
      loading.support_load > 0. && !scene.loaded_blocks().empty();
    if (loaded &&
        loading.support_load_direction ==
          Parameters::SupportLoadDirection::top_normal &&
        (bedding.frame_dip != 0. || !bedding.flat_in_mesh()))
      differences.push_back(
        "Loading/Support load direction = normal to block top presses on "
        "block tops that are not level, so the FEM's support load is not "
        "vertical; the closed forms' P_i is");

    if (bedding.floor_uplift != Geometry::FloorUplift::lifted_flat_bedding)
      return differences;
    const double rise = bedding.rise_at_free_end(scene.geometry.n_blocks,
                                                 scene.geometry.block_width);
    if (scene.uplift_follows_bedding())
      {
        if (!Parameters::lift_matches_rise(loading.floor_lift, rise))
          differences.push_back(fmt::format(
            "Loading/Floor lift = {:g} m bends the FEM's flat bed into "
            "another floor than the bedding the closed forms stand the "
            "blocks on (its rise at the free end is {:g} m)",
            loading.floor_lift,
            rise));
      }
    else if (rise != 0. || loading.uplift_mode == Parameters::UpliftMode::tilt)
      differences.push_back(fmt::format(
        "Loading/Uplift mode moves the FEM's flat bed without bending it "
        "into the bedding the closed forms stand the blocks on (rise {:g} m "
        "at the free end){}",
        rise,
        loading.uplift_mode == Parameters::UpliftMode::tilt ?
          "; a tilt turns the FEM's bed" :
          ""));
    return differences;
  }

  ClosedForms
  evaluate_closed_forms(const Parameters::ScenarioParameters &scene)
  {
    ClosedForms result;
    result.chain          = block_chain(scene);
    result.support_width  = scene.geometry.support_width;
    result.youngs_modulus = scene.material.youngs_modulus();
    result.floor_lift     = face_joint_floor_lift(scene, result.chain);
    result.floor_strength = Strength::uniaxial_compressive_strength(
      scene.strength.intact_ucs, scene.strength.hoek_brown());

    for (const Mechanism mechanism : {Mechanism::no_rotation,
                                      Mechanism::rotation_no_vertical_slip,
                                      Mechanism::rotation_vertical_slip})
      {
        MechanismResult entry{mechanism,
                              solve(mechanism, result.chain),
                              0.,
                              {},
                              std::nullopt};
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
        const bool has_stress =
          entry.forces.status == Analytic::Status::ok &&
          Analytic::has_contact_values(entry.contact.status) &&
          entry.contact.max_stress > 0.;
        if (has_stress)
          entry.floor_safety_factor =
            result.floor_strength / entry.contact.max_stress;
        result.mechanisms.push_back(entry);
      }

    result.scene_differences = scene_differences(scene);
    const auto &no_rotation  = result.mechanisms.front().forces;
    if (!no_rotation.lateral_force.empty())
      result.no_rotation_heights =
        Analytic::centroid_heights(result.chain, no_rotation.lateral_force);
    else
      result.no_rotation_heights.status = no_rotation.status;
    return result;
  }
} // namespace FloorBlock::Scene
