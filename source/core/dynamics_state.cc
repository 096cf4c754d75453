#include <tribos/core/dynamics_state.h>
#include <tribos/core/vector_function.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <cmath>
#include <memory>
#include <sstream>

namespace tribos
{
  template <int dim>
  DynamicsState<dim>::DynamicsState(
    const Parameters::AllParameters          &parameters,
    const Layout                             &layout,
    const MaterialState<dim>                 &materials,
    const IndexSet                           *contact_dofs,
    const std::vector<std::vector<IndexSet>> &reaction_dofs,
    const AffineConstraints<double>          &homogeneous,
    const Vector                             &u)
    : parameters(parameters)
    , layout(layout)
    , time_integrator(parameters.time_stepping)
  {
    const auto     &ts           = parameters.time_stepping;
    const auto     &dof_handler  = *layout.dof_handler;
    const IndexSet &owned        = layout.owned;
    const MPI_Comm  communicator = layout.communicator;
    // The bodies of the mesh only (a list's error names an id it has).
    for (const types::material_id body : materials.bodies())
      densities[body] =
        Parameters::Materials::for_body(parameters.materials.densities,
                                        body,
                                        "Density");

    for (Vector *v : {&velocity_owned,
                      &acceleration,
                      &old_forces,
                      &old_contact_forces,
                      &old_external,
                      &old_internal})
      v->reinit(owned, communicator);
    for (Vector *v : {&ghosted_velocity, &ghosted_acceleration, &ghosted_start})
      v->reinit(owned, layout.relevant, communicator);
    inertia.reinit(layout.system_owned, communicator);

    massless_dofs = IndexSet(dof_handler.n_dofs());
    if (ts.contact_mass_removal && contact_dofs != nullptr)
      massless_dofs = *contact_dofs;
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
      Vector              lumped(owned, communicator);
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
      for (const auto i : owned)
        if (lumped[i] == 0)
          massless_rows.add_index(i);
      massless_rows.compress();
    }

    if (!ts.initial_velocities.empty())
    {
      std::map<types::global_dof_index, Point<dim>> points;
      DoFTools::map_dofs_to_support_points(*layout.mapping,
                                           dof_handler,
                                           points);
      std::map<types::material_id, std::unique_ptr<FunctionParser<dim>>>
        functions;
      for (const auto &v : ts.initial_velocities)
      {
        AssertThrow(materials.bodies().count(v.body_id) == 1,
                    ExcMessage("Parameter <Time stepping/Initial velocity> "
                               "names body " +
                               std::to_string(v.body_id) +
                               ", but the mesh has no cells with that "
                               "material id."));
        functions[v.body_id] =
          make_vector_function<dim>(v.expressions,
                                    "Time stepping/Initial velocity");
      }
      for (const auto dof : owned)
      {
        const auto it = functions.find((*layout.dof_body)[dof]);
        if (it != functions.end())
          velocity_owned[dof] =
            it->second->value(points.at(dof), (*layout.dof_component)[dof]);
      }
      velocity_owned.compress(VectorOperation::insert);
      // Hanging nodes follow their parents, symmetry planes hold the
      // normal velocity at zero; a Dirichlet dof keeps the given velocity
      // (its motion's rate at t = 0 is the user's to make consistent).
      const Vector given = velocity_owned;
      homogeneous.distribute(velocity_owned);
      for (const auto dof : owned)
        if (dirichlet_dofs.is_element(dof))
          velocity_owned[dof] = given[dof];
      velocity_owned.compress(VectorOperation::insert);
    }
    ghosted_velocity = velocity_owned;
    ghosted_start    = u;
  }



  template <int dim>
  void
  DynamicsState<dim>::cell_mass_matrix(
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
  DynamicsState<dim>::for_each_cell_mass(
    const bool                                             remove_contact_mass,
    const std::function<void(const std::vector<types::global_dof_index> &,
                             const FullMatrix<double> &)> &f) const
  {
    const auto                          &fe = *layout.fe;
    FEValues<dim>                        fe_values(*layout.mapping,
                            fe,
                            *layout.quadrature,
                            update_values | update_JxW_values |
                              update_quadrature_points);
    const unsigned int                   n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dof_indices(n);
    std::vector<unsigned int>            component(n);
    for (unsigned int i = 0; i < n; ++i)
      component[i] = fe.system_to_component_index(i).first;
    FullMatrix<double> cell_mass;
    for (const auto &cell : *layout.owned_cells)
    {
      fe_values.reinit(cell);
      cell->get_dof_indices(dof_indices);
      cell_mass_matrix(fe_values,
                       dof_indices,
                       component,
                       densities.at(cell->material_id()),
                       cell_mass,
                       remove_contact_mass);
      f(dof_indices, cell_mass);
    }
  }



  template <int dim>
  void
  DynamicsState<dim>::add_inertia(
    const FEValues<dim>                        &fe_values,
    const std::vector<types::global_dof_index> &dof_indices,
    const std::vector<unsigned int>            &component,
    const types::material_id                    body,
    const Vector                               &u,
    const bool                                  with_matrix,
    dealii::Vector<double>                     &cell_rhs,
    FullMatrix<double>                         &cell_matrix,
    dealii::Vector<double>                     &cell_static,
    dealii::Vector<double>                     &cell_inertia,
    Scratch                                    &scratch) const
  {
    // M a_{n+1-alpha_m} + (1 - alpha_f) R(u_{n+1}) (+ alpha_f R(u_n),
    // added after the loop); Newmark's a_{n+1} follows from u_{n+1}.
    const TimeIntegrator &integrator    = time_integrator;
    const unsigned int    dofs_per_cell = dof_indices.size();
    cell_static                         = cell_rhs;
    const double w                      = integrator.force_weight();
    const double m                      = integrator.mass_weight();
    auto        &mass                   = scratch.mass;
    auto        &a_mid                  = scratch.mid_acceleration;
    auto        &a_end                  = scratch.end_acceleration;
    cell_mass_matrix(fe_values,
                     dof_indices,
                     component,
                     densities.at(body),
                     mass);
    auto &mass_weight = scratch.mass_weight;
    a_mid.resize(dofs_per_cell);
    a_end.resize(dofs_per_cell);
    mass_weight.resize(dofs_per_cell);
    for (unsigned int j = 0; j < dofs_per_cell; ++j)
    {
      const types::global_dof_index dof = dof_indices[j];
      const double                  du  = u[dof] - ghosted_start[dof];
      const double v = ghosted_velocity[dof], a = ghosted_acceleration[dof];
      if (dirichlet_dofs.is_element(dof))
      {
        // Prescribed motion: see TimeIntegrator::prescribed_acceleration.
        a_end[j] = integrator.prescribed_acceleration(du, v);
        a_mid[j] =
          (1. - integrator.alpha_m()) * a_end[j] + integrator.alpha_m() * a;
        mass_weight[j] = integrator.prescribed_mass_weight();
      }
      else
      {
        a_mid[j]       = integrator.mid_acceleration(du, v, a);
        a_end[j]       = integrator.acceleration(du, v, a);
        mass_weight[j] = m;
      }
    }
    cell_rhs *= w;
    if (with_matrix)
      cell_matrix *= w;
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
    {
      double inertia_mid = 0, inertia_end = 0;
      for (unsigned int j = 0; j < dofs_per_cell; ++j)
      {
        inertia_mid += mass(i, j) * a_mid[j];
        inertia_end += mass(i, j) * a_end[j];
        if (with_matrix)
          cell_matrix(i, j) += mass_weight[j] * mass(i, j);
      }
      cell_rhs(i) -= inertia_mid;
      cell_inertia(i) = inertia_end;
    }
  }



  template <int dim>
  void
  DynamicsState<dim>::add_old_forces(
    const AffineConstraints<double> &homogeneous,
    Vector                          &free_residual,
    Vector                          *rhs) const
  {
    if (!inertia_on || time_integrator.alpha_f() == 0)
      return;
    // The alpha_f share of the forces at t_n, condensed like a cell's.
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values;
    for (const auto i : layout.owned)
    {
      indices.push_back(i);
      values.push_back(-time_integrator.alpha_f() * old_forces[i]);
    }
    homogeneous.distribute_local_to_global(values.begin(),
                                           values.end(),
                                           indices.begin(),
                                           free_residual);
    if (rhs != nullptr)
      homogeneous.distribute_local_to_global(values.begin(),
                                             values.end(),
                                             indices.begin(),
                                             *rhs);
  }



  template <int dim>
  std::string
  DynamicsState<dim>::initial_acceleration(
    const std::function<void()>     &assemble_static,
    const Vector                    &free_residual,
    const Vector                    &full_residual,
    const Vector                    *contact_forces,
    const Vector                    &external_forces,
    const AffineConstraints<double> &homogeneous,
    const double                     force_floor)
  {
    // The static residual at t = 0 (no inertia): zero for a body that
    // starts unloaded and out of contact, then a_0 = 0.
    inertia_on = false;
    assemble_static();
    inertia_on                  = true;
    acceleration                = 0;
    const IndexSet &owned       = layout.owned;
    const MPI_Comm  comm        = layout.communicator;
    const auto     &dof_handler = *layout.dof_handler;
    Vector          force(owned, comm);
    for (const auto i : owned)
    {
      force[i] = free_residual[i];
      // The forces at t = 0 for the first step's alpha_f share and the
      // work sums (no inertia yet: a reaction is the static residual). A
      // row without mass is quasi-static: an alpha_f share of its old
      // forces would make its residual alternate in sign from step to step.
      old_forces[i] = massless_rows.is_element(i) ? 0. : full_residual[i];
      old_contact_forces[i] =
        contact_forces != nullptr ? (*contact_forces)[i] : 0.;
      old_external[i] = external_forces[i] +
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
    std::string message;
    if (force.l2_norm() > force_floor)
    {
      DynamicSparsityPattern dsp(layout.relevant);
      DoFTools::make_sparsity_pattern(dof_handler, dsp, homogeneous, false);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 owned,
                                                 comm,
                                                 layout.relevant);
      TrilinosWrappers::SparseMatrix mass;
      mass.reinit(owned, owned, dsp, comm);
      // The bodies' physical mass: a_0 of every node, the contact nodes'
      // included (there it does not enter the balance).
      for_each_cell_mass(false,
                         [&](const std::vector<types::global_dof_index> &dofs,
                             const FullMatrix<double> &cell_mass) {
                           homogeneous.distribute_local_to_global(cell_mass,
                                                                  dofs,
                                                                  mass);
                         });
      mass.compress(VectorOperation::add);

      SolverControl control(10 * dof_handler.n_dofs(), 1e-12 * force.l2_norm());
      SolverCG<Vector>                     cg(control);
      TrilinosWrappers::PreconditionJacobi jacobi;
      jacobi.initialize(mass);
      cg.solve(mass, acceleration, force, jacobi);
      homogeneous.distribute(acceleration);
      message = "  dynamics: initial acceleration from the loads at t = 0 (" +
                std::to_string(control.last_step()) + " CG iterations)";
    }
    ghosted_acceleration = acceleration;
    return message;
  }



  template <int dim>
  std::string
  DynamicsState<dim>::describe() const
  {
    const auto        &ts = parameters.time_stepping;
    std::ostringstream line;
    line << "  dynamics: "
         << (ts.integrator == Parameters::Integrator::newmark ?
               "Newmark" :
               "generalized-alpha (rho_inf = " +
                 std::to_string(ts.spectral_radius) + ")")
         << ", beta = " << time_integrator.beta()
         << ", gamma = " << time_integrator.gamma()
         << ", alpha_m = " << time_integrator.alpha_m()
         << ", alpha_f = " << time_integrator.alpha_f() << ", "
         << (ts.mass_matrix == Parameters::MassMatrix::lumped ? "lumped" :
                                                                "consistent")
         << " mass"
         << (massless_dofs.n_elements() > 0 ?
               ", none on " + std::to_string(massless_dofs.n_elements()) +
                 " contact dofs" :
               std::string())
         << "; initial kinetic energy " << current.kinetic;
    return line.str();
  }



  template class DynamicsState<2>;
  template class DynamicsState<3>;
} // namespace tribos
