#pragma once

#include <output/case_store.h>
#include <output/fem_report.h>
#include <output/result_folder.h>
#include <scene/chapter_figures.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /**
   * @brief The stored record of one FEM sweep case: its inputs, the FEM's
   * face joint (Q_n, contact length, peak stresses, status) and each closed
   * form's Q_n and sigma_max (Eq. 6.53, geometric y) for the same inputs.
   */
  nlohmann::json
  fem_case_record(const Scene::FigurePoint   &point,
                  const Contact::SolveResult &result,
                  const FemReport            &report);

  /** @brief One CSV row per case of @p figure; units in the column names. */
  std::string
  fem_sweep_csv(const std::vector<nlohmann::json> &records,
                const std::string &                figure);

  /**
   * @brief gnuplot script shaped like the chapter's figure: Q at the face
   * (Figures 6.5-6.7, one panel per vertical friction) or sigma_max at the
   * face (Figures 6.10/6.11, one panel per curvature), against bedding
   * friction; FEM as points, closed forms as lines.
   */
  std::string
  fem_sweep_plot(const std::vector<nlohmann::json> &records,
                 const std::string &                figure);

  /**
   * @brief Reads the finished cases among @p case_ids from @p store and
   * writes, per figure they belong to, sweep_fem_<figure>.csv and .png
   * into @p folder.
   * @return The number of finished cases.
   */
  std::size_t
  write_fem_sweep(const CaseStore                &store,
                  const std::vector<std::string> &case_ids,
                  const ResultFolder             &folder);
} // namespace FloorBlock::Output
