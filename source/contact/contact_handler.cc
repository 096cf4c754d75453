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
#include <cstring>
#include <set>
#include <type_traits>

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
    , pairing(parameters)
    , monitor(mpi_communicator)
    , n_displacement_dofs(dof_handler.n_dofs())
  {
    contact_pairs = make_contact_pairs(parameters,
                                       dof_handler,
                                       youngs_modulus,
                                       locally_owned_dofs,
                                       axisymmetric,
                                       n_enforcement_unknowns,
                                       all_contact_dofs);
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
    own_seconds += seconds_since(start);
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



  template <int dim>
  std::vector<std::pair<CellId::binary_type, double>>
  ContactHandler<dim>::take_work()
  {
    std::vector<std::pair<CellId::binary_type, double>> work;
    for (auto &pair : contact_pairs)
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
        if (pair.owned[k] && pair.work[k] > 0)
        {
          const auto &node = pair.slave->nodes()[k];
          work.emplace_back(pair.slave->faces()[node.faces[0]].cell,
                            pair.work[k]);
          pair.work[k] = 0;
        }
    return work;
  }



  template <int dim>
  double
  ContactHandler<dim>::frictional_dissipation() const
  {
    double sum = 0;
    for (const auto &pair : contact_pairs)
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
        if (pair.owned[k] && pair.current[k].closed())
        {
          const auto &r = pair.current[k].result;
          sum += norm(r.traction) * r.slip_increment * r.area;
        }
    return Utilities::MPI::sum(sum, mpi_communicator);
  }



  template <int dim>
  std::vector<char>
  ContactHandler<dim>::committed_state() const
  {
    static_assert(std::is_trivially_copyable_v<NodeState>,
                  "NodeState is written as bytes");
    // Per owned node: pair, node, state; gathered from every process.
    std::vector<char> mine;
    const auto        append = [&mine](const void *data, const size_t size)
    {
      const char *bytes = static_cast<const char *>(data);
      mine.insert(mine.end(), bytes, bytes + size);
    };
    for (unsigned int p = 0; p < contact_pairs.size(); ++p)
      for (unsigned int k = 0; k < contact_pairs[p].n_nodes(); ++k)
        if (contact_pairs[p].owned[k])
        {
          append(&p, sizeof(p));
          append(&k, sizeof(k));
          append(&contact_pairs[p].committed[k], sizeof(NodeState));
        }
    std::vector<std::vector<NodeState>> states(contact_pairs.size());
    std::vector<char>                   ever_near(contact_pairs.size(), 0);
    for (unsigned int p = 0; p < contact_pairs.size(); ++p)
    {
      states[p].resize(contact_pairs[p].n_nodes());
      ever_near[p] = Utilities::MPI::logical_or(contact_pairs[p].ever_near,
                                                mpi_communicator);
    }
    const size_t record = 2 * sizeof(unsigned int) + sizeof(NodeState);
    for (const auto &part : Utilities::MPI::all_gather(mpi_communicator, mine))
      for (size_t offset = 0; offset + record <= part.size(); offset += record)
      {
        unsigned int p, k;
        std::memcpy(&p, part.data() + offset, sizeof(p));
        std::memcpy(&k, part.data() + offset + sizeof(p), sizeof(k));
        std::memcpy(&states[p][k],
                    part.data() + offset + 2 * sizeof(p),
                    sizeof(NodeState));
      }

    // Layout: number of pairs; per pair the number of nodes, ever_near and
    // the states.
    std::vector<char> result;
    const auto        put = [&result](const void *data, const size_t size)
    {
      const char *bytes = static_cast<const char *>(data);
      result.insert(result.end(), bytes, bytes + size);
    };
    const unsigned int n_pairs = contact_pairs.size();
    put(&n_pairs, sizeof(n_pairs));
    for (unsigned int p = 0; p < n_pairs; ++p)
    {
      const unsigned int n = states[p].size();
      put(&n, sizeof(n));
      put(&ever_near[p], 1);
      put(states[p].data(), n * sizeof(NodeState));
    }
    return result;
  }



  template <int dim>
  void
  ContactHandler<dim>::load_committed_state(const std::vector<char> &state,
                                            const double             time)
  {
    size_t     offset = 0;
    const auto get    = [&](void *data, const size_t size)
    {
      AssertThrow(offset + size <= state.size(),
                  ExcMessage("The checkpoint's contact state is truncated."));
      std::memcpy(data, state.data() + offset, size);
      offset += size;
    };
    unsigned int n_pairs;
    get(&n_pairs, sizeof(n_pairs));
    AssertThrow(n_pairs == contact_pairs.size(),
                ExcMessage("The checkpoint has " + std::to_string(n_pairs) +
                           " contact pairs, this run " +
                           std::to_string(contact_pairs.size()) +
                           ": Contact/Pairs must be those of the run that "
                           "wrote it."));
    for (auto &pair : contact_pairs)
    {
      unsigned int n;
      char         near;
      get(&n, sizeof(n));
      AssertThrow(n == pair.n_nodes(),
                  ExcMessage("The checkpoint's contact pair has " +
                             std::to_string(n) + " slave nodes, this run's " +
                             std::to_string(pair.n_nodes()) +
                             ": the mesh must be that of the run that wrote "
                             "it."));
      get(&near, 1);
      get(pair.committed.data(), n * sizeof(NodeState));
      pair.current              = pair.committed;
      pair.ever_near            = near != 0;
      pair.old_slave_positions  = pair.slave_positions;
      pair.old_master_positions = pair.master_positions;
    }
    committed_time = time;
  }



  template <int dim>
  void
  ContactHandler<dim>::begin_increment()
  {
    monitor.begin_increment(contact_pairs);
  }



  template <int dim>
  unsigned int
  ContactHandler<dim>::track_status_changes(const unsigned int limit,
                                            const bool         count)
  {
    return monitor.track(contact_pairs, limit, count);
  }



  template <int dim>
  unsigned int
  ContactHandler<dim>::freeze_chattering(const unsigned int limit)
  {
    return monitor.freeze(contact_pairs, limit);
  }



  template <int dim>
  unsigned int
  ContactHandler<dim>::n_frozen_inadmissible() const
  {
    return monitor.n_frozen_inadmissible(contact_pairs);
  }



  template <int dim>
  unsigned int
  ContactHandler<dim>::release_frozen_inadmissible()
  {
    return monitor.release_inadmissible(contact_pairs);
  }



  template <int dim>
  void
  ContactHandler<dim>::commit()
  {
    // Couplings are added as slave nodes find new master faces and kept
    // through the increment (the pattern must not change inside Newton).
    // At a converged increment those that no node uses any more go once
    // they are a quarter of the pattern's contact couplings: the pattern
    // follows the contact zone instead of growing with the sliding
    // distance, and is rebuilt (with a new symbolic factorization) only
    // when that pays.
    std::vector<std::set<std::pair<unsigned int, unsigned int>>> used(
      contact_pairs.size());
    unsigned int       n_stale = 0, n_kept = 0;
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    n_paired_across = 0;
    for (unsigned int p = 0; p < contact_pairs.size(); ++p)
    {
      auto &pair = contact_pairs[p];
      if (pair.master)
        for (unsigned int k = 0; k < pair.n_nodes(); ++k)
        {
          const int now = pair.current[k].face, before = pair.committed[k].face;
          if (!pair.owned[k] || now < 0)
            continue;
          const unsigned int owner = pair.master->faces()[now].owner;
          n_paired_across += (owner != rank);
          n_owner_changes +=
            (before >= 0 && pair.master->faces()[before].owner != owner);
        }
      pair.committed            = pair.current;
      pair.old_slave_positions  = pair.slave_positions;
      pair.old_master_positions = pair.master_positions;
      if (pair.rigid)
        continue;
      std::vector<unsigned int> faces;
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
      {
        const int face = pair.current[k].face;
        if (pair.owned[k] && !pair.excluded[k] && face >= 0)
        {
          if (pair.mortar)
          {
            pair.mortar_master_faces(k, faces);
            for (const unsigned int f : faces)
              pair.insert_couplings(k, f, used[p]);
          }
          else
            pair.insert_couplings(k, face, used[p]);
        }
      }
      n_kept += used[p].size();
      n_stale += pair.couplings.size() - used[p].size();
    }
    n_stale = Utilities::MPI::sum(n_stale, mpi_communicator);
    n_kept  = Utilities::MPI::sum(n_kept, mpi_communicator);
    if (n_stale > 0 && 3 * n_stale >= n_kept)
    {
      for (unsigned int p = 0; p < contact_pairs.size(); ++p)
        if (!contact_pairs[p].rigid)
          contact_pairs[p].couplings.swap(used[p]);
      outdated = true;
    }
    committed_time = time;
  }



  template <int dim>
  std::pair<unsigned int, unsigned int>
  ContactHandler<dim>::process_crossings() const
  {
    return {Utilities::MPI::sum(n_paired_across, mpi_communicator),
            Utilities::MPI::sum(n_owner_changes, mpi_communicator)};
  }



  template <int dim>
  void
  ContactHandler<dim>::restore()
  {
    for (auto &pair : contact_pairs)
      pair.current = pair.committed;
  }



  template <int dim>
  bool
  ContactHandler<dim>::augmented() const
  {
    for (const auto &pair : contact_pairs)
      if (pair.enforcement->has_outer_update())
        return true;
    return false;
  }



  template <int dim>
  double
  ContactHandler<dim>::augment(const double tolerance)
  {
    double violation = 0;
    for (const auto &pair : contact_pairs)
      if (pair.enforcement->has_outer_update())
        violation = std::max(violation, pair.enforcement->violation(pair));
    violation = Utilities::MPI::max(violation, mpi_communicator);
    if (violation > tolerance)
      for (auto &pair : contact_pairs)
        if (pair.enforcement->has_outer_update())
          pair.enforcement->outer_update(pair);
    return violation;
  }



  template <int dim>
  std::vector<std::string>
  ContactHandler<dim>::setup_warnings() const
  {
    return penalty_warnings(contact_pairs);
  }



  template <int dim>
  std::vector<std::string>
  ContactHandler<dim>::run_warnings() const
  {
    std::vector<std::string> warnings;
    for (const auto &pair : contact_pairs)
      if (Utilities::MPI::max(pair.ever_near ? 1 : 0, mpi_communicator) == 0)
        warnings.push_back(
          "contact pair <" + pair.description.text +
          ">: no slave node came within the search distance of the master "
          "during the run (Contact/Search distance = " +
          to_scientific(parameters.search_distance) +
          "); check the pair's boundary ids and the surfaces' positions.");
    return warnings;
  }



  template <int dim>
  std::vector<std::string>
  ContactHandler<dim>::describe() const
  {
    return tribos::describe(contact_pairs);
  }

  template class ContactHandler<2>;
  template class ContactHandler<3>;
} // namespace tribos
