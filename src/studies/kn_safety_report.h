#pragma once

#include <output/result_folder.h>

#include <studies/kn_safety_sweep.h>

#include <string>

namespace FloorBlock::Studies
{
  /**
   * @brief kn_safety.csv: one row per case, kn_Pa_per_m, ks_Pa_per_m, law,
   * safety_factor_point, safety_factor_line, status, governing_corner (the
   * floor's factor, fem.json's governing corner), face_corner_point,
   * face_corner_line, face_corner_status (the face block's corner at the
   * face joint) and mesh_cells. The rigid law's row has no kn and ks; a
   * status "unresolved" or "not converged" comes without factors (empty
   * cells).
   */
  std::string
  kn_safety_csv(const KnSafetySweep &sweep);

  /**
   * @brief gnuplot script of kn_safety.png: both methods' FS against kn
   * (log axis) for the resolved compliant cases, the rigid law's factors
   * as horizontal lines (the kn -> infinity end, labelled exact), FS = 1.
   */
  std::string
  kn_safety_plot(const KnSafetySweep &sweep);

  /** @brief The terminal's line of one case. */
  std::string
  kn_safety_case_text(const KnSafetyCase &record);

  /** @brief kn_safety.csv and kn_safety.png into @p folder. */
  void
  write_kn_safety(const Output::ResultFolder &folder,
                  const KnSafetySweep        &sweep);
} // namespace FloorBlock::Studies
