#include <tribos/base/exceptions.h>
#include <tribos/base/timing.h>
#include <tribos/core/f_bar.h>
#include <tribos/core/problem.h>

#include <deal.II/base/work_stream.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/full_matrix.h>

#include <chrono>

namespace tribos
{
  namespace
  {
    /** Per-thread workspace of the bulk assembly (WorkStream). */
    template <int dim>
    struct AssemblyScratch
    {
      AssemblyScratch(const FiniteElement<dim>  &fe,
                      const Quadrature<dim>     &quadrature,
                      const Quadrature<dim - 1> &face_quadrature)
        : fe_values(fe,
                    quadrature,
                    update_values | update_gradients |
                      update_quadrature_points | update_JxW_values)
        , fe_values_centre(fe,
                           QGauss<dim>(1),
                           update_values | update_gradients |
                             update_quadrature_points)
        , fe_face_values(fe,
                         face_quadrature,
                         update_values | update_quadrature_points |
                           update_JxW_values)
        , gradients(quadrature.size(), std::vector<Tensor<1, dim>>(dim))
        , values(quadrature.size(), dealii::Vector<double>(dim))
        , centre_gradients(1, std::vector<Tensor<1, dim>>(dim))
        , centre_values(1, dealii::Vector<double>(dim))
        , force(dim)
      {
      }


      AssemblyScratch(const AssemblyScratch &other)
        : AssemblyScratch(other.fe_values.get_fe(),
                          other.fe_values.get_quadrature(),
                          other.fe_face_values.get_quadrature())
      {
      }

      FEValues<dim> fe_values;
      /** F-bar: the deformation gradient at the cell centre. */
      FEValues<dim>                            fe_values_centre;
      FEFaceValues<dim>                        fe_face_values;
      std::vector<std::vector<Tensor<1, dim>>> gradients;
      /** Axisymmetric: the radial displacement (the hoop stretch). */
      std::vector<dealii::Vector<double>>      values;
      std::vector<std::vector<Tensor<1, dim>>> centre_gradients;
      std::vector<dealii::Vector<double>>      centre_values;
      dealii::Vector<double>                   force;
      /** Dynamics: the cell's mass matrix and accelerations. */
      FullMatrix<double>  mass;
      std::vector<double> mid_acceleration, end_acceleration, mass_weight;
    };



    /**
     * One cell's contribution. WorkStream calls the copier in the order of
     * the cells, so the global sums are those of a serial loop, bit for bit.
     */
    struct AssemblyCopy
    {
      AssemblyCopy(const unsigned int dofs_per_cell,
                   const bool         stabilized,
                   const bool         external,
                   const bool         dynamic)
        : cell_matrix(dofs_per_cell, dofs_per_cell)
        , cell_rhs(dofs_per_cell)
        , cell_residual(dofs_per_cell)
        , cell_stabilization(stabilized ? dofs_per_cell : 0)
        , cell_external(external ? dofs_per_cell : 0)
        , cell_static(dynamic ? dofs_per_cell : 0)
        , cell_inertia(dynamic ? dofs_per_cell : 0)
        , dof_indices(dofs_per_cell)
      {
      }

      FullMatrix<double>     cell_matrix;
      dealii::Vector<double> cell_rhs;
      dealii::Vector<double> cell_residual;
      dealii::Vector<double> cell_stabilization;
      /** The applied forces alone (for the stabilization's load ratio and
       * the work of the loads). */
      dealii::Vector<double> cell_external;
      /** Dynamics: -R of the static forces alone, and M a_{n+1}. */
      dealii::Vector<double>               cell_static;
      dealii::Vector<double>               cell_inertia;
      std::vector<types::global_dof_index> dof_indices;
      /** An inverted element's message, rethrown after the loop: an
       * exception must not leave a worker thread. */
      std::string failure;
    };
  } // namespace



  namespace
  {
    /**
     * Zero a vector that the assembly adds to, with what an interrupted
     * assembly left in it: entries added for other processes wait in the
     * Trilinos vector until compress() sends them, and zeroing does not
     * drop them. An assembly that threw (an inverted cell, a mortar
     * element too large: both on every process) never reached its
     * compress(), and the next one added them to its residual (a cutback
     * under MPI retried from a state 8.4 off equilibrium).
     */
    void
    clear(TrilinosWrappers::MPI::Vector &v)
    {
      v.compress(VectorOperation::add);
      v = 0;
    }
  } // namespace



  template <int dim>
  double
  Problem<dim>::assemble_system(const bool                       with_matrix,
                                const AffineConstraints<double> &constraints,
                                const double                     time)
  {
    if (contact)
    {
      TimerOutput::Scope search_timer(timer, "contact search");
      contact->update(ghosted_solution, time);
      if (with_matrix && contact->sparsity_outdated())
        make_sparsity();
    }

    TimerOutput::Scope t(timer, "assembly");
    const Vector      &u = ghosted_displacement();
    if (with_matrix)
    {
      matrix = 0;
      clear(rhs);
    }
    clear(free_residual);
    clear(full_residual);
    const double stabilization  = parameters.nonlinear_solver.stabilization;
    const bool   dynamic        = integrator && with_inertia;
    const bool   track_external = stabilization > 0 || integrator;
    if (stabilization > 0)
      clear(stabilization_forces);
    if (track_external)
      clear(external_forces);
    if (dynamic)
      clear(inertia_forces);
    if (body_force)
      body_force->set_time(time);
    for (auto &[id, function] : neumann_functions)
      function->set_time(time);

    const unsigned int dofs_per_cell = fe->n_dofs_per_cell();
    const unsigned int n_q           = quadrature.size();
    const bool         f_bar         = parameters.finite_element.f_bar;
    const bool         axisymmetric  = parameters.finite_element.axisymmetric;
    std::vector<unsigned int> component(dofs_per_cell);
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      component[i] = fe->system_to_component_index(i).first;

    using CellIterator       = typename DoFHandler<dim>::active_cell_iterator;
    using CellFilter         = FilteredIterator<CellIterator>;
    const auto assemble_cell = [&](const CellIterator   &cell,
                                   AssemblyScratch<dim> &scratch,
                                   AssemblyCopy         &copy)
    {
      auto &fe_values          = scratch.fe_values;
      auto &fe_values_centre   = scratch.fe_values_centre;
      auto &fe_face_values     = scratch.fe_face_values;
      auto &gradients          = scratch.gradients;
      auto &values             = scratch.values;
      auto &centre_gradients   = scratch.centre_gradients;
      auto &centre_values      = scratch.centre_values;
      auto &force              = scratch.force;
      auto &cell_matrix        = copy.cell_matrix;
      auto &cell_rhs           = copy.cell_rhs;
      auto &cell_stabilization = copy.cell_stabilization;
      auto &cell_external      = copy.cell_external;
      auto &dof_indices        = copy.dof_indices;

      Tensor<2, dim> F0, P_eff, P;
      Tensor<4, dim> dP_dF, dP_dF0, A;
      double         J0 = 1;
      Tensor<2, 3>   F3, P3, row3, F3_0, P3_eff, centre_row3;
      Tensor<4, 3>   A3, dP3_dF, dP3_dF0;
      double         centre_radius = 1;

      fe_values.reinit(cell);
      cell->get_dof_indices(dof_indices);
      cell_matrix = 0;
      cell_rhs    = 0;
      if (track_external)
        cell_external = 0;

      fe_values.get_function_gradients(u, gradients);
      if (axisymmetric)
        fe_values.get_function_values(u, values);
      if (f_bar)
      {
        fe_values_centre.reinit(cell);
        fe_values_centre.get_function_gradients(u, centre_gradients);
        F0 = unit_symmetric_tensor<dim>();
        for (unsigned int c = 0; c < dim; ++c)
          F0[c] += centre_gradients[0][c];
        J0 = determinant(F0);
        if (axisymmetric)
        {
          // The volume change of the centre includes its hoop stretch.
          fe_values_centre.get_function_values(u, centre_values);
          centre_radius = fe_values_centre.quadrature_point(0)[0];
          F3_0          = 0;
          for (unsigned int a = 0; a < 2; ++a)
            for (unsigned int b = 0; b < 2; ++b)
              F3_0[a][b] = F0[a][b];
          F3_0[2][2] = 1. + centre_values[0](0) / centre_radius;
          J0         = determinant(F3_0);
        }
      }
      const Material<dim> &material = *materials[cell->material_id()];
      // A symmetric material tangent gives a symmetric cell matrix, but for
      // F-bar's coupling through the centre: then the upper triangle only.
      const bool symmetric = with_matrix && !f_bar && !axisymmetric &&
                             material.has_symmetric_tangent();
      const unsigned int n_history = n_history_variables(cell->material_id());
      const unsigned int offset    = history_offset[cell->active_cell_index()];

      for (unsigned int q = 0; q < n_q; ++q)
      {
        Tensor<2, dim> F = unit_symmetric_tensor<dim>();
        for (unsigned int c = 0; c < dim; ++c)
          F[c] += gradients[q][c];

        const double *old_history =
          n_history ? &history_old[offset + q * n_history] : nullptr;
        double *new_history =
          n_history ? &history_new[offset + q * n_history] : nullptr;

        if (axisymmetric)
        {
          // F = [[F_rr, F_rz, 0], [F_zr, F_zz, 0], [0, 0, 1 + u_r / r]];
          // the virtual deformation gradient of dof i has, besides its
          // in-plane row, phi_i / r in the hoop entry when it is radial.
          const double radius = fe_values.quadrature_point(q)[0];
          F3                  = 0;
          for (unsigned int a = 0; a < 2; ++a)
            for (unsigned int b = 0; b < 2; ++b)
              F3[a][b] = F[a][b];
          F3[2][2] = 1. + values[q](0) / radius;
          // F-bar: the 3D volume change (hoop stretch included) of the
          // centre replaces that of the quadrature point.
          const double s3 = f_bar ? FBar<3>::scale(F3, J0) : 1.;
          axisymmetric_materials[cell->material_id()]->evaluate(s3 * F3,
                                                                old_history,
                                                                new_history,
                                                                P3,
                                                                with_matrix ?
                                                                  &A3 :
                                                                  nullptr);
          if (f_bar)
          {
            FBar<3>::effective(F3,
                               F3_0,
                               s3,
                               P3,
                               with_matrix ? &A3 : nullptr,
                               P3_eff,
                               dP3_dF,
                               dP3_dF0);
            P3 = P3_eff;
            A3 = dP3_dF;
          }
          const double JxW = fe_values.JxW(q) * 2. * numbers::PI * radius;
          if (body_force)
            body_force->vector_value(fe_values.quadrature_point(q), force);
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            const unsigned int    ci     = component[i];
            const Tensor<1, dim> &grad_i = fe_values.shape_grad(i, q);
            const double          hoop_i =
              (ci == 0 ? fe_values.shape_value(i, q) / radius : 0.);
            double r =
              P3[ci][0] * grad_i[0] + P3[ci][1] * grad_i[1] + P3[2][2] * hoop_i;
            if (body_force)
            {
              r -= force[ci] * fe_values.shape_value(i, q);
              if (track_external)
                cell_external(i) +=
                  force[ci] * fe_values.shape_value(i, q) * JxW;
            }
            cell_rhs(i) -= r * JxW;
            if (with_matrix)
            {
              row3 = grad_i[0] * A3[ci][0] + grad_i[1] * A3[ci][1] +
                     hoop_i * A3[2][2];
              for (unsigned int j = 0; j < dofs_per_cell; ++j)
              {
                const unsigned int    cj     = component[j];
                const Tensor<1, dim> &grad_j = fe_values.shape_grad(j, q);
                double                value =
                  row3[cj][0] * grad_j[0] + row3[cj][1] * grad_j[1];
                if (cj == 0)
                  value += row3[2][2] * fe_values.shape_value(j, q) / radius;
                cell_matrix(i, j) += value * JxW;
              }
              if (f_bar)
              {
                // Coupling through the centre's volume change, whose
                // virtual deformation gradient has the hoop entry too.
                centre_row3 = grad_i[0] * dP3_dF0[ci][0] +
                              grad_i[1] * dP3_dF0[ci][1] +
                              hoop_i * dP3_dF0[2][2];
                for (unsigned int j = 0; j < dofs_per_cell; ++j)
                {
                  const unsigned int    cj = component[j];
                  const Tensor<1, dim> &grad_j =
                    fe_values_centre.shape_grad(j, 0);
                  double value = centre_row3[cj][0] * grad_j[0] +
                                 centre_row3[cj][1] * grad_j[1];
                  if (cj == 0)
                    value += centre_row3[2][2] *
                             fe_values_centre.shape_value(j, 0) / centre_radius;
                  cell_matrix(i, j) += value * JxW;
                }
              }
            }
          }
          continue;
        }
        const double s = f_bar ? FBar<dim>::scale(F, J0) : 1.;
        material.evaluate(s * F,
                          old_history,
                          new_history,
                          P,
                          with_matrix ? &A : nullptr);
        if (f_bar)
        {
          FBar<dim>::effective(F,
                               F0,
                               s,
                               P,
                               with_matrix ? &A : nullptr,
                               P_eff,
                               dP_dF,
                               dP_dF0);
          P = P_eff;
          A = dP_dF;
        }

        const double JxW = fe_values.JxW(q);
        if (body_force)
          body_force->vector_value(fe_values.quadrature_point(q), force);

        for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          const unsigned int    ci     = component[i];
          const Tensor<1, dim> &grad_i = fe_values.shape_grad(i, q);
          double                r      = P[ci] * grad_i;
          if (body_force)
          {
            r -= force[ci] * fe_values.shape_value(i, q);
            if (track_external)
              cell_external(i) += force[ci] * fe_values.shape_value(i, q) * JxW;
          }
          cell_rhs(i) -= r * JxW;

          if (with_matrix)
          {
            // A_{ci l cj n} grad_i[l]: the row of A seen by dof i.
            Tensor<2, dim> row;
            for (unsigned int l = 0; l < dim; ++l)
              row += grad_i[l] * A[ci][l];
            for (unsigned int j = (symmetric ? i : 0); j < dofs_per_cell; ++j)
              cell_matrix(i, j) +=
                (row[component[j]] * fe_values.shape_grad(j, q)) * JxW;
            if (f_bar)
            {
              // Coupling through the centre's volume change.
              Tensor<2, dim> centre_row;
              for (unsigned int l = 0; l < dim; ++l)
                centre_row += grad_i[l] * dP_dF0[ci][l];
              for (unsigned int j = 0; j < dofs_per_cell; ++j)
                cell_matrix(i, j) += (centre_row[component[j]] *
                                      fe_values_centre.shape_grad(j, 0)) *
                                     JxW;
            }
          }
        }
      }

      if (symmetric)
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = 0; j < i; ++j)
            cell_matrix(i, j) = cell_matrix(j, i);

      if (!neumann_functions.empty())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
          {
            const auto it = neumann_functions.find(face->boundary_id());
            if (it == neumann_functions.end())
              continue;
            fe_face_values.reinit(cell, face);
            for (unsigned int q = 0; q < face_quadrature.size(); ++q)
            {
              it->second->vector_value(fe_face_values.quadrature_point(q),
                                       force);
              const double ring =
                axisymmetric ?
                  2. * numbers::PI * fe_face_values.quadrature_point(q)[0] :
                  1.;
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                const double f = force[component[i]] *
                                 fe_face_values.shape_value(i, q) *
                                 fe_face_values.JxW(q) * ring;
                cell_rhs(i) += f;
                if (track_external)
                  cell_external(i) += f;
              }
            }
          }

      if (stabilization > 0)
      {
        // Springs to the start of the increment, lumped: stiffness
        // factor * E / h^2 * integral of the shape function.
        const double k = stabilization *
                         materials[cell->material_id()]->youngs_modulus() /
                         (cell->diameter() * cell->diameter());
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          // No spring where the motion is prescribed or follows other dofs
          // (Dirichlet, symmetry, hanging nodes): it would only add to the
          // reactions.
          const types::global_dof_index dof = dof_indices[i];
          cell_stabilization(i)             = 0;
          if (homogeneous_constraints.is_constrained(dof))
            continue;
          double weight = 0;
          for (unsigned int q = 0; q < n_q; ++q)
            weight += fe_values.shape_value(i, q) * fe_values.JxW(q);
          const double f =
            k * weight * (ghosted_solution[dof] - ghosted_anchors[dof]);
          cell_rhs(i) -= f;
          cell_stabilization(i) = f;
          if (with_matrix)
            cell_matrix(i, i) += k * weight;
        }
      }

      if (dynamic)
      {
        // M a_{n+1-alpha_m} + (1 - alpha_f) R(u_{n+1}) (+ alpha_f R(u_n),
        // added after the loop); Newmark's a_{n+1} follows from u_{n+1}.
        copy.cell_static   = cell_rhs;
        const double w     = integrator->force_weight();
        const double m     = integrator->mass_weight();
        auto        &mass  = scratch.mass;
        auto        &a_mid = scratch.mid_acceleration;
        auto        &a_end = scratch.end_acceleration;
        cell_mass_matrix(fe_values,
                         dof_indices,
                         component,
                         densities[cell->material_id()],
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
            a_end[j] = integrator->prescribed_acceleration(du, v);
            a_mid[j] = (1. - integrator->alpha_m()) * a_end[j] +
                       integrator->alpha_m() * a;
            mass_weight[j] = integrator->prescribed_mass_weight();
          }
          else
          {
            a_mid[j]       = integrator->mid_acceleration(du, v, a);
            a_end[j]       = integrator->acceleration(du, v, a);
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
          copy.cell_inertia(i) = inertia_end;
        }
      }
    };

    // The cells in parallel (WorkStream over the threads deal.II was given:
    // the cores of the node divided by its MPI processes); the material
    // laws and the parsed functions are thread-safe, each quadrature point
    // writes only its own history.
    const auto worker = [&](const CellIterator   &cell,
                            AssemblyScratch<dim> &scratch,
                            AssemblyCopy         &copy)
    {
      copy.failure.clear();
      try
      {
        assemble_cell(cell, scratch, copy);
      }
      catch (const InvertedElement &e)
      {
        copy.failure = e.what();
      }
    };
    std::string            failure;
    dealii::Vector<double> cell_residual(dofs_per_cell);
    const auto             copier = [&](const AssemblyCopy &copy)
    {
      if (!copy.failure.empty())
      {
        if (failure.empty())
          failure = copy.failure;
        return;
      }
      if (stabilization > 0)
        stabilization_forces.add(copy.dof_indices, copy.cell_stabilization);
      if (track_external)
        external_forces.add(copy.dof_indices, copy.cell_external);
      if (dynamic)
        inertia_forces.add(copy.dof_indices, copy.cell_inertia);
      // The unconstrained residual carries the reactions (the static forces
      // alone in dynamics).
      cell_residual = dynamic ? copy.cell_static : copy.cell_rhs;
      cell_residual *= -1.;
      full_residual.add(copy.dof_indices, cell_residual);
      homogeneous_constraints.distribute_local_to_global(copy.cell_rhs,
                                                         copy.dof_indices,
                                                         free_residual);
      if (with_matrix)
        constraints.distribute_local_to_global(copy.cell_matrix,
                                               copy.cell_rhs,
                                               copy.dof_indices,
                                               matrix,
                                               rhs);
    };

    const auto bulk_start = std::chrono::steady_clock::now();
    WorkStream::run(
      CellFilter(IteratorFilters::LocallyOwnedCell(),
                 dof_handler.begin_active()),
      CellFilter(IteratorFilters::LocallyOwnedCell(), dof_handler.end()),
      worker,
      copier,
      AssemblyScratch<dim>(*fe, quadrature, face_quadrature),
      AssemblyCopy(dofs_per_cell, stabilization > 0, track_external, dynamic));
    own_assembly_time += seconds_since(bulk_start);
    // Every process throws, or none: a process that left here alone
    // would leave the others waiting in the next collective step (two
    // processes, a cell inverted on one of them: the run hung).
    if (Utilities::MPI::max(failure.empty() ? 0 : 1, mpi_communicator) > 0)
    {
      for (const auto &message :
           Utilities::MPI::all_gather(mpi_communicator, failure))
        if (!message.empty())
          throw InvertedElement(message);
    }

    t.stop();
    if (contact)
    {
      TimerOutput::Scope contact_timer(timer, "contact assembly");
      clear(contact_forces);
      contact->assemble(with_matrix,
                        constraints,
                        homogeneous_constraints,
                        matrix,
                        rhs,
                        free_residual,
                        full_residual,
                        contact_forces);
      contact_forces.compress(VectorOperation::add);
    }

    if (dynamic && integrator->alpha_f() > 0)
    {
      // The alpha_f share of the forces at t_n, condensed like a cell's.
      std::vector<types::global_dof_index> indices;
      std::vector<double>                  values;
      for (const auto i : locally_owned_dofs)
      {
        indices.push_back(i);
        values.push_back(-integrator->alpha_f() * old_forces[i]);
      }
      homogeneous_constraints.distribute_local_to_global(values.begin(),
                                                         values.end(),
                                                         indices.begin(),
                                                         free_residual);
      if (with_matrix)
        homogeneous_constraints.distribute_local_to_global(values.begin(),
                                                           values.end(),
                                                           indices.begin(),
                                                           rhs);
    }

    if (with_matrix)
    {
      matrix.compress(VectorOperation::add);
      rhs.compress(VectorOperation::add);
    }
    free_residual.compress(VectorOperation::add);
    full_residual.compress(VectorOperation::add);
    if (stabilization > 0)
      stabilization_forces.compress(VectorOperation::add);
    if (track_external)
      external_forces.compress(VectorOperation::add);
    if (dynamic)
      inertia_forces.compress(VectorOperation::add);
    return free_residual.l2_norm();
  }

  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
