#include <tribos/base/exceptions.h>
#include <tribos/base/timing.h>
#include <tribos/contact/contact_element.h>
#include <tribos/contact/contact_handler.h>
#include <tribos/contact/mortar_element.h>
#include <tribos/contact/mortar_element_3d.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <chrono>

namespace tribos
{
  template <int dim>
  ContactHandler<dim>::ContactHandler(
    const Parameters::Contact                       &parameters,
    const DoFHandler<dim>                           &dof_handler,
    const std::function<double(types::material_id)> &youngs_modulus,
    const IndexSet                                  &locally_owned_dofs,
    const MPI_Comm                                   mpi_communicator,
    const bool                                       axisymmetric)
    : parameters(parameters)
    , mpi_communicator(mpi_communicator)
    , pairing(parameters, mpi_communicator)
    , monitor(mpi_communicator)
    , n_displacement_dofs(dof_handler.n_dofs())
  {
    contact_pairs   = make_contact_pairs(parameters,
                                       dof_handler,
                                       youngs_modulus,
                                       locally_owned_dofs,
                                       axisymmetric,
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
      if (pair.mortar)
      {
        // A mortar element couples all the master faces of its node with
        // each other: one element per node over the union of its faces.
        for (auto c = pair.couplings.begin(); c != pair.couplings.end();)
        {
          const unsigned int k = c->first;
          pair.element_dofs(k, -1, dofs);
          for (; c != pair.couplings.end() && c->first == k; ++c)
          {
            const auto &face = pair.master->faces()[c->second];
            for (unsigned int i = 0; i < face.n_nodes(); ++i)
              for (const auto dof : pair.master->nodes()[face.node(i)].dofs)
                dofs.push_back(dof);
          }
          std::sort(dofs.begin(), dofs.end());
          dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
          constraints.add_entries_local_to_global(dofs, dsp, false);
        }
      }
      else
        for (const auto &[k, f] : pair.couplings)
        {
          pair.element_dofs(k, f, dofs);
          constraints.add_entries_local_to_global(dofs, dsp, false);
        }
      // The rows of a node's unknowns exist whether it is paired or not.
      if (pair.enforcement->n_node_unknowns() > 0)
        for (unsigned int k = 0; k < pair.n_nodes(); ++k)
          if (pair.owned[k])
          {
            pair.element_dofs(k, -1, dofs);
            constraints.add_entries_local_to_global(dofs, dsp, false);
          }
    }
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
    const auto             start = std::chrono::steady_clock::now();
    constexpr unsigned int n_max =
      std::max(
        {NodeToSegment<dim>::n_dofs,
         NodeToSmoothedSegment::max_dofs,
         2 * (MortarInput::max_slave_nodes + max_mortar_master_nodes),
         3 * (MortarInput3D::max_slave_nodes + max_mortar_master_nodes_3d)}) +
      dim;
    double     R[n_max], K[n_max * n_max];
    const bool consistent =
      parameters.tangent == Parameters::ContactTangent::consistent;

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

    // A mortar element too large for the AD type: the iterate is void
    // (the increment is cut back on every process).
    std::string               too_large;
    std::vector<unsigned int> stencil, master_nodes;
    // 3D mortar: each overlap of a slave and a master face integrated once
    // per pair and assembly (the positions are fixed during it).
    MortarOverlapCache overlap_cache;
    // The rows of an evaluated element (R, K) with the dofs in dofs: the
    // enforcement's last look at the unknowns' rows, then the system.
    const auto add_element =
      [&](const ContactPair<dim> &pair, const unsigned int k, NodeState &state)
    {
      const unsigned int n_unknowns = pair.enforcement->n_node_unknowns();
      if (n_unknowns > 0)
        pair.enforcement->finish_rows(dofs,
                                      dofs.size() - n_unknowns,
                                      homogeneous,
                                      pair.area[k],
                                      state,
                                      R,
                                      K);
      add(dofs.size());
    };
    for (unsigned int p = 0; p < contact_pairs.size(); ++p)
    {
      auto                   &pair        = contact_pairs[p];
      const Enforcement<dim> &enforcement = *pair.enforcement;
      overlap_cache.entries.clear();
      const unsigned int n_unknowns = enforcement.n_node_unknowns();
      RigidInput<dim>    rigid;
      if (pair.rigid)
      {
        rigid.surface   = pair.rigid.get();
        rigid.shift     = pair.rigid->translation(time);
        rigid.shift_old = pair.rigid->translation(committed_time);
      }

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
        // Mortar: the node's element over its slave segments (its weight
        // may still leave it without a master).
        SlaveInput slave;
        if (state.paired)
        {
          slave.position  = x;
          slave.committed = &committed;
          slave.law       = enforcement.law(pair, k, state, homogeneous);
          slave.law.frozen_closed = monitor.frozen(p, k);
          slave.law.frozen_stick  = monitor.frozen_stick(p, k);
          slave.area              = pair.area[k];
          slave.unknowns          = n_unknowns > 0 ? &state.lambda : nullptr;
          slave.consistent        = consistent;
        }
        if (pair.mortar && state.paired)
        {
          using Input =
            std::conditional_t<dim == 2, MortarInput, MortarInput3D>;
          using Element = std::conditional_t<dim == 2, Mortar2D, Mortar3D>;
          Input mortar;
          if constexpr (dim == 3)
            mortar.cache = &overlap_cache;
          if (!mortar_input(pair,
                            k,
                            mortar,
                            stencil,
                            master_nodes,
                            dofs,
                            too_large))
            continue;
          bool         paired = false;
          Vec3<double> point;
          state.result =
            Element::evaluate(slave, mortar, enforcement, R, K, paired, point);
          if (paired)
          {
            const auto &r  = state.result;
            state.point    = point;
            state.slip     = committed.slip + r.slip_increment;
            pair.ever_near = true;
            if (n_unknowns > 0 || r.status != ContactStatus::open)
              add_element(pair, k, state);
            continue;
          }
          state.result = ContactPointResult();
        }

        if (!state.paired || pair.mortar)
        {
          // Off the master (beyond its end or the search distance; mortar:
          // a weight too small, the paired mortar nodes went on above), or
          // excluded: the distance to the master surface, a positive, open
          // gap; the rows of the node's unknowns (Lambda = 0), scaled by
          // its own tributary area (an excluded node has handed its area
          // to others).
          state.result.gap = state.distance;
          if (n_unknowns > 0)
          {
            pair.element_dofs(k, -1, dofs);
            dofs.erase(dofs.begin(), dofs.end() - n_unknowns);
            enforcement.unpaired_rows(state,
                                      pair.slave->nodes()[k].area *
                                        pair.area_factor,
                                      R,
                                      K);
            add(n_unknowns);
          }
          continue;
        }

        const int face = state.face;
        if (pair.smoothed)
        {
          if constexpr (dim == 2)
          {
            SmoothedInput segment;
            bool          has_old[2];
            Vec3<double>  x_old[4];
            smoothed_stencil(pair,
                             face,
                             pair.master_positions,
                             segment.x,
                             segment.has);
            smoothed_stencil(pair,
                             face,
                             pair.old_master_positions,
                             x_old,
                             has_old);
            segment.x_old[0] = x_old[0];
            segment.x_old[1] = x_old[1];
            segment.xi       = state.projection.xi[0];
            state.result     = NodeToSmoothedSegment::evaluate(slave,
                                                           segment,
                                                           enforcement,
                                                           R,
                                                           K);
          }
        }
        else if (pair.master)
        {
          FaceInput<dim> input;
          const auto    &nodes = pair.master->faces()[face].nodes;
          for (unsigned int v = 0; v < MasterFace<dim>::n_nodes; ++v)
          {
            input.x[v]     = pair.master_positions[nodes[v]];
            input.x_old[v] = pair.old_master_positions[nodes[v]];
          }
          input.projection = state.projection;
          input.same_face  = committed.face == face;
          state.result =
            NodeToSegment<dim>::evaluate(slave, input, enforcement, R, K);
        }
        else
          state.result =
            NodeToRigid<dim>::evaluate(slave, rigid, enforcement, R, K);

        const auto &r = state.result;
        state.point   = x - scale(r.gap, r.normal);
        state.slip    = committed.slip + r.slip_increment;
        if (!pair.rigid || r.gap <= parameters.search_distance)
          pair.ever_near = true;
        if (n_unknowns == 0 && r.status == ContactStatus::open)
          continue;

        // The element: the slave, its master nodes (with smoothing also the
        // segment's neighbours) and the node's unknowns.
        pair.element_dofs(k, face, dofs);
        add_element(pair, k, state);
      }
      charge(nullptr);
    }
    own_seconds += seconds_since(start);
    if (Utilities::MPI::max(too_large.empty() ? 0 : 1, mpi_communicator) > 0)
      throw NonConvergence(too_large.empty() ?
                             "a mortar element on another process is too "
                             "large" :
                             too_large);
  }



  template class ContactHandler<2>;
  template class ContactHandler<3>;
} // namespace tribos
