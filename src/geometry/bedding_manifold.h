#pragma once

#include <geometry/assembly_description.h>
#include <geometry/bedding_profile.h>

#include <deal.II/grid/manifold.h>
#include <deal.II/grid/tria.h>

#include <memory>

namespace FloorBlock::Geometry
{
  /**
   * @brief Chart in which the bedding-following curves are straight:
   * pull_back(x, y) = (x, y - y_b(x)), push_forward(x, eta) = (x, eta +
   * y_b(x)). New vertices on block bottoms and tops, the base top and the
   * base bottom (all y_b shifted vertically) land exactly on the curve, and
   * vertical joints stay vertical. Fillet arcs are not reproduced exactly.
   */
  class BeddingManifold : public dealii::ChartManifold<2, 2, 2>
  {
  public:
    explicit BeddingManifold(const BeddingProfile &profile);

    std::unique_ptr<dealii::Manifold<2, 2>>
    clone() const override;

    dealii::Point<2>
    pull_back(const dealii::Point<2> &space_point) const override;

    dealii::Point<2>
    push_forward(const dealii::Point<2> &chart_point) const override;

    dealii::DerivativeForm<1, 2, 2>
    push_forward_gradient(const dealii::Point<2> &chart_point) const override;

  private:
    BeddingProfile profile;
  };

  /**
   * @brief Attach a BeddingManifold for the geometry profile of @p
   * description to every cell and face, so that refinement keeps the
   * bedding exact. Uses manifold id Ids::bedding_manifold.
   */
  void
  attach_bedding_manifold(const AssemblyDescription &description,
                          dealii::Triangulation<2>  &triangulation);
} // namespace FloorBlock::Geometry
