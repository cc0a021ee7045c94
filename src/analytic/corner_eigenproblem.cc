#include <analytic/complex_matrix.h>
#include <analytic/corner_eigenproblem.h>
#include <analytic/williams_field.h>
#include <common/input_error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace FloorBlock::Analytic
{
  namespace
  {
    using Complex       = std::complex<double>;
    constexpr double pi = 3.14159265358979323846;

    /** Puts @p row into matrix row @p i at column block @p block. */
    void
    put(ComplexMatrix     &matrix,
        const unsigned int i,
        const unsigned int block,
        const WilliamsRow &row,
        const Complex      factor = 1.)
    {
      for (unsigned int j = 0; j < 4; ++j)
        matrix(i, 4 * block + j) += factor * row[j];
    }

    /** The two conditions of a face of wedge @p block at angle theta. */
    void
    add_face(ComplexMatrix      &matrix,
             const unsigned int  first_row,
             const unsigned int  block,
             const FaceCondition condition,
             const WilliamsRows &rows)
    {
      switch (condition)
        {
          case FaceCondition::traction_free:
            put(matrix, first_row, block, rows.normal_stress);
            put(matrix, first_row + 1, block, rows.shear_stress);
            break;
          case FaceCondition::clamped:
            put(matrix, first_row, block, rows.radial_displacement);
            put(matrix, first_row + 1, block, rows.angular_displacement);
            break;
          case FaceCondition::rigid_smooth:
            put(matrix, first_row, block, rows.angular_displacement);
            put(matrix, first_row + 1, block, rows.shear_stress);
            break;
        }
    }

    ComplexMatrix
    wedge_matrix(const SingleWedge &wedge, const Complex lambda)
    {
      ComplexMatrix matrix(4);
      add_face(matrix,
               0,
               0,
               wedge.first_face,
               williams_rows(lambda, 0., wedge.material));
      add_face(matrix,
               2,
               0,
               wedge.second_face,
               williams_rows(lambda, wedge.angle, wedge.material));
      return matrix;
    }

    ComplexMatrix
    pair_matrix(const WedgePair &pair, const Complex lambda)
    {
      ComplexMatrix matrix(8);
      add_face(matrix,
               0,
               0,
               FaceCondition::traction_free,
               williams_rows(lambda, pair.first_angle, pair.first_material));
      add_face(matrix,
               2,
               1,
               FaceCondition::traction_free,
               williams_rows(lambda, -pair.second_angle, pair.second_material));
      const WilliamsRows one = williams_rows(lambda, 0., pair.first_material);
      const WilliamsRows two = williams_rows(lambda, 0., pair.second_material);
      // Normal traction and normal displacement are continuous in every
      // state: the wedges stay in contact.
      put(matrix, 4, 0, one.normal_stress);
      put(matrix, 4, 1, two.normal_stress, -1.);
      put(matrix, 5, 0, one.angular_displacement);
      put(matrix, 5, 1, two.angular_displacement, -1.);
      switch (pair.state)
        {
          case InterfaceState::stuck:
            put(matrix, 6, 0, one.shear_stress);
            put(matrix, 6, 1, two.shear_stress, -1.);
            put(matrix, 7, 0, one.radial_displacement);
            put(matrix, 7, 1, two.radial_displacement, -1.);
            break;
          case InterfaceState::frictionless:
            put(matrix, 6, 0, one.shear_stress);
            put(matrix, 7, 1, two.shear_stress);
            break;
          case InterfaceState::slipping:
            put(matrix, 6, 0, one.shear_stress);
            put(matrix, 6, 1, two.shear_stress, -1.);
            // sigma_rt = s mu sigma_tt with sigma_rt = -lambda F' and
            // sigma_tt = lambda (lambda + 1) F: F' + s mu (lambda + 1) F = 0.
            put(matrix, 7, 0, one.shear_stress);
            put(matrix,
                7,
                0,
                one.normal_stress,
                double(pair.slip_sign) * pair.friction_coefficient *
                  (lambda + 1.));
            break;
        }
      return matrix;
    }


    /**
     * Largest |sigma_tt|, |sigma_rt| over a few angles of each wedge,
     * relative to the largest coefficient: ~0 for a stress-free solution
     * (a rigid motion).
     */
    double
    stress_size(const std::vector<Complex>                   &coefficients,
                const Complex                                 lambda,
                const std::vector<std::pair<double, double>> &ranges,
                const std::vector<WedgeMaterial>             &materials)
    {
      double largest = 0.;
      for (unsigned int block = 0; block < ranges.size(); ++block)
        for (int k = 0; k <= 8; ++k)
          {
            const double theta =
              ranges[block].first +
              (ranges[block].second - ranges[block].first) * k / 8.;
            const auto [f, derivative] = airy_angular(
              coefficients, block, lambda, theta, materials[block]);
            largest = std::max({largest,
                                std::abs(lambda * (lambda + 1.) * f),
                                std::abs(lambda * derivative)});
          }
      return largest;
    }

    void
    check_material(const WedgeMaterial &material, const std::string &which)
    {
      if (!(material.shear_modulus > 0.) ||
          !std::isfinite(material.shear_modulus))
        throw InputError(which + " shear modulus",
                         std::to_string(material.shear_modulus),
                         "a finite value > 0 Pa");
      if (!(material.poissons_ratio > -1. && material.poissons_ratio < 0.5))
        throw InputError(which + " Poisson's ratio",
                         std::to_string(material.poissons_ratio),
                         "-1 < nu < 0.5");
    }

    void
    check_angle(const double       angle,
                const std::string &which,
                const double       largest)
    {
      if (!(angle > 0. && angle <= largest))
        throw InputError(which,
                         std::to_string(angle),
                         "0 < angle <= " + std::to_string(largest) + " rad");
    }

    /** Largest hadamard_ratio() accepted as a root. */
    constexpr double root_hadamard_ratio = 1e-10;

    /**
     * The null vector at lambda = 1 without the D columns, or empty. There
     * sin((lambda - 1) theta) vanishes, its column with it in the stress
     * rows, and the determinant has a spurious zero that can hide a genuine
     * one from the scan (no sign change at a double zero): a uniform
     * stress parallel to a free face, e.g. the crack's T-stress, or the
     * bounded field where two flush 90 deg corners meet. Such a mode needs
     * no D coefficient, so the rectangular matrix without the D columns
     * must be rank-deficient (full-pivot elimination, pivots below 1e-10
     * of the largest entry count as zero).
     */
    std::vector<Complex>
    unit_exponent_null_vector(const ComplexMatrix &full)
    {
      std::vector<unsigned int> without_d;
      for (unsigned int j = 0; j < full.n; ++j)
        if (j % 4 != 3)
          without_d.push_back(j);
      return null_vector_in_columns(full, without_d, 1e-10);
    }

    /**
     * sigma_rt / sigma_tt of wedge 0 at theta = 0 (the interface of a
     * pair): -lambda F' / (lambda (lambda + 1) F); NaN where sigma_tt
     * vanishes there.
     */
    Complex
    traction_ratio(const std::vector<Complex> &coefficients,
                   const Complex               lambda,
                   const WedgeMaterial        &material)
    {
      const auto [f, derivative] =
        airy_angular(coefficients, 0, lambda, 0., material);
      const Complex normal = lambda * (lambda + 1.) * f;
      return std::abs(normal) > 1e-12 ? -lambda * derivative / normal :
                                        Complex(std::nan(""), std::nan(""));
    }

    /** Stress-free solutions are rigid motions, not modes. */
    constexpr double rigid_motion_stress = 1e-8;

    /**
     * The modes of a problem given by its matrix: roots of the
     * determinant, each with its null vector, rigid motions left out.
     */
    template <typename MatrixOf>
    std::vector<CornerMode>
    modes_of(const MatrixOf                               &matrix_of,
             const RootSearch                             &search,
             const std::vector<std::pair<double, double>> &ranges,
             const std::vector<WedgeMaterial>             &materials)
    {
      std::vector<CornerMode> modes;
      for (const Complex lambda : complex_roots(
             [&](const Complex z) { return eliminate(matrix_of(z)); }, search))
        {
          if (hadamard_ratio(matrix_of(lambda)) > root_hadamard_ratio)
            continue;
          CornerMode mode;
          mode.exponent = lambda;
          eliminate(matrix_of(lambda), &mode.coefficients);
          if (stress_size(mode.coefficients, lambda, ranges, materials) <
              rigid_motion_stress)
            continue;
          mode.traction_ratio =
            traction_ratio(mode.coefficients, lambda, materials[0]);
          modes.push_back(mode);
        }
      const bool has_unit_mode =
        std::any_of(modes.begin(), modes.end(), [](const CornerMode &mode) {
          return std::abs(mode.exponent - 1.) < 1e-6;
        });
      if (!has_unit_mode && search.smallest_real_part < 1. &&
          search.largest_real_part >= 1.)
        {
          CornerMode mode;
          mode.exponent     = 1.;
          mode.coefficients = unit_exponent_null_vector(matrix_of(1.));
          if (!mode.coefficients.empty() &&
              stress_size(mode.coefficients, 1., ranges, materials) >=
                rigid_motion_stress)
            {
              mode.traction_ratio =
                traction_ratio(mode.coefficients, 1., materials[0]);
              modes.push_back(mode);
              std::sort(modes.begin(),
                        modes.end(),
                        [](const CornerMode &a, const CornerMode &b) {
                          return a.exponent.real() < b.exponent.real();
                        });
            }
        }
      return modes;
    }

    /** Symmetry of a single wedge's mode about its bisector. */
    ModeSymmetry
    symmetry_of(const CornerMode &mode, const SingleWedge &wedge)
    {
      const double middle = wedge.angle / 2.;
      double       even = 0., odd = 0., size = 0.;
      for (const double t : {0.13, 0.37, 0.71})
        {
          const Complex plus = airy_angular(mode.coefficients,
                                            0,
                                            mode.exponent,
                                            middle + t * middle,
                                            wedge.material)
                                 .first;
          const Complex minus = airy_angular(mode.coefficients,
                                             0,
                                             mode.exponent,
                                             middle - t * middle,
                                             wedge.material)
                                  .first;
          even = std::max(even, std::abs(plus - minus));
          odd  = std::max(odd, std::abs(plus + minus));
          size = std::max({size, std::abs(plus), std::abs(minus)});
        }
      if (even <= 1e-8 * size)
        return ModeSymmetry::symmetric;
      if (odd <= 1e-8 * size)
        return ModeSymmetry::antisymmetric;
      return ModeSymmetry::mixed;
    }
  } // namespace

  DundursParameters
  dundurs_parameters(const WedgeMaterial &first, const WedgeMaterial &second)
  {
    check_material(first, "first wedge");
    check_material(second, "second wedge");
    const double gamma = second.shear_modulus / first.shear_modulus;
    const double k1 = first.kolosov(), k2 = second.kolosov();
    const double denominator = gamma * (k1 + 1.) + (k2 + 1.);
    return {(gamma * (k1 + 1.) - (k2 + 1.)) / denominator,
            (gamma * (k1 - 1.) - (k2 - 1.)) / denominator};
  }

  std::string
  to_string(const ModeSymmetry symmetry)
  {
    switch (symmetry)
      {
        case ModeSymmetry::symmetric:
          return "symmetric";
        case ModeSymmetry::antisymmetric:
          return "antisymmetric";
        case ModeSymmetry::mixed:
          break;
      }
    return "mixed";
  }

  std::vector<CornerMode>
  wedge_modes(const SingleWedge &wedge, const RootSearch &search)
  {
    check_angle(wedge.angle, "wedge angle", 2. * pi);
    check_material(wedge.material, "wedge");
    std::vector<CornerMode> modes =
      modes_of([&](
                 const Complex lambda) { return wedge_matrix(wedge, lambda); },
               search,
               {{0., wedge.angle}},
               {wedge.material});
    const bool symmetric_problem = wedge.first_face == wedge.second_face;
    for (CornerMode &mode : modes)
      mode.symmetry =
        symmetric_problem ? symmetry_of(mode, wedge) : ModeSymmetry::mixed;
    return modes;
  }

  std::vector<CornerMode>
  corner_modes(const WedgePair &pair, const RootSearch &search)
  {
    check_angle(pair.first_angle, "first wedge angle", 2. * pi);
    check_angle(pair.second_angle, "second wedge angle", 2. * pi);
    if (pair.first_angle + pair.second_angle > 2. * pi)
      throw InputError("wedge angles",
                       std::to_string(pair.first_angle) + " + " +
                         std::to_string(pair.second_angle),
                       "a sum of at most 2 pi rad");
    check_material(pair.first_material, "first wedge");
    check_material(pair.second_material, "second wedge");
    if (!(pair.friction_coefficient >= 0.) ||
        !std::isfinite(pair.friction_coefficient))
      throw InputError("friction coefficient",
                       std::to_string(pair.friction_coefficient),
                       "a finite value >= 0");
    if (pair.slip_sign != 1 && pair.slip_sign != -1)
      throw InputError("slip sign", std::to_string(pair.slip_sign), "+1 or -1");
    return modes_of(
      [&](const Complex lambda) { return pair_matrix(pair, lambda); },
      search,
      {{0., pair.first_angle}, {-pair.second_angle, 0.}},
      {pair.first_material, pair.second_material});
  }
} // namespace FloorBlock::Analytic
