#ifndef tribos_core_dynamics_state_h
#define tribos_core_dynamics_state_h

#include <tribos/core/material_state.h>
#include <tribos/parameters/all_parameters.h>
#include <tribos/solver/time_integrator.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * The state of implicit dynamics (Time stepping/Integrator = Newmark or
   * generalized-alpha): the integrator, the velocity and acceleration of
   * the displacement dofs at the last converged time, the displacement and
   * the static forces there (the alpha_f share of the balance), the mass
   * (consistent or lumped, with the mass of the contact nodes moved to
   * their cells' other nodes: Contact mass removal), and the energy sums.
   * The inertia of a cell enters the bulk assembly through add_inertia();
   * everything is updated only by commit() (a cut increment needs no
   * restore).
   */
  template <int dim>
  class DynamicsState
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** Kinetic and stored strain energy and the linear momentum. */
    struct Energies
    {
      double         kinetic = 0, stored = 0;
      Tensor<1, dim> momentum;
    };

    /** The dofs and index sets of the problem, what the state lives on. */
    struct Layout
    {
      const DoFHandler<dim> *dof_handler = nullptr;
      /** This process's cells in the order of the sums
       * (Model::owned_cells()). */
      const std::vector<typename DoFHandler<dim>::active_cell_iterator>
        *owned_cells = nullptr;
      /** The cells' reference geometry. */
      const Mapping<dim>       *mapping    = nullptr;
      const FiniteElement<dim> *fe         = nullptr;
      const Quadrature<dim>    *quadrature = nullptr;
      IndexSet                  owned, relevant, system_owned;
      /** Vector component and body of every dof. */
      const std::vector<unsigned char>      *dof_component = nullptr;
      const std::vector<types::material_id> *dof_body      = nullptr;
      MPI_Comm                               communicator;
    };

    /**
     * The state for @p layout: densities per body of @p materials, the
     * massless dofs (the contact dofs @p contact_dofs, if given, with
     * Contact mass removal), the dofs of the Dirichlet conditions
     * (@p reaction_dofs: per condition and component), and the initial
     * velocity (Time stepping/Initial velocity), with @p homogeneous
     * constraints applied. The displacement at t = 0 is @p u.
     */
    DynamicsState(const Parameters::AllParameters          &parameters,
                  const Layout                             &layout,
                  const MaterialState<dim>                 &materials,
                  const IndexSet                           *contact_dofs,
                  const std::vector<std::vector<IndexSet>> &reaction_dofs,
                  const AffineConstraints<double>          &homogeneous,
                  const Vector                             &u);

    const TimeIntegrator &
    integrator() const
    {
      return time_integrator;
    }

    /** The step of the increment that ends at @p time. */
    void
    begin_increment(const double time)
    {
      time_integrator.set_step(time - committed_time);
    }

    /** Whether the assembly adds inertia (not while a_0 is computed). */
    bool
    with_inertia() const
    {
      return inertia_on;
    }

    /** Per-thread buffers of add_inertia(). */
    struct Scratch
    {
      FullMatrix<double>  mass;
      std::vector<double> mid_acceleration, end_acceleration, mass_weight;
    };

    /**
     * The inertia of a cell (FEValues @p fe_values reinitialized on it,
     * @p dof_indices, their @p component, body @p body) at the displacement
     * @p u: M a_{n+1-alpha_m} + (1 - alpha_f) R(u_{n+1}), with -R in
     * @p cell_rhs on entry (its static part is kept in @p cell_static,
     * M a_{n+1} goes to @p cell_inertia).
     */
    void
    add_inertia(const FEValues<dim>                        &fe_values,
                const std::vector<types::global_dof_index> &dof_indices,
                const std::vector<unsigned int>            &component,
                const types::material_id                    body,
                const Vector                               &u,
                const bool                                  with_matrix,
                dealii::Vector<double>                     &cell_rhs,
                FullMatrix<double>                         &cell_matrix,
                dealii::Vector<double>                     &cell_static,
                dealii::Vector<double>                     &cell_inertia,
                Scratch                                    &scratch) const;

    /** The alpha_f share of the forces at t_n, condensed with
     * @p homogeneous into @p free_residual and, if given, @p rhs. */
    void
    add_old_forces(const AffineConstraints<double> &homogeneous,
                   Vector                          &free_residual,
                   Vector                          *rhs) const;

    /** M a_{n+1} of the last assembly (unconstrained), system-sized. */
    Vector &
    inertia_forces()
    {
      return inertia;
    }
    const Vector &
    inertia_forces() const
    {
      return inertia;
    }

    /**
     * M a_0 = f_ext - f_int - f_contact at t = 0, from the forces of a
     * static assembly at t = 0 (@p assemble_static: no inertia): its free
     * residual @p free_residual, the unconstrained @p full_residual, the
     * @p contact_forces and @p external_forces; solved if the force
     * exceeds @p force_floor. Returns the message for the log (empty if
     * a_0 = 0).
     */
    std::string
    initial_acceleration(const std::function<void()>     &assemble_static,
                         const Vector                    &free_residual,
                         const Vector                    &full_residual,
                         const Vector                    *contact_forces,
                         const Vector                    &external_forces,
                         const AffineConstraints<double> &homogeneous,
                         const double                     force_floor);

    /**
     * A converged increment ending at @p time at displacement @p u: the
     * end-of-step velocity and acceleration, the old forces and the
     * energy sums (from the assembly's @p full_residual, @p contact_forces
     * and @p external_forces; the friction's @p dissipation), and the
     * energies with the @p stored strain energy of the new state.
     */
    void
    commit(const Vector                  &u,
           const Vector                  &full_residual,
           const Vector                  *contact_forces,
           const Vector                  &external_forces,
           const double                   dissipation,
           const double                   time,
           const std::function<double()> &stored);

    /** The kinetic energy and momentum of the velocity, and the @p stored
     * energy given (collective). */
    Energies
    energies(const double stored) const;

    /** Call @p f with the dofs and the mass matrix of every locally owned
     * cell (the contact mass removed or not). */
    void
    for_each_cell_mass(
      const bool remove_contact_mass,
      const std::function<void(const std::vector<types::global_dof_index> &,
                               const FullMatrix<double> &)> &f) const;

    /** The velocity at the last converged time (ghosted). */
    const Vector &
    velocity() const
    {
      return ghosted_velocity;
    }

    /** The energies and sums of the last converged state, by name:
     * kinetic_energy, strain_energy, internal_work, contact_work,
     * friction_work, external_work, initial_kinetic_energy. */
    std::map<std::string, double>
    scalars() const;

    const Tensor<1, dim> &
    momentum() const
    {
      return current.momentum;
    }

    /** The vectors a checkpoint keeps, by name (owned entries). */
    std::map<std::string, const Vector *>
    checkpoint_vectors() const;

    /** The energies at t = 0, with the @p stored energy of the initial
     * state (collective). */
    void
    start(const double stored);

    /** Set the state of a restart at @p time: the vectors set by
     * @p set_vector (by the names of checkpoint_vectors()), the
     * @p scalars of scalars() and the displacement @p u. */
    void
    restart(
      const std::function<void(const std::string &, Vector &)> &set_vector,
      const std::map<std::string, double>                      &scalars,
      const Vector                                             &u,
      const double                                              time);

    /** The log line of the setup. */
    std::string
    describe() const;

  private:
    /**
     * The mass matrix of a cell (FEValues @p fe_values reinitialized on
     * it) into @p mass: consistent, or lumped (row sums) with the mass of
     * the massless dofs moved to the cell's others.
     */
    void
    cell_mass_matrix(const FEValues<dim>                        &fe_values,
                     const std::vector<types::global_dof_index> &dof_indices,
                     const std::vector<unsigned int>            &component,
                     const double                                density,
                     FullMatrix<double>                         &mass,
                     const bool remove_contact_mass = true) const;

    const Parameters::AllParameters &parameters;
    Layout                           layout;
    TimeIntegrator                   time_integrator;
    bool                             inertia_on     = true;
    double                           committed_time = 0;
    /** The density of each body of the mesh, by its id. */
    std::map<types::material_id, double> densities;
    Vector velocity_owned, acceleration, ghosted_velocity, ghosted_acceleration,
      ghosted_start;
    /** R = f_int - f_contact - f_ext at t_n (a massless row: 0). */
    Vector old_forces;
    Vector inertia;
    /** The contact, external (applied plus Dirichlet reaction) and internal
     * forces at t_n, for the trapezoidal work sums. */
    Vector old_contact_forces, old_external, old_internal;
    /** Dofs whose lumped mass is moved away, and those whose assembled mass
     * is zero (their rows are quasi-static). */
    IndexSet massless_dofs, massless_rows;
    /** The constrained components of the Dirichlet conditions. */
    IndexSet dirichlet_dofs;
    Energies current;
    double   internal_work = 0, contact_work = 0, friction_work = 0,
           external_work = 0, initial_kinetic_energy = 0;
  };
} // namespace tribos

#endif
