#include <tribos/base/exceptions.h>
#include <tribos/base/interruption.h>
#include <tribos/core/model_checks.h>
#include <tribos/run/simulation.h>
#include <tribos/scene/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <filesystem>
#include <iostream>
#include <sstream>

namespace tribos
{
  template <int dim>
  Simulation<dim>::Simulation(const Parameters::AllParameters &parameters,
                              const MPI_Comm                   mpi_communicator,
                              const Rebalance                 &previous)
    : parameters(parameters)
    , mpi_communicator(mpi_communicator)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , timer(MPI_COMM_SELF, pcout, TimerOutput::never, TimerOutput::wall_times)
    , warnings(mpi_communicator)
    , model(parameters, mpi_communicator, timer, warnings)
    , problem(
        parameters,
        model,
        timer,
        [this](const std::string &line) { pcout << line << std::endl; },
        warnings)
    , checkpointer(parameters,
                   model,
                   problem,
                   timer,
                   [this](const std::string &line)
                   { pcout << line << std::endl; })
    , last_rebalance(previous)
  {
  }



  template <int dim>
  void
  Simulation<dim>::run()
  {
    run_clock.restart();
    problem.setup(last_rebalance.count > 0 ? &last_rebalance.weights : nullptr);
    if (!parameters.restart_directory.empty())
    {
      restart = std::make_unique<Checkpoint>();
      restart->load(parameters.restart_directory);
      // An adapted mesh: the coarse mesh refined to the checkpoint's cells
      // before anything is compared.
      if (parameters.adaptivity.enable)
      {
        AssertThrow(restart->scalars.count("adaptations") == 1,
                    ExcMessage("--restart <" + parameters.restart_directory +
                               ">: the checkpoint was written without "
                               "Adaptivity/Enable: restart with the "
                               "Adaptivity of the run that wrote it."));
        problem.refine_to(restart->cells);
      }
      checkpointer.check(*restart);
    }
    // The last moment a signal leaves the output directory untouched
    // (a rebalanced run's has its earlier steps: it stops in Newton).
    if (last_rebalance.count == 0)
      Interruption::check(mpi_communicator, true);
    output = std::make_unique<RunOutput<dim>>(parameters,
                                              model,
                                              problem,
                                              warnings,
                                              timer);
    output->open(restart.get());

    const auto         n_bodies = problem.materials().bodies().size();
    std::ostringstream header;
    header << "tribos: " << dim << "D scene <" << parameters.scene.name << ">, "
           << model.triangulation().n_global_active_cells() << " cells, "
           << model.dof_handler().n_dofs() << " dofs, " << n_bodies
           << (n_bodies == 1 ? " body, " : " bodies, ")
           << Utilities::MPI::n_mpi_processes(mpi_communicator)
           << " MPI process(es)";
    output->print(header.str());
    // (The scene was built on the first process: in a distributed mesh
    // only there.)
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      for (const auto &line : parameters.scene.geometry->describe())
        output->print("  " + line);
    if (problem.contact() != nullptr)
      for (const auto &line : problem.contact()->describe())
        output->print("  " + line);

    StepperState start;
    if (restart)
    {
      checkpointer.read(*restart);
      start = restart->stepper;
    }
    else
      output->write_step(0, 0.);
    if (last_rebalance.count > 0)
    {
      std::ostringstream line;
      line << "  rebalanced: the contact time's max/min over the processes "
              "was "
           << last_rebalance.imbalance << " in step " << last_rebalance.step
           << "; the mesh is partitioned with the measured contact work";
      output->print(line.str());
      // The state was only the means of the rebalance.
      if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
        std::filesystem::remove_all(last_rebalance.checkpoint);
    }

    make_solvers();
    if (restart && parameters.adaptivity.enable)
      restart_adaptation(start);
    step_clock.restart();
    try
    {
      stepper->run(problem,
                   *this,
                   start,
                   start.change_increment > 0 ? &checkpointer.restart_change() :
                                                nullptr);
    }
    catch (const Interrupted &signal)
    {
      // Between iterations: every file written is whole.
      output->write_summary("INTERRUPTED (" +
                              Interrupted::name(signal.signal_number()) +
                              "); outputs of the converged steps are kept",
                            totals());
      throw;
    }

    end_of_run_warnings();
    output->write_summary("completed", totals());
    const auto        &sums = stepper->totals();
    std::ostringstream line;
    line << "done: " << sums.n_increments << " increments, "
         << sums.n_newton_iterations << " Newton iterations ("
         << totals().n_linear_solves << " with failed attempts), "
         << sums.n_cutbacks << " cutbacks, "
         << (sums.n_rejections > 0 ? std::to_string(sums.n_rejections) +
                                       " increments rejected for accuracy, " :
                                     std::string())
         << last_rebalance.elapsed + run_clock.wall_time() << " s; output in "
         << parameters.output.directory;
    output->print(line.str());
  }



  template <int dim>
  void
  Simulation<dim>::make_solvers()
  {
    // The solvers: the linear solve of a Newton iteration (AMG gets the
    // rigid-body modes as its near-null space), Newton, and the load
    // stepping around it.
    const auto n_multipliers = model.layout().n_multipliers;
    linear_solver = std::make_unique<LinearSolver>(parameters.linear_solver,
                                                   dim,
                                                   n_multipliers > 0);
    linear_solver->set_timer(timer);
    attach_linear_solver();
    newton  = std::make_unique<NewtonSolver>(parameters.nonlinear_solver,
                                            *linear_solver);
    stepper = std::make_unique<LoadStepper>(parameters.time_stepping, *newton);
  }



  template <int dim>
  void
  Simulation<dim>::attach_linear_solver()
  {
    problem.attach(*linear_solver);
    if (model.layout().n_multipliers > 0)
      linear_solver->set_multiplier_blocks(model.dof_handler().n_dofs(), dim);
    if (linear_solver->iterative(problem.system_matrix()))
      linear_solver->set_near_null_space(model.rigid_body_modes(),
                                         parameters.finite_element.degree > 1);
  }



  template <int dim>
  RunTotals
  Simulation<dim>::totals() const
  {
    RunTotals t;
    if (stepper)
      t.stepper = stepper->totals();
    t.n_linear_solves =
      (restart ? restart->stepper.totals.n_linear_solves : 0) +
      (newton ? newton->n_linear_solves() : 0);
    t.linear_solver               = linear_solver.get();
    t.largest_stabilization_ratio = problem.stabilization().largest_ratio();
    t.n_rebalances                = last_rebalance.count;
    t.n_adaptations               = n_adaptations;
    t.n_redone_increments         = n_redone_increments;
    t.rebalance_step              = last_rebalance.step;
    t.imbalance                   = last_rebalance.imbalance;
    return t;
  }



  template <int dim>
  void
  Simulation<dim>::attempt(const unsigned int step,
                           const unsigned int increment,
                           const double       time)
  {
    output->attempt(step, increment, time);
  }



  template <int dim>
  void
  Simulation<dim>::iteration(const IterationRecord &record)
  {
    output->iteration(record);
    Interruption::check(mpi_communicator);
  }



  template <int dim>
  void
  Simulation<dim>::increment_converged(const IncrementRecord &record)
  {
    output->increment_converged(record);
  }



  template <int dim>
  void
  Simulation<dim>::message(const std::string &text)
  {
    output->message(text);
  }



  template <int dim>
  void
  Simulation<dim>::step_completed(const StepRecord &record)
  {
    output->step_completed(record);
    const unsigned int step    = record.step;
    const unsigned int n_steps = parameters.time_stepping.n_step_ends();
    // The indicator of the step's state goes into its output (and decides
    // the adaptation after the step).
    const bool output_step = parameters.output.is_output_step(step, n_steps) ||
                             parameters.time_stepping.is_output_time(step);
    if (parameters.adaptivity.enable && (adapts_after(step) || output_step))
      problem.estimate_error();
    if (output_step)
      output->write_step(step, record.time);
    const unsigned int every = parameters.output.checkpoint_every;
    if (every > 0 && (step % every == 0 || step == n_steps))
      write_checkpoint(step,
                       parameters.output.directory + "/checkpoint-" +
                         Utilities::int_to_string(step, 5));
    check_balance(step);
  }



  template <int dim>
  void
  Simulation<dim>::failed(const std::string &reason)
  {
    end_of_run_warnings();
    output->write_summary("FAILED: " + reason, totals());
  }



  template <int dim>
  void
  Simulation<dim>::end_of_run_warnings()
  {
    if (problem.contact() == nullptr)
      return;
    for (const auto &w : problem.contact()->run_warnings())
      warnings.warn(w);
    // Unloaded by the parameters, a model is loaded by its contact only
    // where bodies were meshed overlapping: a contact force above the
    // round-off bound (a stress of 1e-10 E_max on the model's area; two
    // bodies that merely touch carry round-off) says it was.
    const std::string unloaded = nothing_loads_warning(parameters);
    if (!unloaded.empty() && problem.contact_forces().linfty_norm() <=
                               problem.stagnation_residual_bound())
      warnings.warn(unloaded);
  }



  template <int dim>
  void
  Simulation<dim>::write_checkpoint(const unsigned int step,
                                    const std::string &directory)
  {
    AssertThrow(stepper->state().step == step,
                ExcInternalError("checkpoint of another step"));
    checkpointer.write(stepper->state(),
                       stepper->last_change(),
                       output->pvd_records(),
                       parameters.adaptivity.enable ?
                         std::map<std::string, double>{
                           {"adaptations", n_adaptations},
                           {"redone increments", n_redone_increments}} :
                         std::map<std::string, double>(),
                       directory);
  }



  template class Simulation<2>;
  template class Simulation<3>;
} // namespace tribos
