#include <refinement/matched_refinement.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace FloorBlock::Refinement
{
  namespace
  {
    struct BoundaryFace
    {
      ActiveCell   cell;
      unsigned int face_no;
    };

    std::vector<BoundaryFace>
    faces_with_id(const dealii::Triangulation<2>  &triangulation,
                  const dealii::types::boundary_id id)
    {
      std::vector<BoundaryFace> faces;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == id)
            faces.push_back({cell, f});
      return faces;
    }

    /**
     * Unit vector along a joint: the sum of its face vectors, each turned
     * to agree with the first. A curved joint keeps positions along it
     * monotonic while its tangent turns by less than 90 degrees.
     */
    dealii::Tensor<1, 2>
    mean_direction(const std::vector<BoundaryFace> &faces)
    {
      dealii::Tensor<1, 2> sum;
      dealii::Tensor<1, 2> first;
      for (const auto &[cell, f] : faces)
        {
          dealii::Tensor<1, 2> along =
            cell->face(f)->vertex(1) - cell->face(f)->vertex(0);
          if (first.norm() == 0.)
            first = along;
          sum += (along * first < 0. ? -1. : 1.) * along;
        }
      return sum / sum.norm();
    }

    /** Centre and length of a boundary face (m). */
    struct FaceShape
    {
      dealii::Point<2> centre;
      double           length;
    };

    FaceShape
    shape_of(const BoundaryFace &face)
    {
      const auto accessor = face.cell->face(face.face_no);
      return {accessor->center(), accessor->measure()};
    }

    /**
     * Whether a face (centre, length) is @p other, or its mirror image
     * reflected onto it: centres within @p fraction of the shorter face,
     * lengths within a tenth.
     */
    bool
    same_face(const dealii::Point<2> &centre,
              const double            length,
              const FaceShape        &other,
              const double            fraction)
    {
      return centre.distance(other.centre) <=
               fraction * std::min(length, other.length) &&
             std::abs(length - other.length) <= 0.1 * length;
    }

    /**
     * Coincident faces share their vertices to round-off (Gmsh's periodic
     * copies, then the same deal.II refinement). The first faces of two
     * facing fillets lie within a quarter of their length of each other,
     * as the fillets leave the joint tangentially: a loose tolerance
     * would count them as the common part, tilt the joint line drawn
     * through it, and lose the mirror images beyond (measured: 1e-4 rad,
     * 0.4 mm off at the top of a 1 cm fillet, every fillet face unpaired).
     */
    constexpr double coincident_fraction = 1e-6;
    /** Mirror images are reflected across a line fitted to round-off. */
    constexpr double mirrored_fraction = 0.25;
    /** Whether deal.II will coarsen the parent of @p cell. */
    bool
    parent_will_coarsen(const ActiveCell &cell)
    {
      if (cell->level() == 0)
        return false;
      const auto parent = cell->parent();
      for (unsigned int c = 0; c < parent->n_children(); ++c)
        if (parent->child(c)->has_children() ||
            !parent->child(c)->coarsen_flag_set())
          return false;
      return true;
    }

    void
    keep_parent(const ActiveCell &cell)
    {
      const auto parent = cell->parent();
      for (unsigned int c = 0; c < parent->n_children(); ++c)
        parent->child(c)->clear_coarsen_flag();
    }

    void
    flag_for_refinement(const ActiveCell &cell)
    {
      cell->clear_coarsen_flag();
      cell->set_refine_flag();
    }

    /** One round of copying flags across the joints; true if any changed. */
    bool
    mirror_flags(const std::vector<std::pair<ActiveCell, ActiveCell>> &pairs)
    {
      bool changed = false;
      for (const auto &[a, b] : pairs)
        if (a->refine_flag_set() != b->refine_flag_set())
          {
            flag_for_refinement(a->refine_flag_set() ? b : a);
            changed = true;
          }
      for (const auto &[a, b] : pairs)
        {
          const bool a_coarsens = parent_will_coarsen(a);
          if (a_coarsens != parent_will_coarsen(b))
            {
              keep_parent(a_coarsens ? a : b);
              changed = true;
            }
        }
      return changed;
    }

    double
    distance_to_segment(const dealii::Point<2> &point,
                        const dealii::Point<2> &start,
                        const dealii::Point<2> &end)
    {
      const dealii::Tensor<1, 2> along   = end - start;
      const double               length2 = along.norm_square();
      const double               t       = length2 > 0. ?
                                             std::clamp((point - start) * along / length2, 0., 1.) :
                                             0.;
      return point.distance(start + t * along);
    }

    /**
     * Distance from @p point to a straight-sided convex quadrilateral (0 on
     * or inside it). deal.II numbers the vertices 0, 1, 3, 2 around a quad.
     */
    double
    distance_to_cell(const dealii::Point<2>              &point,
                     const dealii::TriaAccessor<2, 2, 2> &cell)
    {
      constexpr std::array<unsigned int, 4> around = {{0, 1, 3, 2}};
      double nearest     = std::numeric_limits<double>::infinity();
      bool   inside      = true;
      double orientation = 0.;
      for (unsigned int k = 0; k < 4; ++k)
        {
          const auto &start = cell.vertex(around[k]);
          const auto &end   = cell.vertex(around[(k + 1) % 4]);
          nearest = std::min(nearest, distance_to_segment(point, start, end));
          const dealii::Tensor<1, 2> edge = end - start;
          const dealii::Tensor<1, 2> to   = point - start;
          const double               side = edge[0] * to[1] - edge[1] * to[0];
          if (orientation == 0.)
            orientation = side;
          else if (side * orientation < 0.)
            inside = false;
        }
      return inside ? 0. : nearest;
    }

    /** Requests sorted by x, so that on() searches only a window of them. */
    struct SortedRequests
    {
      std::vector<Geometry::LocalSize> requests;
      double                           growth_rate;

      SortedRequests(std::vector<Geometry::LocalSize> unsorted,
                     const double                     growth)
        : requests(std::move(unsorted))
        , growth_rate(growth)
      {
        std::sort(requests.begin(),
                  requests.end(),
                  [](const auto &a, const auto &b) {
                    return a.position.x < b.position.x;
                  });
      }

      /**
       * Smallest graded request on @p cell: Geometry::graded_size() at the
       * distance d_p from request p to the cell (0 inside). Only requests
       * within reach matter: beyond d = s / (g - 1) a request asks for more
       * than the cell's own size s; candidates come from that x window plus the
       * cell's extent.
       */
      double
      on(const dealii::TriaAccessor<2, 2, 2> &cell) const
      {
        const double size = cell_size(cell);
        const double reach =
          (growth_rate > 1. + 1e-12 ? size / (growth_rate - 1.) :
                                      std::numeric_limits<double>::infinity()) +
          cell.diameter();
        const double x         = cell.center()[0];
        const auto   first     = std::lower_bound(requests.begin(),
                                            requests.end(),
                                            x - reach,
                                            [](const auto &a, const double p) {
                                              return a.position.x < p;
                                            });
        double       requested = std::numeric_limits<double>::infinity();
        for (auto it = first;
             it != requests.end() && it->position.x <= x + reach;
             ++it)
          requested =
            std::min(requested,
                     Geometry::graded_size(*it,
                                           growth_rate,
                                           distance_to_cell({it->position.x,
                                                             it->position.y},
                                                            cell)));
        return requested;
      }
    };
  } // namespace

  std::vector<std::pair<ActiveCell, ActiveCell>>
  facing_joint_cells(const dealii::Triangulation<2> &triangulation,
                     const std::vector<JointSides>  &joints)
  {
    std::vector<std::pair<ActiveCell, ActiveCell>> pairs;
    for (const auto &joint : joints)
      {
        const auto side_a = faces_with_id(triangulation, joint.side_a);
        const auto side_b = faces_with_id(triangulation, joint.side_b);
        if (side_a.empty() || side_b.empty())
          continue;
        // Side B's faces sorted by their position along the joint: a match
        // lies within its tolerance in position too (a projection moves no
        // more than the point), so each search scans a window, not the side.
        const dealii::Tensor<1, 2> along_joint = mean_direction(side_a);
        const dealii::Point<2>     start = shape_of(side_a.front()).centre;
        std::vector<FaceShape>     shapes_b;
        for (const auto &face : side_b)
          shapes_b.push_back(shape_of(face));
        std::vector<std::pair<double, std::size_t>> sorted_b;
        for (std::size_t b = 0; b < side_b.size(); ++b)
          sorted_b.emplace_back((shapes_b[b].centre - start) * along_joint, b);
        std::sort(sorted_b.begin(), sorted_b.end());
        std::vector<bool> taken_b(side_b.size(), false);
        // The untaken side-B face that is (the reflection of) @p centre.
        const auto find_b = [&](const dealii::Point<2> &centre,
                                const double            length,
                                const double            fraction) {
          const double position  = (centre - start) * along_joint;
          const double tolerance = fraction * length;
          for (auto entry =
                 std::lower_bound(sorted_b.begin(),
                                  sorted_b.end(),
                                  std::make_pair(position - tolerance,
                                                 std::size_t(0)));
               entry != sorted_b.end() && entry->first <= position + tolerance;
               ++entry)
            if (!taken_b[entry->second] &&
                same_face(centre, length, shapes_b[entry->second], fraction))
              return std::optional<std::size_t>(entry->second);
          return std::optional<std::size_t>();
        };
        std::vector<BoundaryFace> common_a;
        std::vector<std::size_t>  beyond_a;
        // 1. Coincident faces: the common part of the joint.
        for (std::size_t a = 0; a < side_a.size(); ++a)
          {
            const FaceShape shape = shape_of(side_a[a]);
            if (const auto b =
                  find_b(shape.centre, shape.length, coincident_fraction))
              {
                pairs.emplace_back(side_a[a].cell, side_b[*b].cell);
                taken_b[*b] = true;
                common_a.push_back(side_a[a]);
              }
            else
              beyond_a.push_back(a);
          }
        if (common_a.empty() || beyond_a.empty())
          continue;
        // 2. Beyond it, mirror images across the common part's line: the
        // facing top fillets. Matching their centres in the plane, not
        // their positions along the joint, keeps apart the faces near the
        // top of a fillet, which turns away from the joint and where many
        // faces share nearly one position along it.
        const dealii::Tensor<1, 2> direction = mean_direction(common_a);
        dealii::Tensor<1, 2>       normal;
        normal[0]                     = -direction[1];
        normal[1]                     = direction[0];
        const dealii::Point<2> origin = shape_of(common_a.front()).centre;
        for (const std::size_t a : beyond_a)
          {
            const FaceShape        shape = shape_of(side_a[a]);
            const dealii::Point<2> mirror =
              shape.centre - 2. * ((shape.centre - origin) * normal) * normal;
            if (const auto b = find_b(mirror, shape.length, mirrored_fraction))
              {
                pairs.emplace_back(side_a[a].cell, side_b[*b].cell);
                taken_b[*b] = true;
              }
          }
      }
    return pairs;
  }

  void
  prepare_matched_refinement(dealii::Triangulation<2>      &triangulation,
                             const std::vector<JointSides> &joints)
  {
    const auto pairs = facing_joint_cells(triangulation, joints);
    // Each round either changes nothing or adds a refine flag / removes
    // coarsen flags somewhere; far fewer rounds than cells suffice in
    // practice (two or three), this bound only guards against a bug.
    constexpr unsigned int max_rounds = 100;
    for (unsigned int round = 0; round < max_rounds; ++round)
      {
        const bool mirrored = mirror_flags(pairs);
        const bool smoothed = triangulation.prepare_coarsening_and_refinement();
        if (!mirrored && !smoothed)
          return;
      }
    throw std::logic_error("prepare_matched_refinement: the refinement flags "
                           "of the two sides of the joints did not settle");
  }

  unsigned int
  flag_cells_above_requested_size(
    dealii::Triangulation<2>               &triangulation,
    const std::vector<Geometry::LocalSize> &requests,
    const double                            growth_rate)
  {
    if (requests.empty())
      return 0;
    const SortedRequests sorted(requests, growth_rate);
    unsigned int         n_flagged = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell_size(*cell) > std::sqrt(2.) * sorted.on(*cell))
        {
          flag_for_refinement(cell);
          ++n_flagged;
        }
    return n_flagged;
  }

  unsigned int
  flag_smooth_cells_for_coarsening(
    dealii::Triangulation<2>               &triangulation,
    const dealii::Vector<float>            &indicator,
    const double                            fraction,
    const std::vector<Geometry::LocalSize> &requests,
    const double                            growth_rate)
  {
    if (fraction <= 0.)
      return 0;
    if (indicator.size() != triangulation.n_active_cells())
      throw std::logic_error(
        "flag_smooth_cells_for_coarsening: the indicator "
        "has " +
        std::to_string(indicator.size()) + " entries for " +
        std::to_string(triangulation.n_active_cells()) + " cells");
    const SortedRequests    sorted(requests, growth_rate);
    std::vector<ActiveCell> coarsenable;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->level() > 0 && cell_size(*cell->parent()) <=
                                 std::sqrt(2.) * sorted.on(*cell->parent()))
        coarsenable.push_back(cell);
    const std::size_t n_wanted =
      std::min<std::size_t>(coarsenable.size(),
                            static_cast<std::size_t>(
                              fraction * triangulation.n_active_cells()));
    std::partial_sort(coarsenable.begin(),
                      coarsenable.begin() + n_wanted,
                      coarsenable.end(),
                      [&](const ActiveCell &a, const ActiveCell &b) {
                        return indicator[a->active_cell_index()] <
                               indicator[b->active_cell_index()];
                      });
    for (std::size_t k = 0; k < n_wanted; ++k)
      coarsenable[k]->set_coarsen_flag();
    return n_wanted;
  }

  MatchedRefinementSummary
  refine_matched(dealii::Triangulation<2>               &triangulation,
                 const std::vector<JointSides>          &joints,
                 const std::vector<Geometry::LocalSize> &requests,
                 const double                            growth_rate,
                 const dealii::Vector<float>            &indicator,
                 const double                            coarsen_fraction,
                 const unsigned int                      max_passes)
  {
    MatchedRefinementSummary summary;
    summary.n_cells_before = triangulation.n_active_cells();
    for (unsigned int pass = 0; pass < max_passes; ++pass)
      {
        if (pass == 0)
          summary.n_coarsen_flagged = flag_smooth_cells_for_coarsening(
            triangulation, indicator, coarsen_fraction, requests, growth_rate);
        const unsigned int n_refine =
          flag_cells_above_requested_size(triangulation, requests, growth_rate);
        if (n_refine == 0 && (pass > 0 || summary.n_coarsen_flagged == 0))
          break;
        prepare_matched_refinement(triangulation, joints);
        for (const auto &cell : triangulation.active_cell_iterators())
          summary.n_cells_coarsened += cell->coarsen_flag_set() ? 1 : 0;
        triangulation.execute_coarsening_and_refinement();
        ++summary.n_passes;
      }
    summary.n_cells_after = triangulation.n_active_cells();
    return summary;
  }
} // namespace FloorBlock::Refinement
