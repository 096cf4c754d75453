/**
 * DynamicsState, the converged steps: commit() of a step's velocity,
 * acceleration and work sums, the energies, and the checkpoint and restart
 * of the state.
 */

#include <tribos/core/dynamics_state.h>

#include <deal.II/base/mpi.h>

#include <functional>
#include <map>
#include <string>

namespace tribos
{
  template <int dim>
  void
  DynamicsState<dim>::commit(const Vector                  &u,
                             const Vector                  &full_residual,
                             const Vector                  *contact_forces,
                             const Vector                  &external_forces,
                             const double                   dissipation,
                             const double                   time,
                             const std::function<double()> &stored)
  {
    const TimeIntegrator &integrator = time_integrator;
    const IndexSet       &owned      = layout.owned;
    double                works[3]   = {0, 0, 0};
    Vector                external(owned, layout.communicator);
    for (const auto i : owned)
    {
      const double du    = u[i] - ghosted_start[i];
      const double a_old = ghosted_acceleration[i], v_old = ghosted_velocity[i];
      if (dirichlet_dofs.is_element(i))
      {
        acceleration[i]   = integrator.prescribed_acceleration(du, v_old);
        velocity_owned[i] = integrator.prescribed_velocity(du);
      }
      else
      {
        const double a_new = integrator.acceleration(du, v_old, a_old);
        acceleration[i]    = a_new;
        velocity_owned[i]  = integrator.velocity(v_old, a_old, a_new);
      }
      const double contact_force =
        contact_forces != nullptr ? (*contact_forces)[i] : 0.;
      // The applied loads and, on Dirichlet dofs, the reactions
      // f_int - f_contact - f_ext + M a; the internal forces
      // R + f_contact + f_ext.
      external[i] = external_forces[i];
      if (dirichlet_dofs.is_element(i))
        external[i] += full_residual[i] + inertia[i];
      const double internal =
        full_residual[i] + contact_force + external_forces[i];
      // Trapezoidal sums: the work the contact forces take from the bodies,
      // the work the loads and supports give them, the internal work.
      works[0] -= 0.5 * (old_contact_forces[i] + contact_force) * du;
      works[1] += 0.5 * (old_external[i] + external[i]) * du;
      works[2] += 0.5 * (old_internal[i] + internal) * du;
      old_forces[i] = massless_rows.is_element(i) ? 0. : full_residual[i];
      old_contact_forces[i] = contact_force;
      old_internal[i]       = internal;
    }
    for (Vector *v : {&acceleration,
                      &velocity_owned,
                      &old_forces,
                      &old_contact_forces,
                      &old_internal,
                      &external})
      v->compress(VectorOperation::insert);
    old_external = external;
    contact_work += Utilities::MPI::sum(works[0], layout.communicator);
    external_work += Utilities::MPI::sum(works[1], layout.communicator);
    internal_work += Utilities::MPI::sum(works[2], layout.communicator);
    friction_work += dissipation;

    ghosted_velocity     = velocity_owned;
    ghosted_acceleration = acceleration;
    ghosted_start        = u;
    committed_time       = time;
    current              = energies(stored());
  }



  template <int dim>
  typename DynamicsState<dim>::Energies
  DynamicsState<dim>::energies(const double stored) const
  {
    Energies e;
    for_each_cell_mass(
      true,
      [&](const std::vector<types::global_dof_index> &dofs,
          const FullMatrix<double>                   &cell_mass)
      {
        for (unsigned int i = 0; i < dofs.size(); ++i)
          for (unsigned int j = 0; j < dofs.size(); ++j)
          {
            const double p = cell_mass(i, j) * ghosted_velocity[dofs[j]];
            e.kinetic += 0.5 * ghosted_velocity[dofs[i]] * p;
            e.momentum[layout.fe->system_to_component_index(i).first] += p;
          }
      });
    e.kinetic  = Utilities::MPI::sum(e.kinetic, layout.communicator);
    e.stored   = stored;
    e.momentum = Utilities::MPI::sum(e.momentum, layout.communicator);
    return e;
  }



  template <int dim>
  void
  DynamicsState<dim>::start(const double stored)
  {
    current                = energies(stored);
    initial_kinetic_energy = current.kinetic;
  }



  template <int dim>
  std::map<std::string, double>
  DynamicsState<dim>::scalars() const
  {
    return {{"kinetic_energy", current.kinetic},
            {"strain_energy", current.stored},
            {"internal_work", internal_work},
            {"contact_work", contact_work},
            {"friction_work", friction_work},
            {"external_work", external_work},
            {"initial_kinetic_energy", initial_kinetic_energy}};
  }



  template <int dim>
  std::map<std::string, const typename DynamicsState<dim>::Vector *>
  DynamicsState<dim>::checkpoint_vectors() const
  {
    return {{"velocity", &velocity_owned},
            {"acceleration", &acceleration},
            {"old_forces", &old_forces},
            {"old_contact_forces", &old_contact_forces},
            {"old_external", &old_external},
            {"old_internal", &old_internal}};
  }



  template <int dim>
  void
  DynamicsState<dim>::restart(
    const std::function<void(const std::string &, Vector &)> &set_vector,
    const std::map<std::string, double>                      &scalars,
    const Vector                                             &u,
    const double                                              time)
  {
    set_vector("velocity", velocity_owned);
    set_vector("acceleration", acceleration);
    set_vector("old_forces", old_forces);
    set_vector("old_contact_forces", old_contact_forces);
    set_vector("old_external", old_external);
    set_vector("old_internal", old_internal);
    ghosted_velocity       = velocity_owned;
    ghosted_acceleration   = acceleration;
    ghosted_start          = u;
    committed_time         = time;
    current.kinetic        = scalars.at("kinetic_energy");
    current.stored         = scalars.at("strain_energy");
    internal_work          = scalars.at("internal_work");
    contact_work           = scalars.at("contact_work");
    friction_work          = scalars.at("friction_work");
    external_work          = scalars.at("external_work");
    initial_kinetic_energy = scalars.at("initial_kinetic_energy");
    current.momentum       = energies(0.).momentum;
  }



  template class DynamicsState<2>;
  template class DynamicsState<3>;
} // namespace tribos
