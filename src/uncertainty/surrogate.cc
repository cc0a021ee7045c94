#include <openturns/CorrectedLeaveOneOut.hxx>
#include <openturns/FixedStrategy.hxx>
#include <openturns/FunctionalChaosAlgorithm.hxx>
#include <openturns/HermiteFactory.hxx>
#include <openturns/LARS.hxx>
#include <openturns/LeastSquaresMetaModelSelectionFactory.hxx>
#include <openturns/LeastSquaresStrategy.hxx>
#include <openturns/LinearEnumerateFunction.hxx>
#include <openturns/OrthogonalProductPolynomialFactory.hxx>
#include <uncertainty/surrogate.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace FloorBlock::Uncertainty
{
  namespace
  {
    struct Fit
    {
      OT::FunctionalChaosResult result;
      double                    leave_one_out_rms;
    };

    Fit
    fit_of_degree(const OT::Sample       &inputs,
                  const OT::Sample       &outputs,
                  const OT::Distribution &distribution,
                  const std::uint64_t     degree)
    {
      const OT::UnsignedInteger dimension = inputs.getDimension();
      const OT::OrthogonalProductPolynomialFactory basis(
        OT::OrthogonalProductPolynomialFactory::PolynomialFamilyCollection(
          dimension, OT::HermiteFactory()),
        OT::LinearEnumerateFunction(dimension));
      const OT::UnsignedInteger n_candidates =
        basis.getEnumerateFunction().getStrataCumulatedCardinal(degree);
      const OT::FixedStrategy        adaptive(basis, n_candidates);
      const OT::LARS                 lars;
      const OT::CorrectedLeaveOneOut leave_one_out;
      const OT::LeastSquaresStrategy projection{
        OT::LeastSquaresMetaModelSelectionFactory(lars, leave_one_out)};
      OT::FunctionalChaosAlgorithm algorithm(
        inputs, outputs, distribution, adaptive, projection);
      algorithm.run();
      const OT::FunctionalChaosResult result = algorithm.getResult();
      // The relative error is the leave-one-out mean square over the
      // outputs' variance.
      const double variance = outputs.computeVariance()[0];
      return {result, std::sqrt(result.getRelativeErrors()[0] * variance)};
    }

    /**
     * Residuals of @p n_folds-fold cross validation of the fit of
     * @p degree: each fold predicted by a fit on the others (terms selected
     * anew), points dealt to the folds in turn.
     */
    OT::Sample
    cross_validation_residuals(const OT::Sample       &inputs,
                               const OT::Sample       &outputs,
                               const OT::Distribution &distribution,
                               const std::uint64_t     degree,
                               const std::uint64_t     n_folds)
    {
      const OT::UnsignedInteger n_points = inputs.getSize();
      OT::Sample                residuals(0, 1);
      for (std::uint64_t fold = 0; fold < n_folds; ++fold)
        {
          OT::Sample train_x(0, inputs.getDimension()), train_y(0, 1);
          OT::Sample test_x(0, inputs.getDimension()), test_y(0, 1);
          for (OT::UnsignedInteger i = 0; i < n_points; ++i)
            {
              OT::Sample &x = i % n_folds == fold ? test_x : train_x;
              OT::Sample &y = i % n_folds == fold ? test_y : train_y;
              x.add(inputs[i]);
              y.add(outputs[i]);
            }
          if (train_x.getSize() < inputs.getDimension() + 2 ||
              test_x.getSize() == 0)
            continue;
          const Fit fit = fit_of_degree(train_x, train_y, distribution, degree);
          residuals.add(fit.result.getMetaModel()(test_x) - test_y);
        }
      return residuals;
    }

    double
    root_mean_square(const OT::Sample &residuals)
    {
      double sum_of_squares = 0.;
      for (OT::UnsignedInteger i = 0; i < residuals.getSize(); ++i)
        sum_of_squares += residuals(i, 0) * residuals(i, 0);
      return residuals.getSize() == 0 ?
               HUGE_VAL :
               std::sqrt(sum_of_squares / residuals.getSize());
    }
  } // namespace

  Surrogate
  fit_chaos_surrogate(const OT::Sample       &inputs,
                      const OT::Sample       &outputs,
                      const OT::Distribution &distribution,
                      const std::uint64_t     max_degree,
                      const std::uint64_t     n_folds)
  {
    if (inputs.getSize() != outputs.getSize() ||
        inputs.getDimension() != distribution.getDimension() ||
        outputs.getDimension() != 1)
      throw std::invalid_argument(
        "uncertainty: a surrogate needs as many outputs (one each) as input "
        "points, of the distribution's dimension");
    if (inputs.getSize() < inputs.getDimension() + 2)
      throw std::invalid_argument(
        "uncertainty: a surrogate needs at least inputs + 2 points");

    // The degree is chosen by the cross-validation error: the
    // leave-one-out error of LARS's own selection favours the largest
    // degree, whose extra terms then miss new points.
    const std::uint64_t folds =
      std::min<std::uint64_t>(n_folds, inputs.getSize());
    Surrogate  surrogate;
    OT::Sample best_residuals(0, 1);
    double     best_error = HUGE_VAL;
    for (std::uint64_t degree = 1; degree <= max_degree; ++degree)
      {
        const OT::Sample residuals = cross_validation_residuals(
          inputs, outputs, distribution, degree, folds);
        const double error = root_mean_square(residuals);
        if (error < best_error)
          {
            best_error       = error;
            best_residuals   = residuals;
            surrogate.degree = degree;
          }
      }
    const Fit fit =
      fit_of_degree(inputs, outputs, distribution, surrogate.degree);
    surrogate.model                = fit.result.getMetaModel();
    surrogate.n_terms              = fit.result.getIndices().getSize();
    surrogate.leave_one_out_rms    = fit.leave_one_out_rms;
    surrogate.n_folds              = folds;
    surrogate.cross_validation_rms = best_error;
    OT::Sample magnitudes(best_residuals.getSize(), 1);
    for (OT::UnsignedInteger i = 0; i < best_residuals.getSize(); ++i)
      magnitudes(i, 0) = std::abs(best_residuals(i, 0));
    if (magnitudes.getSize() > 0)
      surrogate.stated_error = magnitudes.computeQuantile(0.95)[0];
    return surrogate;
  }

  HeldOutErrors
  held_out_errors(const OT::Function &surrogate,
                  const OT::Sample   &inputs,
                  const OT::Sample   &outputs,
                  const double        stated_error)
  {
    HeldOutErrors errors;
    errors.n_points = inputs.getSize();
    if (errors.n_points == 0)
      return errors;
    const OT::Sample predicted      = surrogate(inputs);
    double           sum_of_squares = 0.;
    std::uint64_t    n_within       = 0;
    for (OT::UnsignedInteger i = 0; i < errors.n_points; ++i)
      {
        const double error = predicted(i, 0) - outputs(i, 0);
        sum_of_squares += error * error;
        errors.largest = std::max(errors.largest, std::abs(error));
        n_within += std::abs(error) <= stated_error;
      }
    errors.rms = std::sqrt(sum_of_squares / errors.n_points);
    errors.share_within_stated =
      static_cast<double>(n_within) / errors.n_points;
    return errors;
  }
} // namespace FloorBlock::Uncertainty
