#include <geometry/gmsh_geometry.h>
#include <geometry/ids.h>

#include <gmsh.h>

#include <map>
#include <utility>

namespace FloorBlock::Geometry
{
  namespace
  {
    namespace occ = gmsh::model::occ;

    /** Points of one body, shared by its consecutive curves only. */
    class BodyPoints
    {
    public:
      int
      tag(const Point2 &point)
      {
        const auto key      = std::make_pair(point.x, point.y);
        const auto existing = tags.find(key);
        if (existing != tags.end())
          return existing->second;
        const int created = occ::addPoint(point.x, point.y, 0.0);
        tags.emplace(key, created);
        return created;
      }

    private:
      std::map<std::pair<double, double>, int> tags;
    };

    bool
    lexicographically_less(const Point2 &first, const Point2 &second)
    {
      return first.x < second.x || (first.x == second.x && first.y < second.y);
    }

    int
    add_curve(const Segment &segment, BodyPoints &points)
    {
      const bool reversed = lexicographically_less(segment.end, segment.start);
      const Point2 &from  = reversed ? segment.end : segment.start;
      const Point2 &to    = reversed ? segment.start : segment.end;
      const int     from_tag = points.tag(from);
      const int     to_tag   = points.tag(to);
      switch (segment.kind)
        {
          case SegmentKind::line:
            return occ::addLine(from_tag, to_tag);
          case SegmentKind::quadratic:
            case SegmentKind::arc: {
              // The control point / centre is only a construction point.
              const int helper =
                occ::addPoint(segment.control.x, segment.control.y, 0.0);
              const int curve = segment.kind == SegmentKind::quadratic ?
                                  occ::addBezier({from_tag, helper, to_tag}) :
                                  occ::addCircleArc(from_tag, helper, to_tag);
              occ::remove({{0, helper}});
              return curve;
            }
        }
      return -1;
    }
  } // namespace

  GmshAssembly
  build_gmsh_geometry(const AssemblyOutline &outline)
  {
    GmshAssembly assembly;
    for (const BodyOutline &body : outline.bodies)
      {
        BodyPoints       points;
        std::vector<int> curves;
        for (const Segment &segment : body.segments)
          curves.push_back(add_curve(segment, points));
        const int loop = occ::addCurveLoop(curves);
        assembly.surface_tags.push_back(occ::addPlaneSurface({loop}));
        assembly.curve_tags.push_back(curves);
      }
    occ::synchronize();

    std::map<int, std::vector<int>> curves_by_id;
    for (unsigned int body = 0; body < outline.bodies.size(); ++body)
      {
        const BodyOutline &outline_body = outline.bodies[body];
        const int          material     = outline_body.material_id;
        gmsh::model::addPhysicalGroup(2,
                                      {assembly.surface_tags[body]},
                                      material);
        gmsh::model::setPhysicalName(2, material, Ids::material_name(material));
        for (unsigned int segment = 0; segment < outline_body.segments.size();
             ++segment)
          curves_by_id[outline_body.segments[segment].boundary_id].push_back(
            assembly.curve_tags[body][segment]);
      }
    const unsigned int n_blocks = outline.bodies.size() - 2;
    for (const auto &[id, curves] : curves_by_id)
      {
        gmsh::model::addPhysicalGroup(1, curves, id);
        gmsh::model::setPhysicalName(1, id, Ids::boundary_name(id, n_blocks));
      }
    return assembly;
  }
} // namespace FloorBlock::Geometry
