#pragma once

#include <contact/results.h>

#include <string>

namespace FloorBlock::Output
{
  /**
   * @brief A 3D joint's contact area as a table: one row per node pair of
   * every cross-section (JointReport::along_face), with the patch of joint
   * surface the pair stands for (z from the section's share of the face,
   * arc position from the midpoints to its neighbours along the joint), its
   * normal traction and state. Empty for a joint without sections (2D).
   */
  std::string
  contact_area_csv(const Contact::JointReport &joint);

  /**
   * @brief The same as a picture (gnuplot PNG): every closed pair's patch
   * filled with its normal traction (MPa), open ones left blank, the
   * joint's surface unrolled as distance along the face (z) against
   * distance along the joint; the vertical range is the closed zone with a
   * margin. Nothing is drawn for a joint without sections.
   * @throws std::runtime_error if gnuplot fails (render_png()).
   */
  void
  write_contact_area_picture(const Contact::JointReport &joint,
                             const std::string          &png_path);
} // namespace FloorBlock::Output
