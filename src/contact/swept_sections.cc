#include <contact/swept_sections.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <limits>

namespace FloorBlock::Contact
{
  namespace
  {
    /**
     * Slice positions closer than this fraction of the face length are
     * one section: the swept mesh copies the slice coordinates into every
     * node, so only round-off separates a section's nodes.
     */
    constexpr double same_section_tolerance = 1e-9;

    /** deal.II's faces of a hexahedron normal to z: 4 (z-) and 5 (z+). */
    constexpr unsigned int bottom_face_of_hexahedron = 4;
  } // namespace

  template <int dim>
  double
  face_length_of(const dealii::Triangulation<dim> &triangulation)
  {
    if constexpr (dim == 2)
      {
        (void)triangulation;
        return 1.;
      }
    else
      {
        // Over the locally owned cells and then all processes: a
        // distributed mesh holds only part of the face here.
        double low  = std::numeric_limits<double>::infinity();
        double high = -std::numeric_limits<double>::infinity();
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              {
                low  = std::min(low, cell->vertex(v)[dim - 1]);
                high = std::max(high, cell->vertex(v)[dim - 1]);
              }
        const MPI_Comm communicator = triangulation.get_communicator();
        return dealii::Utilities::MPI::max(high, communicator) -
               dealii::Utilities::MPI::min(low, communicator);
      }
  }

  template <int dim>
  double
  smallest_in_plane_cell(const dealii::Triangulation<dim> &triangulation)
  {
    double smallest = std::numeric_limits<double>::infinity();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if constexpr (dim == 2)
            smallest = std::min(smallest, cell->diameter());
          else
            smallest =
              std::min(smallest,
                       cell->face(bottom_face_of_hexahedron)->diameter());
        }
    return dealii::Utilities::MPI::min(smallest,
                                       triangulation.get_communicator());
  }

  std::vector<std::vector<unsigned int>>
  sections_along_face(const std::vector<ContactNode<3>> &nodes,
                      std::vector<unsigned int>          members,
                      const double                       face_length)
  {
    std::sort(members.begin(),
              members.end(),
              [&](const unsigned int a, const unsigned int b) {
                return nodes[a].position[2] < nodes[b].position[2];
              });
    std::vector<std::vector<unsigned int>> sections;
    double section_z = -std::numeric_limits<double>::infinity();
    for (const unsigned int p : members)
      {
        const double z = nodes[p].position[2];
        if (z - section_z > same_section_tolerance * face_length)
          {
            sections.emplace_back();
            section_z = z;
          }
        sections.back().push_back(p);
      }
    return sections;
  }

  std::vector<double>
  section_lengths(const std::vector<ContactNode<3>>            &nodes,
                  const std::vector<std::vector<unsigned int>> &sections,
                  const double                                  face_length)
  {
    std::vector<double> weights;
    double              joint_weight = 0.;
    for (const auto &section : sections)
      {
        double weight = 0.;
        for (const unsigned int p : section)
          weight += nodes[p].weight;
        weights.push_back(weight);
        joint_weight += weight;
      }
    std::vector<double> lengths;
    for (const double weight : weights)
      lengths.push_back(
        joint_weight > 0. ? face_length * weight / joint_weight : 0.);
    return lengths;
  }

  template <int dim>
  std::vector<double>
  weights_along_joint(const std::vector<ContactNode<dim>> &nodes,
                      const unsigned int                   n_joints,
                      const double                         face_length)
  {
    std::vector<double> weights;
    for (const auto &node : nodes)
      weights.push_back(node.weight);
    if constexpr (dim == 3)
      {
        std::vector<std::vector<unsigned int>> members(n_joints);
        for (unsigned int p = 0; p < nodes.size(); ++p)
          members[nodes[p].joint].push_back(p);
        for (const auto &joint : members)
          {
            const auto sections =
              sections_along_face(nodes, joint, face_length);
            const auto lengths = section_lengths(nodes, sections, face_length);
            for (unsigned int k = 0; k < sections.size(); ++k)
              for (const unsigned int p : sections[k])
                weights[p] =
                  lengths[k] > 0. ? nodes[p].weight / lengths[k] : 0.;
          }
      }
    else
      {
        (void)n_joints;
        (void)face_length;
      }
    return weights;
  }

  template double
  face_length_of(const dealii::Triangulation<2> &);
  template double
  face_length_of(const dealii::Triangulation<3> &);
  template double
  smallest_in_plane_cell(const dealii::Triangulation<2> &);
  template double
  smallest_in_plane_cell(const dealii::Triangulation<3> &);
  template std::vector<double>
  weights_along_joint(const std::vector<ContactNode<2>> &,
                      const unsigned int,
                      const double);
  template std::vector<double>
  weights_along_joint(const std::vector<ContactNode<3>> &,
                      const unsigned int,
                      const double);
} // namespace FloorBlock::Contact
