#include <common/input_error.h>
#include <material/elastic_law.h>

#include <cmath>
#include <string>

namespace FloorBlock::Material
{
  namespace
  {
    template <int dim>
    dealii::SymmetricTensor<4, dim>
    isotropic_stiffness(const double lame_lambda, const double shear_modulus)
    {
      dealii::SymmetricTensor<4, dim> result;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = 0; l < dim; ++l)
              result[i][j][k][l] =
                lame_lambda * (i == j) * (k == l) +
                shear_modulus * ((i == k) * (j == l) + (i == l) * (j == k));
      return result;
    }

    void
    require_positive(const char *name, const double value)
    {
      if (!(value > 0.) || !std::isfinite(value))
        throw InputError(name, std::to_string(value), "a finite value > 0 Pa");
    }
  } // namespace

  template <int dim>
  ElasticLaw<dim>::ElasticLaw(const double lame_lambda,
                              const double shear_modulus)
    : lambda(lame_lambda)
    , mu(shear_modulus)
    , stiffness(isotropic_stiffness<dim>(lame_lambda, shear_modulus))
  {}

  template <int dim>
  ElasticLaw<dim>
  ElasticLaw<dim>::from_youngs_poisson(const double youngs_modulus,
                                       const double poissons_ratio)
  {
    require_positive("Young's modulus", youngs_modulus);
    if (!(poissons_ratio > -1. && poissons_ratio < 0.5))
      throw InputError("Poisson's ratio",
                       std::to_string(poissons_ratio),
                       "-1 < nu < 0.5");
    const double shear = youngs_modulus / (2. * (1. + poissons_ratio));
    const double lame  = youngs_modulus * poissons_ratio /
                        ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
    return ElasticLaw(lame, shear);
  }

  template <int dim>
  ElasticLaw<dim>
  ElasticLaw<dim>::from_bulk_shear(const double bulk_modulus,
                                   const double shear_modulus)
  {
    require_positive("Bulk modulus", bulk_modulus);
    require_positive("Shear modulus", shear_modulus);
    // nu = (3K - 2G) / (2 (3K + G)) lies in (-1, 0.5) for any positive K
    // and G, so no further range check is needed.
    return ElasticLaw(bulk_modulus - 2. / 3. * shear_modulus, shear_modulus);
  }

  template <int dim>
  double
  ElasticLaw<dim>::lame_lambda() const
  {
    return lambda;
  }

  template <int dim>
  double
  ElasticLaw<dim>::shear_modulus() const
  {
    return mu;
  }

  template <int dim>
  double
  ElasticLaw<dim>::youngs_modulus() const
  {
    return mu * (3. * lambda + 2. * mu) / (lambda + mu);
  }

  template <int dim>
  double
  ElasticLaw<dim>::poissons_ratio() const
  {
    return lambda / (2. * (lambda + mu));
  }

  template <int dim>
  double
  ElasticLaw<dim>::plane_strain_modulus() const
  {
    const double nu = poissons_ratio();
    return youngs_modulus() / (1. - nu * nu);
  }

  template <int dim>
  dealii::SymmetricTensor<2, dim>
  ElasticLaw<dim>::stress(const dealii::SymmetricTensor<2, dim> &strain) const
  {
    return lambda * dealii::trace(strain) *
             dealii::unit_symmetric_tensor<dim>() +
           2. * mu * strain;
  }

  template <int dim>
  const dealii::SymmetricTensor<4, dim> &
  ElasticLaw<dim>::stiffness_tensor() const
  {
    return stiffness;
  }

  template <int dim>
  double
  ElasticLaw<dim>::out_of_plane_stress(
    const dealii::SymmetricTensor<2, dim> &strain) const
  {
    return dim == 2 ? lambda * dealii::trace(strain) : 0.;
  }

  template class ElasticLaw<2>;
  template class ElasticLaw<3>;
} // namespace FloorBlock::Material
