#pragma once

#include <contact/results.h>

#include <string>
#include <vector>

namespace FloorBlock::Compare
{
  /**
   * @brief Which joint governs one figure of the FEM solution: the joint
   * with the largest value over the scene, beside the face joint's value.
   * The chapter judges the face joint, but on a steep or heavily loaded
   * floor another vertical joint or a bedding joint can carry more.
   */
  struct GoverningJoint
  {
    /** The figure's key with its unit ("sigma_max_Pa", ...). */
    std::string figure;
    /** In words, for the report ("pointwise peak normal stress", ...). */
    std::string description;
    /** The joint with the largest value ("vertical 7", "bedding 6"). */
    std::string joint;
    double      value = 0.;
    /**
     * Where the value sits (m, the scene's frame): the peak's node for a
     * stress, the joint's peak position for a force (its corner).
     */
    double x = 0.;
    double y = 0.;
    /** The face joint ("vertical n") and its value of the same figure. */
    std::string face_joint;
    double      face_value = 0.;

    /** The governing joint is the face joint (it is on ties, to 1e-9). */
    bool
    is_face_joint() const;
  };

  /**
   * @brief The governing joint of each figure at one increment: the largest
   * Q among the vertical joints, and the largest pointwise peak, averaged
   * peak and mean contact stress among all joints (vertical and bedding).
   * Empty when the increment has no joints.
   */
  std::vector<GoverningJoint>
  governing_joints(const Contact::IncrementResult &increment,
                   unsigned int                    n_blocks);
} // namespace FloorBlock::Compare
