// The elastic law: Lamé constants from (E, nu) and from (K, G) against
// hand-computed values, the plane-strain stress of simple strains, and the
// input checks.
#include <common/input_error.h>
#include <material/elastic_law.h>

#include <deal.II/base/symmetric_tensor.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using FloorBlock::InputError;
  using FloorBlock::Material::ElasticLaw;

  // Every expected value below is a few exact operations away from the
  // inputs: only round-off separates it from the computed one.
  constexpr double relative_tolerance = 1e-12;

  void
  expect_relative(const double actual, const double expected)
  {
    EXPECT_NEAR(actual, expected, relative_tolerance * std::abs(expected))
      << "expected " << expected;
  }

  // E = 10 GPa, nu = 0.25 by hand: mu = E / (2 (1 + nu)) = 10 / 2.5 = 4 GPa,
  // lambda = E nu / ((1 + nu)(1 - 2 nu)) = 2.5 / (1.25 x 0.5) = 4 GPa.
  TEST(ElasticLaw, LameConstantsFromYoungsModulusAndPoissonsRatio)
  {
    const auto law = ElasticLaw<2>::from_youngs_poisson(10e9, 0.25);
    expect_relative(law.lame_lambda(), 4e9);
    expect_relative(law.shear_modulus(), 4e9);
    expect_relative(law.youngs_modulus(), 10e9);
    expect_relative(law.poissons_ratio(), 0.25);
    // E* = E / (1 - nu^2) = 10 / 0.9375 GPa.
    expect_relative(law.plane_strain_modulus(), 10e9 / 0.9375);
  }

  // The chapter's Table 6.1 rock, K = 9 GPa, G = 6.7 GPa, by hand:
  // lambda = K - 2G/3 = 4.5333... GPa, E = 9KG / (3K + G) = 542.7e18 /
  // 33.7e9 Pa, nu = (3K - 2G) / (2 (3K + G)) = 13.6 / 67.4.
  TEST(ElasticLaw, LameConstantsFromBulkAndShearModulus)
  {
    const auto law = ElasticLaw<2>::from_bulk_shear(9e9, 6.7e9);
    expect_relative(law.lame_lambda(), 9e9 - 2. / 3. * 6.7e9);
    expect_relative(law.shear_modulus(), 6.7e9);
    expect_relative(law.youngs_modulus(), 542.7e18 / 33.7e9);
    expect_relative(law.poissons_ratio(), 13.6 / 67.4);
  }

  // Both constructors describe the same rock when (E, nu) come from (K, G).
  TEST(ElasticLaw, BothConstructorsAgreeOnTheSameRock)
  {
    const auto from_k_g = ElasticLaw<3>::from_bulk_shear(9e9, 6.7e9);
    const auto from_e_nu =
      ElasticLaw<3>::from_youngs_poisson(from_k_g.youngs_modulus(),
                                         from_k_g.poissons_ratio());
    expect_relative(from_e_nu.lame_lambda(), from_k_g.lame_lambda());
    expect_relative(from_e_nu.shear_modulus(), from_k_g.shear_modulus());
  }

  // Plane strain, lambda = mu = 4 GPa. Uniaxial strain eps_xx = 1e-3:
  // sigma_xx = (lambda + 2 mu) eps = 12 MPa, sigma_yy = sigma_zz = lambda eps
  // = 4 MPa. Pure shear eps_xy = 1e-3: sigma_xy = 2 mu eps = 8 MPa, no
  // normal stress.
  TEST(ElasticLaw, PlaneStrainStressOfUniaxialAndShearStrain)
  {
    const auto law = ElasticLaw<2>::from_youngs_poisson(10e9, 0.25);

    dealii::SymmetricTensor<2, 2> uniaxial;
    uniaxial[0][0]                            = 1e-3;
    const dealii::SymmetricTensor<2, 2> axial = law.stress(uniaxial);
    expect_relative(axial[0][0], 12e6);
    expect_relative(axial[1][1], 4e6);
    EXPECT_EQ(axial[0][1], 0.);
    expect_relative(law.out_of_plane_stress(uniaxial), 4e6);

    dealii::SymmetricTensor<2, 2> shear;
    shear[0][1]                             = 1e-3;
    const dealii::SymmetricTensor<2, 2> tau = law.stress(shear);
    expect_relative(tau[0][1], 8e6);
    EXPECT_EQ(tau[0][0], 0.);
    EXPECT_EQ(tau[1][1], 0.);
    EXPECT_EQ(law.out_of_plane_stress(shear), 0.);
  }

  // The stiffness tensor is the stress map: C : eps = stress(eps) for a
  // general strain, and C_xxxx = lambda + 2 mu, C_xxyy = lambda, C_xyxy = mu.
  TEST(ElasticLaw, StiffnessTensorIsTheStressMap)
  {
    const auto  law = ElasticLaw<2>::from_youngs_poisson(10e9, 0.25);
    const auto &c   = law.stiffness_tensor();
    expect_relative(c[0][0][0][0], 12e9);
    expect_relative(c[0][0][1][1], 4e9);
    expect_relative(c[0][1][0][1], 4e9);

    dealii::SymmetricTensor<2, 2> strain;
    strain[0][0]                                    = 3e-4;
    strain[1][1]                                    = -1e-4;
    strain[0][1]                                    = 2e-4;
    const dealii::SymmetricTensor<2, 2> direct      = law.stress(strain);
    const dealii::SymmetricTensor<2, 2> contraction = c * strain;
    // Relative to the stress's size: a component can cancel to round-off.
    EXPECT_LE((contraction - direct).norm(),
              relative_tolerance * direct.norm());
    expect_relative(contraction[0][0], 12e9 * 3e-4 - 4e9 * 1e-4);
    expect_relative(contraction[0][1], 8e9 * 2e-4);
  }

  // 3D has no out-of-plane stress to report.
  TEST(ElasticLaw, NoOutOfPlaneStressIn3D)
  {
    const auto law = ElasticLaw<3>::from_youngs_poisson(10e9, 0.25);
    dealii::SymmetricTensor<2, 3> strain;
    strain[0][0] = 1e-3;
    EXPECT_EQ(law.out_of_plane_stress(strain), 0.);
    expect_relative(law.stress(strain)[2][2], 4e6);
  }

  TEST(ElasticLaw, RejectsInputsOutsideTheirRanges)
  {
    EXPECT_THROW(ElasticLaw<2>::from_youngs_poisson(0., 0.25), InputError);
    EXPECT_THROW(ElasticLaw<2>::from_youngs_poisson(-1e9, 0.25), InputError);
    EXPECT_THROW(ElasticLaw<2>::from_youngs_poisson(10e9, 0.5), InputError);
    EXPECT_THROW(ElasticLaw<2>::from_youngs_poisson(10e9, -1.), InputError);
    EXPECT_THROW(ElasticLaw<2>::from_bulk_shear(0., 6.7e9), InputError);
    EXPECT_THROW(ElasticLaw<2>::from_bulk_shear(9e9, -6.7e9), InputError);
    EXPECT_NO_THROW(ElasticLaw<2>::from_youngs_poisson(10e9, 0.49));
    EXPECT_NO_THROW(ElasticLaw<2>::from_youngs_poisson(10e9, -0.5));
  }
} // namespace
