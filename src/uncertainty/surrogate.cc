#include <openturns/ComposedFunction.hxx>
#include <openturns/CorrectedLeaveOneOut.hxx>
#include <openturns/FixedStrategy.hxx>
#include <openturns/FunctionalChaosAlgorithm.hxx>
#include <openturns/HermiteFactory.hxx>
#include <openturns/Interval.hxx>
#include <openturns/KrigingAlgorithm.hxx>
#include <openturns/LARS.hxx>
#include <openturns/LeastSquaresMetaModelSelectionFactory.hxx>
#include <openturns/LeastSquaresStrategy.hxx>
#include <openturns/LinearBasisFactory.hxx>
#include <openturns/LinearEnumerateFunction.hxx>
#include <openturns/Log.hxx>
#include <openturns/MaternModel.hxx>
#include <openturns/OrthogonalProductPolynomialFactory.hxx>
#include <uncertainty/surrogate.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

namespace FloorBlock::Uncertainty
{
  namespace
  {
    /** Fits one kind of surrogate to (inputs, outputs). */
    using Fitter =
      std::function<OT::Function(const OT::Sample &, const OT::Sample &)>;

    struct Candidate
    {
      std::string   kind;
      std::uint64_t chaos_degree;
      Fitter        fit;
    };

    /** Hides OpenTURNS' warnings while it lives. */
    class QuietWarnings
    {
    public:
      QuietWarnings()
        : shown(OT::Log::Flags())
      {
        OT::Log::Show(shown & ~OT::Log::WARN);
      }
      ~QuietWarnings()
      {
        OT::Log::Show(shown);
      }
      QuietWarnings(const QuietWarnings &) = delete;
      QuietWarnings &
      operator=(const QuietWarnings &) = delete;

    private:
      const OT::Log::Severity shown;
    };

    OT::Function
    chaos_of_degree(const OT::Sample       &inputs,
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
      return algorithm.getResult().getMetaModel();
    }

    OT::Function
    kriging(const OT::Sample       &inputs,
            const OT::Sample       &outputs,
            const OT::Distribution &distribution)
    {
      // In the normal scores the inputs are independent standard normals,
      // so one range of length scales suits every input: from a tenth of a
      // standard deviation (an output that changes within a few cases'
      // spacing is noise to a surrogate) to a hundred (an input it does
      // not depend on).
      const OT::Function to_scores =
        distribution.getIsoProbabilisticTransformation();
      const std::uint64_t   dimension = inputs.getDimension();
      const OT::MaternModel covariance(OT::Point(dimension, 1.), 2.5);
      // The constructor warns on every call that it sets default bounds
      // of the scales (replaced below), and the likelihood's optimiser
      // warns where it stops short of an optimum: the cross validation
      // judges the fit whatever the optimiser reached.
      const QuietWarnings  quiet;
      OT::KrigingAlgorithm algorithm(to_scores(inputs),
                                     outputs,
                                     covariance,
                                     OT::LinearBasisFactory(dimension).build());
      algorithm.setOptimizationBounds(
        OT::Interval(OT::Point(dimension, 0.1), OT::Point(dimension, 100.)));
      algorithm.run();
      return OT::ComposedFunction(algorithm.getResult().getMetaModel(),
                                  to_scores);
    }

    /**
     * Residuals of @p n_folds-fold cross validation of @p fit, in the
     * points' order: each fold predicted by a fit on the others, points
     * dealt to the folds in turn.
     */
    std::vector<double>
    cross_validation_residuals(const OT::Sample   &inputs,
                               const OT::Sample   &outputs,
                               const Fitter       &fit,
                               const std::uint64_t n_folds)
    {
      const OT::UnsignedInteger n_points = inputs.getSize();
      std::vector<double>       residuals(n_points, 0.);
      for (std::uint64_t fold = 0; fold < n_folds; ++fold)
        {
          OT::Sample train_x(0, inputs.getDimension()), train_y(0, 1);
          OT::Sample test_x(0, inputs.getDimension());
          std::vector<OT::UnsignedInteger> tested;
          for (OT::UnsignedInteger i = 0; i < n_points; ++i)
            if (i % n_folds == fold)
              {
                test_x.add(inputs[i]);
                tested.push_back(i);
              }
            else
              {
                train_x.add(inputs[i]);
                train_y.add(outputs[i]);
              }
          const OT::Sample predicted = fit(train_x, train_y)(test_x);
          for (std::size_t k = 0; k < tested.size(); ++k)
            residuals[tested[k]] = predicted(k, 0) - outputs(tested[k], 0);
        }
      return residuals;
    }

    double
    root_mean_square(const std::vector<double> &residuals)
    {
      double sum_of_squares = 0.;
      for (const double r : residuals)
        sum_of_squares += r * r;
      return std::sqrt(sum_of_squares / residuals.size());
    }

    /** The split-conformal 95 % bound of Surrogate::stated_error. */
    double
    conformal_bound(const std::vector<double> &residuals)
    {
      std::vector<double> magnitudes;
      for (const double r : residuals)
        magnitudes.push_back(std::abs(r));
      std::sort(magnitudes.begin(), magnitudes.end());
      const std::size_t n = magnitudes.size();
      const auto        rank =
        static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(n + 1)));
      return magnitudes[std::min(rank, n) - 1];
    }
  } // namespace

  Surrogate
  fit_surrogate(const OT::Sample       &inputs,
                const OT::Sample       &outputs,
                const OT::Distribution &distribution,
                const std::uint64_t     max_chaos_degree,
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

    std::vector<Candidate> candidates;
    for (std::uint64_t degree = 1; degree <= max_chaos_degree; ++degree)
      candidates.push_back(
        {"sparse polynomial chaos of degree " + std::to_string(degree) +
           " (Hermite in the inputs' normal scores, LARS)",
         degree,
         [&distribution, degree](const OT::Sample &x, const OT::Sample &y) {
           return chaos_of_degree(x, y, distribution, degree);
         }});
    candidates.push_back(
      {"kriging in the inputs' normal scores (linear trend, Matern 5/2 "
       "covariance, maximum likelihood)",
       0,
       [&distribution](const OT::Sample &x, const OT::Sample &y) {
         return kriging(x, y, distribution);
       }});

    // Chosen by the cross-validation error: the leave-one-out error of
    // LARS's own selection favours the largest degree, whose extra terms
    // then miss new points, and kriging's likelihood says nothing of new
    // points at all.
    const std::uint64_t folds =
      std::min<std::uint64_t>(n_folds, inputs.getSize());
    Surrogate           surrogate;
    const Candidate    *best = nullptr;
    std::vector<double> best_residuals;
    double              best_error = HUGE_VAL;
    std::string         failures;
    for (const Candidate &candidate : candidates)
      {
        // A candidate the points cannot carry (a kriging whose covariance
        // matrix is singular, a chaos with more terms than points) drops
        // out; the others compete.
        std::vector<double> residuals;
        try
          {
            residuals =
              cross_validation_residuals(inputs, outputs, candidate.fit, folds);
          }
        catch (const std::exception &error)
          {
            failures += "\n  " + candidate.kind + ": " + error.what();
            continue;
          }
        const double error = root_mean_square(residuals);
        if (error < best_error)
          {
            best_error     = error;
            best_residuals = residuals;
            best           = &candidate;
          }
      }
    if (best == nullptr)
      throw std::runtime_error(
        "uncertainty: no surrogate could be fitted to the points:" + failures);
    surrogate.model                = best->fit(inputs, outputs);
    surrogate.kind                 = best->kind;
    surrogate.chaos_degree         = best->chaos_degree;
    surrogate.n_folds              = folds;
    surrogate.cross_validation_rms = best_error;
    surrogate.stated_error         = conformal_bound(best_residuals);
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
