// The corner eigen-solver (Williams' wedge eigenproblem, single wedges and
// two wedges in contact) against published exponents, each with its source,
// and against its own limits (a stuck similar pair is one body).
#include <analytic/complex_roots.h>
#include <analytic/corner_eigenproblem.h>
#include <common/input_error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

using namespace FloorBlock::Analytic;

namespace
{
  constexpr double pi = 3.14159265358979323846;

  /** The exponents of @p modes, lowest first. */
  template <typename Modes>
  std::complex<double>
  exponent(const Modes &modes, const std::size_t k)
  {
    EXPECT_GT(modes.size(), k);
    return k < modes.size() ? modes[k].exponent :
                              std::complex<double>(std::nan(""));
  }
} // namespace

TEST(ComplexRoots, FindsSimpleRealComplexAndDoubleRoots)
{
  using Complex = std::complex<double>;
  const auto f  = [](const Complex z) {
    return (z - 0.3) * (z - 0.7) * ((z - 0.5) * (z - 0.5) + 0.04) * (z - 1.4) *
           (z - 1.4);
  };
  const auto roots = complex_roots(f, RootSearch{});
  ASSERT_EQ(roots.size(), 4u);
  EXPECT_NEAR(std::abs(roots[0] - Complex(0.3)), 0., 1e-12);
  EXPECT_NEAR(std::abs(roots[1] - Complex(0.5, 0.2)), 0., 1e-12);
  EXPECT_NEAR(std::abs(roots[2] - Complex(0.7)), 0., 1e-12);
  // A double root converges only linearly: to about 1e-8.
  EXPECT_NEAR(std::abs(roots[3] - Complex(1.4)), 0., 1e-7);
}

// M. L. Williams, "Stress singularities resulting from various boundary
// conditions in angular corners of plates in extension", J. Appl. Mech. 19
// (1952) 526-528: a traction-free 270 deg corner (an L-shaped plate's
// re-entrant corner) has lambda = 0.544484 (symmetric) and 0.908529
// (antisymmetric), the roots of lambda sin(2 beta) +- sin(2 lambda beta) = 0
// with 2 beta = 3 pi / 2.
TEST(WedgeModes, ReEntrantCornerOfWilliams1952)
{
  SingleWedge corner;
  corner.angle     = 1.5 * pi;
  const auto modes = wedge_modes(corner);
  EXPECT_NEAR(exponent(modes, 0).real(), 0.544484, 1e-6);
  EXPECT_NEAR(exponent(modes, 0).imag(), 0., 1e-12);
  EXPECT_EQ(modes.at(0).symmetry, ModeSymmetry::symmetric);
  EXPECT_NEAR(exponent(modes, 1).real(), 0.908529, 1e-6);
  EXPECT_EQ(modes.at(1).symmetry, ModeSymmetry::antisymmetric);
  // The characteristic equations themselves, to round-off.
  for (const auto &mode : {modes.at(0), modes.at(1)})
    {
      const double lambda = mode.exponent.real();
      const double sign   = mode.symmetry == ModeSymmetry::symmetric ? 1. : -1.;
      EXPECT_NEAR(lambda * std::sin(1.5 * pi) +
                    sign * std::sin(1.5 * pi * lambda),
                  0.,
                  1e-12);
    }
}

// A crack (a 360 deg traction-free wedge): lambda = 1/2, the square-root
// singularity of fracture mechanics (M. L. Williams, J. Appl. Mech. 24,
// 1957). It is a double root (modes I and II); the solver lists it once.
TEST(WedgeModes, CrackTipHasTheSquareRootSingularity)
{
  SingleWedge crack;
  crack.angle = 2. * pi;
  EXPECT_NEAR(std::abs(exponent(wedge_modes(crack), 0) - 0.5), 0., 1e-10);
}

// The crack's second term is the T-stress, a uniform stress along the crack
// (lambda = 1, stress ~ r^0; Williams 1957), where the Airy basis
// degenerates: found by the solver's separate check at lambda = 1.
TEST(WedgeModes, CrackHasTheTStressTerm)
{
  SingleWedge crack;
  crack.angle      = 2. * pi;
  const auto modes = wedge_modes(crack);
  EXPECT_NEAR(std::abs(exponent(modes, 1) - 1.), 0., 1e-12);
  EXPECT_EQ(modes.at(1).symmetry, ModeSymmetry::symmetric);
}

// Two flush 90 deg corners pressed together (the face joint of the chapter's
// scene: the block's and the face block's top corners meet at floor level)
// stuck are one half-plane with a straight free edge: no singular mode, the
// lowest is the bounded lambda = 1 (a uniform stress across the joint,
// shear-free on it); frictionless likewise.
TEST(CornerModes, FlushSquareCornersAreNotSingular)
{
  WedgePair flush;
  flush.first_angle  = pi / 2.;
  flush.second_angle = pi / 2.;
  for (const auto state : {InterfaceState::stuck, InterfaceState::frictionless})
    {
      flush.state      = state;
      const auto modes = corner_modes(flush);
      EXPECT_NEAR(std::abs(exponent(modes, 0) - 1.), 0., 1e-12);
      EXPECT_NEAR(std::abs(modes.at(0).traction_ratio), 0., 1e-9);
    }
}

// The edge of a rigid flat punch on an elastic half-plane:
// - frictionless: p ~ r^(-1/2), lambda = 1/2;
// - bonded (no slip): lambda = 1/2 + i epsilon, epsilon = ln(3 - 4 nu) /
//   (2 pi) in plane strain, the oscillating singularity;
// (K. L. Johnson, Contact Mechanics, CUP 1985, sections 2.8 and 5.3; the
// half-plane is a 180 deg wedge with the punch face rigid.)
TEST(WedgeModes, RigidPunchEdgeFrictionlessAndBonded)
{
  SingleWedge half_plane;
  half_plane.angle                   = pi;
  half_plane.material.poissons_ratio = 0.3;
  half_plane.first_face              = FaceCondition::rigid_smooth;
  EXPECT_NEAR(std::abs(exponent(wedge_modes(half_plane), 0) - 0.5), 0., 1e-10);

  half_plane.first_face = FaceCondition::clamped;
  for (const double nu : {0., 0.3, 0.45})
    {
      half_plane.material.poissons_ratio = nu;
      const std::complex<double> expected(0.5,
                                          std::log(3. - 4. * nu) / (2. * pi));
      EXPECT_NEAR(std::abs(exponent(wedge_modes(half_plane), 0) - expected),
                  0.,
                  1e-10)
        << "nu = " << nu;
    }
}

// A flat rigid punch sliding with friction mu: the two edges have
// lambda = 1/2 -+ gamma, tan(pi gamma) = mu (1 - 2 nu) / (2 (1 - nu))
// (Johnson 1985, section 2.8, after Muskhelishvili), here as the pair
// elastic half-plane + a second wedge 1e8 times stiffer, slipping either
// way.
TEST(CornerModes, SlidingRigidPunchEdges)
{
  WedgePair punch;
  punch.first_angle                    = pi;
  punch.second_angle                   = pi;
  punch.first_material.poissons_ratio  = 0.3;
  punch.second_material.shear_modulus  = 1e8;
  punch.second_material.poissons_ratio = 0.3;
  punch.state                          = InterfaceState::slipping;
  punch.friction_coefficient           = 0.5;
  const double gamma =
    std::atan(0.5 * (1. - 2. * 0.3) / (2. * (1. - 0.3))) / pi;
  punch.slip_sign = 1;
  EXPECT_NEAR(exponent(corner_modes(punch), 0).real(), 0.5 - gamma, 1e-7);
  punch.slip_sign = -1;
  EXPECT_NEAR(exponent(corner_modes(punch), 0).real(), 0.5 + gamma, 1e-7);
}

// Interface crack between dissimilar half-planes: lambda = 1/2 + i epsilon,
// epsilon = ln((1 - beta) / (1 + beta)) / (2 pi) (M. L. Williams, Bull.
// Seismol. Soc. Am. 49, 1959; J. R. Rice, J. Appl. Mech. 55, 1988), with
// Dundurs' beta. Our exponents have Im >= 0: |epsilon|.
TEST(CornerModes, InterfaceCrackOscillates)
{
  WedgePair crack;
  crack.first_angle                    = pi;
  crack.second_angle                   = pi;
  crack.first_material.shear_modulus   = 10.;
  crack.first_material.poissons_ratio  = 0.25;
  crack.second_material.poissons_ratio = 0.35;
  const double beta =
    dundurs_parameters(crack.first_material, crack.second_material).beta;
  const double epsilon =
    std::abs(std::log((1. - beta) / (1. + beta)) / (2. * pi));
  EXPECT_GT(epsilon, 0.05);
  EXPECT_NEAR(std::abs(exponent(corner_modes(crack), 0) -
                       std::complex<double>(0.5, epsilon)),
              0.,
              1e-10);
}

// A stuck interface between similar materials is no interface: a square
// block edge stuck on a similar half-plane is one body with a traction-free
// 270 deg corner, so it has Williams' exponents (above).
TEST(CornerModes, StuckSimilarPairIsTheMonolithicCorner)
{
  WedgePair corner;
  corner.first_angle  = pi / 2.;
  corner.second_angle = pi;
  const auto modes    = corner_modes(corner);
  EXPECT_NEAR(exponent(modes, 0).real(), 0.544484, 1e-6);
  EXPECT_NEAR(exponent(modes, 1).real(), 0.908529, 1e-6);
  // The lowest mode's shear-to-normal ratio on the interface: what friction
  // must exceed for the corner to stay stuck under it.
  EXPECT_TRUE(std::isfinite(modes.at(0).traction_ratio.real()));
  EXPECT_NEAR(modes.at(0).traction_ratio.imag(), 0., 1e-9);
}

// Frictionless contact of two similar half-planes whose contact ends at
// the origin is a closed crack with free faces beyond it: lambda = 1/2.
TEST(CornerModes, FrictionlessHalfPlanesHaveTheCrackExponent)
{
  WedgePair pair;
  pair.first_angle  = pi;
  pair.second_angle = pi;
  pair.state        = InterfaceState::frictionless;
  EXPECT_NEAR(std::abs(exponent(corner_modes(pair), 0) - 0.5), 0., 1e-10);
}

// A slipping mode satisfies Coulomb's law on the interface by construction:
// sigma_rt / sigma_tt = slip_sign mu.
TEST(CornerModes, SlippingModeHasTheCoulombTractionRatio)
{
  WedgePair corner;
  corner.first_angle          = pi / 2.;
  corner.second_angle         = pi;
  corner.state                = InterfaceState::slipping;
  corner.friction_coefficient = 0.3;
  for (const int sign : {1, -1})
    {
      corner.slip_sign = sign;
      const auto modes = corner_modes(corner);
      ASSERT_FALSE(modes.empty());
      EXPECT_NEAR(modes[0].traction_ratio.real(), sign * 0.3, 1e-9);
    }
}

TEST(CornerModes, RefusesBadInputNamingIt)
{
  WedgePair corner;
  corner.first_angle  = pi / 2.;
  corner.second_angle = 2. * pi;
  EXPECT_THROW(corner_modes(corner), FloorBlock::InputError);
  corner.second_angle                  = pi;
  corner.first_material.poissons_ratio = 0.5;
  EXPECT_THROW(corner_modes(corner), FloorBlock::InputError);
  corner.first_material.poissons_ratio = 0.3;
  corner.friction_coefficient          = -0.1;
  EXPECT_THROW(corner_modes(corner), FloorBlock::InputError);
  SingleWedge wedge;
  wedge.angle = 0.;
  EXPECT_THROW(wedge_modes(wedge), FloorBlock::InputError);
}
