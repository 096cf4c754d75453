#ifndef tribos_core_checkpointer_h
#define tribos_core_checkpointer_h

#include <tribos/core/checkpoint.h>
#include <tribos/core/model.h>
#include <tribos/core/problem.h>
#include <tribos/parameters/all_parameters.h>
#include <tribos/solver/load_stepper.h>

#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * Checkpoints and restarts of a Problem on its Model: the converged state
   * written per active cell and per slave node, so that a run can go on
   * from it with another number of MPI processes and either Parallel/Mesh
   * (the mesh is the same: it is built from the parameter file; cells are
   * named by their CellId, which no partition changes). A checkpoint is
   * checked against the run before anything is read (sizes, the parameters
   * the state depends on, the mesh's moments).
   */
  template <int dim>
  class Checkpointer
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** @p timer gets the writing in its section "output"; @p log prints
     * the restart's line. */
    Checkpointer(const Parameters::AllParameters                &parameters,
                 const Model<dim>                               &model,
                 Problem<dim>                                   &problem,
                 TimerOutput                                    &timer,
                 const std::function<void(const std::string &)> &log);

    /**
     * The converged state after nominal step @p stepper.step (the stepper's
     * state, the change of its last increment @p change, the VTU series
     * @p pvd_records, the run's own counts @p run_scalars, e.g. its
     * adaptations) into @p directory. Collective.
     */
    void
    write(const StepperState                                &stepper,
          const Vector                                      &change,
          const std::vector<std::pair<double, std::string>> &pvd_records,
          const std::map<std::string, double>               &run_scalars,
          const std::string                                 &directory) const;

    /** Whether @p checkpoint fits this run (mesh, dofs, the entries that
     * define the model, steps): a clear error before any output is
     * touched, naming every entry that differs with both values.
     * Collective. */
    void
    check(const Checkpoint &checkpoint) const;

    /**
     * Whether a restart may give the entry @p path ("Section/Entry")
     * another value than the run that wrote the checkpoint: where the run
     * ends (Time stepping/End time, Number of steps), how its remaining
     * increments are sized and solved (the other entries of Time stepping
     * but the integrator's, Nonlinear solver, Linear solver, Parallel), what
     * it writes (Output, Verification) and the name of the mesh file (its
     * mesh is compared: cells, dofs, the vertices' and ids' moments). Every
     * other entry defines the model the checkpoint's state belongs to (the
     * scene, the element, materials, loads, contact, Adaptivity) and must
     * be the checkpoint's: an allow-list, so that an entry added later is
     * compared unless it is put here on purpose.
     */
    static bool
    may_change_at_restart(const std::string &path);

    /** The entries of may_change_at_restart(), for messages and the
     * README. */
    static std::string
    may_change_at_restart_list();

    /** Read @p checkpoint into the state of the (set up) problem.
     * Collective. */
    void
    read(const Checkpoint &checkpoint);

    /** A restart's change of the unknowns over its last increment (the
     * load stepper's extrapolation goes on from it). */
    const Vector &
    restart_change() const;
    /** The same, to be carried over onto an adapted mesh. */
    Vector &
    restart_change();

  private:
    /** What a checkpoint's state depends on beyond the sizes of the
     * mesh and dofs, by name, as text: every entry but those of
     * may_change_at_restart(), as written, the materials' constants as
     * parsed (resolved_values()). checkpointer_fingerprint.cc. */
    std::map<std::string, std::string>
    fingerprint() const;
    /** The scene's name, the pairs with the penalty formulation and
     * master smoothing each got (automatic resolved), the material models
     * and constants (parsed: the same numbers written otherwise are the
     * same model). */
    std::map<std::string, std::string>
    resolved_values() const;
    /** The entries of this run that differ from @p checkpoint's
     * fingerprint, each "name <there> there, <here> here". */
    std::vector<std::string>
    changed_entries(const Checkpoint &checkpoint) const;
    /** Moments of the vertex coordinates of the mesh (collective). */
    std::map<std::string, double>
    geometry_moments() const;
    /** The values of @p v (dof-sized, owned) per active cell, gathered on
     * rank 0 in CellId order (the cells' CellIds into @p cells if given). */
    std::vector<double>
    cell_values(const Vector                         &v,
                std::vector<std::array<unsigned, 4>> *cells = nullptr) const;
    /** Set the owned entries of @p v (dof-sized or the system vector) from
     * cell_values() of the cells @p cells of a checkpoint. */
    void
    set_from_cell_values(const std::vector<std::array<unsigned, 4>> &cells,
                         const std::vector<double>                  &values,
                         Vector                                     &v) const;

    const Parameters::AllParameters               &parameters;
    const Model<dim>                              &model;
    Problem<dim>                                  &problem;
    TimerOutput                                   &timer;
    const std::function<void(const std::string &)> log;
    MPI_Comm                                       mpi_communicator;
    /** See restart_change(). */
    Vector change_of_restart;
  };
} // namespace tribos

#endif
