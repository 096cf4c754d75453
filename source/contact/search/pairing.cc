#include <tribos/base/timing.h>
#include <tribos/contact/search/master_exchange.h>
#include <tribos/contact/search/pairing.h>

#include <chrono>

namespace tribos
{
  template <int dim>
  Pairing<dim>::Pairing(const Parameters::Contact &parameters,
                        const MPI_Comm             communicator)
    : parameters(parameters)
    , communicator(communicator)
  {
  }



  template <int dim>
  bool
  Pairing<dim>::update(ContactPair<dim>                    &pair,
                       const TrilinosWrappers::MPI::Vector &solution)
  {
    const auto &slave_nodes = pair.slave->nodes();
    for (const unsigned int k : pair.read_slave_nodes)
    {
      pair.slave_positions[k] = slave_nodes[k].reference;
      for (unsigned int d = 0; d < dim; ++d)
        pair.slave_positions[k][d] += solution[slave_nodes[k].dofs[d]];
    }
    const unsigned int n_unknowns = pair.enforcement->n_node_unknowns();
    // The enforcement's unknowns are unknowns of the system: read those
    // of the own nodes (only their elements use them).
    if (n_unknowns > 0)
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
        for (unsigned int d = 0; d < n_unknowns && pair.owned[k]; ++d)
          pair.current[k].lambda[d] =
            solution[pair.first_unknown + n_unknowns * k + d];

    // A deformable master: the faces that can reach this process's slave
    // nodes, and their search tree.
    if (pair.master)
    {
      const auto start = std::chrono::steady_clock::now();
      exchanged.values += exchange_master_nodes(pair,
                                                solution,
                                                parameters.search_distance,
                                                communicator);
      exchanged.seconds += seconds_since(start);
    }

    bool new_coupling = false;
    for (unsigned int k = 0; k < pair.n_nodes(); ++k)
      if (pair.owned[k] && !pair.excluded[k])
        new_coupling = pair.discretization->pair_node(pair, k) || new_coupling;
    return new_coupling;
  }

  template class Pairing<2>;
  template class Pairing<3>;
} // namespace tribos
