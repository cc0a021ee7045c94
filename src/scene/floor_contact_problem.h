#pragma once

#include <string>

#include <contact/contact_problem.h>
#include <material/elastic_law.h>

#include <map>

namespace FloorBlock::Scene
{
  /**
   * @brief Plain description of the chapter's block-assembly physics on a
   * mesh that follows the id scheme of geometry/ids.h.
   */
  struct FloorProblemSettings
  {
    unsigned int n_blocks = 6;
    /** Elastic law of blocks, face block and base (Table 6.1: K 9 GPa, G 6.7
     * GPa). */
    Material::ElasticLaw<2> rock =
      Material::ElasticLaw<2>::from_bulk_shear(9e9, 6.7e9);
    /** Density of blocks and face block (kg/m^3); the base is weightless (it is
     * displacement driven). */
    double density = 2500.;
    /** Gravity acceleration magnitude (m/s^2), acting in -y. */
    double                gravity = 9.81;
    Contact::JointLawKind law     = Contact::JointLawKind::compliant;
    /** Vertical fractures (Table 6.1: kn 9 GPa/m, ks 6.7 GPa/m). */
    Contact::JointConstants vertical_joints;
    /** Bedding joint under the blocks. */
    Contact::JointConstants bedding_joints;
    /** Support pressure on the top of block i (Pa), keyed by chapter index i.
     */
    std::map<unsigned int, double> support_pressures;
    /**
     * Support pressure straight down per unit horizontal length (true), as
     * the closed forms' vertical P_i, or normal to the block top (false).
     */
    bool                    vertical_support_load = true;
    Contact::UpliftSettings uplift;
    Loading::LoadSteps      steps;
    /**
     * Dip of the frame's x axis below the horizontal (rad): gravity and
     * vertical support loads act along (sin, -cos) of it.
     */
    double frame_dip = 0.;
    /**
     * The blocks stand on a rigid half-plane y <= 0 (moved by the
     * uplift) instead of the elastic base; the mesh has no base.
     */
    bool rigid_base = false;
  };

  /**
   * @brief Joints, supports and loads of the block assembly.
   *
   * Joints (side A -> side B, normal from A to B):
   *  - "vertical j", j = 1..n: 3000+j (block j+1 / face block) -> 2000+j
   *    (block j); its normal force is the FEM Q_j;
   *  - "bedding i", i = 1..n: base top 5000+i -> block bottom 4000+i; on
   *    a rigid base, block bottom 4000+i against the plane y = 0, which
   *    the uplift moves.
   * The vertical joints are listed first: at a sharp corner on the
   * bedding the bedding keeps the crosspoint (Contact::
   * remove_crosspoint_pairs).
   * Supports: the face block is held fixed on its outer side (7005) and its
   * bottom (4000), so no contact is modelled under it; the base bottom
   * (7001) follows the uplift (zero in stages 1 and 2).
   */
  Contact::ContactProblem<2>
  make_floor_contact_problem(const FloorProblemSettings &settings);

  /** @brief The name make_floor_contact_problem() gives vertical joint j. */
  std::string
  vertical_joint_name(unsigned int j);

  /** @brief Whether @p name is a vertical joint's ("vertical j"). */
  bool
  is_vertical_joint(const std::string &name);
} // namespace FloorBlock::Scene
