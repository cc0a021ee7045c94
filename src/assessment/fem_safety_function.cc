#include <common/wall_clock.h>

#include <assessment/fem_safety_function.h>
#include <fmt/format.h>

#include <stdexcept>

namespace FloorBlock::Assessment
{
  FemSafetyFactor::FemSafetyFactor(const SceneSource &source,
                                   const std::string &case_folder,
                                   const std::string &prefix,
                                   std::ostream      &progress)
    : state(std::make_shared<State>(
        State{source, Output::CaseStore(case_folder), prefix, &progress, {}}))
  {}

  FemSafetyFactor *
  FemSafetyFactor::clone() const
  {
    return new FemSafetyFactor(*this);
  }

  OT::Point
  FemSafetyFactor::operator()(const OT::Point &input) const
  {
    return operator()(OT::Sample(1, input))[0];
  }

  OT::Sample
  FemSafetyFactor::operator()(const OT::Sample &inputs) const
  {
    if (inputs.getDimension() != getInputDimension())
      throw std::invalid_argument(fmt::format(
        "FEM safety factor: {} inputs given, the scene has {} uncertain",
        inputs.getDimension(),
        getInputDimension()));
    CaseDraws draws;
    for (OT::UnsignedInteger i = 0; i < inputs.getSize(); ++i)
      {
        draws.ids.push_back(
          fmt::format("{}_{:06d}", state->prefix, state->cases.size() + i + 1));
        draws.points.emplace_back(inputs[i].begin(), inputs[i].end());
      }
    const CaseBatch batch = solve_safety_cases(
      state->source, draws, state->store, MPI_COMM_WORLD, *state->progress);
    if (!batch.complete)
      throw DeadlineReached();
    state->n_from_earlier_runs += batch.n_from_earlier_runs;

    OT::Sample values(inputs.getSize(), 1);
    for (OT::UnsignedInteger i = 0; i < inputs.getSize(); ++i)
      {
        const SafetyCase &c = batch.cases[i];
        if (!c.solved())
          throw std::runtime_error("FEM case " + c.id + " (" + c.status +
                                   "): " + c.message +
                                   "; it has no safety factor");
        values(i, 0) = c.safety_factor;
        state->cases.push_back(c);
      }
    callsNumber_.fetchAndAdd(inputs.getSize());
    return values;
  }

  OT::UnsignedInteger
  FemSafetyFactor::getInputDimension() const
  {
    return state->source.inputs.size();
  }

  OT::UnsignedInteger
  FemSafetyFactor::getOutputDimension() const
  {
    return 1;
  }

  const std::vector<SafetyCase> &
  FemSafetyFactor::cases() const
  {
    return state->cases;
  }

  unsigned int
  FemSafetyFactor::n_from_earlier_runs() const
  {
    return state->n_from_earlier_runs;
  }
} // namespace FloorBlock::Assessment
