/**
 * The Model's adaptation (Adaptivity): flag the cells by an error
 * indicator, refine and coarsen the p4est mesh, and carry dof vectors and
 * quadrature-point data over to the new cells.
 */

#include <tribos/core/model.h>
#include <tribos/core/model_checks.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/cell_data_transfer.templates.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace tribos
{
  namespace
  {
    /**
     * For each point of @p to (points of a cell's quadrature mapped into
     * one reference cell), the index of the nearest point of @p from.
     */
    template <int dim>
    std::vector<unsigned int>
    nearest_points(const std::vector<Point<dim>> &from,
                   const std::vector<Point<dim>> &to)
    {
      std::vector<unsigned int> nearest(to.size());
      for (unsigned int i = 0; i < to.size(); ++i)
      {
        double best = std::numeric_limits<double>::max();
        for (unsigned int j = 0; j < from.size(); ++j)
          if (to[i].distance_square(from[j]) < best - 1e-14)
          {
            best       = to[i].distance_square(from[j]);
            nearest[i] = j;
          }
      }
      return nearest;
    }

    /** Quadrature point @p x of child @p child (isotropic refinement of a
     * quadrilateral or hexahedron) in its parent's reference cell. */
    template <int dim>
    Point<dim>
    in_parent(const Point<dim> &x, const unsigned int child)
    {
      Point<dim> y;
      for (unsigned int d = 0; d < dim; ++d)
        y[d] = 0.5 * (x[d] + ((child >> d) & 1));
      return y;
    }
  } // namespace



  template <int dim>
  parallel::distributed::Triangulation<dim> &
  Model<dim>::adaptive_triangulation()
  {
    auto *tria = dynamic_cast<parallel::distributed::Triangulation<dim> *>(
      triangulation_storage.get());
    AssertThrow(tria != nullptr,
                ExcInternalError("adaptation needs Adaptivity/Enable"));
    return *tria;
  }



  template <int dim>
  bool
  Model<dim>::mark(const dealii::Vector<float> &indicator,
                   const ContactZone<dim>      &zone)
  {
    auto       &tria        = adaptive_triangulation();
    const auto &a           = parameters.adaptivity;
    using Strategy          = Parameters::Adaptivity::Strategy;
    namespace refinement    = parallel::distributed::GridRefinement;
    const auto apply_levels = [&]()
    {
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          if (cell->level() >= static_cast<int>(a.maximum_level))
            cell->clear_refine_flag();
          if (cell->level() <= static_cast<int>(a.minimum_level))
            cell->clear_coarsen_flag();
        }
    };
    // Contact zone depth: the cells near a zone to the finest level that
    // the flags give a cell of the zone, the master faces it touches no
    // larger than 1.5 times its finest slave face; none of them coarsened.
    const auto refine_zone = [&]()
    {
      if (zone.boxes.empty())
        return;
      const auto zone_cell = [&](const auto &cell)
      {
        return zone.slave_size[cell->active_cell_index()] > 0;
      };
      int finest = -1;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() && zone_cell(cell))
          finest =
            std::max(finest, cell->level() + (cell->refine_flag_set() ? 1 : 0));
      finest          = std::min(Utilities::MPI::max(finest, mpi_communicator),
                        static_cast<int>(a.maximum_level));
      const auto near = [&](const Point<dim> &x)
      {
        for (const auto &box : zone.boxes)
        {
          double width = 0, distance = 0;
          for (unsigned int d = 0; d < dim; ++d)
          {
            width            = std::max(width, box.side_length(d));
            const double out = std::max(
              {box.lower_bound(d) - x[d], x[d] - box.upper_bound(d), 0.});
            distance += out * out;
          }
          if (std::sqrt(distance) <= a.contact_zone_depth * width)
            return true;
        }
        return false;
      };
      double slave_size = std::numeric_limits<double>::max();
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() &&
            (zone_cell(cell) || near(cell->center())))
        {
          cell->clear_coarsen_flag();
          if (cell->level() < finest)
            cell->set_refine_flag();
          if (zone_cell(cell))
            slave_size = std::min(slave_size,
                                  zone.slave_size[cell->active_cell_index()] *
                                    (cell->refine_flag_set() ? 0.5 : 1.));
        }
      slave_size = Utilities::MPI::min(slave_size, mpi_communicator);
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() &&
            zone.master_size[cell->active_cell_index()] > 0)
        {
          cell->clear_coarsen_flag();
          if (zone.master_size[cell->active_cell_index()] > 1.5 * slave_size &&
              cell->level() < static_cast<int>(a.maximum_level))
            cell->set_refine_flag();
        }
    };
    if (a.strategy == Strategy::fixed_fraction)
      refinement::refine_and_coarsen_fixed_fraction(tria,
                                                    indicator,
                                                    a.refine_fraction,
                                                    a.coarsen_fraction);
    else
      refinement::refine_and_coarsen_fixed_number(tria,
                                                  indicator,
                                                  a.refine_fraction,
                                                  a.coarsen_fraction);
    apply_levels();
    refine_zone();

    // Counted as p4est will carry them out (a cell is coarsened only with
    // all its siblings, and the levels of neighbours differ by one).
    const auto count = [&]()
    {
      tria.prepare_coarsening_and_refinement();
      unsigned long refine = 0, coarsen = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          refine += cell->refine_flag_set() ? 1 : 0;
          coarsen += cell->coarsen_flag_set() ? 1 : 0;
        }
      return std::make_pair(Utilities::MPI::sum(refine, mpi_communicator),
                            Utilities::MPI::sum(coarsen, mpi_communicator));
    };
    auto [n_refine, n_coarsen] = count();

    // A cut keeps the share of the cells coarsened.
    const double coarsen_fraction = n_coarsen / tria.n_global_active_cells();
    std::tie(n_refine, n_coarsen) = fit_budget(
      n_refine,
      n_coarsen,
      [&](const double fraction)
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned())
          {
            cell->clear_refine_flag();
            cell->clear_coarsen_flag();
          }
        refinement::refine_and_coarsen_fixed_number(tria,
                                                    indicator,
                                                    fraction,
                                                    coarsen_fraction);
        apply_levels();
        // Without refinement left the zone is not made uniform either.
        if (fraction > 0)
          refine_zone();
        return count();
      });
    return n_refine + n_coarsen > 0;
  }


  template <int dim>
  std::pair<double, double>
  Model<dim>::fit_budget(
    double                                                  n_refine,
    double                                                  n_coarsen,
    const std::function<std::pair<double, double>(double)> &flag_fraction)
  {
    const auto &a    = parameters.adaptivity;
    const auto &tria = adaptive_triangulation();
    // The budgets. Dofs (Maximum dofs), estimated on the safe side: a
    // refined cell adds (children - 1) cells of 1.25 times the mean dofs
    // per cell (a cell at a boundary or next to a coarser one adds more
    // than the mean), a coarsened group of siblings removes only the dofs
    // of its centre. Cells, always: as many as the memory holds by the
    // estimate that refuses a Scene/Refinement (adaptive_cell_limit()),
    // so that no input (Maximum level 20, Refine fraction 0.98, 20 initial
    // cycles: 6 GB in 3 minutes) outgrows the machine, and a run under a
    // limit of its address space stops refining before std::bad_alloc. The
    // refinement is cut until both estimates fit (p4est's balance may add
    // cells to any cut: counted again each time).
    const double n_cells    = tria.n_global_active_cells();
    const double n_children = GeometryInfo<dim>::max_children_per_cell;
    const double n_dofs     = dofs.n_dofs();
    const double added      = 1.25 * n_dofs / n_cells * (n_children - 1);
    const double removed    = fe().n_components();
    const double dof_limit  = a.maximum_dofs > 0 ?
                                double(a.maximum_dofs) :
                                std::numeric_limits<double>::infinity();
    const double cell_limit =
      adaptive_cell_limit<dim>(parameters, n_cells, mpi_communicator);
    const auto expected = [&](const double refine, const double coarsen)
    {
      return n_dofs + refine * added - coarsen / n_children * removed;
    };
    const auto expected_cells = [&](const double refine, const double coarsen)
    {
      return n_cells + (refine - coarsen / n_children) * (n_children - 1);
    };
    const auto too_many = [&](const double refine, const double coarsen)
    {
      return expected(refine, coarsen) > dof_limit ||
             expected_cells(refine, coarsen) > cell_limit;
    };
    if (too_many(n_refine, n_coarsen))
    {
      // The memory's limit (not the user's) is noted once: the run goes on
      // on a coarser mesh than its entries ask for.
      if (expected_cells(n_refine, n_coarsen) > cell_limit && !memory_limited)
      {
        memory_limited = true;
        std::ostringstream text;
        text.precision(3);
        text << "Adaptivity: a refinement to about "
             << expected_cells(n_refine, n_coarsen)
             << " cells was limited to about " << cell_limit
             << ", as many as the memory of this run holds (its machines', "
                "or the address space its processes have left under their "
                "limit) at about "
             << adaptive_memory_factor *
                  bytes_per_cell(dim, parameters.finite_element.degree) / 1e3
             << " kB per cell; the run goes on on the coarser mesh. "
                "Adaptivity/Maximum dofs, a smaller Maximum level or Refine "
                "fraction refine less; a finer mesh needs more memory or "
                "processes on more machines.";
        warnings.warn(text.str());
      }
      double fraction = n_refine / n_cells;
      while (fraction > 0 && too_many(n_refine, n_coarsen))
      {
        const double room = std::min(
          (dof_limit - n_dofs + n_coarsen / n_children * removed) / added,
          (cell_limit - n_cells) / (n_children - 1) + n_coarsen / n_children);
        fraction = std::min(0.8 * fraction, std::max(0., room) / n_cells);
        if (fraction * n_cells < 1)
          fraction = 0;
        std::tie(n_refine, n_coarsen) = flag_fraction(fraction);
      }
    }
    return {n_refine, n_coarsen};
  }



  template <int dim>
  std::vector<TrilinosWrappers::MPI::Vector>
  Model<dim>::adapt(const std::vector<const Vector *> &fields,
                    std::vector<std::vector<double>>  &cell_data)
  {
    auto &tria = adaptive_triangulation();

    // Quadrature-point data: a child's point takes the value of the
    // parent's point nearest to it, a parent's point that of the nearest
    // point of the child it lies in. Copies, not averages: a homogeneous
    // state stays exactly homogeneous, and a plastic state stays on its
    // manifold (det C_p = 1), which an average would leave.
    const std::vector<Point<dim>> &points = cell_quadrature.get_points();
    const unsigned int             n_q    = points.size();
    const unsigned int n_children = GeometryInfo<dim>::max_children_per_cell;
    std::vector<std::vector<unsigned int>>             from_parent(n_children);
    std::vector<std::pair<unsigned int, unsigned int>> from_children(n_q);
    for (unsigned int c = 0; c < n_children; ++c)
    {
      std::vector<Point<dim>> mapped;
      for (const auto &x : points)
        mapped.push_back(in_parent(x, c));
      from_parent[c] = nearest_points(points, mapped);
    }
    for (unsigned int q = 0; q < n_q; ++q)
    {
      unsigned int child = 0;
      for (unsigned int d = 0; d < dim; ++d)
        child |= (points[q][d] >= 0.5 ? 1u : 0u) << d;
      std::vector<Point<dim>> mapped;
      for (const auto &x : points)
        mapped.push_back(in_parent(x, child));
      from_children[q] = {child, nearest_points(mapped, {points[q]})[0]};
    }
    using Data = std::vector<double>;
    const auto refine =
      [&](const typename Triangulation<dim>::cell_iterator &, const Data parent)
    {
      std::vector<Data> children(n_children);
      if (parent.empty())
        return children;
      const unsigned int n = parent.size() / n_q;
      for (unsigned int c = 0; c < n_children; ++c)
        for (unsigned int q = 0; q < n_q; ++q)
          children[c].insert(children[c].end(),
                             parent.begin() + from_parent[c][q] * n,
                             parent.begin() + (from_parent[c][q] + 1) * n);
      return children;
    };
    const auto coarsen = [&](const typename Triangulation<dim>::cell_iterator &,
                             const std::vector<Data> &children)
    {
      Data parent;
      if (children[0].empty())
        return parent;
      const unsigned int n = children[0].size() / n_q;
      for (unsigned int q = 0; q < n_q; ++q)
      {
        const auto &[c, p] = from_children[q];
        AssertThrow(children[c].size() == n * n_q,
                    ExcInternalError("cells of one parent with different "
                                     "materials"));
        parent.insert(parent.end(),
                      children[c].begin() + p * n,
                      children[c].begin() + (p + 1) * n);
      }
      return parent;
    };

    tria.prepare_coarsening_and_refinement();
    parallel::distributed::SolutionTransfer<dim, Vector> transfer(dofs);
    transfer.prepare_for_coarsening_and_refinement(fields);
    parallel::distributed::
      CellDataTransfer<dim, dim, std::vector<std::vector<double>>>
        data_transfer(tria, true, refine, coarsen);
    data_transfer.prepare_for_coarsening_and_refinement(cell_data);

    tria.execute_coarsening_and_refinement();
    distribute_dofs();

    std::vector<Vector>   result(fields.size());
    std::vector<Vector *> out;
    for (auto &v : result)
    {
      v.reinit(layout_.locally_owned_dofs, mpi_communicator);
      out.push_back(&v);
    }
    transfer.interpolate(out);
    cell_data.assign(tria.n_active_cells(), {});
    data_transfer.unpack(cell_data);
    return result;
  }



  template <int dim>
  bool
  Model<dim>::refine_to(const std::vector<std::array<unsigned int, 4>> &cells)
  {
    auto               &tria = adaptive_triangulation();
    std::vector<CellId> target;
    for (const auto &binary : cells)
      target.emplace_back(binary);
    std::sort(target.begin(), target.end());

    // In CellId order a cell's descendants follow it at once: a cell not
    // in the list is refined if the next entry descends from it.
    bool refined = false;
    for (;;)
    {
      unsigned int n_flagged = 0, n_foreign = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          const CellId id = cell->id();
          const auto   it = std::lower_bound(target.begin(), target.end(), id);
          if (it != target.end() && *it == id)
            continue;
          if (it != target.end() && id.is_ancestor_of(*it))
          {
            cell->set_refine_flag();
            ++n_flagged;
          }
          else
            ++n_foreign;
        }
      n_foreign = Utilities::MPI::sum(n_foreign, mpi_communicator);
      AssertThrow(n_foreign == 0,
                  ExcMessage(
                    "--restart <" + parameters.restart_directory +
                    ">: the checkpoint's mesh is not a refinement of this "
                    "run's coarse mesh (" +
                    std::to_string(n_foreign) +
                    " cells neither in it nor refined in it): restart with "
                    "the scene, mesh and Adaptivity of the run that wrote "
                    "it."));
      if (Utilities::MPI::sum(n_flagged, mpi_communicator) == 0)
        break;
      tria.execute_coarsening_and_refinement();
      refined = true;
    }
    if (refined)
      distribute_dofs();
    return refined;
  }



  template class Model<2>;
  template class Model<3>;
} // namespace tribos
