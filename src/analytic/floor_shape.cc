#include <analytic/floor_shape.h>
#include <common/input_error.h>

#include <cmath>
#include <string>

namespace FloorBlock::Analytic
{
  namespace
  {
    void
    require_positive(const double       value,
                     const std::string &name,
                     const std::string &units)
    {
      if (!(std::isfinite(value) && value > 0.))
        throw InputError(name, std::to_string(value), "> 0 " + units);
    }

    /// A chain of @p n_blocks blocks of width @p block_width.
    void
    require_chain(const std::size_t n_blocks, const double block_width)
    {
      if (n_blocks == 0)
        throw InputError("Number of blocks", "0", ">= 1");
      require_positive(block_width, "Block width", "m");
    }

    /// Finite inputs can still overflow; say so instead of returning inf.
    double
    finite_or_throw(const double value, const std::string &name)
    {
      if (!std::isfinite(value))
        throw InputError(name,
                         std::to_string(value),
                         "a finite value (inputs too large)");
      return value;
    }
  } // namespace

  std::vector<double>
  parabolic_inclinations(const std::size_t n_blocks,
                         const double      block_width,
                         const double      curvature_length)
  {
    require_chain(n_blocks, block_width);
    require_positive(curvature_length, "Floor curvature length k", "m");
    std::vector<double> inclinations;
    for (std::size_t block = 0; block < n_blocks; ++block)
      {
        // Whole block widths between block (index) and the face.
        const double blocks_from_face =
          static_cast<double>(n_blocks - 1 - block);
        inclinations.push_back(std::atan((2. * blocks_from_face + 1.) *
                                         block_width / curvature_length));
      }
    return inclinations;
  }

  double
  parabolic_bedding_rise(const std::size_t n_blocks,
                         const double      block_width,
                         const double      curvature_length)
  {
    require_chain(n_blocks, block_width);
    require_positive(curvature_length, "Floor curvature length k", "m");
    const double chain_length = static_cast<double>(n_blocks) * block_width;
    return finite_or_throw(chain_length * chain_length / curvature_length,
                           "Bedding rise (nL)^2/k");
  }

  double
  planar_bedding_rise(const std::size_t n_blocks,
                      const double      block_width,
                      const double      inclination)
  {
    require_chain(n_blocks, block_width);
    if (!(std::abs(inclination) < M_PI_2))
      throw InputError("Bedding inclination",
                       std::to_string(inclination),
                       "finite, between -pi/2 and pi/2 rad");
    return finite_or_throw(static_cast<double>(n_blocks) * block_width *
                             std::tan(inclination),
                           "Bedding rise nL tan(alpha)");
  }

  double
  joint_floor_lift(const double inclination_away_side,
                   const double inclination_face_side,
                   const double block_width)
  {
    require_positive(block_width, "Block width", "m");
    const double relative_rotation =
      inclination_away_side - inclination_face_side;
    if (!(std::abs(relative_rotation) < M_PI_2))
      throw InputError("Relative rotation of the joint faces",
                       std::to_string(relative_rotation),
                       "finite, between -pi/2 and pi/2 rad");
    return finite_or_throw(block_width * std::tan(relative_rotation),
                           "Floor lift y = L tan(relative rotation)");
  }

  double
  youngs_modulus_from_bulk_shear(const double bulk_modulus,
                                 const double shear_modulus)
  {
    require_positive(bulk_modulus, "Bulk modulus", "Pa");
    require_positive(shear_modulus, "Shear modulus", "Pa");
    // With the ratio of the smaller to the larger modulus (<= 1) no
    // intermediate can overflow: 9KG/(3K+G) = G 9/(3 + G/K) = K 9/(3K/G + 1).
    // Only E itself can exceed the double range, which is then refused.
    if (shear_modulus <= bulk_modulus)
      return finite_or_throw(shear_modulus *
                               (9. / (3. + shear_modulus / bulk_modulus)),
                             "Young's modulus from K and G");
    return finite_or_throw(bulk_modulus *
                             (9. / (3. * bulk_modulus / shear_modulus + 1.)),
                           "Young's modulus from K and G");
  }

  double
  poisson_ratio_from_bulk_shear(const double bulk_modulus,
                                const double shear_modulus)
  {
    require_positive(bulk_modulus, "Bulk modulus", "Pa");
    require_positive(shear_modulus, "Shear modulus", "Pa");
    // (3K-2G)/(2(3K+G)) written with a ratio <= 1, free of overflow.
    if (shear_modulus <= bulk_modulus)
      {
        const double ratio = shear_modulus / bulk_modulus;
        return (3. - 2. * ratio) / (2. * (3. + ratio));
      }
    const double ratio = bulk_modulus / shear_modulus;
    return (3. * ratio - 2.) / (2. * (3. * ratio + 1.));
  }
} // namespace FloorBlock::Analytic
