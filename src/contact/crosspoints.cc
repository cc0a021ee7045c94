#include <contact/crosspoints.h>

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
  std::vector<bool>
  crosspoint_pairs(const std::vector<ContactNode<dim>> &nodes,
                   const std::vector<bool>             &is_exact)
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

    std::vector<bool> yields(nodes.size(), false);
    for (unsigned int p = 0; p < nodes.size(); ++p)
      if (is_exact[nodes[p].joint])
        for (const auto key : node_keys(nodes[p]))
          if (latest_joint.at(key) > nodes[p].joint)
            yields[p] = true;
    return yields;
  }

  template std::vector<bool>
  crosspoint_pairs(const std::vector<ContactNode<2>> &,
                   const std::vector<bool> &);
  template std::vector<bool>
  crosspoint_pairs(const std::vector<ContactNode<3>> &,
                   const std::vector<bool> &);
} // namespace FloorBlock::Contact
