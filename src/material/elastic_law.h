#pragma once

#include <deal.II/base/symmetric_tensor.h>

namespace FloorBlock::Material
{
  /**
   * @brief Isotropic linear elastic law, a small value class in the spirit
   * of step-42's ConstitutiveLaw: it knows the Lamé constants and nothing
   * about meshes.
   *
   * In 2D the strain and stress tensors are the in-plane parts of a plane
   * strain state (\f$\varepsilon_{zz}=0\f$), so the 2D Lamé form
   * \f$\sigma = \lambda\,\mathrm{tr}(\varepsilon) I + 2\mu\varepsilon\f$ is
   * exact; the out-of-plane stress is available from
   * out_of_plane_stress().
   */
  template <int dim>
  class ElasticLaw
  {
  public:
    /**
     * @brief Law from Young's modulus and Poisson's ratio.
     * @param[in] youngs_modulus E > 0 (Pa).
     * @param[in] poissons_ratio -1 < nu < 0.5 (-).
     * Throws FloorBlock::InputError outside these ranges.
     */
    static ElasticLaw
    from_youngs_poisson(const double youngs_modulus,
                        const double poissons_ratio);

    /**
     * @brief Law from bulk and shear modulus (the UDEC input of the
     * chapter's Table 6.1). Plane strain uses the 3D bulk modulus:
     * \f$\lambda = K - \tfrac{2}{3}G\f$.
     * @param[in] bulk_modulus K > 0 (Pa).
     * @param[in] shear_modulus G > 0 (Pa).
     */
    static ElasticLaw
    from_bulk_shear(const double bulk_modulus, const double shear_modulus);

    /**
     * @brief The same material in dimension dim as @p law in another (the
     * 2D plane-strain law of a scene swept into 3D): equal Lamé constants,
     * copied, not recomputed.
     */
    template <int other_dim>
    static ElasticLaw
    same_material_as(const ElasticLaw<other_dim> &law)
    {
      return ElasticLaw(law.lame_lambda(), law.shear_modulus());
    }

    /** @brief First Lamé constant (Pa). */
    double
    lame_lambda() const;
    /** @brief Shear modulus (Pa). */
    double
    shear_modulus() const;
    /** @brief Young's modulus (Pa). */
    double
    youngs_modulus() const;
    /** @brief Poisson's ratio (-). */
    double
    poissons_ratio() const;
    /** @brief Plane-strain modulus \f$E^* = E/(1-\nu^2)\f$ (Pa). */
    double
    plane_strain_modulus() const;

    /** @brief Cauchy stress (Pa) for the small strain @p strain (-). */
    dealii::SymmetricTensor<2, dim>
    stress(const dealii::SymmetricTensor<2, dim> &strain) const;

    /** @brief The constant elasticity tensor \f$C\f$ (Pa). */
    const dealii::SymmetricTensor<4, dim> &
    stiffness_tensor() const;

    /**
     * @brief Out-of-plane stress \f$\sigma_{zz} = \lambda\,
     * \mathrm{tr}(\varepsilon)\f$ of a plane-strain state (Pa); zero in
     * 3D where it is not needed.
     */
    double
    out_of_plane_stress(const dealii::SymmetricTensor<2, dim> &strain) const;

  private:
    ElasticLaw(const double lame_lambda, const double shear_modulus);

    const double                          lambda;
    const double                          mu;
    const dealii::SymmetricTensor<4, dim> stiffness;
  };
} // namespace FloorBlock::Material
