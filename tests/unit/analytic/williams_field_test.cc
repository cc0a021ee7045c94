// The Williams field rows against Hooke's law (plane strain): the strains of
// the displacement rows equal the strains the stress rows give, for complex
// exponents and arbitrary coefficients; and the dense complex elimination.
#include <analytic/complex_matrix.h>
#include <analytic/williams_field.h>

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

using namespace FloorBlock::Analytic;
using Complex = std::complex<double>;

namespace
{
  Complex
  combine(const WilliamsRow &row, const std::vector<Complex> &c)
  {
    return row[0] * c[0] + row[1] * c[1] + row[2] * c[2] + row[3] * c[3];
  }
} // namespace

// sigma_rr = (F'' + (lambda + 1) F), sigma_tt = lambda (lambda + 1) F,
// sigma_rt = -lambda F' (times r^(lambda-1)); with u = r^lambda U(theta):
// eps_rr = lambda U_r, eps_tt = U_r + U_t', gamma_rt = U_r' + (lambda - 1) U_t;
// plane strain: 2G eps_rr = (1 - nu) s_rr - nu s_tt, 2G eps_tt = (1 - nu)
// s_tt - nu s_rr, G gamma_rt = s_rt. Derivatives in theta by central
// differences (h = 1e-6), hence the 1e-7 relative tolerance.
TEST(WilliamsRows, SatisfyHookesLawInPlaneStrain)
{
  const WedgeMaterial        material{3.5e9, 0.27};
  const double               g  = material.shear_modulus;
  const double               nu = material.poissons_ratio;
  const std::vector<Complex> c  = {{0.3, -0.1},
                                   {-0.7, 0.2},
                                   {1.1, 0.4},
                                   {0.5, -0.9}};
  const double               h  = 1e-6;
  for (const Complex lambda :
       {Complex(0.5445, 0.), Complex(0.6, 0.15), Complex(1.7, -0.3)})
    for (const double theta : {-2.1, -0.4, 0.3, 1.2, 2.9})
      {
        const auto at = [&](const double t) {
          return williams_rows(lambda, t, material);
        };
        const WilliamsRows rows = at(theta);
        const Complex      f    = combine(rows.normal_stress, c);
        const Complex      f1   = combine(rows.shear_stress, c);
        const Complex      f2   = (combine(at(theta + h).shear_stress, c) -
                            combine(at(theta - h).shear_stress, c)) /
                           (2. * h);
        const Complex u_r  = combine(rows.radial_displacement, c);
        const Complex u_t  = combine(rows.angular_displacement, c);
        const Complex du_r = (combine(at(theta + h).radial_displacement, c) -
                              combine(at(theta - h).radial_displacement, c)) /
                             (2. * h);
        const Complex du_t = (combine(at(theta + h).angular_displacement, c) -
                              combine(at(theta - h).angular_displacement, c)) /
                             (2. * h);
        const Complex s_rr  = f2 + (lambda + 1.) * f;
        const Complex s_tt  = lambda * (lambda + 1.) * f;
        const Complex s_rt  = -lambda * f1;
        const double  scale = std::abs(s_rr) + std::abs(s_tt) + std::abs(s_rt);
        EXPECT_NEAR(std::abs(2. * g * lambda * u_r -
                             ((1. - nu) * s_rr - nu * s_tt)),
                    0.,
                    1e-7 * scale);
        EXPECT_NEAR(std::abs(2. * g * (u_r + du_t) -
                             ((1. - nu) * s_tt - nu * s_rr)),
                    0.,
                    1e-7 * scale);
        EXPECT_NEAR(std::abs(g * (du_r + (lambda - 1.) * u_t) - s_rt),
                    0.,
                    1e-7 * scale);
      }
}

TEST(ComplexMatrix, DeterminantAndNullVector)
{
  ComplexMatrix m(3);
  // Rows 1 and 2 independent, row 3 = row 1 + i row 2: singular.
  const Complex i(0., 1.);
  const Complex rows[2][3] = {{1., 2., 3.}, {0., 1., {4., 1.}}};
  for (unsigned int j = 0; j < 3; ++j)
    {
      m(0, j) = rows[0][j];
      m(1, j) = rows[1][j];
      m(2, j) = rows[0][j] + i * rows[1][j];
    }
  std::vector<Complex> null;
  EXPECT_LT(std::abs(eliminate(m, &null)), 1e-12);
  EXPECT_LT(hadamard_ratio(m), 1e-14);
  for (unsigned int r = 0; r < 3; ++r)
    {
      Complex product = 0.;
      for (unsigned int j = 0; j < 3; ++j)
        product += m(r, j) * null[j];
      EXPECT_LT(std::abs(product), 1e-12);
    }
  // A regular matrix: det of diag(2, 3i, -1) is -6i.
  ComplexMatrix d(3);
  d(0, 0) = 2.;
  d(1, 1) = 3. * i;
  d(2, 2) = -1.;
  EXPECT_LT(std::abs(eliminate(d) - Complex(0., -6.)), 1e-14);
  EXPECT_NEAR(hadamard_ratio(d), 1., 1e-14);
  // Columns 0 and 2 of [[1, 5, 2], [2, 7, 4], [3, 1, 6]] are dependent.
  ComplexMatrix r(3);
  const double  values[3][3] = {{1., 5., 2.}, {2., 7., 4.}, {3., 1., 6.}};
  for (unsigned int a = 0; a < 3; ++a)
    for (unsigned int b = 0; b < 3; ++b)
      r(a, b) = values[a][b];
  const auto v = null_vector_in_columns(r, {0, 2}, 1e-12);
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[1], Complex(0.));
  EXPECT_LT(std::abs(2. * v[0] + 4. * v[2]), 1e-12);
  EXPECT_TRUE(null_vector_in_columns(r, {0, 1}, 1e-12).empty());
}
