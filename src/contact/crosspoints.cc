#include <contact/crosspoints.h>

#include <limits>
#include <map>

namespace FloorBlock::Contact
{
  namespace
  {
    /** The mesh nodes of a pair, named by their first DoF. */
    template <int dim>
    std::vector<dealii::types::global_dof_index>
    node_keys(const ContactNode<dim> &node)
    {
      std::vector<dealii::types::global_dof_index> keys{node.dofs_a[0]};
      if (!node.against_rigid_obstacle())
        keys.push_back(node.dofs_b[0]);
      return keys;
    }
  } // namespace

  template <int dim>
  unsigned int
  remove_crosspoint_pairs(std::vector<ContactNode<dim>> &nodes,
                          const std::vector<bool>       &is_exact)
  {
    // The latest exact joint each mesh node is paired on.
    std::map<dealii::types::global_dof_index, unsigned int> latest_joint;
    for (const auto &node : nodes)
      if (is_exact[node.joint])
        for (const auto key : node_keys(node))
          {
            auto [entry, added] = latest_joint.emplace(key, node.joint);
            if (!added && entry->second < node.joint)
              entry->second = node.joint;
          }

    std::vector<bool> removed(nodes.size(), false);
    unsigned int      n_removed = 0;
    for (unsigned int p = 0; p < nodes.size(); ++p)
      if (is_exact[nodes[p].joint])
        for (const auto key : node_keys(nodes[p]))
          if (latest_joint.at(key) > nodes[p].joint && !removed[p])
            {
              removed[p] = true;
              ++n_removed;
            }

    // Each removed pair's weight goes to the nearest kept pair of its
    // joint, so that the joint's weights still integrate its length.
    for (unsigned int p = 0; p < nodes.size(); ++p)
      if (removed[p])
        {
          unsigned int nearest  = nodes.size();
          double       distance = std::numeric_limits<double>::infinity();
          for (unsigned int q = 0; q < nodes.size(); ++q)
            if (!removed[q] && nodes[q].joint == nodes[p].joint &&
                nodes[q].position.distance(nodes[p].position) < distance)
              {
                nearest  = q;
                distance = nodes[q].position.distance(nodes[p].position);
              }
          if (nearest < nodes.size())
            nodes[nearest].weight += nodes[p].weight;
        }

    std::vector<ContactNode<dim>> kept;
    kept.reserve(nodes.size() - n_removed);
    for (unsigned int p = 0; p < nodes.size(); ++p)
      if (!removed[p])
        kept.push_back(nodes[p]);
    nodes = std::move(kept);
    return n_removed;
  }

  template unsigned int
  remove_crosspoint_pairs(std::vector<ContactNode<2>> &,
                          const std::vector<bool> &);
  template unsigned int
  remove_crosspoint_pairs(std::vector<ContactNode<3>> &,
                          const std::vector<bool> &);
} // namespace FloorBlock::Contact
