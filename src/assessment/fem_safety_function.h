#pragma once

#include <assessment/safety_cases.h>
#include <openturns/EvaluationImplementation.hxx>

#include <memory>
#include <string>

namespace FloorBlock::Assessment
{
  /**
   * @brief The FEM's safety factor as an OpenTURNS function of the
   * uncertain inputs, for studies that evaluate the FEM on every draw
   * (brute-force Monte Carlo): a sample is one batch of FEM cases
   * (solve_safety_cases(): spread over the MPI ranks, stored, resumed),
   * named @p prefix_000001, ... in the order the algorithm asks for them,
   * so a rerun with the same seed reuses every finished case.
   *
   * Every rank must evaluate the same samples in the same order (the same
   * seeded algorithm on each). A case that does not solve has no safety
   * factor: the evaluation throws, naming it.
   */
  class FemSafetyFactor : public OT::EvaluationImplementation
  {
  public:
    FemSafetyFactor(const SceneSource &source,
                    const std::string &case_folder,
                    const std::string &prefix,
                    std::ostream      &progress);

    FemSafetyFactor *
    clone() const override;

    OT::Point
    operator()(const OT::Point &input) const override;

    OT::Sample
    operator()(const OT::Sample &inputs) const override;

    OT::UnsignedInteger
    getInputDimension() const override;

    OT::UnsignedInteger
    getOutputDimension() const override;

    /** @brief Every case evaluated so far, in order. */
    const std::vector<SafetyCase> &
    cases() const;

    /** @brief Of them, those an earlier run had stored. */
    unsigned int
    n_from_earlier_runs() const;

  private:
    /** Shared by the clones OpenTURNS makes, so the case count is one. */
    struct State
    {
      SceneSource             source;
      Output::CaseStore       store;
      std::string             prefix;
      std::ostream           *progress;
      std::vector<SafetyCase> cases;
      unsigned int            n_from_earlier_runs = 0;
    };
    std::shared_ptr<State> state;
  };
} // namespace FloorBlock::Assessment
