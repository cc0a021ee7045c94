#pragma once

#include <contact/joint_law.h>
#include <rigid/block_motion.h>
#include <rigid/joint_layout.h>
#include <rigid/model_description.h>

#include <vector>

namespace FloorBlock::RigidBlocks
{
  /** Per joint, per integration point (same order as JointSet::joints()). */
  template <typename T>
  using PerPoint = std::vector<std::vector<T>>;

  using JointHistories = PerPoint<Contact::JointHistory<2>>;
  using JointResponses = PerPoint<Contact::JointResponse<2>>;

  /**
   * @brief The joints of a scene with their Coulomb laws, and the
   * kinematics that turn block motions into joint jumps.
   *
   * Every integration point uses Contact::CoulombJoint, the same law as
   * the FE model's compliant joints: \f$t_n = k_n \max(-g, 0)\f$ (or down
   * to the tensile strength while intact), shear by return mapping with
   * ks. The jump at a point p is \f$[u] = u_B(p) - u_A(p)\f$; the sides
   * start in contact with zero gap, as in the conforming mesh.
   */
  class JointSet
  {
  public:
    explicit JointSet(const ModelDescription &description);

    const std::vector<JointGeometry> &
    joints() const;

    /** Centroids of the blocks, index i - 1 (m). */
    const std::vector<dealii::Point<2>> &
    centroids() const;

    unsigned int
    n_blocks() const;

    /** @brief Law of a joint (bedding or vertical constants). */
    const Contact::CoulombJoint<2> &
    law(const JointGeometry &joint) const;

    /**
     * @brief Displacement (m) of the side @p body at @p point: block motion,
     * zero for the face block, the prescribed uplift field for the base.
     */
    dealii::Tensor<1, 2>
    side_displacement(const BodyRef                  &body,
                      const dealii::Point<2>         &point,
                      const std::vector<BlockMotion> &motions,
                      const double                    uplift_factor) const;

    /**
     * @brief Evaluate the law at every point.
     * @param[in] motions Motion of every block.
     * @param[in] uplift_factor Fraction of the prescribed base uplift (-).
     * @param[in] histories Converged history of every point.
     */
    JointResponses
    evaluate(const std::vector<BlockMotion> &motions,
             const double                    uplift_factor,
             const JointHistories           &histories) const;

    /** @brief Histories of a fresh scene: intact joints, no shear, no slip. */
    JointHistories
    virgin_histories() const;

  private:
    std::vector<JointGeometry>    joint_list;
    std::vector<dealii::Point<2>> block_centroids;
    Contact::UpliftSettings       uplift;
    Contact::CoulombJoint<2>      bedding_law;
    Contact::CoulombJoint<2>      vertical_law;
  };

  /**
   * @brief History after an increment converged with @p responses: shear
   * traction and slip become the new reference; cohesion and tensile
   * strength are lost for good where a point slipped or opened (the UDEC
   * convention, as in the FE model's commit).
   */
  JointHistories
  committed_histories(const JointHistories &previous,
                      const JointResponses &responses);
} // namespace FloorBlock::RigidBlocks
