#include <common/input_error.h>
#include <parameters/sections.h>

namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Selection;

  namespace
  {
    /**
     * Why the rigid-block model cannot represent the scene, or "" if it
     * can. Its joints are springs (kn, ks), and its support load is a
     * vertical line load, so a load normal to the block top is the same
     * load only where the top is level.
     */
    std::string
    rigid_model_limitation(const BeddingParameters &bedding,
                           const JointParameters   &joints,
                           const LoadingParameters &loading)
    {
      if (joints.law == Contact::JointLawKind::rigid)
        return "Joints/Law = rigid: rigid blocks stand on the joint "
               "springs kn, ks of the compliant law";
      if (bedding.rigid_base)
        return "Bedding/Base = rigid: the rigid model's blocks stand on the "
               "elastic base's joint springs";
      if (bedding.frame_dip != 0.)
        return "Bedding/Frame dip > 0: the rigid model's gravity is "
               "vertical in its frame";
      if (loading.support_load_direction == SupportLoadDirection::top_normal &&
          !bedding.flat_in_mesh())
        return "Loading/Support load direction = normal to block top on an "
               "inclined block top: the rigid model applies the support "
               "load vertically";
      return "";
    }
  } // namespace

  void
  ModelParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Model");
    prm.declare_entry(
      "Blocks",
      "elastic",
      Selection("elastic|rigid|auto"),
      "Which model computes the numbers of `solve` and `run` (the closed "
      "forms are always evaluated as well). elastic: the contact FEM "
      "(Gmsh mesh; deformable blocks, face block and base). rigid: rigid "
      "blocks, 3 DOF each, on the same compliant Coulomb joints "
      "integrated along every joint, with the same loads, uplift and load "
      "steps (src/rigid/README.md); its solve is about 50 times cheaper "
      "(0.1 s against 5 s on params/default.prm), no mesh and no VTU "
      "files; sharp corners (Geometry/Corner rounding radius is "
      "ignored); needs Joints/Law = compliant. auto: rigid when Model/"
      "Outputs = forces and the scene is one the rigid model represents, "
      "elastic otherwise. The rigid model also uses Solver/Gravity steps, "
      "Support load steps, Uplift steps, Newton tolerance, Max Newton "
      "iterations, Max cutbacks and Averaging length; the other Solver and "
      "Mesh entries apply to the elastic FEM only. Units: none.");
    prm.declare_entry(
      "Outputs",
      "contact stress",
      Selection("forces|contact stress"),
      "What the run is for; read only when Model/Blocks = auto. forces: "
      "the lateral forces Q_j and the joint shear forces, which the rigid "
      "blocks reproduce (face-joint Q within 0.2 % of the elastic FEM with "
      "sharp corners and 1.8 % of it with the default 1 cm rounding on "
      "params/default.prm, 0.5 % on tests/scenarios/three_blocks.prm; "
      "src/rigid/README.md); contact stress: the contact length and area "
      "and the peak stress at the block corners (Eqs. 6.51-6.53), which "
      "depend on the deformation of the blocks near the corner and need "
      "the elastic FEM (rigid blocks on joint springs give a face-joint "
      "contact 11-18 % shorter and a peak stress 22-24 % higher on the "
      "default scene). Units: none.");
    prm.declare_entry(
      "Rigid points per joint",
      "400",
      Integer(2, 100000),
      "Trapezoid points along every joint of the rigid-block model, both "
      "end points included; the spacing H/(points - 1) must resolve the "
      "shortest contact zone of interest (5 mm for H = 2 m at 400). `run` "
      "estimates the rigid model's discretisation error with twice as "
      "many points. Units: none.");
    prm.leave_subsection();
  }

  void
  ModelParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Model");
    const std::string model = prm.get("Blocks");
    blocks                  = model == "rigid" ? BlockModel::rigid :
                              model == "auto"  ? BlockModel::automatic :
                                                 BlockModel::elastic;
    outputs = prm.get("Outputs") == "forces" ? RequestedOutputs::forces :
                                               RequestedOutputs::contact_stress;
    rigid_points_per_joint = prm.get_integer("Rigid points per joint");
    prm.leave_subsection();
  }

  void
  ModelParameters::choose(const BeddingParameters &bedding,
                          const JointParameters   &joints,
                          const LoadingParameters &loading)
  {
    const std::string limitation =
      rigid_model_limitation(bedding, joints, loading);
    switch (blocks)
      {
        case BlockModel::elastic:
          chosen        = BlockModel::elastic;
          choice_reason = "Model/Blocks = elastic";
          return;
        case BlockModel::rigid:
          if (!limitation.empty())
            throw InputError("Model/Blocks",
                             "rigid",
                             "elastic or auto for this scene (" + limitation +
                               ")");
          chosen        = BlockModel::rigid;
          choice_reason = "Model/Blocks = rigid";
          return;
        case BlockModel::automatic:
          if (outputs == RequestedOutputs::contact_stress)
            {
              chosen        = BlockModel::elastic;
              choice_reason = "Model/Blocks = auto and Model/Outputs = "
                              "contact stress: corner contact needs the "
                              "elastic FEM";
            }
          else if (!limitation.empty())
            {
              chosen        = BlockModel::elastic;
              choice_reason = "Model/Blocks = auto, Model/Outputs = forces, "
                              "but the rigid model cannot represent the "
                              "scene (" +
                              limitation + ")";
            }
          else
            {
              chosen        = BlockModel::rigid;
              choice_reason = "Model/Blocks = auto and Model/Outputs = "
                              "forces: rigid blocks give Q";
            }
          return;
      }
  }
} // namespace FloorBlock::Parameters
