#include <geometry/bedding_manifold.h>
#include <geometry/ids.h>

namespace FloorBlock::Geometry
{
  BeddingManifold::BeddingManifold(const BeddingProfile &profile)
    : profile(profile)
  {}

  std::unique_ptr<dealii::Manifold<2, 2>>
  BeddingManifold::clone() const
  {
    return std::make_unique<BeddingManifold>(profile);
  }

  dealii::Point<2>
  BeddingManifold::pull_back(const dealii::Point<2> &space_point) const
  {
    return {space_point[0], space_point[1] - profile.height(space_point[0])};
  }

  dealii::Point<2>
  BeddingManifold::push_forward(const dealii::Point<2> &chart_point) const
  {
    return {chart_point[0], chart_point[1] + profile.height(chart_point[0])};
  }

  dealii::DerivativeForm<1, 2, 2>
  BeddingManifold::push_forward_gradient(
    const dealii::Point<2> &chart_point) const
  {
    dealii::DerivativeForm<1, 2, 2> gradient;
    gradient[0][0] = 1.0;
    gradient[0][1] = 0.0;
    gradient[1][0] = profile.slope(chart_point[0]);
    gradient[1][1] = 1.0;
    return gradient;
  }

  void
  attach_bedding_manifold(const AssemblyDescription &description,
                          dealii::Triangulation<2>  &triangulation)
  {
    triangulation.set_all_manifold_ids(Ids::bedding_manifold);
    triangulation.set_manifold(Ids::bedding_manifold,
                               BeddingManifold(BeddingProfile::geometry_profile(
                                 description)));
  }
} // namespace FloorBlock::Geometry
