#include <geometry/bedding_profile.h>
#include <rigid/joint_layout.h>

#include <cmath>

namespace FloorBlock::RigidBlocks
{
  namespace
  {
    /** Trapezoid weight of point k of n_points over an interval of length
     * h_total. */
    double
    trapezoid_weight(const unsigned int k,
                     const unsigned int n_points,
                     const double       interval_length)
    {
      const double spacing = interval_length / (n_points - 1);
      return (k == 0 || k + 1 == n_points) ? spacing / 2. : spacing;
    }

    /** Distance from the face of the face-side edge of block i (index i-1). */
    double
    face_side_x(const Geometry::AssemblyDescription &assembly,
                const unsigned int                   block_index)
    {
      return (assembly.n_blocks - 1 - block_index) * assembly.block_width;
    }

    JointGeometry
    vertical_joint(const Geometry::AssemblyDescription &assembly,
                   const Geometry::BeddingProfile      &profile,
                   const unsigned int                   joint_number,
                   const unsigned int                   n_points)
    {
      JointGeometry joint;
      joint.kind   = JointKind::vertical;
      joint.number = joint_number;
      joint.name   = "vertical " + std::to_string(joint_number);
      joint.side_a = {BodyKind::block, joint_number - 1};
      joint.side_b = joint_number == assembly.n_blocks ?
                       BodyRef{BodyKind::face_block, 0} :
                       BodyRef{BodyKind::block, joint_number};
      // Joint j is the face-side edge of block j.
      const double x_joint = face_side_x(assembly, joint_number - 1);
      const double y_top   = profile.height(x_joint) + assembly.block_height;
      const double height  = assembly.block_height;
      for (unsigned int k = 0; k < n_points; ++k)
        {
          JointPoint point;
          point.coordinate = height * k / (n_points - 1);
          point.position = dealii::Point<2>(x_joint, y_top - point.coordinate);
          point.weight   = trapezoid_weight(k, n_points, height);
          // From block j (x >= x_joint) towards the face (x < x_joint).
          point.normal  = dealii::Tensor<1, 2>({-1., 0.});
          point.tangent = dealii::Tensor<1, 2>({0., 1.});
          joint.points.push_back(point);
        }
      return joint;
    }

    JointGeometry
    bedding_joint(const Geometry::AssemblyDescription &assembly,
                  const Geometry::BeddingProfile      &profile,
                  const unsigned int                   block_number,
                  const unsigned int                   n_points)
    {
      JointGeometry joint;
      joint.kind           = JointKind::bedding;
      joint.number         = block_number;
      joint.name           = "bedding " + std::to_string(block_number);
      joint.side_a         = {BodyKind::base, 0};
      joint.side_b         = {BodyKind::block, block_number - 1};
      const double x_start = face_side_x(assembly, block_number - 1);
      const double width   = assembly.block_width;
      for (unsigned int k = 0; k < n_points; ++k)
        {
          JointPoint point;
          point.coordinate        = width * k / (n_points - 1);
          const double x          = x_start + point.coordinate;
          const double slope      = profile.slope(x);
          const double arc_factor = std::sqrt(1. + slope * slope);
          point.position          = dealii::Point<2>(x, profile.height(x));
          point.weight = trapezoid_weight(k, n_points, width) * arc_factor;
          // Base (below) into block (above).
          point.normal  = dealii::Tensor<1, 2>({-slope, 1.}) / arc_factor;
          point.tangent = dealii::Tensor<1, 2>({1., slope}) / arc_factor;
          joint.points.push_back(point);
        }
      return joint;
    }
  } // namespace

  dealii::Point<2>
  block_centroid(const Geometry::AssemblyDescription &assembly,
                 const unsigned int                   block_index)
  {
    const Geometry::BeddingProfile profile =
      Geometry::BeddingProfile::geometry_profile(assembly);
    const double x_start = face_side_x(assembly, block_index);
    const double x_end   = x_start + assembly.block_width;
    return dealii::Point<2>((x_start + x_end) / 2.,
                            profile.integral(x_start, x_end) /
                                assembly.block_width +
                              assembly.block_height / 2.);
  }

  std::vector<JointGeometry>
  build_joints(const Geometry::AssemblyDescription &assembly,
               const unsigned int                   n_points)
  {
    const Geometry::BeddingProfile profile =
      Geometry::BeddingProfile::geometry_profile(assembly);
    std::vector<JointGeometry> joints;
    for (unsigned int number = 1; number <= assembly.n_blocks; ++number)
      joints.push_back(vertical_joint(assembly, profile, number, n_points));
    for (unsigned int number = 1; number <= assembly.n_blocks; ++number)
      joints.push_back(bedding_joint(assembly, profile, number, n_points));
    return joints;
  }
} // namespace FloorBlock::RigidBlocks
