#include <tribos/base/exceptions.h>
#include <tribos/contact/contact_handler.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cstring>
#include <set>
#include <type_traits>

// ContactHandler's state between increments: what the search and the
// assembly (contact_handler.cc) leave in the contact pairs is committed,
// restored after a cutback, written to and read from checkpoints,
// augmented and watched for chattering here.
namespace tribos
{
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

    // The couplings of the sparsity pattern, gathered: a restart that
    // rebuilt them from its first search would factorize a matrix of
    // another pattern (another fill-reducing ordering, other rounding).
    std::vector<std::vector<std::pair<unsigned int, unsigned int>>> couplings(
      contact_pairs.size());
    for (unsigned int p = 0; p < contact_pairs.size(); ++p)
    {
      const std::vector<std::pair<unsigned int, unsigned int>> mine(
        contact_pairs[p].couplings.begin(),
        contact_pairs[p].couplings.end());
      for (const auto &part :
           Utilities::MPI::all_gather(mpi_communicator, mine))
        couplings[p].insert(couplings[p].end(), part.begin(), part.end());
      std::sort(couplings[p].begin(), couplings[p].end());
    }

    // Layout: number of pairs; per pair the number of nodes, ever_near,
    // the states, the number of couplings and the couplings.
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
      const unsigned int n_couplings = couplings[p].size();
      put(&n_couplings, sizeof(n_couplings));
      for (const auto &[k, face] : couplings[p])
      {
        put(&k, sizeof(k));
        put(&face, sizeof(face));
      }
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
      // This process's couplings: those of the slave nodes it owns (the
      // only ones it pairs).
      unsigned int n_couplings;
      get(&n_couplings, sizeof(n_couplings));
      pair.couplings.clear();
      for (unsigned int c = 0; c < n_couplings; ++c)
      {
        unsigned int k, face;
        get(&k, sizeof(k));
        get(&face, sizeof(face));
        AssertThrow(k < n && (pair.master == nullptr ||
                              face < pair.master->faces().size()),
                    ExcMessage("The checkpoint's contact couplings do not "
                               "fit this run's surfaces: the mesh must be "
                               "that of the run that wrote it."));
        if (pair.owned[k] && !pair.excluded[k])
          pair.couplings.insert(pair.couplings.end(), {k, face});
      }
      pair.current              = pair.committed;
      pair.ever_near            = near != 0;
      pair.old_slave_positions  = pair.slave_positions;
      pair.old_master_positions = pair.master_positions;
    }
    AssertThrow(offset == state.size(),
                ExcMessage("The checkpoint's contact state has " +
                           std::to_string(state.size() - offset) +
                           " bytes more than this run's contact pairs "
                           "read: Contact/Pairs must be those of the run "
                           "that wrote it."));
    outdated       = true;
    committed_time = time;
  }



  template <int dim>
  void
  ContactHandler<dim>::start_at(const TrilinosWrappers::MPI::Vector &solution,
                                const double                         time)
  {
    update(solution, time);
    bool self_contact = false;
    for (auto &pair : contact_pairs)
    {
      pair.old_slave_positions  = pair.slave_positions;
      pair.old_master_positions = pair.master_positions;
      self_contact = self_contact || pair.description.self_contact();
    }
    // The self-contact search compares a node's place with the one it had
    // at the start of the increment (which the first search here did not
    // know yet): search again from the positions now known.
    if (self_contact)
      update(solution, time);
    committed_time = time;
  }



  template <int dim>
  void
  ContactHandler<dim>::begin_increment()
  {
    monitor.begin_increment(contact_pairs);
  }



  template <int dim>
  void
  ContactHandler<dim>::watch_iteration(
    const unsigned int                              iteration,
    const double                                    residual,
    const std::function<void(const std::string &)> &say)
  {
    monitor.after_iteration(contact_pairs, iteration, residual, say);
  }



  template <int dim>
  bool
  ContactHandler<dim>::accept_iterate(
    const std::function<void(const std::string &)> &say)
  {
    // A slave node in contact at the increment's start whose contact
    // normal has turned over went through the master: a node inside a
    // rigid circle or sphere that passes its centre is pushed out through
    // the far side, a node behind a face meets the master's far side. The
    // penalty's force then changes its sign, and the contact lets go with
    // no word (a block whose top was held, pushed through by a circle
    // with a penalty of 0.1 E/h: the force rose to 0.064, then fell to 0
    // as the circle came out at the top, exit 0). The increment is cut;
    // where smaller ones go through too, the run stops with this message.
    unsigned int n_through = 0;
    std::string  first;
    for (const auto &pair : contact_pairs)
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
      {
        const auto &before = pair.committed[k].result;
        const auto &now    = pair.current[k].result;
        if (!pair.owned[k] || !pair.committed[k].closed() ||
            !pair.current[k].paired || dot(before.normal, now.normal) >= 0)
          continue;
        if (n_through++ == 0)
        {
          const auto &x = pair.slave_positions[k];
          first         = "contact pair <" + pair.description.text +
                  ">, the slave node at (" + to_scientific(x[0]) + ", " +
                  to_scientific(x[1]) +
                  (dim == 3 ? ", " + to_scientific(x[2]) : std::string()) + ")";
        }
      }
    const unsigned int n_all = Utilities::MPI::sum(n_through, mpi_communicator);
    if (n_all > 0)
    {
      // The first one's description from the first process that has one.
      const auto all = Utilities::MPI::all_gather(mpi_communicator, first);
      first          = *std::find_if(all.begin(),
                            all.end(),
                            [](const std::string &s) { return !s.empty(); });
      throw NonConvergence(
        std::to_string(n_all) +
        " slave node(s) in contact at the increment's start went through "
        "the master (their contact normal turned over; first " +
        first +
        "): the contact does not hold them, a body pushed against what it "
        "cannot pass (a support, another body) or a penalty too soft for "
        "the load (Contact/Penalty factor); cutting the increment");
    }
    return monitor.accept(contact_pairs, say);
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
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
        if (pair.owned[k] && !pair.excluded[k] && pair.current[k].face >= 0)
          pair.discretization->used_couplings(pair, k, used[p]);
      n_kept += used[p].size();
      n_stale += pair.couplings.size() - used[p].size();
    }
    n_stale = Utilities::MPI::sum(n_stale, mpi_communicator);
    n_kept  = Utilities::MPI::sum(n_kept, mpi_communicator);
    if (n_stale > 0 && 3 * n_stale >= n_kept)
    {
      for (unsigned int p = 0; p < contact_pairs.size(); ++p)
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
  ContactHandler<dim>::outer_update(unsigned int &n_augmentations)
  {
    bool   any       = false;
    double violation = 0;
    for (const auto &pair : contact_pairs)
      if (pair.enforcement->has_outer_update())
      {
        any = true;
        for (unsigned int k = 0; k < pair.n_nodes(); ++k)
          if (pair.owned[k])
            violation = std::max(
              violation,
              pair.enforcement->violation(pair.current[k],
                                          pair.slave->nodes()[k].size));
      }
    if (!any)
      return false;
    violation              = Utilities::MPI::max(violation, mpi_communicator);
    const double tolerance = parameters.augmentation_tolerance;
    if (violation <= tolerance)
      return false;
    for (auto &pair : contact_pairs)
      if (pair.enforcement->has_outer_update())
        for (auto &state : pair.current)
          pair.enforcement->outer_update(state);
    if (n_augmentations >= parameters.max_augmentations)
      throw NonConvergence("penetration " + to_scientific(violation) +
                           " of the element size after " +
                           std::to_string(n_augmentations) +
                           " augmentations (Contact/Maximum augmentations)");
    ++n_augmentations;
    return true;
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
