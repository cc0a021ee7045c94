#include <common/input_error.h>
#include <geometry/bedding_profile.h>
#include <geometry/body_outline.h>
#include <geometry/ids.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>

namespace FloorBlock::Geometry
{
  namespace
  {
    /** Two fillets are mirror images if they agree to this fraction of the
     * block width. */
    constexpr double mirror_tolerance_factor = 1e-12;

    /**
     * A block corner: where the vertical side and the bedding-following
     * curve (bottom or top) meet, possibly replaced by a fillet arc tangent
     * to both. Without rounding, side_point == curve_point is the corner.
     */
    struct Corner
    {
      Point2 side_point;
      Point2 curve_point;
      Point2 centre;
      bool   rounded;
    };

    /** The four corners of one body, as seen from inside it. */
    struct BodyCorners
    {
      Corner bottom_left;
      Corner bottom_right;
      Corner top_right;
      Corner top_left;
    };

    /** Horizontal extent and ids of one block or of the face block. */
    struct BlockFrame
    {
      double                     x_left;
      double                     x_right;
      dealii::types::material_id material_id;
      dealii::types::boundary_id bottom_id;
      dealii::types::boundary_id top_id;
      dealii::types::boundary_id left_id;
      dealii::types::boundary_id right_id;
    };

    Point2
    point_on(const BeddingProfile &profile, const double x, const double shift)
    {
      return {x, profile.height(x) + shift};
    }

    /**
     * Fillet in the corner between the vertical line x = x_side and the
     * curve y = profile(x) + shift, starting at the distance d (the
     * rounding length, as UDEC defines its corner rounding) from the corner
     * along the vertical side. The body lies towards inward_x (+1: x >
     * x_side) and inward_y (+1: above the curve).
     *
     * Because both bodies of a vertical joint start their fillets at the
     * same height, the straight parts of the two joint sides coincide. The
     * arc radius follows from tangency: on a flat bedding it is d; at an
     * interior angle theta between straight edges it is d tan(theta/2).
     *
     * Unknowns: the tangent point x_t on the curve and the radius rho. The
     * centre is (x_side + inward_x rho, y_s) seen from the side and
     * (x_t, y(x_t)) + rho inward_y (-y', 1)/sqrt(1 + y'^2) seen from the
     * curve. The x components give rho(x_t) = (x_t - x_side) /
     * (inward_x + inward_y s(x_t)) with s = y'/sqrt(1 + y'^2), |s| < 1; the
     * y components leave g(x_t) = y(x_t) + inward_y rho(x_t) / sqrt(1 +
     * y'^2) - y_s, which is -inward_y d at x_t = x_side and changes sign
     * once the circle reaches y_s. Bisection finds x_t to round-off.
     * Returns rounded = false with no fillet when no sign change occurs
     * within @p reach (the fillet does not fit).
     */
    Corner
    corner(const BeddingProfile &profile,
           const double          x_side,
           const double          inward_x,
           const double          inward_y,
           const double          shift,
           const double          rounding_length,
           const double          reach,
           bool                 &fits)
    {
      const Point2 sharp = point_on(profile, x_side, shift);
      if (rounding_length == 0.0)
        return {sharp, sharp, sharp, false};

      const double side_y    = sharp.y + inward_y * rounding_length;
      const auto   radius_at = [&](const double x_tangent) {
        const double slope = profile.slope(x_tangent);
        const double sine  = slope / std::sqrt(1.0 + slope * slope);
        return (x_tangent - x_side) / (inward_x + inward_y * sine);
      };
      const auto mismatch = [&](const double x_tangent) {
        const double slope = profile.slope(x_tangent);
        return profile.height(x_tangent) + shift +
               inward_y * radius_at(x_tangent) /
                 std::sqrt(1.0 + slope * slope) -
               side_y;
      };
      double toward_side = x_side;
      double away        = x_side + inward_x * reach;
      if ((mismatch(away) > 0.0) != (inward_y > 0.0))
        {
          fits = false;
          return {sharp, sharp, sharp, false};
        }
      // 200 halvings shrink the bracket far below one ulp of x.
      constexpr unsigned int max_bisections = 200;
      for (unsigned int step = 0; step < max_bisections; ++step)
        {
          const double middle = (toward_side + away) / 2.0;
          if (middle == toward_side || middle == away)
            break;
          if ((mismatch(middle) > 0.0) == (inward_y > 0.0))
            away = middle;
          else
            toward_side = middle;
        }
      const double x_tangent = (toward_side + away) / 2.0;
      return {{x_side, side_y},
              point_on(profile, x_tangent, shift),
              {x_side + inward_x * radius_at(x_tangent), side_y},
              true};
    }

    BodyCorners
    body_corners(const BeddingProfile &profile,
                 const BlockFrame     &frame,
                 const double          height,
                 const double          rounding_length,
                 bool                 &fits)
    {
      const double reach = frame.x_right - frame.x_left;
      return {
        corner(
          profile, frame.x_left, +1.0, +1.0, 0.0, rounding_length, reach, fits),
        corner(profile,
               frame.x_right,
               -1.0,
               +1.0,
               0.0,
               rounding_length,
               reach,
               fits),
        corner(profile,
               frame.x_right,
               -1.0,
               -1.0,
               height,
               rounding_length,
               reach,
               fits),
        corner(profile,
               frame.x_left,
               +1.0,
               -1.0,
               height,
               rounding_length,
               reach,
               fits)};
    }

    Segment
    curve_piece(const BeddingProfile            &profile,
                const double                     x_start,
                const double                     x_end,
                const double                     shift,
                const dealii::types::boundary_id id)
    {
      const bool straight = profile.is_straight(x_start, x_end);
      return {straight ? SegmentKind::line : SegmentKind::quadratic,
              point_on(profile, x_start, shift),
              point_on(profile, x_end, shift),
              {(x_start + x_end) / 2.0,
               profile.bezier_control_height(x_start, x_end, shift)},
              id};
    }

    /** Appends the fillet arc of a rounded corner; returns its index (none if
     * sharp). */
    std::optional<unsigned int>
    add_fillet(const Corner                    &corner,
               const bool                       from_side,
               const dealii::types::boundary_id id,
               std::vector<Segment>            &segments)
    {
      if (!corner.rounded)
        return std::nullopt;
      segments.push_back({SegmentKind::arc,
                          from_side ? corner.side_point : corner.curve_point,
                          from_side ? corner.curve_point : corner.side_point,
                          corner.centre,
                          id});
      return segments.size() - 1;
    }

    /**
     * Vertical segments at x from y_start to y_end, split at the given
     * heights that lie strictly between: the ends of the neighbour's
     * straight side, so that the common part is one segment on both sides.
     */
    void
    add_vertical_side(const double                     x,
                      const double                     y_start,
                      const double                     y_end,
                      std::vector<double>              breaks,
                      const dealii::types::boundary_id id,
                      std::vector<Segment>            &segments)
    {
      const double y_low  = std::min(y_start, y_end);
      const double y_high = std::max(y_start, y_end);
      breaks.erase(std::remove_if(breaks.begin(),
                                  breaks.end(),
                                  [&](const double y) {
                                    return !(y > y_low && y < y_high);
                                  }),
                   breaks.end());
      std::sort(breaks.begin(), breaks.end());
      if (y_start > y_end)
        std::reverse(breaks.begin(), breaks.end());
      double y_previous = y_start;
      for (const double y : breaks)
        {
          segments.push_back(
            {SegmentKind::line, {x, y_previous}, {x, y}, {x, y}, id});
          y_previous = y;
        }
      segments.push_back(
        {SegmentKind::line, {x, y_previous}, {x, y_end}, {x, y_end}, id});
    }

    [[noreturn]] void
    refuse_rounding(const AssemblyDescription &description,
                    const std::string         &where)
    {
      std::ostringstream value;
      value << description.corner_rounding_radius;
      throw InputError("Geometry/Corner rounding radius",
                       value.str() + " m",
                       "the corner fillets do not fit " + where +
                         "; use 0 (sharp) or a radius well below half the "
                         "smallest block side (units: m)");
    }

    std::vector<BlockFrame>
    block_frames(const AssemblyDescription &description)
    {
      const unsigned int      n_blocks = description.n_blocks;
      const double            width    = description.block_width;
      std::vector<BlockFrame> frames;
      for (unsigned int block = 1; block <= n_blocks; ++block)
        {
          const double x_left = (n_blocks - block) * width;
          frames.push_back({x_left,
                            (n_blocks - block + 1) * width,
                            Ids::block_material(block),
                            Ids::bedding_block_side(block),
                            Ids::floor_surface(block),
                            Ids::vertical_joint_free_side(block),
                            block == 1 ?
                              Ids::free_side_of_block_1 :
                              Ids::vertical_joint_face_side(block - 1)});
        }
      frames.push_back({-description.face_block_width,
                        0.0,
                        Ids::face_block_material,
                        Ids::bedding_block_side(Ids::face_block_index),
                        Ids::floor_surface(Ids::face_block_index),
                        Ids::face_block_outer_side,
                        Ids::vertical_joint_face_side(n_blocks)});
      return frames;
    }

    /** Midpoint of a fillet arc, or the sharp corner itself. */
    Point2
    corner_middle(const Corner &corner)
    {
      if (!corner.rounded)
        return corner.side_point;
      const double radius    = std::hypot(corner.side_point.x - corner.centre.x,
                                       corner.side_point.y - corner.centre.y);
      const double to_side_x = corner.side_point.x - corner.centre.x;
      const double to_side_y = corner.side_point.y - corner.centre.y;
      const double to_curve_x = corner.curve_point.x - corner.centre.x;
      const double to_curve_y = corner.curve_point.y - corner.centre.y;
      const double sum_x      = to_side_x + to_curve_x;
      const double sum_y      = to_side_y + to_curve_y;
      const double norm       = std::hypot(sum_x, sum_y);
      return {corner.centre.x + radius * sum_x / norm,
              corner.centre.y + radius * sum_y / norm};
    }

    /** Indices of the top fillets of every body (frames order), to pair them
     * across the vertical joints. */
    struct TopFillets
    {
      std::vector<std::optional<unsigned int>> left;
      std::vector<std::optional<unsigned int>> right;
    };

    /** The corners of every body, refusing a rounding radius that does not
     * fit. */
    std::vector<BodyCorners>
    all_body_corners(const AssemblyDescription     &description,
                     const BeddingProfile          &profile,
                     const std::vector<BlockFrame> &frames)
    {
      std::vector<BodyCorners> corners;
      for (const BlockFrame &frame : frames)
        {
          bool fits = true;
          corners.push_back(body_corners(profile,
                                         frame,
                                         description.block_height,
                                         description.corner_rounding_radius,
                                         fits));
          if (!fits)
            refuse_rounding(description,
                            "on " + Ids::material_name(frame.material_id));
        }
      return corners;
    }

    /** The outline of every block body (frames order), with the segment
     * indices of its top fillets. */
    TopFillets
    add_block_bodies(const AssemblyDescription      &description,
                     const BeddingProfile           &profile,
                     const std::vector<BlockFrame>  &frames,
                     const std::vector<BodyCorners> &corners,
                     AssemblyOutline                &outline)
    {
      const double height = description.block_height;
      TopFillets   top_fillets;
      for (unsigned int index = 0; index < frames.size(); ++index)
        {
          const BlockFrame  &frame = frames[index];
          const BodyCorners &own   = corners[index];
          const std::string  where =
            "on " + Ids::material_name(frame.material_id);
          if (!(own.bottom_left.curve_point.x <
                  own.bottom_right.curve_point.x &&
                own.top_left.curve_point.x < own.top_right.curve_point.x &&
                own.bottom_left.side_point.y < own.top_left.side_point.y &&
                own.bottom_right.side_point.y < own.top_right.side_point.y))
            refuse_rounding(description, where);

          std::vector<double> right_breaks;
          if (index > 0)
            right_breaks = {corners[index - 1].bottom_left.side_point.y,
                            corners[index - 1].top_left.side_point.y};
          std::vector<double> left_breaks;
          if (index + 1 < frames.size())
            left_breaks = {corners[index + 1].bottom_right.side_point.y,
                           corners[index + 1].top_right.side_point.y};

          BodyOutline           body{frame.material_id, {}};
          std::vector<Segment> &segments = body.segments;
          segments.push_back(curve_piece(profile,
                                         own.bottom_left.curve_point.x,
                                         own.bottom_right.curve_point.x,
                                         0.0,
                                         frame.bottom_id));
          add_fillet(own.bottom_right, false, frame.bottom_id, segments);
          add_vertical_side(frame.x_right,
                            own.bottom_right.side_point.y,
                            own.top_right.side_point.y,
                            right_breaks,
                            frame.right_id,
                            segments);
          top_fillets.right.push_back(
            add_fillet(own.top_right, true, frame.right_id, segments));
          segments.push_back(curve_piece(profile,
                                         own.top_right.curve_point.x,
                                         own.top_left.curve_point.x,
                                         height,
                                         frame.top_id));
          top_fillets.left.push_back(
            add_fillet(own.top_left, false, frame.left_id, segments));
          add_vertical_side(frame.x_left,
                            own.top_left.side_point.y,
                            own.bottom_left.side_point.y,
                            left_breaks,
                            frame.left_id,
                            segments);
          add_fillet(own.bottom_left, true, frame.bottom_id, segments);
          outline.bodies.push_back(body);
        }
      return top_fillets;
    }

    /** The base body: the bedding shifted down by its thickness (none on a
     * rigid base, which the contact solver models as an obstacle, not a
     * body). */
    void
    add_base_body(const AssemblyDescription      &description,
                  const BeddingProfile           &profile,
                  const std::vector<BlockFrame>  &frames,
                  const std::vector<BodyCorners> &corners,
                  AssemblyOutline                &outline)
    {
      if (description.rigid_base)
        return;
      // From the outer side of the face block to the free side of block
      // 1; the top is split under every fillet tangent point so that the
      // contact part of each bedding joint is a single segment on both
      // sides.
      const double thickness = description.base_thickness;
      const double x_face    = frames.back().x_left;
      const double x_free    = frames.front().x_right;
      BodyOutline  base{Ids::base_material, {}};
      base.segments.push_back(
        curve_piece(profile, x_face, 0.0, -thickness, Ids::base_bottom));
      base.segments.push_back(
        curve_piece(profile, 0.0, x_free, -thickness, Ids::base_bottom));
      base.segments.push_back({SegmentKind::line,
                               point_on(profile, x_free, -thickness),
                               point_on(profile, x_free, 0.0),
                               {},
                               Ids::base_end_free_side});
      for (unsigned int index = 0; index < frames.size(); ++index)
        {
          const BlockFrame                &frame = frames[index];
          const BodyCorners               &own   = corners[index];
          const dealii::types::boundary_id id    = Ids::bedding_base_side(
            frame.bottom_id - Ids::bedding_block_side(0));
          const std::array<double, 4> stations{{frame.x_right,
                                                own.bottom_right.curve_point.x,
                                                own.bottom_left.curve_point.x,
                                                frame.x_left}};
          for (unsigned int piece = 0; piece + 1 < stations.size(); ++piece)
            if (stations[piece] != stations[piece + 1])
              base.segments.push_back(curve_piece(
                profile, stations[piece], stations[piece + 1], 0.0, id));
        }
      base.segments.push_back({SegmentKind::line,
                               point_on(profile, x_face, 0.0),
                               point_on(profile, x_face, -thickness),
                               {},
                               Ids::base_end_face_side});
      outline.bodies.push_back(base);
    }

    /** Every pair of segments of two bodies with the same geometry: a
     * joint. */
    void
    pair_joints(AssemblyOutline &outline)
    {
      for (unsigned int first = 0; first < outline.bodies.size(); ++first)
        for (unsigned int second = first + 1; second < outline.bodies.size();
             ++second)
          for (unsigned int a = 0; a < outline.bodies[first].segments.size();
               ++a)
            for (unsigned int b = 0; b < outline.bodies[second].segments.size();
                 ++b)
              if (same_geometry(outline.bodies[first].segments[a],
                                outline.bodies[second].segments[b]))
                outline.joint_pairs.push_back({{first, a}, {second, b}});
    }

    /** The top fillets facing each other across every vertical joint. */
    void
    pair_top_fillets(const AssemblyDescription     &description,
                     const std::vector<BlockFrame> &frames,
                     const TopFillets              &top_fillets,
                     AssemblyOutline               &outline)
    {
      // Top fillets across vertical joint j: block j = frames[index] (its
      // left side is the joint) and its left neighbour frames[index + 1].
      // Mirror images are recognised to round-off of the block width: the
      // two arcs come from separate bisections.
      const double mirror_tolerance =
        mirror_tolerance_factor * description.block_width;
      for (unsigned int index = 0; index + 1 < frames.size(); ++index)
        if (top_fillets.left[index] && top_fillets.right[index + 1])
          {
            FilletPair pair{{index, *top_fillets.left[index]},
                            {index + 1, *top_fillets.right[index + 1]},
                            frames[index].x_left,
                            false};
            pair.mirror = mirror_geometry(
              outline.bodies[index].segments[pair.master.segment],
              outline.bodies[index + 1].segments[pair.slave.segment],
              pair.joint_x,
              mirror_tolerance);
            outline.fillet_pairs.push_back(pair);
          }
    }

    /** The points the mesh refines toward: the contact corners. */
    void
    add_refinement_points(const AssemblyDescription      &description,
                          const std::vector<BlockFrame>  &frames,
                          const std::vector<BodyCorners> &corners,
                          AssemblyOutline                &outline)
    {
      // Contact corners: every corner on a vertical joint (both bodies) and
      // every block corner on the bedding; not the free top corner of block 1
      // nor the outer corners of the face block, where nothing presses --
      // unless they are rounded: a fillet needs cells smaller than itself.
      const unsigned int face_index = frames.size() - 1;
      const bool         rounded    = description.corner_rounding_radius > 0.0;
      for (unsigned int index = 0; index < frames.size(); ++index)
        {
          const BodyCorners          &own     = corners[index];
          std::vector<const Corner *> contact = {&own.bottom_right};
          if (index != 0 || rounded)
            contact.push_back(&own.top_right);
          if (index != face_index || rounded)
            {
              contact.push_back(&own.bottom_left);
              contact.push_back(&own.top_left);
            }
          for (const Corner *corner : contact)
            outline.refinement_points.push_back(corner_middle(*corner));
        }
    }
  } // namespace

  AssemblyOutline
  build_outline(const AssemblyDescription &description)
  {
    const BeddingProfile profile =
      BeddingProfile::geometry_profile(description);
    // frames[0..n-1] = blocks 1..n, frames[n] = face block; the left
    // neighbour of frame f (towards the face) is frame f+1.
    const std::vector<BlockFrame>  frames = block_frames(description);
    const std::vector<BodyCorners> corners =
      all_body_corners(description, profile, frames);

    AssemblyOutline  outline;
    const TopFillets top_fillets =
      add_block_bodies(description, profile, frames, corners, outline);
    add_base_body(description, profile, frames, corners, outline);
    pair_joints(outline);
    pair_top_fillets(description, frames, top_fillets, outline);
    add_refinement_points(description, frames, corners, outline);
    return outline;
  }

  double
  outline_area(const BodyOutline &body)
  {
    // Green: area = 1/2 closed integral of (x y' - y x') dt.
    const auto cross = [](const Point2 &first, const Point2 &second) {
      return first.x * second.y - first.y * second.x;
    };
    double twice_area = 0.0;
    for (const Segment &segment : body.segments)
      switch (segment.kind)
        {
          case SegmentKind::line:
            twice_area += cross(segment.start, segment.end);
            break;
            case SegmentKind::quadratic: {
              // B x B' is a cubic in t: 2-point Gauss-Legendre is exact.
              const double offset = 0.5 / std::sqrt(3.0);
              for (const double t : {0.5 - offset, 0.5 + offset})
                {
                  const Point2 &p0 = segment.start;
                  const Point2 &p1 = segment.control;
                  const Point2 &p2 = segment.end;
                  const double  s  = 1.0 - t;
                  const Point2  position{s * s * p0.x + 2 * s * t * p1.x +
                                          t * t * p2.x,
                                        s * s * p0.y + 2 * s * t * p1.y +
                                          t * t * p2.y};
                  const Point2  tangent{2 * s * (p1.x - p0.x) +
                                         2 * t * (p2.x - p1.x),
                                       2 * s * (p1.y - p0.y) +
                                         2 * t * (p2.y - p1.y)};
                  twice_area += 0.5 * cross(position, tangent);
                }
              break;
            }
            case SegmentKind::arc: {
              // x = c + r (cos th, sin th): x y' - y x' = r^2 + r (cx cos th +
              // cy sin th).
              const Point2 &centre = segment.control;
              const Point2  from{segment.start.x - centre.x,
                                segment.start.y - centre.y};
              const Point2  to{segment.end.x - centre.x,
                              segment.end.y - centre.y};
              const double  radius_squared = from.x * from.x + from.y * from.y;
              const double  sweep =
                std::atan2(cross(from, to), from.x * to.x + from.y * to.y);
              twice_area += radius_squared * sweep +
                            centre.x * (to.y - from.y) -
                            centre.y * (to.x - from.x);
              break;
            }
        }
    return twice_area / 2.0;
  }

  double
  arc_length(const Segment &arc)
  {
    const Point2 from{arc.start.x - arc.control.x, arc.start.y - arc.control.y};
    const Point2 to{arc.end.x - arc.control.x, arc.end.y - arc.control.y};
    const double sweep = std::atan2(std::abs(from.x * to.y - from.y * to.x),
                                    from.x * to.x + from.y * to.y);
    return std::hypot(from.x, from.y) * sweep;
  }

  bool
  mirror_geometry(const Segment &first,
                  const Segment &second,
                  const double   mirror_x,
                  const double   tolerance)
  {
    const auto mirrored = [&](const Point2 &point) {
      return Point2{2.0 * mirror_x - point.x, point.y};
    };
    const auto close = [&](const Point2 &a, const Point2 &b) {
      return std::abs(a.x - b.x) <= tolerance &&
             std::abs(a.y - b.y) <= tolerance;
    };
    if (first.kind != second.kind)
      return false;
    const bool same_ends = (close(mirrored(first.start), second.start) &&
                            close(mirrored(first.end), second.end)) ||
                           (close(mirrored(first.start), second.end) &&
                            close(mirrored(first.end), second.start));
    return same_ends && (first.kind == SegmentKind::line ||
                         close(mirrored(first.control), second.control));
  }

  bool
  same_geometry(const Segment &first, const Segment &second)
  {
    const auto equal = [](const Point2 &a, const Point2 &b) {
      return a.x == b.x && a.y == b.y;
    };
    if (first.kind != second.kind)
      return false;
    const bool same_ends =
      (equal(first.start, second.start) && equal(first.end, second.end)) ||
      (equal(first.start, second.end) && equal(first.end, second.start));
    return same_ends && (first.kind == SegmentKind::line ||
                         equal(first.control, second.control));
  }
} // namespace FloorBlock::Geometry
