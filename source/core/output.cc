#include <tribos/base/write_atomically.h>
#include <tribos/core/problem.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
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



  template <int dim>
  void
  Problem<dim>::write_vtu(const unsigned int step, const double time)
  {
    TimerOutput::Scope t(timer, "output");
    const std::string  dir = parameters.output.directory + "/";
    if (contact)
      contact_output->write_csv(dir + "contact-" +
                                Utilities::int_to_string(step, 5) + ".csv");
    if (!parameters.output.write_vtu)
      return;

    // Cell averages of the Cauchy stress: honest for every material,
    // including those whose stress lives only at quadrature points.
    const unsigned int n_stress = (dim == 2 ? 4 : 6);
    const unsigned int stress_index[6][2] =
      {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
    const char                         *stress_names[6] = {"stress_xx",
                                                           "stress_yy",
                                                           "stress_zz",
                                                           "stress_xy",
                                                           "stress_yz",
                                                           "stress_xz"};
    std::vector<dealii::Vector<double>> stress(
      n_stress,
      dealii::Vector<double>(triangulation.n_active_cells()));
    dealii::Vector<double> von_mises(triangulation.n_active_cells());
    dealii::Vector<double> plastic_strain(triangulation.n_active_cells());
    dealii::Vector<double> body_id(triangulation.n_active_cells());
    dealii::Vector<double> subdomain(triangulation.n_active_cells());
    bool                   any_history = false;
    for (const auto &m : materials)
      any_history = any_history || m->n_history_variables() > 0;
    for (const auto &m : axisymmetric_materials)
      any_history = any_history || m->n_history_variables() > 0;

    const bool axisymmetric = parameters.finite_element.axisymmetric;
    std::vector<SymmetricTensor<2, 3>> sums(triangulation.n_active_cells());
    std::vector<double>                volume(triangulation.n_active_cells()),
      peeq(triangulation.n_active_cells());
    for_each_material_point(
      [&](const auto           &cell,
          const FEValues<dim>  &fe_values,
          const unsigned int    q,
          const Tensor<2, dim> &F,
          const Tensor<2, 3>   &F3,
          const double         *history)
      {
        // Axisymmetric: stress_zz is the hoop stress.
        const unsigned int index = cell->active_cell_index();
        const double       JxW   = fe_values.JxW(q);
        if (axisymmetric)
        {
          const auto &material = *axisymmetric_materials[cell->material_id()];
          sums[index] += JxW * material.cauchy_stress(F3, history);
          peeq[index] += JxW * material.equivalent_plastic_strain(history);
        }
        else
        {
          const auto &material = *materials[cell->material_id()];
          sums[index] += JxW * material.cauchy_stress(F, history);
          peeq[index] += JxW * material.equivalent_plastic_strain(history);
        }
        volume[index] += JxW;
      });
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const unsigned int          index   = cell->active_cell_index();
        const SymmetricTensor<2, 3> average = sums[index] / volume[index];
        for (unsigned int s = 0; s < n_stress; ++s)
          stress[s][index] = average[stress_index[s][0]][stress_index[s][1]];
        const SymmetricTensor<2, 3> dev = deviator(average);
        von_mises[index]                = std::sqrt(1.5 * (dev * dev));
        plastic_strain[index]           = peeq[index] / volume[index];
        body_id[index]                  = cell->material_id();
        subdomain[index]                = cell->subdomain_id();
      }

    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    using cell_iterator = typename Triangulation<dim>::active_cell_iterator;
    const auto next_owned =
      [](const Triangulation<dim> &tria, cell_iterator cell)
    {
      while (cell != tria.end() && !cell->is_locally_owned())
        ++cell;
      return cell;
    };
    data_out.set_cell_selection(
      [next_owned](const Triangulation<dim> &tria)
      { return next_owned(tria, tria.begin_active()); },
      [next_owned](const Triangulation<dim>                         &tria,
                   const typename Triangulation<dim>::cell_iterator &cell)
      {
        cell_iterator next(cell);
        return next_owned(tria, ++next);
      });
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(ghosted_displacement(),
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             interpretation);
    if (integrator)
      data_out.add_data_vector(ghosted_velocity,
                               std::vector<std::string>(dim, "velocity"),
                               DataOut<dim>::type_dof_data,
                               interpretation);
    for (unsigned int s = 0; s < n_stress; ++s)
      data_out.add_data_vector(stress[s], stress_names[s]);
    data_out.add_data_vector(von_mises, "von_mises");
    if (any_history)
      data_out.add_data_vector(plastic_strain, "PEEQ");
    data_out.add_data_vector(body_id, "body_id");
    // Contact fields at the slave nodes, under the names Abaqus and
    // CalculiX users know: scalars on the support points of the mesh's
    // degree (on Q2 the faces' middle nodes carry contact too), CSHEAR as a
    // vector.
    FE_Q<dim>       node_fe(parameters.finite_element.degree);
    DoFHandler<dim> node_dof_handler(triangulation);
    std::array<TrilinosWrappers::MPI::Vector, 4> contact_scalars;
    Vector                                       contact_shear;
    Vector                                       contact_force;
    if (contact)
    {
      // The contact force on every node (slave and master), the nodal
      // resultant of the contact tractions.
      Vector owned(locally_owned_dofs, mpi_communicator);
      for (const auto i : locally_owned_dofs)
        owned[i] = contact_forces[i];
      owned.compress(VectorOperation::insert);
      contact_force.reinit(locally_owned_dofs,
                           locally_relevant_dofs,
                           mpi_communicator);
      contact_force = owned;
      data_out.add_data_vector(contact_force,
                               std::vector<std::string>(dim, "contact_force"),
                               DataOut<dim>::type_dof_data,
                               interpretation);
      node_dof_handler.distribute_dofs(node_fe);
      std::map<types::global_dof_index, types::global_dof_index> scalar_dof;
      std::vector<types::global_dof_index> cell_dofs(fe->n_dofs_per_cell()),
        node_dofs(node_fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
        {
          const typename DoFHandler<dim>::active_cell_iterator node_cell(
            &triangulation,
            cell->level(),
            cell->index(),
            &node_dof_handler);
          cell->get_dof_indices(cell_dofs);
          node_cell->get_dof_indices(node_dofs);
          // The x dof of each support point names the node.
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
          {
            const auto [component, index] = fe->system_to_component_index(i);
            if (component == 0)
              scalar_dof[cell_dofs[i]] = node_dofs[index];
          }
        }
      const IndexSet node_owned = node_dof_handler.locally_owned_dofs();
      IndexSet       node_relevant;
      DoFTools::extract_locally_relevant_dofs(node_dof_handler, node_relevant);
      for (auto &v : contact_scalars)
        v.reinit(node_owned, mpi_communicator);
      Vector owned_shear(locally_owned_dofs, mpi_communicator);
      contact_output->nodal_fields(scalar_dof, contact_scalars, owned_shear);
      contact_shear.reinit(locally_owned_dofs,
                           locally_relevant_dofs,
                           mpi_communicator);
      contact_shear = owned_shear;
      for (auto &v : contact_scalars)
      {
        Vector ghosted(node_owned, node_relevant, mpi_communicator);
        ghosted = v;
        v.swap(ghosted);
      }
      const char *names[4] = {"CPRESS", "COPEN", "CSLIP", "CSTATUS"};
      for (unsigned int i = 0; i < 4; ++i)
        data_out.add_data_vector(node_dof_handler,
                                 contact_scalars[i],
                                 names[i]);
      data_out.add_data_vector(contact_shear,
                               std::vector<std::string>(dim, "CSHEAR"),
                               DataOut<dim>::type_dof_data,
                               interpretation);
    }

    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    if (n_ranks > 1)
      data_out.add_data_vector(subdomain, "subdomain");
    data_out.build_patches(parameters.finite_element.degree);

    // zlib's fastest level: deal.II's default (best compression) took five
    // times as long for files 12 % smaller (Hertz 2D, doc/benchmarks.md).
    DataOutBase::VtkFlags flags;
    flags.time              = time;
    flags.cycle             = step;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);

    const std::string base = "solution-" + Utilities::int_to_string(step, 5);
    if (n_ranks == 1)
    {
      write_atomically(dir + base + ".vtu",
                       [&](std::ostream &out) { data_out.write_vtu(out); });
      pvd_records.emplace_back(time, base + ".vtu");
    }
    else
    {
      const std::string piece =
        base + "." + Utilities::int_to_string(rank, 4) + ".vtu";
      write_atomically(dir + piece,
                       [&](std::ostream &out) { data_out.write_vtu(out); });
      MPI_Barrier(mpi_communicator);
      if (rank == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < n_ranks; ++r)
          pieces.push_back(base + "." + Utilities::int_to_string(r, 4) +
                           ".vtu");
        write_atomically(dir + base + ".pvtu",
                         [&](std::ostream &out)
                         { data_out.write_pvtu_record(out, pieces); });
      }
      pvd_records.emplace_back(time, base + ".pvtu");
    }
    if (rank == 0)
      write_atomically(dir + "solution.pvd",
                       [&](std::ostream &out)
                       { DataOutBase::write_pvd_record(out, pvd_records); });
  }



  template <int dim>
  void
  Problem<dim>::warn(const std::string &message)
  {
    warnings.push_back(message);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::cerr << "tribos: WARNING: " << message << std::endl;
  }



  template <int dim>
  void
  Problem<dim>::write_summary(const std::string &status)
  {
    // Load balance: each process's time in the sections its share of the
    // cells and of the contact zone sets (collective, so before rank 0
    // alone goes on). A contact zone on one process makes the others wait.
    const std::vector<std::pair<std::string, Utilities::MPI::MinMaxAvg>>
      balance = {
        {"assembly",
         Utilities::MPI::min_max_avg(own_assembly_time, mpi_communicator)},
        {"contact",
         Utilities::MPI::min_max_avg(contact ? contact->own_time() : 0.,
                                     mpi_communicator)}};
    // The slave nodes each process evaluates (the contact's share of the
    // work, whatever their state).
    const auto slave_nodes =
      Utilities::MPI::min_max_avg(contact ?
                                    double(contact->n_own_slave_nodes()) :
                                    0.,
                                  mpi_communicator);
    // Communication: the values each process receives per update of the
    // ghosted solution (all of them, and the contact's share), and the
    // contact across processes.
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    const auto ghosts =
      Utilities::MPI::min_max_avg(double(system_relevant.n_elements() -
                                         system_owned.n_elements()),
                                  mpi_communicator);
    const auto contact_ghosts =
      Utilities::MPI::min_max_avg(double(n_contact_ghosts), mpi_communicator);
    const auto crossings =
      contact ? contact->process_crossings() : std::pair<unsigned, unsigned>();
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    const auto peak_memory =
      Utilities::MPI::min_max_avg(memory.VmHWM / 1024., mpi_communicator);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    const StepperTotals totals = stepper ? stepper->totals() : StepperTotals();
    const auto wall  = timer.get_summary_data(TimerOutput::total_wall_time);
    const auto calls = timer.get_summary_data(TimerOutput::n_calls);
    double     total = 0;
    for (const auto &[section, seconds] : wall)
      total += seconds;

    write_atomically(
      parameters.output.directory + "/summary.txt",
      [&](std::ostream &out)
      {
        out << "status            " << status << '\n'
            << "dimension         " << dim << '\n'
            << "scene             " << parameters.scene.name << '\n'
            << "cells             " << triangulation.n_global_active_cells()
            << '\n'
            << "dofs              " << dof_handler.n_dofs() << '\n'
            << "contact dofs      "
            << (contact ? contact->contact_dofs().n_elements() : 0) << '\n'
            << "multipliers       " << n_multipliers << '\n'
            << "bodies            " << n_bodies << '\n'
            << "MPI processes     "
            << Utilities::MPI::n_mpi_processes(mpi_communicator) << '\n'
            << "increments        " << totals.n_increments << '\n'
            << "newton iterations " << totals.n_newton_iterations << '\n'
            << "newton iterations (all attempts) "
            << (restart ? restart->stepper.totals.n_linear_solves : 0) +
                 (newton ? newton->n_linear_solves() : 0)
            << '\n'
            << "cutbacks          " << totals.n_cutbacks << '\n'
            << "linear solver     "
            << (linear_solver && !linear_solver->method().empty() ?
                  linear_solver->method() :
                  "none")
            << '\n';
        if (linear_solver && linear_solver->n_iterations() > 0)
          out << "linear iterations " << linear_solver->n_iterations() << '\n'
              << "AMG setups        "
              << linear_solver->n_preconditioner_setups() << '\n';
        if (linear_solver && linear_solver->n_refinements() > 0)
          out << "refinement steps  " << linear_solver->n_refinements() << '\n';
        if (parameters.nonlinear_solver.stabilization > 0)
          out << "largest stabilization ratio "
              << totals.largest_stabilization_ratio << '\n';
        out << "peak memory       " << peak_memory.max
            << " MB per process (max), " << peak_memory.sum << " MB in all\n";
        if (n_ranks > 1)
        {
          for (const auto &[section, t] : balance)
          {
            out << "balance " << std::left << std::setw(10) << section
                << std::right << "min " << t.min << " s, max " << t.max
                << " s, max/min ";
            if (t.min > 0)
              out << t.max / t.min << '\n';
            else
              out << (t.max > 0 ? "inf" : "-") << '\n';
          }
          if (contact)
            out << "balance slave nodes min " << slave_nodes.min << ", max "
                << slave_nodes.max << " per process\n";
          out << "ghost values      max " << ghosts.max << " per process ("
              << 8 * ghosts.max << " bytes per update), of which contact "
              << contact_ghosts.max << '\n';
          if (contact)
            out << "contact across processes " << crossings.first
                << " slave nodes at the end, " << crossings.second
                << " master face changes of process\n";
        }
        if (contact && slave_nodes.sum > 0 && balance[0].second.sum > 0)
        {
          // A cell with a slave face carries about one slave node: its
          // weight is one cell's assembly and one node's contact work,
          // in units of a cell's assembly (sums over the processes).
          const double per_cell =
            balance[0].second.sum / triangulation.n_global_active_cells();
          const double per_node = balance[1].second.sum / slave_nodes.sum;
          out << "contact cell weight " << std::lround(1 + per_node / per_cell)
              << " would balance the measured work (Parallel/Contact cell "
                 "weight = "
              << parameters.parallel.contact_cell_weight << ")\n";
        }
        if (last_rebalance.count > 0)
          out << "rebalanced        " << last_rebalance.count
              << " time(s), the last after step " << last_rebalance.step
              << " (contact time max/min " << last_rebalance.imbalance
              << "); balance and sections since then\n";
        for (const auto &w : warnings)
          out << "warning           " << w << '\n';
        out << "\nsection               calls    wall [s]  share\n";
        for (const auto &[section, seconds] : wall)
          out << std::left << std::setw(20) << section << std::right
              << std::setw(8) << static_cast<unsigned int>(calls.at(section))
              << ' ' << std::setw(11) << std::fixed << std::setprecision(4)
              << seconds << ' ' << std::setw(6) << std::setprecision(2)
              << (total > 0 ? 100 * seconds / total : 0) << "%\n"
              << std::defaultfloat;
      });
  }

  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
