#include <contact/crosspoints.h>

#include <algorithm>
#include <map>
#include <numeric>

namespace FloorBlock::Contact
{
  namespace
  {
    /** The rigid obstacle and every fixed node: one vertex, the ground. */
    constexpr dealii::types::global_dof_index ground_key =
      dealii::numbers::invalid_dof_index;

    /** Disjoint sets of graph nodes, with path halving. */
    class NodeSets
    {
    public:
      unsigned int
      index(const dealii::types::global_dof_index key)
      {
        const auto [entry, added] = indices.emplace(key, parents.size());
        if (added)
          parents.push_back(parents.size());
        return entry->second;
      }

      unsigned int
      root(unsigned int node)
      {
        while (parents[node] != node)
          node = parents[node] = parents[parents[node]];
        return node;
      }

      /** Joins the sets of a and b; false if they were one set already. */
      bool
      join(const unsigned int a, const unsigned int b)
      {
        const unsigned int root_a = root(a), root_b = root(b);
        if (root_a == root_b)
          return false;
        parents[root_a] = root_b;
        return true;
      }

    private:
      std::map<dealii::types::global_dof_index, unsigned int> indices;
      std::vector<unsigned int>                               parents;
    };
  } // namespace

  template <int dim>
  std::vector<bool>
  crosspoint_pairs(const std::vector<ContactNode<dim>> &nodes,
                   const std::vector<bool>             &is_exact,
                   const dealii::IndexSet              &fixed_dofs)
  {
    const auto vertex_of = [&](const auto &dofs) {
      for (unsigned int c = 0; c < dim; ++c)
        if (!fixed_dofs.is_element(dofs[c]))
          return dofs[0];
      return ground_key;
    };
    // Graph: mesh nodes (named by their first DoF) and the obstacle are the
    // vertices, exact pairs the edges. A cycle means redundant constraints;
    // a spanning forest built from the latest joints down keeps them, and
    // every edge that would close a cycle yields.
    std::vector<unsigned int> order(nodes.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(),
                     order.end(),
                     [&](const unsigned int a, const unsigned int b) {
                       return nodes[a].joint > nodes[b].joint;
                     });
    NodeSets          sets;
    std::vector<bool> yields(nodes.size(), false);
    for (const unsigned int p : order)
      {
        const ContactNode<dim> &node = nodes[p];
        if (!is_exact[node.joint])
          continue;
        const unsigned int a = sets.index(vertex_of(node.dofs_a));
        const unsigned int b = sets.index(
          node.against_rigid_obstacle() ? ground_key : vertex_of(node.dofs_b));
        yields[p] = !sets.join(a, b);
      }
    return yields;
  }

  template std::vector<bool>
  crosspoint_pairs(const std::vector<ContactNode<2>> &,
                   const std::vector<bool> &,
                   const dealii::IndexSet &);
  template std::vector<bool>
  crosspoint_pairs(const std::vector<ContactNode<3>> &,
                   const std::vector<bool> &,
                   const dealii::IndexSet &);
} // namespace FloorBlock::Contact
