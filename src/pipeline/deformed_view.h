#pragma once

#include <contact/contact_solver.h>

#include <string>

namespace FloorBlock::Pipeline
{
  /**
   * @brief deformed.png: the blocks displaced by a magnified copy of the
   * solver's last converged displacement, coloured by the major principal
   * compressive stress, every joint node marked by its state (stick, slip,
   * open), the face on the right.
   * @param[in] model The elastic laws the solver was given. The picture the
   * chapter's Figure 6.4 shows from UDEC. Writes nothing when no increment has
   * converged.
   */
  void
  write_deformed_view(const Contact::ContactSolver<2> &solver,
                      const Fem::ElasticModel<2>      &model,
                      const std::string               &png_path);
} // namespace FloorBlock::Pipeline
