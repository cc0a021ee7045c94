#pragma once

#include <output/result_folder.h>
#include <scene/chapter_figures.h>

#include <vector>

namespace FloorBlock::Pipeline
{
  /**
   * @brief Runs the contact FEM for every figure point without a finished
   * case file (results/<scene>/cases/<id>.json), then, on rank 0, writes
   * one CSV and one PNG per figure with FEM points beside the closed-form
   * curves.
   *
   * Each case solves in a scratch folder outside the results and stores
   * only its JSON record, atomically: an interrupted case leaves nothing.
   * Cases are split over the MPI ranks (`mpirun -np N floorblock sweep
   * --fem`); a rerun skips finished cases.
   *
   * @param[in] limit Run at most this many cases of the list (0: all).
   * @return The number of cases that still lack a result (0 when complete).
   */
  unsigned int
  run_fem_sweep(const std::vector<Scene::FigurePoint> &points,
                const Output::ResultFolder            &folder,
                const unsigned int                     limit);
} // namespace FloorBlock::Pipeline
