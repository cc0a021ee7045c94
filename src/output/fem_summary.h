#pragma once

#include <contact/results.h>
#include <geometry/assembly_mesher.h>
#include <output/fem_report.h>

#include <string>

namespace FloorBlock::Output
{
  /**
   * @brief Terminal summary of a solve: one line per joint, the state, and
   * times.
   * @param[in] report The typed FEM report (its mesh is set for a meshed
   * elastic solve only).
   * @param[in] result The converged increments and wall times.
   * @param[in] mesh Cells and meshing time, printed when report.mesh is set.
   */
  std::string
  fem_summary_text(const FemReport                &report,
                   const Contact::SolveResult     &result,
                   const Geometry::MeshStatistics &mesh);
} // namespace FloorBlock::Output
