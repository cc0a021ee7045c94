#pragma once

#include <contact/results.h>
#include <output/fem_report.h>
#include <parameters/scenario_parameters.h>

#include <string>

namespace FloorBlock::Pipeline
{
  /**
   * @brief The FEM report of a solve's converged increments: the totals of
   * Newton iterations and cutbacks, and the force balance of each
   * increment and the worst over them.
   *
   * An increment that carries no load (Compare::check_load with the
   * blocks' E) divides round-off by round-off: its relative error is
   * reported as 0 and it is left out of the worst relative error; the
   * absolute error |applied load + support reactions| (N/m) covers every
   * increment. The model particulars (failure record, overlap check, mesh,
   * rigid-model note) are the caller's to add.
   *
   * @param[in] converged Status "converged", else "not converged".
   * @param[in] status_text Why, in words.
   * @param[in] cutbacks_before_failure Cutbacks of an increment that failed
   *   for good (not among the result's increments); 0 for a converged run.
   */
  Output::FemReport
  make_fem_report(const Contact::SolveResult           &result,
                  const Parameters::ScenarioParameters &scene,
                  const std::string                    &model,
                  const bool                            converged,
                  const std::string                    &status_text,
                  const unsigned int cutbacks_before_failure = 0);
} // namespace FloorBlock::Pipeline
