#include <tribos/contact/chattering_monitor.h>

namespace tribos
{
  template <int dim>
  ChatteringMonitor<dim>::ChatteringMonitor(const MPI_Comm mpi_communicator)
    : mpi_communicator(mpi_communicator)
  {
  }



  template <int dim>
  void
  ChatteringMonitor<dim>::begin_increment(
    const std::vector<ContactPair<dim>> &pairs)
  {
    status.resize(pairs.size());
    changes.resize(pairs.size());
    held.resize(pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
    {
      status[p].assign(pairs[p].n_nodes(), -1);
      changes[p].assign(pairs[p].n_nodes(), 0);
      held[p].assign(pairs[p].n_nodes(), false);
    }
  }



  template <int dim>
  unsigned int
  ChatteringMonitor<dim>::track(const std::vector<ContactPair<dim>> &pairs,
                                const unsigned int                   limit,
                                const bool                           count)
  {
    if (status.size() != pairs.size())
      begin_increment(pairs);
    unsigned int n_chattering = 0;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (unsigned int k = 0; k < pairs[p].n_nodes(); ++k)
        if (pairs[p].owned[k])
        {
          const int now = pairs[p].current[k].closed() ? 1 : 0;
          if (count && status[p][k] >= 0 && now != status[p][k])
            ++changes[p][k];
          status[p][k] = now;
          if (changes[p][k] > limit)
            ++n_chattering;
        }
    return Utilities::MPI::sum(n_chattering, mpi_communicator);
  }



  template <int dim>
  unsigned int
  ChatteringMonitor<dim>::freeze(const std::vector<ContactPair<dim>> &pairs,
                                 const unsigned int                   limit)
  {
    unsigned int n = 0;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (unsigned int k = 0; k < pairs[p].n_nodes(); ++k)
        if (pairs[p].owned[k] && changes[p][k] > limit)
        {
          held[p][k] = true;
          ++n;
        }
    return Utilities::MPI::sum(n, mpi_communicator);
  }



  template <int dim>
  unsigned int
  ChatteringMonitor<dim>::n_frozen_in_tension(
    const std::vector<ContactPair<dim>> &pairs) const
  {
    unsigned int n = 0;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (unsigned int k = 0; k < pairs[p].n_nodes(); ++k)
        if (held_in_tension(pairs, p, k))
          ++n;
    return Utilities::MPI::sum(n, mpi_communicator);
  }

  template <int dim>
  unsigned int
  ChatteringMonitor<dim>::release_in_tension(
    const std::vector<ContactPair<dim>> &pairs)
  {
    unsigned int n = 0;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (unsigned int k = 0; k < pairs[p].n_nodes(); ++k)
        if (held_in_tension(pairs, p, k))
        {
          held[p][k]    = false;
          changes[p][k] = 0;
          ++n;
        }
    return Utilities::MPI::sum(n, mpi_communicator);
  }



  template class ChatteringMonitor<2>;
  template class ChatteringMonitor<3>;
} // namespace tribos
