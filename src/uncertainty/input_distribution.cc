#include <common/input_error.h>

#include <openturns/Beta.hxx>
#include <openturns/ComposedDistribution.hxx>
#include <openturns/CorrelationMatrix.hxx>
#include <openturns/LogNormalFactory.hxx>
#include <openturns/LogNormalMuSigma.hxx>
#include <openturns/Normal.hxx>
#include <openturns/NormalCopula.hxx>
#include <openturns/Triangular.hxx>
#include <openturns/TruncatedDistribution.hxx>
#include <openturns/TruncatedNormal.hxx>
#include <openturns/Uniform.hxx>
#include <uncertainty/input_distribution.h>

#include <algorithm>

namespace FloorBlock::Uncertainty
{
  using Parameters::DistributionFamily;

  OT::Distribution
  marginal_distribution(const Parameters::UncertainInput &input)
  {
    const std::vector<double> &a = input.arguments;
    OT::Distribution           marginal;
    switch (input.family)
      {
        case DistributionFamily::normal:
          marginal =
            input.truncated() ?
              OT::Distribution(OT::TruncatedNormal(a[0], a[1], a[2], a[3])) :
              OT::Distribution(OT::Normal(a[0], a[1]));
          break;
          case DistributionFamily::lognormal: {
            // The user gives the value's mean and standard deviation.
            const OT::Distribution lognormal =
              OT::LogNormalMuSigma(a[0], a[1]).getDistribution();
            marginal = input.truncated() ?
                         OT::Distribution(OT::TruncatedDistribution(
                           lognormal, std::max(a[2], 0.), a[3])) :
                         lognormal;
            break;
          }
        case DistributionFamily::uniform:
          marginal = OT::Uniform(a[0], a[1]);
          break;
        case DistributionFamily::triangular:
          marginal = OT::Triangular(a[0], a[1], a[2]);
          break;
        case DistributionFamily::beta:
          marginal = OT::Beta(a[0], a[1], a[2], a[3]);
          break;
      }
    marginal.setDescription(OT::Description(1, input.path));
    return marginal;
  }

  OT::Distribution
  input_distribution(
    const std::vector<Parameters::UncertainInput>   &inputs,
    const std::vector<Parameters::InputCorrelation> &correlations)
  {
    OT::ComposedDistribution::DistributionCollection marginals;
    for (const auto &input : inputs)
      marginals.add(marginal_distribution(input));
    if (correlations.empty())
      return OT::ComposedDistribution(marginals);

    const auto index_of = [&](const std::string &path) {
      return static_cast<OT::UnsignedInteger>(
        std::find_if(inputs.begin(),
                     inputs.end(),
                     [&](const auto &input) { return input.path == path; }) -
        inputs.begin());
    };
    OT::CorrelationMatrix matrix(inputs.size());
    std::string           listed;
    for (const auto &correlation : correlations)
      {
        matrix(index_of(correlation.first), index_of(correlation.second)) =
          correlation.value;
        listed += (listed.empty() ? "" : "; ") + correlation.text;
      }
    if (!matrix.isPositiveDefinite())
      throw InputError("Uncertainty/Correlations",
                       listed,
                       "a positive definite correlation matrix: these "
                       "correlations cannot hold together (weaken the "
                       "strongest, or make their signs consistent)");
    return OT::ComposedDistribution(marginals, OT::NormalCopula(matrix));
  }
} // namespace FloorBlock::Uncertainty
