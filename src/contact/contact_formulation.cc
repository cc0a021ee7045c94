#include <contact/compliant_formulation.h>
#include <contact/contact_formulation.h>
#include <contact/exact_formulation.h>

namespace FloorBlock::Contact
{
  template <int dim>
  bool
  try_plain_starts(const Loading::LoadState           &state,
                   const Loading::FailedStartRecorder &record_failed_start,
                   const LoadStateStarts<dim>         &starts,
                   IncrementResult                    &increment,
                   std::string                        &failure_reason)
  {
    increment = IncrementResult();
    if (starts.prediction > 0.)
      {
        if (starts.solve(
              state.factors, starts.prediction, increment, failure_reason))
          return true;
        // The extrapolated start can lie where a very stiff joint law
        // makes the active set cycle (kn = 1e14 Pa/m, two-block test);
        // the plain start is tried before any cutback, so a start the
        // predictor spoils costs a retry, not a cutback.
        record_failed_start("extrapolated start", failure_reason);
        increment = IncrementResult();
      }
    return starts.solve(state.factors, 0., increment, failure_reason);
  }

  template <int dim>
  std::unique_ptr<ContactFormulation<dim>>
  make_contact_formulation(
    const ContactSystem<dim>                        &system,
    PairLaws<dim>                                   &laws,
    const dealii::TrilinosWrappers::SparsityPattern &pattern,
    dealii::TrilinosWrappers::SparseMatrix          &matrix,
    dealii::ConditionalOStream                      &console)
  {
    if (laws.any_exact())
      return std::make_unique<ExactFormulation<dim>>(system,
                                                     std::move(laws.owned),
                                                     laws.laws,
                                                     laws.penalty_laws,
                                                     laws.exact_laws,
                                                     pattern,
                                                     matrix,
                                                     console);
    return std::make_unique<CompliantFormulation<dim>>(system,
                                                       std::move(laws.owned),
                                                       laws.laws);
  }

  template std::unique_ptr<ContactFormulation<2>>
  make_contact_formulation(const ContactSystem<2> &,
                           PairLaws<2> &,
                           const dealii::TrilinosWrappers::SparsityPattern &,
                           dealii::TrilinosWrappers::SparseMatrix &,
                           dealii::ConditionalOStream &);
  template std::unique_ptr<ContactFormulation<3>>
  make_contact_formulation(const ContactSystem<3> &,
                           PairLaws<3> &,
                           const dealii::TrilinosWrappers::SparsityPattern &,
                           dealii::TrilinosWrappers::SparseMatrix &,
                           dealii::ConditionalOStream &);
  template bool
  try_plain_starts(const Loading::LoadState &,
                   const Loading::FailedStartRecorder &,
                   const LoadStateStarts<2> &,
                   IncrementResult &,
                   std::string &);
  template bool
  try_plain_starts(const Loading::LoadState &,
                   const Loading::FailedStartRecorder &,
                   const LoadStateStarts<3> &,
                   IncrementResult &,
                   std::string &);
} // namespace FloorBlock::Contact
