#include <tribos/core/vector_function.h>
#include <tribos/postprocess/run_output.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <regex>
#include <sstream>

namespace tribos
{
  namespace
  {
    const char *const axis = "xyz";

    /**
     * The step of a file or folder name of the run's own output series,
     * which a fresh run may remove: solution-NNNNN.vtu, solution-NNNNN.pvtu,
     * solution-NNNNN.RRRR.vtu, contact-NNNNN.csv, checkpoint-NNNNN (NNNNN
     * five digits or more), each possibly with the ".part" of an
     * interrupted write. Nothing for every other name.
     */
    std::optional<unsigned long>
    series_step(const std::string &name)
    {
      static const std::regex series(
        R"((solution-([0-9]{5,})(\.[0-9]{4})?\.(vtu|pvtu)|)"
        R"(contact-([0-9]{5,})\.csv|checkpoint-([0-9]{5,}))(\.part|\.old)?)");
      std::smatch match;
      if (!std::regex_match(name, match, series))
        return std::nullopt;
      for (const unsigned int group : {2u, 5u, 6u})
        if (match[group].matched && match[group].length() < 10)
          return std::stoul(match[group].str());
      return std::nullopt;
    }

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
  RunOutput<dim>::RunOutput(const Parameters::AllParameters &parameters,
                            const Model<dim>                &model,
                            const Problem<dim>              &problem,
                            const Warnings                  &warnings,
                            TimerOutput                     &timer)
    : model(model)
    , problem(problem)
    , warnings(warnings)
    , parameters(parameters)
    , mpi_communicator(model.communicator())
    , timer(timer)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
  {
    if (problem.contact() != nullptr)
      contact_output = std::make_unique<ContactOutput<dim>>(*problem.contact());
    if (!parameters.verification.exact_displacement.empty())
      exact_displacement =
        make_vector_function<dim>(parameters.verification.exact_displacement,
                                  "Verification/Exact displacement");
  }



  template <int dim>
  void
  RunOutput<dim>::mesh_changed()
  {
    if (problem.contact() != nullptr)
      contact_output = std::make_unique<ContactOutput<dim>>(*problem.contact());
    find_probe_dofs();
  }



  template <int dim>
  void
  RunOutput<dim>::print(const std::string &line)
  {
    pcout << line << std::endl;
  }



  template <int dim>
  void
  RunOutput<dim>::message(const std::string &text)
  {
    print(text);
  }



  template <int dim>
  void
  RunOutput<dim>::open(const Checkpoint *restart)
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
          directory_lock =
            std::make_unique<DirectoryLock>(dir, "Output/Directory");
        }
      });

    const std::vector<std::string> columns = history_columns();
    if (restart != nullptr)
      records = restart->pvd_records;
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
                                                  "order",
                                                  "correction_norm"},
                         root,
                         keep);
                     });
    // Only once the CSV files of an earlier run have been read (a restart
    // refuses a malformed one before anything is lost).
    on_every_process(
      mpi_communicator,
      [&]()
      {
        if (!root)
          return;
        // Remove the series files and checkpoints of an earlier run, so
        // that the folder holds one consistent run: only names of the
        // run's own series (solution-NNNNN.vtu, .pvtu and rank pieces,
        // contact-NNNNN.csv, checkpoint-NNNNN/, and their ".part"
        // leftovers); a user's contact-notes.txt or
        // checkpoint-important/ stays. A restart keeps those of the steps
        // up to its checkpoint (and the checkpoint it reads).
        std::vector<std::filesystem::path> stale;
        for (const auto &entry : std::filesystem::directory_iterator(dir))
        {
          const auto step = series_step(entry.path().filename().string());
          if (!step)
            continue;
          const bool is_checkpoint =
            entry.path().filename().string().rfind("checkpoint-", 0) == 0;
          std::error_code same;
          if ((is_checkpoint ? entry.is_directory() :
                               entry.is_regular_file()) &&
              (!restart || *step > restart->stepper.step) &&
              !(restart &&
                std::filesystem::equivalent(entry.path(),
                                            parameters.restart_directory,
                                            same)))
            stale.push_back(entry.path());
        }
        for (const auto &path : stale)
          std::filesystem::remove_all(path);
      });
  }



  template <int dim>
  void
  RunOutput<dim>::find_probe_dofs()
  {
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
      for (const auto &cell : model.dof_handler().active_cell_iterators())
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
    }
  }



  template <int dim>
  std::vector<std::string>
  RunOutput<dim>::history_columns()
  {
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
    find_probe_dofs();
    for (unsigned int k = 0; k < probe_dofs.size(); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        columns.push_back("probe" + std::to_string(k) + "_u" + axis[d]);
    if (contact_output)
    {
      for (const auto &name : contact_output->column_names())
        columns.push_back(name);
      columns.push_back("augmentations");
      columns.push_back("chattering_nodes");
    }
    if (problem.dynamics() != nullptr)
    {
      for (const char *name : {"kinetic_energy",
                               "strain_energy",
                               "internal_work",
                               "contact_work",
                               "friction_work",
                               "external_work",
                               "total_energy",
                               "energy_error"})
        columns.push_back(name);
      for (unsigned int d = 0; d < dim; ++d)
        columns.push_back(std::string("momentum_") + "xyz"[d]);
    }
    if (parameters.nonlinear_solver.stabilization > 0)
    {
      columns.push_back("stabilization_force");
      columns.push_back("stabilization_ratio");
      columns.push_back("stabilization_relaxations");
    }
    if (parameters.adaptivity.enable)
      columns.push_back("dofs");
    return columns;
  }



  template <int dim>
  std::pair<double, double>
  RunOutput<dim>::displacement_errors(const double time) const
  {
    const auto &dof_handler   = model.dof_handler();
    const auto &triangulation = model.triangulation();
    exact_displacement->set_time(time);
    const ReferenceCell   cell_kind = model.fe().reference_cell();
    const Quadrature<dim> error_quadrature =
      cell_kind.template get_gauss_type_quadrature<dim>(
        // deal.II's simplex Gauss rules go up to 4 points per direction
        // (exact for degree 7).
        cell_kind.is_simplex() ? 4 : parameters.finite_element.degree + 3);
    const Mapping<dim>   &mapping = model.mapping();
    dealii::Vector<float> cellwise(triangulation.n_active_cells());
    VectorTools::integrate_difference(mapping,
                                      dof_handler,
                                      problem.displacement(),
                                      *exact_displacement,
                                      cellwise,
                                      error_quadrature,
                                      VectorTools::L2_norm);
    const double l2 = VectorTools::compute_global_error(triangulation,
                                                        cellwise,
                                                        VectorTools::L2_norm);
    VectorTools::integrate_difference(mapping,
                                      dof_handler,
                                      problem.displacement(),
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
  RunOutput<dim>::attempt(const unsigned int step,
                          const unsigned int increment,
                          const double       time)
  {
    current_step      = step;
    current_increment = increment;
    current_time      = time;
  }



  template <int dim>
  void
  RunOutput<dim>::iteration(const IterationRecord &r)
  {
    convergence_csv->add_row({double(current_step),
                              double(current_increment),
                              current_time,
                              double(r.iteration),
                              r.residual,
                              r.relative_residual,
                              r.update_norm,
                              r.step_length,
                              r.order,
                              r.correction_norm});
  }



  template <int dim>
  void
  RunOutput<dim>::increment_converged(const IncrementRecord &record)
  {
    // The residual at the converged state: the last assembly was the one
    // that found convergence.
    const IncrementReport &report = record.report;
    const double           time   = record.time;
    std::vector<double>    row    = {double(record.step),
                                     double(record.increment),
                                     time,
                                     time / parameters.time_stepping.end_time,
                                     double(report.n_iterations),
                                     double(report.n_iterations_all),
                                     report.residual,
                                     double(record.n_cutbacks),
                                     record.wall_time};
    for (const double f : problem.reaction_forces())
      row.push_back(f);
    if (exact_displacement)
    {
      const auto [l2, h1] = displacement_errors(time);
      row.push_back(l2);
      row.push_back(h1);
    }
    const auto &owned = model.layout().locally_owned_dofs;
    for (const auto &dofs : probe_dofs)
      for (const auto dof : dofs)
        row.push_back(Utilities::MPI::sum(owned.is_element(dof) ?
                                            double(problem.unknowns()[dof]) :
                                            0.,
                                          mpi_communicator));
    if (contact_output)
    {
      for (const double value : contact_output->columns())
        row.push_back(value);
      row.push_back(problem.contact_counters().n_augmentations);
      row.push_back(problem.contact_counters().n_chattering);
    }
    if (const auto *dynamics = problem.dynamics())
    {
      // total_energy: the bodies' energy plus what the contact took (the
      // penalty springs' energy, friction, impact losses). energy_error:
      // what the time integrator created (> 0) or dissipated (< 0), the
      // balance of the trapezoidal work sums E_kin - E_kin,0 + W_int +
      // W_contact - W_external: zero to round-off for Newmark's average
      // acceleration rule, whatever the material and the contact.
      const auto   e = dynamics->scalars();
      const double total =
        e.at("kinetic_energy") + e.at("strain_energy") + e.at("contact_work");
      for (const double value :
           {e.at("kinetic_energy"),
            e.at("strain_energy"),
            e.at("internal_work"),
            e.at("contact_work"),
            e.at("friction_work"),
            e.at("external_work"),
            total,
            e.at("kinetic_energy") - e.at("initial_kinetic_energy") +
              e.at("internal_work") + e.at("contact_work") -
              e.at("external_work")})
        row.push_back(value);
      for (unsigned int d = 0; d < dim; ++d)
        row.push_back(dynamics->momentum()[d]);
    }
    if (parameters.nonlinear_solver.stabilization > 0)
    {
      const auto &springs = problem.stabilization().last_increment();
      row.push_back(springs.force);
      row.push_back(springs.ratio);
      row.push_back(springs.relaxations);
    }
    if (parameters.adaptivity.enable)
      row.push_back(model.dof_handler().n_dofs());
    history_csv->add_row(row);
  }



  template <int dim>
  void
  RunOutput<dim>::step_completed(const StepRecord &r)
  {
    std::ostringstream line;
    line << "step " << std::setw(4) << r.step << "/" << r.n_steps
         << "  t=" << std::setw(9) << std::setprecision(4) << r.time
         << "  lf=" << std::fixed << std::setprecision(3) << r.load_factor
         << std::defaultfloat << "  incr " << r.n_increments << "  newton "
         << std::setw(3) << r.n_iterations << " (all " << r.n_iterations_all
         << ")"
         << "  |R|=" << std::scientific << std::setprecision(2) << r.residual
         << std::defaultfloat << "  cutbacks " << r.n_cutbacks;
    if (r.n_rejections > 0)
      line << "  rejected " << r.n_rejections;
    if (contact_output)
    {
      const ContactStatistics s = contact_output->statistics();
      line << "  active/stick/slip " << s.n_active << "/" << s.n_stick << "/"
           << s.n_slip;
    }
    line << "  " << std::setprecision(3) << r.elapsed << " s  ETA " << r.eta
         << " s";
    print(line.str());
  }



  template class RunOutput<2>;
  template class RunOutput<3>;
} // namespace tribos
