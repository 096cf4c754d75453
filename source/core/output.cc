#include <tribos/core/problem.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <sstream>

namespace tribos
{
  namespace
  {
    const char *const axis = "xyz";

    /**
     * Runs @p work on every process and fails on all of them if it failed
     * on any: the output files are opened by the first process only, and a
     * failure there alone would leave the others waiting in the next
     * collective step.
     */
    void
    on_every_process(const MPI_Comm               communicator,
                     const std::function<void()> &work)
    {
      std::string failure;
      try
      {
        work();
      }
      catch (const ExceptionBase &error)
      {
        std::ostringstream message;
        error.print_info(message);
        failure = message.str();
        // print_info indents and ends the message; main() does it again.
        failure.erase(0, failure.find_first_not_of(" "));
        failure.erase(failure.find_last_not_of("\n") + 1);
      }
      catch (const std::exception &error)
      {
        failure = error.what();
      }
      for (const auto &message :
           Utilities::MPI::all_gather(communicator, failure))
        AssertThrow(message.empty(), ExcMessage(message));
    }
  } // namespace



  template <int dim>
  void
  Problem<dim>::open_output()
  {
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    const std::string dir = parameters.output.directory;
    on_every_process(
      mpi_communicator,
      [&]()
      {
        if (root)
        {
          std::error_code error;
          std::filesystem::create_directories(dir, error);
          AssertThrow(!error && std::filesystem::is_directory(dir),
                      ExcMessage("Parameter <Output/Directory> = <" + dir +
                                 ">: cannot create the directory (" +
                                 error.message() + ")."));
          // Remove the series files of an earlier run, so that the folder
          // holds one consistent run; other files are left alone.
          // A restart keeps those of the steps up to its checkpoint.
          for (const auto &entry : std::filesystem::directory_iterator(dir))
          {
            const std::string name = entry.path().filename().string();
            for (const std::string prefix : {"solution-", "contact-"})
              if (name.rfind(prefix, 0) == 0)
              {
                unsigned int step = 0;
                try
                {
                  step = std::stoul(name.substr(prefix.size(), 5));
                }
                catch (...)
                {
                }
                if (entry.is_regular_file() &&
                    (!restart || step > restart->stepper.step))
                  std::filesystem::remove(entry.path());
              }
          }
        }
      });

    std::vector<std::string> columns = {"step",
                                        "increment",
                                        "time",
                                        "load_factor",
                                        "newton_iterations",
                                        "newton_iterations_all",
                                        "residual",
                                        "cutbacks",
                                        "wall_time"};
    for (const auto &c : parameters.boundary_conditions.dirichlet)
      for (unsigned int d = 0; d < dim; ++d)
        columns.push_back("RF" + std::to_string(c.boundary_id) + "_" + axis[d]);
    if (exact_displacement)
    {
      columns.push_back("error_L2");
      columns.push_back("error_H1");
    }
    // Probes: the vertex nearest to each point, over every process's own
    // cells.
    probe_dofs.clear();
    for (unsigned int k = 0; k < parameters.output.probes.size(); ++k)
    {
      const auto &p = parameters.output.probes[k];
      AssertThrow(p.size() == dim,
                  ExcMessage("Parameter <Output/Probes>: point " +
                             std::to_string(k) + " needs " +
                             std::to_string(dim) + " coordinates."));
      Point<dim> point;
      for (unsigned int d = 0; d < dim; ++d)
        point[d] = p[d];
      // Ties (a point halfway between vertices, coincident vertices of
      // two bodies) go by position, then by body: the same vertex for
      // every partition.
      using Key         = std::array<double, dim + 2>;
      const auto key_of = [&point](const auto &cell, const unsigned int v)
      {
        Key key;
        key[0] = cell->vertex(v).distance(point);
        for (unsigned int d = 0; d < dim; ++d)
          key[d + 1] = cell->vertex(v)[d];
        key[dim + 1] = cell->material_id();
        return key;
      };
      std::pair<Key, std::array<types::global_dof_index, dim>> best;
      best.first.fill(std::numeric_limits<double>::max());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto v : cell->vertex_indices())
            if (const Key key = key_of(cell, v); key < best.first)
            {
              best.first = key;
              for (unsigned int d = 0; d < dim; ++d)
                best.second[d] = cell->vertex_dof_index(v, d);
            }
      const auto candidates =
        Utilities::MPI::all_gather(mpi_communicator, best);
      probe_dofs.push_back(
        std::min_element(candidates.begin(), candidates.end())->second);
      for (unsigned int d = 0; d < dim; ++d)
        columns.push_back("probe" + std::to_string(k) + "_u" + axis[d]);
    }
    if (contact)
    {
      for (const auto &name : contact_output->column_names())
        columns.push_back(name);
      columns.push_back("augmentations");
      columns.push_back("chattering_nodes");
    }
    if (integrator)
      for (const char *name : {"kinetic_energy",
                               "strain_energy",
                               "internal_work",
                               "contact_work",
                               "friction_work",
                               "external_work",
                               "total_energy",
                               "energy_error"})
        columns.push_back(name);
    if (integrator)
      for (unsigned int d = 0; d < dim; ++d)
        columns.push_back(std::string("momentum_") + "xyz"[d]);
    if (parameters.nonlinear_solver.stabilization > 0)
    {
      columns.push_back("stabilization_force");
      columns.push_back("stabilization_ratio");
      columns.push_back("stabilization_relaxations");
    }
    // A restart continues the earlier run's files after its checkpoint.
    const long keep = restart ? long(restart->stepper.totals.n_increments) : -1;
    on_every_process(mpi_communicator,
                     [&]()
                     {
                       history_csv =
                         std::make_unique<CsvWriter>(dir + "/history.csv",
                                                     columns,
                                                     root,
                                                     keep);
                       convergence_csv = std::make_unique<CsvWriter>(
                         dir + "/convergence.csv",
                         std::vector<std::string>{"step",
                                                  "increment",
                                                  "time",
                                                  "iteration",
                                                  "residual",
                                                  "relative_residual",
                                                  "update_norm",
                                                  "line_search_step",
                                                  "order"},
                         root,
                         keep);
                     });
  }



  template <int dim>
  std::vector<double>
  Problem<dim>::reaction_forces() const
  {
    std::vector<double> forces;
    for (const auto &per_component : reaction_dofs)
      for (unsigned int d = 0; d < dim; ++d)
      {
        double sum = 0;
        for (const auto dof : per_component[d])
          if (locally_owned_dofs.is_element(dof))
            sum += full_residual[dof] + (integrator ? inertia_forces[dof] : 0.);
        forces.push_back(Utilities::MPI::sum(sum, mpi_communicator));
      }
    return forces;
  }



  template <int dim>
  std::pair<double, double>
  Problem<dim>::displacement_errors(const double time) const
  {
    exact_displacement->set_time(time);
    const QGauss<dim> error_quadrature(parameters.finite_element.degree + 3);
    dealii::Vector<float> cellwise(triangulation.n_active_cells());
    VectorTools::integrate_difference(dof_handler,
                                      ghosted_displacement(),
                                      *exact_displacement,
                                      cellwise,
                                      error_quadrature,
                                      VectorTools::L2_norm);
    const double l2 = VectorTools::compute_global_error(triangulation,
                                                        cellwise,
                                                        VectorTools::L2_norm);
    VectorTools::integrate_difference(dof_handler,
                                      ghosted_displacement(),
                                      *exact_displacement,
                                      cellwise,
                                      error_quadrature,
                                      VectorTools::H1_seminorm);
    const double h1 =
      VectorTools::compute_global_error(triangulation,
                                        cellwise,
                                        VectorTools::H1_seminorm);
    return {l2, h1};
  }



  template <int dim>
  void
  Problem<dim>::write_increment(const unsigned int     step,
                                const unsigned int     increment,
                                const double           time,
                                const IncrementReport &report,
                                const unsigned int     n_cutbacks,
                                const double           wall_time)
  {
    // full_residual holds R at the converged state: the last assembly was
    // the one that found convergence.
    std::vector<double> row = {double(step),
                               double(increment),
                               time,
                               time / parameters.time_stepping.end_time,
                               double(report.n_iterations),
                               double(report.n_iterations_all),
                               report.residual,
                               double(n_cutbacks),
                               wall_time};
    for (const double f : reaction_forces())
      row.push_back(f);
    if (exact_displacement)
    {
      const auto [l2, h1] = displacement_errors(time);
      row.push_back(l2);
      row.push_back(h1);
    }
    for (const auto &dofs : probe_dofs)
      for (const auto dof : dofs)
        row.push_back(Utilities::MPI::sum(locally_owned_dofs.is_element(dof) ?
                                            double(owned_solution[dof]) :
                                            0.,
                                          mpi_communicator));
    if (contact)
    {
      for (const double value : contact_output->columns())
        row.push_back(value);
      row.push_back(report.n_augmentations);
      row.push_back(report.n_chattering);
    }
    if (integrator)
    {
      // total_energy: the bodies' energy plus what the contact took (the
      // penalty springs' energy, friction, impact losses). energy_error:
      // what the time integrator created (> 0) or dissipated (< 0), the
      // balance of the trapezoidal work sums E_kin - E_kin,0 + W_int +
      // W_contact - W_external: zero to round-off for Newmark's average
      // acceleration rule, whatever the material and the contact.
      const double total = kinetic_energy + strain_energy + contact_work;
      for (const double value :
           {kinetic_energy,
            strain_energy,
            internal_work,
            contact_work,
            friction_work,
            external_work,
            total,
            kinetic_energy - initial_kinetic_energy + internal_work +
              contact_work - external_work})
        row.push_back(value);
      for (unsigned int d = 0; d < dim; ++d)
        row.push_back(momentum[d]);
    }
    if (parameters.nonlinear_solver.stabilization > 0)
    {
      row.push_back(report.stabilization_force);
      row.push_back(report.stabilization_ratio);
      row.push_back(report.n_relaxations);
    }
    history_csv->add_row(row);
  }



  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
