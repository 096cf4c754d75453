/**
 * Implicit dynamics: the mass matrix, the initial state, and the update of
 * the velocity, acceleration and energies at every converged increment.
 * The inertia terms of the residual and tangent are added per cell in
 * assembly.cc.
 */

#include <tribos/core/problem.h>
#include <tribos/core/vector_function.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <cmath>

namespace tribos
{
  template <int dim>
  void
  Problem<dim>::setup_dynamics()
  {
    const auto &ts = parameters.time_stepping;
    if (!ts.dynamic())
      return;
    integrator = std::make_unique<TimeIntegrator>(ts);

    densities.clear();
    for (unsigned int body = 0; body < materials.size(); ++body)
      densities.push_back(
        Parameters::Materials::for_body(parameters.materials.densities,
                                        body,
                                        "Density"));

    for (Vector *v : {&velocity,
                      &acceleration,
                      &old_forces,
                      &old_contact_forces,
                      &old_external,
                      &old_internal})
      v->reinit(locally_owned_dofs, mpi_communicator);
    for (Vector *v : {&ghosted_velocity, &ghosted_acceleration, &ghosted_start})
      v->reinit(locally_owned_dofs, locally_relevant_dofs, mpi_communicator);
    inertia_forces.reinit(system_owned, mpi_communicator);

    massless_dofs = IndexSet(dof_handler.n_dofs());
    if (ts.contact_mass_removal && contact)
      massless_dofs = contact->contact_dofs();
    if (contact && !ts.contact_mass_removal)
      warn("dynamics with contact and mass on the contact nodes: each impact "
           "makes the contact force oscillate and creates or destroys "
           "energy (the Signorini bar gains a factor 6-11, doc/dynamics.md); "
           "Time stepping/Mass matrix = lumped with Contact mass removal = "
           "true removes both.");
    dirichlet_dofs        = IndexSet(dof_handler.n_dofs());
    const auto &dirichlet = parameters.boundary_conditions.dirichlet;
    for (unsigned int c = 0; c < dirichlet.size(); ++c)
      for (const unsigned int d : dirichlet[c].components)
        dirichlet_dofs.add_indices(reaction_dofs[c][d]);
    dirichlet_dofs.compress();

    // The rows whose assembled lumped mass is zero.
    massless_rows = IndexSet(dof_handler.n_dofs());
    if (massless_dofs.n_elements() > 0)
    {
      Vector              lumped(locally_owned_dofs, mpi_communicator);
      std::vector<double> diagonal;
      for_each_cell_mass(true,
                         [&](const std::vector<types::global_dof_index> &dofs,
                             const FullMatrix<double> &cell_mass)
                         {
                           diagonal.resize(dofs.size());
                           for (unsigned int i = 0; i < dofs.size(); ++i)
                             diagonal[i] = cell_mass(i, i);
                           lumped.add(dofs, diagonal);
                         });
      lumped.compress(VectorOperation::add);
      for (const auto i : locally_owned_dofs)
        if (lumped[i] == 0)
          massless_rows.add_index(i);
      massless_rows.compress();
    }

    if (!ts.initial_velocities.empty())
    {
      std::map<types::global_dof_index, Point<dim>> points;
      DoFTools::map_dofs_to_support_points(MappingQ1<dim>(),
                                           dof_handler,
                                           points);
      std::map<types::material_id, std::unique_ptr<FunctionParser<dim>>>
        functions;
      for (const auto &v : ts.initial_velocities)
      {
        AssertThrow(body_ids.count(v.body_id) == 1,
                    ExcMessage("Parameter <Time stepping/Initial velocity> "
                               "names body " +
                               std::to_string(v.body_id) +
                               ", but the mesh has no cells with that "
                               "material id."));
        functions[v.body_id] =
          make_vector_function<dim>(v.expressions,
                                    "Time stepping/Initial velocity");
      }
      for (const auto dof : locally_owned_dofs)
      {
        const auto it = functions.find(dof_body[dof]);
        if (it != functions.end())
          velocity[dof] = it->second->value(points.at(dof), dof_component[dof]);
      }
      velocity.compress(VectorOperation::insert);
      // Hanging nodes follow their parents, symmetry planes hold the
      // normal velocity at zero; a Dirichlet dof keeps the given velocity
      // (its motion's rate at t = 0 is the user's to make consistent).
      const Vector given = velocity;
      homogeneous_constraints.distribute(velocity);
      for (const auto dof : locally_owned_dofs)
        if (dirichlet_dofs.is_element(dof))
          velocity[dof] = given[dof];
      velocity.compress(VectorOperation::insert);
    }
    ghosted_velocity = velocity;
    ghosted_start    = ghosted_displacement();
    compute_initial_acceleration();
    if (contact)
      contact->set_force_weight(integrator->force_weight());
    const Energies e       = energies();
    kinetic_energy         = e.kinetic;
    strain_energy          = e.stored;
    momentum               = e.momentum;
    initial_kinetic_energy = e.kinetic;
    pcout << "  dynamics: "
          << (ts.integrator == Parameters::Integrator::newmark ?
                "Newmark" :
                "generalized-alpha (rho_inf = " +
                  std::to_string(ts.spectral_radius) + ")")
          << ", beta = " << integrator->beta()
          << ", gamma = " << integrator->gamma()
          << ", alpha_m = " << integrator->alpha_m()
          << ", alpha_f = " << integrator->alpha_f() << ", "
          << (ts.mass_matrix == Parameters::MassMatrix::lumped ? "lumped" :
                                                                 "consistent")
          << " mass"
          << (massless_dofs.n_elements() > 0 ?
                ", none on " + std::to_string(massless_dofs.n_elements()) +
                  " contact dofs" :
                std::string())
          << "; initial kinetic energy " << e.kinetic << std::endl;
  }



  template <int dim>
  void
  Problem<dim>::cell_mass_matrix(
    const FEValues<dim>                        &fe_values,
    const std::vector<types::global_dof_index> &dof_indices,
    const std::vector<unsigned int>            &component,
    const double                                density,
    FullMatrix<double>                         &mass,
    const bool                                  remove_contact_mass) const
  {
    const unsigned int n = dof_indices.size();
    mass.reinit(n, n);
    const bool axisymmetric = parameters.finite_element.axisymmetric;
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
    {
      const double weight =
        density * fe_values.JxW(q) *
        (axisymmetric ? 2. * numbers::PI * fe_values.quadrature_point(q)[0] :
                        1.);
      for (unsigned int i = 0; i < n; ++i)
      {
        const double phi_i = fe_values.shape_value(i, q) * weight;
        for (unsigned int j = 0; j < n; ++j)
          if (component[i] == component[j])
            mass(i, j) += phi_i * fe_values.shape_value(j, q);
      }
    }
    if (parameters.time_stepping.mass_matrix != Parameters::MassMatrix::lumped)
      return;

    std::vector<double> lumped(n, 0.);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        lumped[i] += mass(i, j);
    if (remove_contact_mass && massless_dofs.n_elements() > 0)
      for (unsigned int c = 0; c < dim; ++c)
      {
        // Move the mass of the cell's contact nodes to its other nodes,
        // proportionally: the cell's mass, and so the body's, is kept.
        double removed = 0, kept = 0;
        for (unsigned int i = 0; i < n; ++i)
          if (component[i] == c)
            (massless_dofs.is_element(dof_indices[i]) ? removed : kept) +=
              lumped[i];
        if (removed == 0 || kept == 0)
          continue;
        for (unsigned int i = 0; i < n; ++i)
          if (component[i] == c)
            lumped[i] = massless_dofs.is_element(dof_indices[i]) ?
                          0. :
                          lumped[i] * (kept + removed) / kept;
      }
    mass = 0;
    for (unsigned int i = 0; i < n; ++i)
      mass(i, i) = lumped[i];
  }



  template <int dim>
  void
  Problem<dim>::for_each_cell_mass(
    const bool                                             remove_contact_mass,
    const std::function<void(const std::vector<types::global_dof_index> &,
                             const FullMatrix<double> &)> &f) const
  {
    FEValues<dim>                        fe_values(*fe,
                            quadrature,
                            update_values | update_JxW_values |
                              update_quadrature_points);
    const unsigned int                   n = fe->n_dofs_per_cell();
    std::vector<types::global_dof_index> dof_indices(n);
    std::vector<unsigned int>            component(n);
    for (unsigned int i = 0; i < n; ++i)
      component[i] = fe->system_to_component_index(i).first;
    FullMatrix<double> cell_mass;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        fe_values.reinit(cell);
        cell->get_dof_indices(dof_indices);
        cell_mass_matrix(fe_values,
                         dof_indices,
                         component,
                         densities[cell->material_id()],
                         cell_mass,
                         remove_contact_mass);
        f(dof_indices, cell_mass);
      }
  }



  template <int dim>
  void
  Problem<dim>::compute_initial_acceleration()
  {
    // The static residual at t = 0 (no inertia): zero for a body that
    // starts unloaded and out of contact, then a_0 = 0.
    with_inertia = false;
    assemble_system(false, homogeneous_constraints, 0.);
    with_inertia = true;
    acceleration = 0;
    Vector force(locally_owned_dofs, mpi_communicator);
    for (const auto i : locally_owned_dofs)
    {
      force[i] = free_residual[i];
      // The forces at t = 0 for the first step's alpha_f share and the
      // work sums (no inertia yet: a reaction is the static residual). A
      // row without mass is quasi-static: an alpha_f share of its old
      // forces would make its residual alternate in sign from step to step.
      old_forces[i] = massless_rows.is_element(i) ? 0. : full_residual[i];
      old_contact_forces[i] = contact ? contact_forces[i] : 0.;
      old_external[i]       = external_forces[i] +
                        (dirichlet_dofs.is_element(i) ? full_residual[i] : 0.);
      old_internal[i] =
        full_residual[i] + old_contact_forces[i] + external_forces[i];
    }
    for (Vector *v : {&force,
                      &old_forces,
                      &old_contact_forces,
                      &old_external,
                      &old_internal})
      v->compress(VectorOperation::insert);
    if (force.l2_norm() > stagnation_bound)
    {
      DynamicSparsityPattern dsp(locally_relevant_dofs);
      DoFTools::make_sparsity_pattern(dof_handler,
                                      dsp,
                                      homogeneous_constraints,
                                      false);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 locally_owned_dofs,
                                                 mpi_communicator,
                                                 locally_relevant_dofs);
      TrilinosWrappers::SparseMatrix mass;
      mass.reinit(locally_owned_dofs,
                  locally_owned_dofs,
                  dsp,
                  mpi_communicator);
      // The bodies' physical mass: a_0 of every node, the contact nodes'
      // included (there it does not enter the balance).
      for_each_cell_mass(false,
                         [&](const std::vector<types::global_dof_index> &dofs,
                             const FullMatrix<double> &cell_mass) {
                           homogeneous_constraints
                             .distribute_local_to_global(cell_mass, dofs, mass);
                         });
      mass.compress(VectorOperation::add);

      SolverControl control(10 * dof_handler.n_dofs(), 1e-12 * force.l2_norm());
      SolverCG<Vector>                     cg(control);
      TrilinosWrappers::PreconditionJacobi jacobi;
      jacobi.initialize(mass);
      cg.solve(mass, acceleration, force, jacobi);
      homogeneous_constraints.distribute(acceleration);
      pcout << "  dynamics: initial acceleration from the loads at t = 0 ("
            << control.last_step() << " CG iterations)" << std::endl;
    }
    ghosted_acceleration = acceleration;
  }



  template <int dim>
  void
  Problem<dim>::commit_dynamics()
  {
    const Vector &u        = ghosted_displacement();
    double        works[3] = {0, 0, 0};
    Vector        external(locally_owned_dofs, mpi_communicator);
    for (const auto i : locally_owned_dofs)
    {
      const double du    = u[i] - ghosted_start[i];
      const double a_old = ghosted_acceleration[i], v_old = ghosted_velocity[i];
      if (dirichlet_dofs.is_element(i))
      {
        acceleration[i] = integrator->prescribed_acceleration(du, v_old);
        velocity[i]     = integrator->prescribed_velocity(du);
      }
      else
      {
        const double a_new = integrator->acceleration(du, v_old, a_old);
        acceleration[i]    = a_new;
        velocity[i]        = integrator->velocity(v_old, a_old, a_new);
      }
      // The applied loads and, on Dirichlet dofs, the reactions
      // f_int - f_contact - f_ext + M a; the internal forces
      // R + f_contact + f_ext.
      external[i] = external_forces[i];
      if (dirichlet_dofs.is_element(i))
        external[i] += full_residual[i] + inertia_forces[i];
      const double internal =
        full_residual[i] + contact_forces[i] + external_forces[i];
      // Trapezoidal sums: the work the contact forces take from the bodies,
      // the work the loads and supports give them, the internal work.
      works[0] -= 0.5 * (old_contact_forces[i] + contact_forces[i]) * du;
      works[1] += 0.5 * (old_external[i] + external[i]) * du;
      works[2] += 0.5 * (old_internal[i] + internal) * du;
      old_forces[i] = massless_rows.is_element(i) ? 0. : full_residual[i];
      old_contact_forces[i] = contact_forces[i];
      old_internal[i]       = internal;
    }
    for (Vector *v : {&acceleration,
                      &velocity,
                      &old_forces,
                      &old_contact_forces,
                      &old_internal,
                      &external})
      v->compress(VectorOperation::insert);
    old_external = external;
    contact_work += Utilities::MPI::sum(works[0], mpi_communicator);
    external_work += Utilities::MPI::sum(works[1], mpi_communicator);
    internal_work += Utilities::MPI::sum(works[2], mpi_communicator);
    if (contact)
      friction_work += contact->frictional_dissipation();

    ghosted_velocity     = velocity;
    ghosted_acceleration = acceleration;
    ghosted_start        = u;
    committed_time       = time;
    const Energies e     = energies();
    kinetic_energy       = e.kinetic;
    strain_energy        = e.stored;
    momentum             = e.momentum;
  }



  template <int dim>
  typename Problem<dim>::Energies
  Problem<dim>::energies() const
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
            e.momentum[fe->system_to_component_index(i).first] += p;
          }
      });
    // The stored energy at the deformation gradient the stress sees.
    const bool axisymmetric = parameters.finite_element.axisymmetric;
    for_each_material_point(
      [&](const auto           &cell,
          const FEValues<dim>  &fe_values,
          const unsigned int    q,
          const Tensor<2, dim> &F,
          const Tensor<2, 3>   &F3,
          const double         *history)
      {
        if (axisymmetric)
          e.stored += axisymmetric_materials[cell->material_id()]
                        ->stored_energy(F3, history) *
                      fe_values.JxW(q) * 2. * numbers::PI *
                      fe_values.quadrature_point(q)[0];
        else
          e.stored +=
            materials[cell->material_id()]->stored_energy(F, history) *
            fe_values.JxW(q);
      });
    e.kinetic  = Utilities::MPI::sum(e.kinetic, mpi_communicator);
    e.stored   = Utilities::MPI::sum(e.stored, mpi_communicator);
    e.momentum = Utilities::MPI::sum(e.momentum, mpi_communicator);
    return e;
  }

  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
