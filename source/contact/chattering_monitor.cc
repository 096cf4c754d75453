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
    slip_direction.resize(pairs.size());
    reversals.resize(pairs.size());
    held_stick.resize(pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
    {
      const unsigned int n = pairs[p].n_nodes();
      status[p].assign(n, -1);
      changes[p].assign(n, 0);
      held[p].assign(n, false);
      slip_direction[p].assign(n, Vec3<double>{{0., 0., 0.}});
      reversals[p].assign(n, 0);
      held_stick[p].assign(n, false);
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
          const auto &result = pairs[p].current[k].result;
          const int   now    = pairs[p].current[k].closed() ? 1 : 0;
          if (count && status[p][k] >= 0 && now != status[p][k])
            ++changes[p][k];
          status[p][k] = now;

          Vec3<double> direction{{0., 0., 0.}};
          const double magnitude = norm(result.traction);
          if (result.status == ContactStatus::slip && magnitude > 0)
            direction = scale(1. / magnitude, result.traction);
          // Reversals in a row: an iteration without one ends the count
          // (sporadic reversals while a wide slip zone settles, as in the
          // 3D upsetting, are not a cycle).
          if (count && dot(direction, slip_direction[p][k]) < 0)
            ++reversals[p][k];
          else
            reversals[p][k] = 0;
          slip_direction[p][k] = direction;
          if (changes[p][k] > limit || reversals[p][k] > limit)
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
        if (pairs[p].owned[k])
        {
          if (changes[p][k] > limit)
            held[p][k] = true;
          if (reversals[p][k] > limit)
            held_stick[p][k] = true;
          if (held[p][k] || held_stick[p][k])
            ++n;
        }
    return Utilities::MPI::sum(n, mpi_communicator);
  }



  template <int dim>
  unsigned int
  ChatteringMonitor<dim>::n_frozen_inadmissible(
    const std::vector<ContactPair<dim>> &pairs) const
  {
    unsigned int n = 0;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (unsigned int k = 0; k < pairs[p].n_nodes(); ++k)
        if (held_inadmissible(pairs, p, k))
          ++n;
    return Utilities::MPI::sum(n, mpi_communicator);
  }

  template <int dim>
  unsigned int
  ChatteringMonitor<dim>::release_inadmissible(
    const std::vector<ContactPair<dim>> &pairs)
  {
    unsigned int n = 0;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (unsigned int k = 0; k < pairs[p].n_nodes(); ++k)
        if (held_inadmissible(pairs, p, k))
        {
          held[p][k]       = false;
          changes[p][k]    = 0;
          held_stick[p][k] = false;
          reversals[p][k]  = 0;
          ++n;
        }
    return Utilities::MPI::sum(n, mpi_communicator);
  }



  template class ChatteringMonitor<2>;
  template class ChatteringMonitor<3>;
} // namespace tribos
