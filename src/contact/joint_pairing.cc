#include <common/input_error.h>
#include <contact/joint_pairing.h>
#include <fem/face_values.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>

namespace FloorBlock::Contact
{
  namespace
  {
    /** Coincident nodes lie closer than this fraction of the smallest cell. */
    constexpr double position_tolerance_factor = 1e-6;

    template <int dim>
    struct SideNode
    {
      dealii::Point<dim>                               position;
      double                                           weight = 0.;
      dealii::Tensor<1, dim>                           normal_sum;
      std::array<dealii::types::global_dof_index, dim> dofs;
    };

    /**
     * The side's nodes as every process sees them: a distributed mesh
     * gives each process the faces of its own cells, so a node's weight
     * and normal are the sums of the processes' parts, and the partners
     * across a joint (another body, often another process) are known
     * everywhere. Every process then pairs the whole joint alike. On one
     * process the nodes come back unchanged.
     */
    template <int dim>
    std::map<dealii::types::global_dof_index, SideNode<dim>>
    merge_over_processes(
      const std::map<dealii::types::global_dof_index, SideNode<dim>> &local,
      const MPI_Comm communicator)
    {
      if (dealii::Utilities::MPI::n_mpi_processes(communicator) == 1)
        return local;
      // Flat records: dofs, position, weight, normal sum (2 dim + 1 + dim).
      std::vector<double> packed;
      for (const auto &[dof, node] : local)
        {
          for (unsigned int c = 0; c < dim; ++c)
            packed.push_back(static_cast<double>(node.dofs[c]));
          for (unsigned int c = 0; c < dim; ++c)
            packed.push_back(node.position[c]);
          packed.push_back(node.weight);
          for (unsigned int c = 0; c < dim; ++c)
            packed.push_back(node.normal_sum[c]);
        }
      const unsigned int record = 3 * dim + 1;
      std::map<dealii::types::global_dof_index, SideNode<dim>> merged;
      for (const auto &part :
           dealii::Utilities::MPI::all_gather(communicator, packed))
        for (std::size_t r = 0; r + record <= part.size(); r += record)
          {
            const double *const values = part.data() + r;
            SideNode<dim>      &node =
              merged[static_cast<dealii::types::global_dof_index>(values[0])];
            for (unsigned int c = 0; c < dim; ++c)
              {
                node.dofs[c] =
                  static_cast<dealii::types::global_dof_index>(values[c]);
                node.position[c] = values[dim + c];
                node.normal_sum[c] += values[2 * dim + 1 + c];
              }
            node.weight += values[2 * dim];
          }
      return merged;
    }

    /** All nodes of one boundary id, keyed by their x-component DoF. */
    template <int dim>
    std::vector<SideNode<dim>>
    collect_side(const Fem::FeSpace<dim>         &space,
                 const dealii::types::boundary_id side)
    {
      using namespace dealii;
      const FiniteElement<dim> &fe          = space.fe();
      FEFaceValues<dim>         face_values = Fem::boundary_face_values(space);
      const unsigned int        n_cell_dofs = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index>             dof_indices(n_cell_dofs);
      std::map<types::global_dof_index, SideNode<dim>> nodes;
      for (const auto &cell : space.dof_handler().active_cell_iterators())
        for (const unsigned int face_no : cell->face_indices())
          {
            const auto face = cell->face(face_no);
            if (!cell->is_locally_owned())
              continue;
            if (!face->at_boundary() || face->boundary_id() != side)
              continue;
            face_values.reinit(cell, face_no);
            cell->get_dof_indices(dof_indices);
            for (unsigned int i = 0; i < n_cell_dofs; ++i)
              {
                if (fe.system_to_component_index(i).first != 0 ||
                    !fe.has_support_on_face(i, face_no))
                  continue;
                SideNode<dim> &node = nodes[dof_indices[i]];
                // FESystem of dim equal FE_Q: the components of one node
                // are consecutive cell DoFs.
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    Assert(fe.system_to_component_index(i + c).first == c,
                           ExcInternalError());
                    node.dofs[c] = dof_indices[i + c];
                  }
                node.position = space.mapping().transform_unit_to_real_cell(
                  cell, fe.unit_support_point(i));
                for (const unsigned int q :
                     face_values.quadrature_point_indices())
                  {
                    const double integral =
                      face_values.shape_value(i, q) * face_values.JxW(q);
                    node.weight += integral;
                    node.normal_sum += integral * face_values.normal_vector(q);
                  }
              }
          }
      nodes =
        merge_over_processes(nodes, space.dof_handler().get_communicator());
      if (nodes.empty())
        throw InputError("joint side with boundary id " + std::to_string(side) +
                         " has no faces in the mesh");
      std::vector<SideNode<dim>> result;
      for (const auto &entry : nodes)
        result.push_back(entry.second);
      return result;
    }

    template <int dim>
    ContactNode<dim>
    make_contact_node(const SideNode<dim> &node, const unsigned int joint)
    {
      ContactNode<dim> contact;
      contact.joint    = joint;
      contact.position = node.position;
      contact.weight   = node.weight;
      contact.normal   = node.normal_sum / node.normal_sum.norm();
      contact.dofs_a   = node.dofs;
      contact.dofs_b.fill(dealii::numbers::invalid_dof_index);
      return contact;
    }

    template <int dim>
    std::string
    describe(const dealii::Point<dim> &point)
    {
      std::ostringstream text;
      text << "(" << point << ")";
      return text.str();
    }
  } // namespace

  namespace
  {
    /**
     * In-plane (x, y) part of a position or direction: the 2D joint line
     * of a 3D joint swept along z (Geometry::extrude_assembly).
     */
    template <int dim>
    dealii::Tensor<1, 2>
    in_plane(const dealii::Tensor<1, dim> &vector)
    {
      if constexpr (dim == 2)
        return vector;
      else
        return dealii::Tensor<1, 2>({vector[0], vector[1]});
    }

    /** A 2D direction as a dim vector (z = 0 in 3D). */
    template <int dim>
    dealii::Tensor<1, dim>
    from_plane(const dealii::Tensor<1, 2> &vector)
    {
      if constexpr (dim == 2)
        return vector;
      else
        return dealii::Tensor<1, dim>({vector[0], vector[1], 0.});
    }

    /**
     * Straight line through the common part of a joint, in the x-y plane
     * (2D; in 3D the line every cross-section of the swept joint shares).
     */
    struct JointLine
    {
      dealii::Point<2>     origin;
      dealii::Tensor<1, 2> tangent;
      /** Unit normal out of side A. */
      dealii::Tensor<1, 2> normal;
      /** Extent of the common part along the tangent (m). */
      double low  = 0.;
      double high = 0.;
    };

    /**
     * Chord of the coincident side-A nodes: its two farthest-apart nodes
     * (for a straight joint exactly its line). The normal is oriented like
     * side A's summed face normals.
     */
    template <int dim>
    JointLine
    joint_line(const std::vector<SideNode<dim>> &common)
    {
      const auto farthest_from = [&](const dealii::Point<2> &from) {
        dealii::Point<2> far = from;
        for (const auto &node : common)
          {
            const dealii::Point<2> position(in_plane(node.position));
            if (position.distance(from) > far.distance(from))
              far = position;
          }
        return far;
      };
      JointLine              line;
      const dealii::Point<2> first =
        farthest_from(dealii::Point<2>(in_plane(common.front().position)));
      const dealii::Point<2> last = farthest_from(first);
      dealii::Tensor<1, 2>   normal_sum;
      for (const auto &node : common)
        normal_sum += in_plane(node.normal_sum);
      line.origin = first;
      if (first.distance(last) > 0.)
        {
          line.tangent   = (last - first) / first.distance(last);
          line.normal[0] = line.tangent[1];
          line.normal[1] = -line.tangent[0];
          if (line.normal * normal_sum < 0.)
            line.normal *= -1.;
        }
      else
        {
          // One common node: its own normal is the best estimate.
          line.normal     = normal_sum / normal_sum.norm();
          line.tangent[0] = -line.normal[1];
          line.tangent[1] = line.normal[0];
        }
      line.high = (last - first) * line.tangent;
      return line;
    }

    /** Unpaired nodes of one side beyond the two ends of the common part. */
    template <int dim>
    struct EndNodes
    {
      std::vector<const SideNode<dim> *> low;
      std::vector<const SideNode<dim> *> high;
    };

    /**
     * Sorts the unpaired nodes @p nodes of a side (of one cross-section in
     * 3D) to the two ends of the common part, nearest first; a node on the
     * common part itself has no place here: the meshes do not match.
     */
    template <int dim>
    EndNodes<dim>
    split_by_end(const std::vector<const SideNode<dim> *> &nodes,
                 const JointLine                          &line,
                 const double                              tolerance,
                 const std::string                        &joint_name)
    {
      EndNodes<dim> ends;
      const auto    along = [&](const SideNode<dim> *node) {
        return (dealii::Point<2>(in_plane(node->position)) - line.origin) *
               line.tangent;
      };
      for (const SideNode<dim> *node : nodes)
        {
          const double position = along(node);
          if (position < line.low - tolerance)
            ends.low.push_back(node);
          else if (position > line.high + tolerance)
            ends.high.push_back(node);
          else
            throw InputError(joint_name + ": node at " +
                             describe(node->position) +
                             " has no coincident partner");
        }
      std::sort(ends.low.begin(), ends.low.end(), [&](auto a, auto b) {
        return along(a) > along(b);
      });
      std::sort(ends.high.begin(), ends.high.end(), [&](auto a, auto b) {
        return along(a) < along(b);
      });
      return ends;
    }

    /**
     * Pairs the nodes beyond one end if the two sides are mirror images
     * there: equal numbers of nodes, and the k-th of side B on the normal
     * line of the k-th of side A (in 3D in the same cross-section), not
     * behind it. Otherwise no pair.
     */
    template <int dim>
    std::vector<ContactNode<dim>>
    mirror_pairs(const std::vector<const SideNode<dim> *> &nodes_a,
                 const std::vector<const SideNode<dim> *> &nodes_b,
                 const JointLine                          &line,
                 const double                              tolerance,
                 const unsigned int                        joint)
    {
      if (nodes_a.empty() || nodes_a.size() != nodes_b.size())
        return {};
      std::vector<ContactNode<dim>> pairs;
      for (unsigned int k = 0; k < nodes_a.size(); ++k)
        {
          const dealii::Tensor<1, dim> offset =
            nodes_b[k]->position - nodes_a[k]->position;
          const double gap = in_plane(offset) * line.normal;
          if (std::abs(in_plane(offset) * line.tangent) > tolerance ||
              gap < -tolerance)
            return {};
          if constexpr (dim == 3)
            if (std::abs(offset[2]) > tolerance)
              return {};
          ContactNode<dim> pair = make_contact_node(*nodes_a[k], joint);
          pair.normal           = from_plane<dim>(line.normal);
          pair.weight =
            std::max(0., in_plane(nodes_a[k]->normal_sum) * line.normal);
          pair.initial_gap = std::max(0., gap);
          pair.dofs_b      = nodes_b[k]->dofs;
          pairs.push_back(pair);
        }
      return pairs;
    }

    /**
     * The unpaired nodes of a side grouped by cross-section: one group in
     * 2D, one per z (to @p tolerance) in 3D, where the swept mesh repeats
     * the 2D joint's nodes at every slice position.
     */
    template <int dim>
    std::vector<std::vector<const SideNode<dim> *>>
    unpaired_by_section(const std::vector<SideNode<dim>> &nodes,
                        const std::vector<bool>          &taken,
                        const double                      tolerance)
    {
      std::vector<const SideNode<dim> *> unpaired;
      for (unsigned int k = 0; k < nodes.size(); ++k)
        if (!taken[k])
          unpaired.push_back(&nodes[k]);
      if constexpr (dim == 2)
        return {unpaired};
      else
        {
          std::sort(unpaired.begin(), unpaired.end(), [](auto a, auto b) {
            return a->position[2] < b->position[2];
          });
          std::vector<std::vector<const SideNode<dim> *>> sections;
          for (const SideNode<dim> *node : unpaired)
            {
              if (sections.empty() ||
                  node->position[2] - sections.back().front()->position[2] >
                    tolerance)
                sections.emplace_back();
              sections.back().push_back(node);
            }
          return sections;
        }
    }

    /**
     * The nodes of both sides that have no coincident partner, paired
     * where they mirror each other; in 3D cross-section by cross-section
     * (a side-A section without side-B nodes at its z leaves its nodes
     * free).
     */
    template <int dim>
    std::vector<ContactNode<dim>>
    pair_beyond_common_part(const std::vector<SideNode<dim>> &nodes_a,
                            const std::vector<bool>          &taken_a,
                            const std::vector<SideNode<dim>> &nodes_b,
                            const std::vector<bool>          &taken_b,
                            const double                      tolerance,
                            const std::string                &joint_name,
                            const unsigned int                joint,
                            PairingSummary                   &summary)
    {
      std::vector<SideNode<dim>> common;
      for (unsigned int k = 0; k < nodes_a.size(); ++k)
        if (taken_a[k])
          common.push_back(nodes_a[k]);
      const JointLine line  = joint_line(common);
      const auto sections_a = unpaired_by_section(nodes_a, taken_a, tolerance);
      const auto sections_b = unpaired_by_section(nodes_b, taken_b, tolerance);
      const auto section_z  = [](const auto &section) {
        if constexpr (dim == 2)
          return 0.;
        else
          return section.front()->position[2];
      };
      std::vector<ContactNode<dim>> pairs;
      std::vector<bool>             b_section_used(sections_b.size(), false);
      for (const auto &section_a : sections_a)
        {
          // The side-B nodes of the same cross-section, if any.
          static const std::vector<const SideNode<dim> *> none;
          const std::vector<const SideNode<dim> *>       *section_b = &none;
          for (unsigned int s = 0; s < sections_b.size(); ++s)
            if (std::abs(section_z(sections_b[s]) - section_z(section_a)) <=
                tolerance)
              {
                section_b         = &sections_b[s];
                b_section_used[s] = true;
              }
          const EndNodes<dim> ends_a =
            split_by_end(section_a, line, tolerance, joint_name);
          const EndNodes<dim> ends_b =
            split_by_end(*section_b, line, tolerance, joint_name);
          for (const auto &[end_a, end_b] :
               {std::make_pair(&ends_a.low, &ends_b.low),
                std::make_pair(&ends_a.high, &ends_b.high)})
            {
              const std::vector<ContactNode<dim>> mirrored =
                mirror_pairs(*end_a, *end_b, line, tolerance, joint);
              pairs.insert(pairs.end(), mirrored.begin(), mirrored.end());
              summary.n_mirrored += mirrored.size();
              if (mirrored.empty())
                {
                  summary.n_free_a += end_a->size();
                  summary.n_free_b += end_b->size();
                }
            }
        }
      // Side-B sections without side-A nodes: free, unless they lie on
      // the common part (non-matching meshes).
      for (unsigned int s = 0; s < sections_b.size(); ++s)
        if (!b_section_used[s])
          {
            const EndNodes<dim> ends_b =
              split_by_end(sections_b[s], line, tolerance, joint_name);
            summary.n_free_b += ends_b.low.size() + ends_b.high.size();
          }
      return pairs;
    }
  } // namespace

  template <int dim>
  std::vector<ContactNode<dim>>
  pair_joint_nodes(const Fem::FeSpace<dim>         &space,
                   const dealii::types::boundary_id side_a,
                   const dealii::types::boundary_id side_b,
                   const unsigned int               joint_index,
                   PairingSummary                  *summary)
  {
    const std::vector<SideNode<dim>> nodes_a = collect_side(space, side_a);
    const std::vector<SideNode<dim>> nodes_b = collect_side(space, side_b);
    const std::string                joint_name =
      "joint " + std::to_string(side_a) + "/" + std::to_string(side_b);
    const double tolerance =
      position_tolerance_factor * space.minimal_cell_diameter();
    std::vector<ContactNode<dim>> pairs;
    std::vector<bool>             taken_a(nodes_a.size(), false);
    std::vector<bool>             taken_b(nodes_b.size(), false);
    for (unsigned int a = 0; a < nodes_a.size(); ++a)
      for (unsigned int b = 0; b < nodes_b.size() && !taken_a[a]; ++b)
        if (!taken_b[b] &&
            nodes_a[a].position.distance(nodes_b[b].position) < tolerance)
          {
            ContactNode<dim> pair = make_contact_node(nodes_a[a], joint_index);
            pair.dofs_b           = nodes_b[b].dofs;
            pairs.push_back(pair);
            taken_a[a] = true;
            taken_b[b] = true;
          }
    PairingSummary counts;
    counts.n_coincident = pairs.size();
    if (pairs.empty())
      throw InputError(joint_name + ": node at " +
                       describe(nodes_a.front().position) +
                       " has no coincident partner (the meshes of the two "
                       "sides do not match)");
    const std::vector<ContactNode<dim>> beyond =
      pair_beyond_common_part(nodes_a,
                              taken_a,
                              nodes_b,
                              taken_b,
                              tolerance,
                              joint_name,
                              joint_index,
                              counts);
    pairs.insert(pairs.end(), beyond.begin(), beyond.end());
    if (summary != nullptr)
      *summary = counts;
    return pairs;
  }

  template <int dim>
  std::vector<ContactNode<dim>>
  pair_nodes_with_plane(const Fem::FeSpace<dim>         &space,
                        const dealii::types::boundary_id side,
                        const dealii::Point<dim>        &plane_point,
                        const dealii::Tensor<1, dim>    &plane_normal,
                        const double                     curvature,
                        const unsigned int               joint_index)
  {
    std::vector<ContactNode<dim>> pairs;
    for (const auto &node : collect_side(space, side))
      {
        ContactNode<dim> pair = make_contact_node(node, joint_index);
        pair.normal           = plane_normal / plane_normal.norm();
        const dealii::Tensor<1, dim> offset = node.position - plane_point;
        const double                 normal_offset = offset * pair.normal;
        // s^2 = |x - p0|^2 - ((x - p0) . n)^2 in any dimension.
        const double along_squared =
          std::max(0., offset.norm_square() - normal_offset * normal_offset);
        pair.initial_gap = -normal_offset + 0.5 * curvature * along_squared;
        pairs.push_back(pair);
      }
    return pairs;
  }

  template std::vector<ContactNode<2>>
  pair_joint_nodes(const Fem::FeSpace<2> &,
                   const dealii::types::boundary_id,
                   const dealii::types::boundary_id,
                   const unsigned int,
                   PairingSummary *);
  template std::vector<ContactNode<2>>
  pair_nodes_with_plane(const Fem::FeSpace<2> &,
                        const dealii::types::boundary_id,
                        const dealii::Point<2> &,
                        const dealii::Tensor<1, 2> &,
                        const double,
                        const unsigned int);
  // 3D: the joint swept along z (Geometry::extrude_assembly), its
  // fillets mirrored cross-section by cross-section.
  template std::vector<ContactNode<3>>
  pair_joint_nodes(const Fem::FeSpace<3> &,
                   const dealii::types::boundary_id,
                   const dealii::types::boundary_id,
                   const unsigned int,
                   PairingSummary *);
  template std::vector<ContactNode<3>>
  pair_nodes_with_plane(const Fem::FeSpace<3> &,
                        const dealii::types::boundary_id,
                        const dealii::Point<3> &,
                        const dealii::Tensor<1, 3> &,
                        const double,
                        const unsigned int);
} // namespace FloorBlock::Contact
