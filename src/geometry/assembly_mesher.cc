#include <common/atomic_file.h>
#include <geometry/assembly_mesher.h>
#include <geometry/body_outline.h>
#include <geometry/gmsh_geometry.h>
#include <geometry/gmsh_scope.h>

#include <gmsh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>

namespace FloorBlock::Geometry
{
  namespace
  {
    namespace mesh = gmsh::model::mesh;

    /**
     * Spacing of the non-matching side, relative to the corner size:
     * uniform, so coarser than the graded master side at the corners and
     * finer far from them; the two sides then genuinely differ.
     */
    constexpr double non_matching_spacing_ratio = 1.5;

    /** Gmsh element type number of a 4-node quadrilateral. */
    constexpr int gmsh_quadrangle = 3;

    /** Gmsh 2D algorithm 6: Frontal-Delaunay (8 crashes in 4.8 with a
     * background field). */
    constexpr int frontal_delaunay = 6;
    /** Blossom recombination followed by subdivision: quads only. */
    constexpr int blossom_full_quad = 3;

    const std::vector<double> identity_transform =
      {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

    void
    set_size_field(const AssemblyOutline        &outline,
                   const AssemblyDescription    &description,
                   const std::vector<LocalSize> &local_sizes)
    {
      // Refinement points become Gmsh points only for the field: they are
      // not part of any surface and carry no physical group.
      std::vector<double> point_tags;
      for (const Point2 &point : outline.refinement_points)
        point_tags.push_back(gmsh::model::occ::addPoint(point.x, point.y, 0.0));
      gmsh::model::occ::synchronize();

      const int distance = mesh::field::add("Distance");
      mesh::field::setNumbers(distance, "NodesList", point_tags);
      const int          size = mesh::field::add("MathEval");
      std::ostringstream formula;
      formula.precision(17);
      formula << "min(" << description.mesh_far_size << ", "
              << description.mesh_corner_size << " + "
              << description.mesh_growth_rate - 1.0 << " * F" << distance
              << ")";
      mesh::field::setString(size, "F", formula.str());
      const int local      = add_local_size_field(local_sizes,
                                             description.mesh_growth_rate,
                                             description.mesh_far_size);
      int       background = size;
      if (local >= 0)
        {
          background = mesh::field::add("Min");
          mesh::field::setNumbers(background,
                                  "FieldsList",
                                  {double(size), double(local)});
        }
      mesh::field::setAsBackgroundMesh(background);

      gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
      gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
      gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
      gmsh::option::setNumber("Mesh.Algorithm", frontal_delaunay);
      gmsh::option::setNumber("Mesh.RecombinationAlgorithm", blossom_full_quad);
      gmsh::option::setNumber("Mesh.RecombineAll", 1);
    }

    unsigned int
    constrain_joint_sides(const AssemblyOutline     &outline,
                          const GmshAssembly        &assembly,
                          const AssemblyDescription &description)
    {
      unsigned int n_matched = 0;
      for (const JointPair &pair : outline.joint_pairs)
        {
          const int master =
            assembly.curve_tags[pair.master.body][pair.master.segment];
          const int slave =
            assembly.curve_tags[pair.slave.body][pair.slave.segment];
          if (description.matching_joints)
            {
              mesh::setPeriodic(1, {slave}, {master}, identity_transform);
              ++n_matched;
            }
          else
            {
              const Segment &segment =
                outline.bodies[pair.slave.body].segments[pair.slave.segment];
              const double chord = std::hypot(segment.end.x - segment.start.x,
                                              segment.end.y - segment.start.y);
              // Blossom full-quad recombination halves every 1D mesh, so
              // the number of intervals must be even.
              const int half_intervals =
                std::max(1,
                         static_cast<int>(
                           std::ceil(chord / (2.0 * non_matching_spacing_ratio *
                                              description.mesh_corner_size))));
              const int n_intervals = 2 * half_intervals;
              mesh::setTransfiniteCurve(slave, n_intervals + 1);
            }
        }
      return n_matched;
    }

    /**
     * Fewest cell edges on a fillet arc: 4, so that every fillet has a node
     * at its middle and is resolved however coarse the corner size.
     */
    constexpr int min_fillet_intervals = 4;

    /**
     * Fixed node counts on the fillet arcs: uniform in angle (OCC circles
     * are parametrised by angle) with about the corner size as the final
     * spacing. The two top fillets across a vertical joint get the count of
     * the master, so where they are mirror images (level floor) their nodes
     * are mirror images too -- at identical heights, which is what the
     * contact pairing needs to put a fillet node against its partner across
     * the joint (Contact::pair_joint_nodes).
     */
    void
    mesh_fillets(const AssemblyOutline        &outline,
                 const GmshAssembly           &assembly,
                 const AssemblyDescription    &description,
                 const std::vector<LocalSize> &local_sizes)
    {
      const auto n_nodes = [&](const SegmentRef &ref) {
        const Segment &arc    = outline.bodies[ref.body].segments[ref.segment];
        const double   growth = description.mesh_growth_rate;
        const double   spacing =
          std::min({description.mesh_corner_size,
                    local_size_at(local_sizes, growth, arc.start),
                    local_size_at(local_sizes, growth, arc.end)});
        // Blossom full-quad recombination meshes half the intervals and
        // halves them, so the number of intervals must be even.
        const int half_intervals =
          std::max(min_fillet_intervals / 2,
                   static_cast<int>(
                     std::ceil(arc_length(arc) / (2.0 * spacing))));
        return 2 * half_intervals + 1;
      };
      for (unsigned int body = 0; body < outline.bodies.size(); ++body)
        for (unsigned int segment = 0;
             segment < outline.bodies[body].segments.size();
             ++segment)
          if (outline.bodies[body].segments[segment].kind == SegmentKind::arc)
            mesh::setTransfiniteCurve(assembly.curve_tags[body][segment],
                                      n_nodes({body, segment}));
      for (const FilletPair &pair : outline.fillet_pairs)
        mesh::setTransfiniteCurve(
          assembly.curve_tags[pair.slave.body][pair.slave.segment],
          n_nodes(pair.master));
    }

    /** Count quads and their distinct nodes; refuse any other cell type. */
    void
    count_cells_and_nodes(MeshStatistics &statistics)
    {
      std::vector<int>                      types;
      std::vector<std::vector<std::size_t>> element_tags;
      std::vector<std::vector<std::size_t>> node_tags;
      mesh::getElements(types, element_tags, node_tags, 2);
      std::set<std::size_t> nodes;
      statistics.n_cells = 0;
      for (unsigned int kind = 0; kind < types.size(); ++kind)
        {
          if (types[kind] != gmsh_quadrangle && !element_tags[kind].empty())
            throw std::runtime_error("Gmsh left " +
                                     std::to_string(element_tags[kind].size()) +
                                     " non-quadrilateral cells (element type " +
                                     std::to_string(types[kind]) + ")");
          statistics.n_cells += element_tags[kind].size();
          nodes.insert(node_tags[kind].begin(), node_tags[kind].end());
        }
      statistics.n_nodes = nodes.size();
    }
  } // namespace

  MeshStatistics
  write_gmsh_mesh(const AssemblyDescription    &description,
                  const std::string            &msh_path,
                  const std::vector<LocalSize> &local_sizes)
  {
    validate(description);
    validate_local_sizes(local_sizes, description);
    const auto start = std::chrono::steady_clock::now();

    const AssemblyOutline outline = build_outline(description);
    MeshStatistics        statistics;
    // Gmsh reports some failures by throwing a plain std::string.
    try
      {
        GmshScope gmsh_scope;
        gmsh::model::add("floorblock_assembly");
        const GmshAssembly assembly = build_gmsh_geometry(outline);
        set_size_field(outline, description, local_sizes);
        statistics.n_matched_pairs =
          constrain_joint_sides(outline, assembly, description);
        mesh_fillets(outline, assembly, description, local_sizes);
        mesh::generate(2);
        count_cells_and_nodes(statistics);
        statistics.n_bodies = outline.bodies.size();
        gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
        // Gmsh picks the format from the extension, so the temporary name
        // keeps ".msh"; the rename makes the file appear complete or not at
        // all.
        const std::string temporary = temporary_name_for(msh_path) + ".msh";
        gmsh::write(temporary);
        if (!std::filesystem::exists(temporary))
          throw std::runtime_error("Gmsh could not write " + temporary);
        commit_temporary_file(temporary, msh_path);
      }
    catch (const std::string &message)
      {
        throw std::runtime_error("Gmsh failed to mesh the assembly: " +
                                 message);
      }
    statistics.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    return statistics;
  }

  std::vector<double>
  cad_body_areas(const AssemblyDescription &description)
  {
    validate(description);
    const AssemblyOutline outline = build_outline(description);
    GmshScope             gmsh_scope;
    gmsh::model::add("floorblock_areas");
    const GmshAssembly  assembly = build_gmsh_geometry(outline);
    std::vector<double> areas;
    for (const int surface : assembly.surface_tags)
      {
        double area = 0.0;
        gmsh::model::occ::getMass(2, surface, area);
        areas.push_back(area);
      }
    return areas;
  }
} // namespace FloorBlock::Geometry
