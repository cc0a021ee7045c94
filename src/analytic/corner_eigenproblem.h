#pragma once

#include <analytic/complex_roots.h>
#include <analytic/williams_field.h>

#include <complex>
#include <string>
#include <vector>

namespace FloorBlock::Analytic
{
  /** @brief Dundurs' bimaterial parameters (alpha, beta), plane strain. */
  struct DundursParameters
  {
    double alpha = 0.;
    double beta  = 0.;
  };

  /**
   * @brief Dundurs' parameters of the pair: with Gamma = G2 / G1,
   * alpha = (Gamma (k1 + 1) - (k2 + 1)) / (Gamma (k1 + 1) + (k2 + 1)),
   * beta = (Gamma (k1 - 1) - (k2 - 1)) / (Gamma (k1 + 1) + (k2 + 1))
   * (J. Dundurs, J. Appl. Mech. 36, 1969). Both 0 for similar materials.
   */
  DundursParameters
  dundurs_parameters(const WedgeMaterial &first, const WedgeMaterial &second);

  /** How a wedge face is held. */
  enum class FaceCondition
  {
    traction_free, ///< sigma_tt = sigma_rt = 0
    clamped,       ///< u_r = u_t = 0
    rigid_smooth   ///< u_t = 0, sigma_rt = 0: frictionless rigid contact
  };

  /** @brief One elastic wedge 0 <= theta <= angle with its two faces. */
  struct SingleWedge
  {
    double        angle = 0.; ///< rad, in (0, 2 pi]
    WedgeMaterial material;
    FaceCondition first_face  = FaceCondition::traction_free; ///< theta = 0
    FaceCondition second_face = FaceCondition::traction_free; ///< theta = angle
  };

  /** State of the interface between the two wedges of a contact corner. */
  enum class InterfaceState
  {
    stuck,        ///< tractions and both displacements continuous
    frictionless, ///< normal traction and u_t continuous, no shear
    slipping      ///< also sigma_rt = slip_sign mu sigma_tt (Coulomb)
  };

  /**
   * @brief Two wedges meeting at a contact corner: wedge 1 (the block
   * corner) occupies 0 <= theta <= first_angle, wedge 2 (the body it is
   * pressed on) -second_angle <= theta <= 0; the interface is theta = 0,
   * the outer faces are traction-free. A square block edge on a flat:
   * first_angle = pi/2, second_angle = pi.
   *
   * Slip sign: on the interface sigma_rt = slip_sign mu sigma_tt, with
   * sigma_tt < 0 in compression. Wedge 1's outward normal there is
   * -e_theta, so its shear traction is -sigma_rt e_r: slip_sign = +1 puts
   * it along +r (away from the corner) when pressed, so friction resists
   * wedge 1 slipping towards the corner (-r) relative to wedge 2.
   */
  struct WedgePair
  {
    double         first_angle  = 0.; ///< rad, in (0, 2 pi)
    double         second_angle = 0.; ///< rad, in (0, 2 pi)
    WedgeMaterial  first_material;
    WedgeMaterial  second_material;
    InterfaceState state                = InterfaceState::stuck;
    double         friction_coefficient = 0.; ///< mu >= 0 (slipping)
    int            slip_sign            = 1;  ///< +1 or -1 (slipping)
  };

  /** Symmetry of a single wedge's mode about its bisector. */
  enum class ModeSymmetry
  {
    symmetric,     ///< sigma_tt even about the bisector (mode I)
    antisymmetric, ///< sigma_tt odd (mode II)
    mixed          ///< neither, or not a symmetric problem
  };

  /** @brief "symmetric", "antisymmetric", "mixed". */
  std::string
  to_string(ModeSymmetry symmetry);

  /**
   * @brief One eigen-solution of the corner: stresses ~ r^(lambda - 1)
   * S(theta), displacements ~ r^lambda U(theta), from the Airy function
   * r^(lambda + 1) F(theta) with F = A cos((lambda + 1) theta) +
   * B sin((lambda + 1) theta) + C cos((lambda - 1) theta) +
   * D sin((lambda - 1) theta) in each wedge (M. L. Williams, J. Appl. Mech.
   * 19, 1952).
   */
  struct CornerMode
  {
    std::complex<double> exponent; ///< lambda (Im >= 0)
    /** A, B, C, D of wedge 1, then of wedge 2 (pair), max |.| = 1. */
    std::vector<std::complex<double>> coefficients;
    ModeSymmetry                      symmetry = ModeSymmetry::mixed;
    /**
     * sigma_rt / sigma_tt on the interface theta = 0 (pair), or on the
     * face theta = 0 (single wedge; NaN where sigma_tt vanishes there):
     * the traction ratio that friction must exceed for the mode to stay
     * stuck (D. A. Hills, D. Dini).
     */
    std::complex<double> traction_ratio;
  };

  /**
   * @brief Modes of a single wedge, lowest real part first, with
   * 0 < Re lambda <= search.largest_real_part; stress-free solutions
   * (rigid motions, e.g. lambda = 1 of a free wedge) are left out.
   * @throws FloorBlock::InputError for an angle outside (0, 2 pi], a
   * shear modulus <= 0 or a Poisson's ratio outside (-1, 0.5).
   */
  std::vector<CornerMode>
  wedge_modes(const SingleWedge &wedge, const RootSearch &search = {});

  /**
   * @brief Modes of a contact corner (see WedgePair), as wedge_modes().
   * @throws FloorBlock::InputError as wedge_modes(), and for a negative
   * friction coefficient or a slip sign other than +-1.
   */
  std::vector<CornerMode>
  corner_modes(const WedgePair &pair, const RootSearch &search = {});
} // namespace FloorBlock::Analytic
