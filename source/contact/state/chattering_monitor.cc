#include <tribos/base/exceptions.h>
#include <tribos/contact/state/chattering_monitor.h>

#include <algorithm>
#include <limits>

namespace tribos
{
  template <int dim>
  ChatteringMonitor<dim>::ChatteringMonitor(
    const Parameters::Contact &parameters,
    const MPI_Comm             mpi_communicator)
    : parameters(parameters)
    , mpi_communicator(mpi_communicator)
  {
  }



  template <int dim>
  void
  ChatteringMonitor<dim>::after_iteration(
    const std::vector<ContactPair<dim>>            &pairs,
    const unsigned int                              iteration,
    const double                                    residual,
    const std::function<void(const std::string &)> &say)
  {
    // Counted only while Newton makes no progress: an inexact (iterative)
    // solve, a coarse first iterate or a wide contact zone change many
    // statuses on the way (3D Hertz with GMRES: 104 nodes counted as
    // chattering and 4 cutbacks, none once only stalled iterations count).
    const bool stalled = iteration >= 2 && residual >= 0.5 * best_residual;
    if (iteration >= 1)
      best_residual = std::min(best_residual, residual);
    const unsigned int flips = parameters.chattering_flips;
    const unsigned int n     = track(pairs, flips, stalled);
    n_chattering_seen        = std::max(n_chattering_seen, n);
    const std::string what =
      "chattering: " + std::to_string(n) +
      " slave node(s) changed contact status or reversed their slip more "
      "than " +
      std::to_string(flips) +
      " times in this increment (Contact/Chattering flips)";
    const auto remedy = parameters.chattering_remedy;
    if (n > 0 && remedy == Parameters::ChatteringRemedy::cutback)
      throw NonConvergence(what + "; remedy: cut the increment "
                                  "(Contact/Chattering remedy = cutback)");
    if (n > 0 && remedy == Parameters::ChatteringRemedy::freeze && n > n_frozen)
    {
      n_frozen = freeze(pairs, flips);
      say("  " + what +
          ": held closed (reversing slip: in stick) for the rest of "
          "the increment (Contact/Chattering remedy = freeze)");
    }
  }



  template <int dim>
  bool
  ChatteringMonitor<dim>::accept(
    const std::vector<ContactPair<dim>>            &pairs,
    const std::function<void(const std::string &)> &say)
  {
    if (n_frozen == 0)
      return true;
    const unsigned int n_inadmissible = n_frozen_inadmissible(pairs);
    // Once per increment the held nodes in tension (held in stick: beyond
    // the Coulomb cone) are let go and Newton goes on from this iterate: the
    // freeze only had to get Newton out of its cycle (load-controlled 3D
    // Hertz: a converged iterate with 4 held nodes in tension; cutting back
    // cost 20.5 s and 43 iterations, releasing them 12.1 s and 25). A second
    // time the increment is cut.
    if (n_inadmissible > 0 && !released)
    {
      released = true;
      n_frozen -= release_inadmissible(pairs);
      say("  chattering: " + std::to_string(n_inadmissible) +
          " held node(s) ended in tension, off the master or (held in "
          "stick) beyond the Coulomb cone: released, Newton goes on");
      return false;
    }
    if (n_inadmissible > 0)
      throw NonConvergence(
        std::to_string(n_inadmissible) +
        " chattering node(s) held ended in tension, off the master or "
        "beyond the Coulomb cone (Contact/Chattering remedy = freeze): "
        "cutting the increment");
    return true;
  }



  template <int dim>
  void
  ChatteringMonitor<dim>::begin_increment(
    const std::vector<ContactPair<dim>> &pairs)
  {
    n_chattering_seen = 0;
    best_residual     = std::numeric_limits<double>::infinity();
    n_frozen          = 0;
    released          = false;
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
