#include <tribos/base/import_constraints.h>

#include <deal.II/dofs/dof_tools.h>

#include <algorithm>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <iterator>
#include <map>
#include <utility>
#include <vector>

namespace tribos
{
  namespace
  {
    /** A constraint line as its owner sends it. */
    struct Line
    {
      types::global_dof_index                                 dof           = 0;
      double                                                  inhomogeneity = 0;
      std::vector<std::pair<types::global_dof_index, double>> entries;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &dof &inhomogeneity &entries;
      }
    };
  } // namespace



  void
  import_constraints(AffineConstraints<double>   &constraints,
                     const std::vector<IndexSet> &owned_per_process,
                     const IndexSet              &relevant,
                     const MPI_Comm               communicator)
  {
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    if (n_ranks == 1)
      return;
    const unsigned int rank  = Utilities::MPI::this_mpi_process(communicator);
    const IndexSet    &owned = owned_per_process[rank];

    // The owners' ranges are contiguous and ordered: the owner of a dof is
    // the last process whose first dof is not after it.
    std::vector<std::pair<types::global_dof_index, unsigned int>> starts;
    for (unsigned int r = 0; r < n_ranks; ++r)
      if (owned_per_process[r].n_elements() > 0)
        starts.emplace_back(owned_per_process[r].nth_index_in_set(0), r);
    std::map<unsigned int, std::vector<types::global_dof_index>> requests;
    for (const auto dof : relevant)
      if (!owned.is_element(dof))
      {
        const auto it =
          std::upper_bound(starts.begin(),
                           starts.end(),
                           dof,
                           [](const types::global_dof_index d, const auto &s)
                           { return d < s.first; });
        AssertThrow(it != starts.begin(), ExcInternalError());
        const unsigned int owner = std::prev(it)->second;
        AssertThrow(owned_per_process[owner].is_element(dof),
                    ExcMessage("import_constraints: the owned dofs of the "
                               "processes are not contiguous ranges."));
        requests[owner].push_back(dof);
      }

    const auto line_of = [&constraints](const types::global_dof_index dof)
    {
      Line        line;
      const auto *entries = constraints.get_constraint_entries(dof);
      line.dof            = dof;
      line.inhomogeneity  = constraints.get_inhomogeneity(dof);
      if (entries != nullptr)
        line.entries.assign(entries->begin(), entries->end());
      return line;
    };
    std::map<unsigned int, std::vector<Line>> answers;
    for (const auto &[requester, dofs] :
         Utilities::MPI::some_to_some(communicator, requests))
    {
      auto &lines = answers[requester];
      for (const auto dof : dofs)
        if (constraints.is_constrained(dof))
          lines.push_back(line_of(dof));
    }
    const auto received = Utilities::MPI::some_to_some(communicator, answers);

    // The own lines as they are, every other line as its owner has it.
    AffineConstraints<double> consistent(constraints.get_local_lines());
    const auto                add = [&consistent](const Line &line)
    {
      consistent.add_line(line.dof);
      consistent.add_entries(line.dof, line.entries);
      consistent.set_inhomogeneity(line.dof, line.inhomogeneity);
    };
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        add(line_of(line.index));
    for (const auto &[owner, lines] : received)
      for (const auto &line : lines)
        add(line);
    constraints.copy_from(consistent);
  }



  template <int dim>
  AffineConstraints<double>
  hanging_node_constraints(const DoFHandler<dim>       &dof_handler,
                           const IndexSet              &relevant,
                           const std::vector<IndexSet> &owned_per_process)
  {
    AffineConstraints<double> hanging(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging);
    import_constraints(hanging,
                       owned_per_process,
                       relevant,
                       dof_handler.get_triangulation().get_communicator());
    hanging.close();
    return hanging;
  }

  template AffineConstraints<double>
  hanging_node_constraints(const DoFHandler<2> &,
                           const IndexSet &,
                           const std::vector<IndexSet> &);
  template AffineConstraints<double>
  hanging_node_constraints(const DoFHandler<3> &,
                           const IndexSet &,
                           const std::vector<IndexSet> &);
} // namespace tribos
