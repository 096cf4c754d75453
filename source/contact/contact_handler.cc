#include <tribos/base/exceptions.h>
#include <tribos/base/timing.h>
#include <tribos/contact/contact_handler.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

namespace tribos
{
  template <int dim>
  ContactHandler<dim>::ContactHandler(
    const Parameters::Contact                       &parameters,
    const DoFHandler<dim>                           &dof_handler,
    const std::function<double(types::material_id)> &youngs_modulus,
    const IndexSet                                  &locally_owned_dofs,
    const MPI_Comm                                   mpi_communicator,
    const bool                                       axisymmetric,
    const Mapping<dim>                              *curved_geometry)
    : parameters(parameters)
    , mpi_communicator(mpi_communicator)
    , pairing(parameters, mpi_communicator)
    , monitor(parameters, mpi_communicator)
    , n_displacement_dofs(dof_handler.n_dofs())
  {
    contact_pairs   = make_contact_pairs(parameters,
                                       dof_handler,
                                       youngs_modulus,
                                       locally_owned_dofs,
                                       axisymmetric,
                                       curved_geometry,
                                       n_enforcement_unknowns,
                                       all_contact_dofs);
    slave_read_dofs = IndexSet(dof_handler.n_dofs());
    for (const auto &pair : contact_pairs)
      for (const unsigned int k : pair.read_slave_nodes)
        for (const auto dof : pair.slave->nodes()[k].dofs)
          slave_read_dofs.add_index(dof);
    slave_read_dofs.compress();
  }



  template <int dim>
  void
  ContactHandler<dim>::update(const TrilinosWrappers::MPI::Vector &solution,
                              const double                         t)
  {
    const auto start  = std::chrono::steady_clock::now();
    time              = t;
    bool new_coupling = false;
    for (auto &pair : contact_pairs)
      new_coupling = pairing.update(pair, solution) || new_coupling;
    const auto exchanged = pairing.take_exchanged();
    exchange.largest     = std::max(exchange.largest, exchanged.values);
    exchange.total += exchanged.values;
    ++exchange.n_searches;
    own_seconds += seconds_since(start) - exchanged.seconds;
    if (Utilities::MPI::max(new_coupling ? 1 : 0, mpi_communicator) == 1)
      outdated = true;
  }



  template <int dim>
  void
  ContactHandler<dim>::add_couplings(
    DynamicSparsityPattern          &dsp,
    const AffineConstraints<double> &constraints)
  {
    outdated = false;
    std::vector<types::global_dof_index> dofs;
    for (const auto &pair : contact_pairs)
    {
      pair.discretization->add_couplings(pair, constraints, dsp);
      // The rows of a node's unknowns exist whether it is paired or not.
      if (pair.enforcement->n_node_unknowns() > 0)
        for (unsigned int k = 0; k < pair.n_nodes(); ++k)
          if (pair.owned[k])
          {
            pair.discretization->element_dofs(pair, k, -1, dofs);
            constraints.add_entries_local_to_global(dofs, dsp, false);
          }
    }
  }



  template <int dim>
  void
  ContactHandler<dim>::size_element_buffers()
  {
    unsigned int n_max = 0;
    for (const auto &pair : contact_pairs)
      n_max = std::max(n_max, pair.discretization->max_element_dofs());
    element_residual.resize(n_max);
    element_matrix.resize(n_max * n_max);
  }



  template <int dim>
  SlaveInput
  ContactHandler<dim>::slave_input(const unsigned int               p,
                                   const unsigned int               k,
                                   const AffineConstraints<double> &homogeneous)
  {
    ContactPair<dim> &pair  = contact_pairs[p];
    NodeState        &state = pair.current[k];
    SlaveInput        slave;
    slave.position  = pair.slave_positions[k];
    slave.committed = &pair.committed[k];
    slave.law       = pair.enforcement->law(pair, k, state, homogeneous);
    slave.law.frozen_closed = monitor.frozen(p, k);
    slave.law.frozen_stick  = monitor.frozen_stick(p, k);
    slave.area              = pair.area[k];
    slave.unknowns =
      pair.enforcement->n_node_unknowns() > 0 ? &state.lambda : nullptr;
    slave.consistent =
      parameters.tangent == Parameters::ContactTangent::consistent;
    return slave;
  }



  template <int dim>
  double
  ContactHandler<dim>::step_limit(const TrilinosWrappers::MPI::Vector &trial,
                                  const double                         t,
                                  const double                         fraction,
                                  const AffineConstraints<double> &homogeneous)
  {
    // What the trial search and evaluation change, to be put back.
    std::vector<std::vector<NodeState>>                          states;
    std::vector<std::set<std::pair<unsigned int, unsigned int>>> couplings;
    for (const auto &pair : contact_pairs)
    {
      states.push_back(pair.current);
      couplings.push_back(pair.couplings);
    }
    const bool   was_outdated = outdated;
    const double seconds      = own_seconds;
    const auto   volume       = exchange;

    update(trial, t);
    size_element_buffers();
    std::vector<types::global_dof_index> dofs;
    std::string                          refusal;
    double                               limit = 1;
    for (unsigned int p = 0; p < contact_pairs.size(); ++p)
    {
      auto &pair = contact_pairs[p];
      pair.discretization->begin_assembly(pair, time, committed_time);
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
      {
        NodeState &state = pair.current[k];
        if (!pair.owned[k] || pair.excluded[k])
          continue;
        // The gap at the trial point: its element's, or the distance to
        // the master.
        double gap = state.distance;
        if (state.paired)
        {
          state.result = ContactPointResult();
          const auto outcome =
            pair.discretization->evaluate(pair,
                                          k,
                                          slave_input(p, k, homogeneous),
                                          element_residual.data(),
                                          nullptr,
                                          dofs,
                                          refusal);
          if (outcome.kind == ElementOutcome::Kind::element)
            gap = state.result.gap;
        }
        // From the last evaluation's gap g0 towards it linearly: the
        // penetration may grow by fraction h.
        const double g0 = states[p][k].result.gap;
        if (!std::isfinite(gap) || !std::isfinite(g0) || gap >= g0)
          continue;
        const double allowed =
          std::max(0., -g0) + fraction * pair.slave->nodes()[k].size;
        if (-gap > allowed)
          limit = std::min(limit, (g0 + allowed) / (g0 - gap));
      }
    }

    for (unsigned int p = 0; p < contact_pairs.size(); ++p)
    {
      contact_pairs[p].current.swap(states[p]);
      contact_pairs[p].couplings.swap(couplings[p]);
    }
    outdated    = was_outdated;
    own_seconds = seconds;
    exchange    = volume;
    return Utilities::MPI::min(limit, mpi_communicator);
  }



  template <int dim>
  void
  ContactHandler<dim>::assemble(const bool                       with_matrix,
                                const AffineConstraints<double> &constraints,
                                const AffineConstraints<double> &homogeneous,
                                TrilinosWrappers::SparseMatrix  &matrix,
                                TrilinosWrappers::MPI::Vector   &rhs,
                                TrilinosWrappers::MPI::Vector   &free_residual,
                                TrilinosWrappers::MPI::Vector   &full_residual,
                                TrilinosWrappers::MPI::Vector   &contact_forces)
  {
    const auto start = std::chrono::steady_clock::now();
    size_element_buffers();
    double *R = element_residual.data(), *K = element_matrix.data();

    // Element buffers, reused for every slave node (sized per element).
    std::vector<types::global_dof_index> dofs, force_dofs;
    dealii::Vector<double>               local_rhs, local_residual;
    std::vector<double>                  local_force;
    FullMatrix<double>                   local_matrix;
    const auto                           add = [&](const unsigned int n)
    {
      local_rhs.reinit(n);
      local_residual.reinit(n);
      for (unsigned int i = 0; i < n; ++i)
      {
        local_rhs(i)      = -force_weight * R[i];
        local_residual(i) = R[i];
      }
      full_residual.add(dofs, local_residual);
      // The forces on the nodes: the displacement rows only.
      force_dofs.clear();
      local_force.clear();
      for (unsigned int i = 0; i < n; ++i)
        if (dofs[i] < n_displacement_dofs)
        {
          force_dofs.push_back(dofs[i]);
          local_force.push_back(-R[i]);
        }
      if (!force_dofs.empty())
        contact_forces.add(force_dofs, local_force);
      homogeneous.distribute_local_to_global(local_rhs, dofs, free_residual);
      if (with_matrix)
      {
        local_matrix.reinit(n, n);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            local_matrix(i, j) = force_weight * K[i * n + j];
        constraints.distribute_local_to_global(local_matrix,
                                               local_rhs,
                                               dofs,
                                               matrix,
                                               rhs);
      }
    };

    // An element that cannot be evaluated (a mortar element too large for
    // the AD type): the iterate is void (the increment is cut back on
    // every process).
    std::string refusal;
    for (unsigned int p = 0; p < contact_pairs.size(); ++p)
    {
      auto                       &pair           = contact_pairs[p];
      const Enforcement<dim>     &enforcement    = *pair.enforcement;
      ContactDiscretization<dim> &discretization = *pair.discretization;
      const unsigned int          n_unknowns = enforcement.n_node_unknowns();
      discretization.begin_assembly(pair, time, committed_time);

      // Each node's share of the time (charged when the next one starts).
      auto       lap    = std::chrono::steady_clock::now();
      double    *worker = nullptr;
      const auto charge = [&](double *next)
      {
        if (worker != nullptr)
          *worker += seconds_since(lap);
        lap    = std::chrono::steady_clock::now();
        worker = next;
      };
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
      {
        if (!pair.owned[k])
          continue;
        charge(&pair.work[k]);
        NodeState          &state     = pair.current[k];
        const NodeState    &committed = pair.committed[k];
        const Vec3<double> &x         = pair.slave_positions[k];
        state.result                  = ContactPointResult();
        state.slip                    = committed.slip;
        state.point                   = x;
        if (state.paired)
        {
          const SlaveInput     slave = slave_input(p, k, homogeneous);
          const ElementOutcome outcome =
            discretization.evaluate(pair, k, slave, R, K, dofs, refusal);
          if (outcome.kind == ElementOutcome::Kind::refused)
            continue;
          if (outcome.kind == ElementOutcome::Kind::element)
          {
            state.slip = committed.slip + state.result.slip_increment;
            if (outcome.near)
              pair.ever_near = true;
            // The element: the enforcement's last look at the unknowns'
            // rows, then the system (an open node without unknowns has
            // none).
            if (n_unknowns > 0)
              enforcement.finish_rows(dofs,
                                      dofs.size() - n_unknowns,
                                      homogeneous,
                                      pair.area[k],
                                      state,
                                      R,
                                      K);
            if (n_unknowns > 0 || state.result.status != ContactStatus::open)
              add(dofs.size());
            continue;
          }
          // Paired by the search, but without a master after all (a
          // mortar weight too small).
          state.result = ContactPointResult();
        }

        // Off the master (beyond its end or the search distance), or
        // excluded: the distance to the master surface, a positive, open
        // gap; the rows of the node's unknowns (Lambda = 0), scaled by its
        // own tributary area (an excluded node has handed its area to
        // others).
        state.result.gap = state.distance;
        if (n_unknowns > 0)
        {
          dofs.clear();
          pair.append_unknown_dofs(k, dofs);
          enforcement.unpaired_rows(state,
                                    pair.slave->nodes()[k].area *
                                      pair.area_factor,
                                    R,
                                    K);
          add(n_unknowns);
        }
      }
      charge(nullptr);
    }
    own_seconds += seconds_since(start);
    if (Utilities::MPI::max(refusal.empty() ? 0 : 1, mpi_communicator) > 0)
      throw NonConvergence(refusal.empty() ?
                             "a contact element on another process cannot be "
                             "evaluated" :
                             refusal);
  }



  template class ContactHandler<2>;
  template class ContactHandler<3>;
} // namespace tribos
