#include <common/input_error.h>
#include <contact/joint_pairing.h>

#include <deal.II/fe/fe_values.h>

#include <map>
#include <sstream>
#include <string>

namespace FloorBlock
{
  namespace Contact
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

      /** All nodes of one boundary id, keyed by their x-component DoF. */
      template <int dim>
      std::vector<SideNode<dim>>
      collect_side(const Fem::FeSpace<dim>         &space,
                   const dealii::types::boundary_id side)
      {
        using namespace dealii;
        const FiniteElement<dim> &fe = space.fe();
        FEFaceValues<dim> face_values(space.mapping(),
                                      fe,
                                      space.face_quadrature(),
                                      update_values | update_normal_vectors |
                                        update_JxW_values);
        const unsigned int n_cell_dofs = fe.n_dofs_per_cell();
        std::vector<types::global_dof_index> dof_indices(n_cell_dofs);
        std::map<types::global_dof_index, SideNode<dim>> nodes;
        for (const auto &cell : space.dof_handler().active_cell_iterators())
          for (const unsigned int face_no : cell->face_indices())
            {
              const auto face = cell->face(face_no);
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
        if (nodes.empty())
          throw InputError("joint side with boundary id " +
                           std::to_string(side) + " has no faces in the mesh");
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

    template <int dim>
    std::vector<ContactNode<dim>>
    pair_joint_nodes(const Fem::FeSpace<dim>         &space,
                     const dealii::types::boundary_id side_a,
                     const dealii::types::boundary_id side_b,
                     const unsigned int               joint_index)
    {
      const std::vector<SideNode<dim>> nodes_a = collect_side(space, side_a);
      const std::vector<SideNode<dim>> nodes_b = collect_side(space, side_b);
      if (nodes_a.size() != nodes_b.size())
        throw InputError("joint " + std::to_string(side_a) + "/" +
                         std::to_string(side_b) + " has " +
                         std::to_string(nodes_a.size()) + " and " +
                         std::to_string(nodes_b.size()) +
                         " nodes on its sides: the meshes do not match");
      const double tolerance =
        position_tolerance_factor * space.minimal_cell_diameter();
      std::vector<ContactNode<dim>> pairs;
      std::vector<bool>             taken(nodes_b.size(), false);
      for (const auto &node : nodes_a)
        {
          bool found = false;
          for (unsigned int b = 0; b < nodes_b.size() && !found; ++b)
            if (!taken[b] &&
                node.position.distance(nodes_b[b].position) < tolerance)
              {
                ContactNode<dim> pair = make_contact_node(node, joint_index);
                pair.dofs_b           = nodes_b[b].dofs;
                pairs.push_back(pair);
                taken[b] = true;
                found    = true;
              }
          if (!found)
            throw InputError("joint " + std::to_string(side_a) + "/" +
                             std::to_string(side_b) + ": node at " +
                             describe(node.position) +
                             " has no coincident partner");
        }
      return pairs;
    }

    template <int dim>
    std::vector<ContactNode<dim>>
    pair_nodes_with_plane(const Fem::FeSpace<dim>         &space,
                          const dealii::types::boundary_id side,
                          const dealii::Point<dim>        &plane_point,
                          const dealii::Tensor<1, dim>    &plane_normal,
                          const unsigned int               joint_index)
    {
      std::vector<ContactNode<dim>> pairs;
      for (const auto &node : collect_side(space, side))
        {
          ContactNode<dim> pair = make_contact_node(node, joint_index);
          pair.normal           = plane_normal / plane_normal.norm();
          pair.initial_gap      = (plane_point - node.position) * pair.normal;
          pairs.push_back(pair);
        }
      return pairs;
    }

    template std::vector<ContactNode<2>>
    pair_joint_nodes(const Fem::FeSpace<2> &,
                     const dealii::types::boundary_id,
                     const dealii::types::boundary_id,
                     const unsigned int);
    template std::vector<ContactNode<2>>
    pair_nodes_with_plane(const Fem::FeSpace<2> &,
                          const dealii::types::boundary_id,
                          const dealii::Point<2> &,
                          const dealii::Tensor<1, 2> &,
                          const unsigned int);
  } // namespace Contact
} // namespace FloorBlock
