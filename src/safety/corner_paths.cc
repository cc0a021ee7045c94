#include <corner/corner_site.h>
#include <safety/corner_paths.h>

#include <cmath>

namespace FloorBlock::Safety
{
  std::vector<CornerPath>
  floor_corner_paths(const Parameters::ScenarioParameters &scene)
  {
    const unsigned int n = scene.geometry.n_blocks;
    const double       r = scene.geometry.corner_rounding_radius;
    // From the sharp corner to the fillet's middle along the bisector.
    const double       inset = (std::sqrt(2.) - 1.) * r / std::sqrt(2.);
    std::vector<CornerPath> paths;
    for (unsigned int j = 1; j <= n; ++j)
      {
        const Corner::CornerSite site = Corner::floor_corner_site(scene, j);
        const double             x    = site.corner.x;
        // Block j lies at +x of its joint (body_outline.h), block j+1 and
        // the face block at -x.
        for (const double side : {+1., -1.})
          {
            CornerPath path;
            path.joint      = j;
            path.joint_name = site.joint_name;
            path.block      = side > 0. ? "block " + std::to_string(j) :
                              j == n    ? std::string("face block") :
                                          "block " + std::to_string(j + 1);
            path.direction  = {side / std::sqrt(2.), -1. / std::sqrt(2.)};
            path.start      = {x + side * inset, site.top - inset};
            paths.push_back(path);
          }
      }
    return paths;
  }
} // namespace FloorBlock::Safety
