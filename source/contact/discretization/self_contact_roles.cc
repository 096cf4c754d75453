#include <tribos/contact/contact_pair.h>
#include <tribos/contact/discretization/self_contact_roles.h>

#include <deal.II/base/mpi.templates.h>

#include <algorithm>
#include <map>
#include <set>
#include <vector>

namespace tribos
{
  template <int dim>
  void
  assign_self_contact_roles(
    ContactPair<dim>                             &pair,
    const std::vector<std::vector<unsigned int>> &targets_of,
    const std::vector<bool>                      &was_slave,
    const MPI_Comm                                communicator)
  {
    // Per owned near node: the node, whether it was a slave at the last
    // converged increment, the nodes of its faces.
    std::vector<unsigned int> mine;
    for (unsigned int k = 0; k < pair.n_nodes(); ++k)
      if (pair.owned[k] && !pair.excluded[k] && !targets_of[k].empty())
      {
        mine.push_back(k);
        mine.push_back(was_slave[k] ? 1 : 0);
        mine.push_back(targets_of[k].size());
        mine.insert(mine.end(), targets_of[k].begin(), targets_of[k].end());
      }

    // The whole graph, on every process in the same order: each node's
    // face nodes (targets) and its undirected neighbours.
    std::map<unsigned int, std::vector<unsigned int>> targets;
    std::map<unsigned int, std::set<unsigned int>>    neighbours;
    std::set<unsigned int>                            slaves_before;
    for (const auto &part : Utilities::MPI::all_gather(communicator, mine))
      for (unsigned int i = 0; i < part.size(); i += 3 + part[i + 2])
      {
        const unsigned int k = part[i];
        if (part[i + 1] == 1)
          slaves_before.insert(k);
        targets[k].assign(part.begin() + i + 3,
                          part.begin() + i + 3 + part[i + 2]);
        for (const unsigned int m : targets[k])
        {
          neighbours[k].insert(m);
          neighbours[m].insert(k);
        }
      }

    // Colour each component from its seed; 0 slave, 1 master.
    std::map<unsigned int, int> colour;
    for (const auto &[first, unused] : neighbours)
    {
      (void)unused;
      if (colour.count(first) == 1)
        continue;
      // The component (its nodes in increasing order) and its seed.
      std::set<unsigned int>    component{first};
      std::vector<unsigned int> queue{first};
      for (unsigned int q = 0; q < queue.size(); ++q)
        for (const unsigned int m : neighbours[queue[q]])
          if (component.insert(m).second)
            queue.push_back(m);
      // The seed is paired (a node that is only a face's node would make
      // the nodes on that face masters and leave the contact to nobody).
      int seed = -1;
      for (const unsigned int k : component)
        if (targets.count(k) == 1 && slaves_before.count(k) == 1)
        {
          seed = k;
          break;
        }
      for (const unsigned int k : component)
        if (seed < 0 && targets.count(k) == 1)
          seed = k;
      // Breadth first from the seed; an edge between two equal colours
      // means the component is not two-sided.
      colour[seed] = 0;
      queue.assign(1, seed);
      bool two_sided = true;
      for (unsigned int q = 0; q < queue.size(); ++q)
        for (const unsigned int m : neighbours[queue[q]])
        {
          const auto c = colour.find(m);
          if (c == colour.end())
          {
            colour[m] = 1 - colour[queue[q]];
            queue.push_back(m);
          }
          else if (c->second == colour[queue[q]])
            two_sided = false;
        }
      if (two_sided)
        continue;
      // The mutual rule: of two nodes each in the other's face, the
      // larger is the master.
      for (const unsigned int k : component)
      {
        colour[k]      = 0;
        const auto own = targets.find(k);
        if (own == targets.end())
          continue;
        for (const unsigned int m : own->second)
        {
          const auto other = targets.find(m);
          if (m < k && other != targets.end() &&
              std::count(other->second.begin(), other->second.end(), k) > 0)
            colour[k] = 1;
        }
      }
    }

    // A master gives up its pairing only where a slave holds the contact:
    // a node on a slave's face.
    std::set<unsigned int> covered;
    for (const auto &[k, on] : targets)
      if (colour[k] == 0)
        covered.insert(on.begin(), on.end());
    for (const auto &[k, c] : colour)
      if (c == 1 && pair.owned[k] && targets.count(k) == 1 &&
          covered.count(k) == 1)
      {
        pair.current[k].paired = false;
        pair.current[k].face   = -1;
      }
  }

  template void
  assign_self_contact_roles(ContactPair<2> &,
                            const std::vector<std::vector<unsigned int>> &,
                            const std::vector<bool> &,
                            const MPI_Comm);
  template void
  assign_self_contact_roles(ContactPair<3> &,
                            const std::vector<std::vector<unsigned int>> &,
                            const std::vector<bool> &,
                            const MPI_Comm);
} // namespace tribos
