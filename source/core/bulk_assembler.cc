#include <tribos/base/exceptions.h>
#include <tribos/base/timing.h>
#include <tribos/core/bulk_assembler.h>
#include <tribos/core/vector_function.h>

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
      AssemblyScratch(const Kinematics<dim>     &kinematics,
                      const Quadrature<dim - 1> &face_quadrature)
        : kinematics(kinematics.clone())
        , fe_face_values(kinematics.values().get_mapping(),
                         kinematics.values().get_fe(),
                         face_quadrature,
                         update_values | update_quadrature_points |
                           update_JxW_values)
        , force(dim)
      {
      }

      AssemblyScratch(const AssemblyScratch &other)
        : AssemblyScratch(*other.kinematics,
                          other.fe_face_values.get_quadrature())
      {
      }

      std::unique_ptr<Kinematics<dim>>     kinematics;
      FEFaceValues<dim>                    fe_face_values;
      dealii::Vector<double>               force;
      typename DynamicsState<dim>::Scratch inertia;
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
        , cell_stabilization(stabilized ? dofs_per_cell : 0)
        , cell_external(external ? dofs_per_cell : 0)
        , cell_static(dynamic ? dofs_per_cell : 0)
        , cell_inertia(dynamic ? dofs_per_cell : 0)
        , dof_indices(dofs_per_cell)
      {
      }

      FullMatrix<double>     cell_matrix;
      dealii::Vector<double> cell_rhs;
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



    /**
     * The Neumann tractions @p functions (by boundary id) on the boundary
     * faces of @p cell into @p copy's -R (and its applied forces if
     * @p track_external), with the @p kinematics' ring factor.
     */
    template <int dim>
    void
    add_tractions(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const std::map<types::boundary_id, std::unique_ptr<FunctionParser<dim>>>
                                      &functions,
      const Kinematics<dim>           &kinematics,
      const std::vector<unsigned int> &component,
      const bool                       track_external,
      AssemblyScratch<dim>            &scratch,
      AssemblyCopy                    &copy)
    {
      auto              &force           = scratch.force;
      auto              &fe_face_values  = scratch.fe_face_values;
      const unsigned int dofs_per_cell   = component.size();
      const unsigned int n_face_q_points = fe_face_values.n_quadrature_points;
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
        {
          const auto it = functions.find(face->boundary_id());
          if (it == functions.end())
            continue;
          fe_face_values.reinit(cell, face);
          for (unsigned int q = 0; q < n_face_q_points; ++q)
          {
            it->second->vector_value(fe_face_values.quadrature_point(q), force);
            const double ring =
              kinematics.ring(fe_face_values.quadrature_point(q));
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
            {
              const double f = force[component[i]] *
                               fe_face_values.shape_value(i, q) *
                               fe_face_values.JxW(q) * ring;
              copy.cell_rhs(i) += f;
              if (track_external)
                copy.cell_external(i) += f;
            }
          }
        }
    }



    /**
     * The stabilization springs of @p cell (stiffness @p factor E / h^2,
     * lumped) from the unknowns @p solution to their @p anchors into
     * @p copy's -R, springs' forces and (@p with_matrix) tangent; none on
     * the dofs @p homogeneous constrains.
     */
    template <int dim>
    void
    add_springs(const typename DoFHandler<dim>::active_cell_iterator &cell,
                const FEValues<dim>                                  &fe_values,
                const double                                          factor,
                const double                         youngs_modulus,
                const AffineConstraints<double>     &homogeneous,
                const TrilinosWrappers::MPI::Vector &solution,
                const TrilinosWrappers::MPI::Vector &anchors,
                const bool                           with_matrix,
                AssemblyCopy                        &copy)
    {
      // Springs to the start of the increment, lumped: stiffness
      // factor * E / h^2 * integral of the shape function.
      const double k =
        factor * youngs_modulus / (cell->diameter() * cell->diameter());
      for (unsigned int i = 0; i < copy.dof_indices.size(); ++i)
      {
        // No spring where the motion is prescribed or follows other dofs
        // (Dirichlet, symmetry, hanging nodes): it would only add to the
        // reactions.
        const types::global_dof_index dof = copy.dof_indices[i];
        copy.cell_stabilization(i)        = 0;
        if (homogeneous.is_constrained(dof))
          continue;
        double weight = 0;
        for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
          weight += fe_values.shape_value(i, q) * fe_values.JxW(q);
        const double f = k * weight * (solution[dof] - anchors[dof]);
        copy.cell_rhs(i) -= f;
        copy.cell_stabilization(i) = f;
        if (with_matrix)
          copy.cell_matrix(i, i) += k * weight;
      }
    }



    /**
     * The material part of @p cell's assembly at the displacement @p u
     * (ghosted) into @p copy, which it first zeroes: the internal forces,
     * the body force @p body_force (null: none) and, if @p with_matrix,
     * the tangent at the @p n_q quadrature points, the applied forces
     * alone too if @p track_external; with a symmetric tangent the upper
     * triangle, copied to the lower. Separate from the boundary loads,
     * springs and inertia the worker adds after it (add_tractions(),
     * add_springs(), DynamicsState::add_inertia()).
     */
    template <int dim>
    void
    add_material_terms(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const TrilinosWrappers::MPI::Vector                  &u,
      MaterialState<dim>                                   &materials,
      const FunctionParser<dim>                            *body_force,
      const unsigned int                                    n_q,
      const bool                                            with_matrix,
      const bool                                            track_external,
      AssemblyScratch<dim>                                 &scratch,
      AssemblyCopy                                         &copy)
    {
      Kinematics<dim>   &kinematics    = *scratch.kinematics;
      auto              &force         = scratch.force;
      auto              &cell_matrix   = copy.cell_matrix;
      auto              &cell_rhs      = copy.cell_rhs;
      const unsigned int dofs_per_cell = copy.dof_indices.size();

      kinematics.reinit(cell, u);
      const FEValues<dim> &fe_values = kinematics.values();
      cell->get_dof_indices(copy.dof_indices);
      cell_matrix = 0;
      cell_rhs    = 0;
      if (track_external)
        copy.cell_external = 0;

      // A symmetric material tangent gives a symmetric cell matrix where
      // the kinematics keep it (not F-bar's coupling through the centre):
      // then the upper triangle only.
      const types::material_id body = cell->material_id();
      const bool upper_only = with_matrix && kinematics.keeps_symmetry() &&
                              materials.material(body).has_symmetric_tangent();
      CellTerms terms{cell_rhs,
                      cell_matrix,
                      track_external ? &copy.cell_external : nullptr,
                      with_matrix,
                      upper_only};
      for (unsigned int q = 0; q < n_q; ++q)
      {
        if (body_force)
          body_force->vector_value(fe_values.quadrature_point(q), force);
        kinematics.add_point(q,
                             {materials,
                              body,
                              materials.old_history(cell, q),
                              materials.new_history(cell, q),
                              body_force ? &force : nullptr},
                             terms);
      }
      if (upper_only)
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = 0; j < i; ++j)
            cell_matrix(i, j) = cell_matrix(j, i);
    }



    /**
     * Add one cell's @p copy to the system and the force vectors of
     * @p targets (the matrix and right-hand side with @p constraints, the
     * free residual with @p homogeneous; the static forces alone in the
     * unconstrained residual if @p dynamic). @p cell_residual is a buffer.
     */
    template <int dim>
    void
    add_cell(const AssemblyCopy                         &copy,
             const typename BulkAssembler<dim>::Targets &targets,
             const AffineConstraints<double>            &constraints,
             const AffineConstraints<double>            &homogeneous,
             const bool                                  dynamic,
             dealii::Vector<double>                     &cell_residual)
    {
      if (targets.stabilization != nullptr)
        targets.stabilization->add(copy.dof_indices, copy.cell_stabilization);
      if (targets.external != nullptr)
        targets.external->add(copy.dof_indices, copy.cell_external);
      if (dynamic)
        targets.inertia->add(copy.dof_indices, copy.cell_inertia);
      // The unconstrained residual carries the reactions (the static forces
      // alone in dynamics).
      cell_residual = dynamic ? copy.cell_static : copy.cell_rhs;
      cell_residual *= -1.;
      targets.full_residual->add(copy.dof_indices, cell_residual);
      homogeneous.distribute_local_to_global(copy.cell_rhs,
                                             copy.dof_indices,
                                             *targets.free_residual);
      if (targets.matrix != nullptr)
        constraints.distribute_local_to_global(copy.cell_matrix,
                                               copy.cell_rhs,
                                               copy.dof_indices,
                                               *targets.matrix,
                                               *targets.rhs);
    }
    /**
     * Throw InvertedElement on every process if a cell was inverted on
     * any: @p failure is this process's message (empty: none), the first
     * process's with one is thrown. Collective. Every process throws, or
     * none: a process that left here alone would leave the others waiting
     * in the next collective step (two processes, a cell inverted on one
     * of them: the run hung).
     */
    void
    throw_if_inverted_anywhere(const std::string &failure,
                               const MPI_Comm     mpi_communicator)
    {
      if (Utilities::MPI::max(failure.empty() ? 0 : 1, mpi_communicator) > 0)
      {
        for (const auto &message :
             Utilities::MPI::all_gather(mpi_communicator, failure))
          if (!message.empty())
            throw InvertedElement(message);
      }
    }
  } // namespace



  template <int dim>
  BulkAssembler<dim>::BulkAssembler(
    const Parameters::AllParameters &parameters,
    const std::vector<typename DoFHandler<dim>::active_cell_iterator>
                              &owned_cells,
    const Mapping<dim>        &mapping,
    const FESystem<dim>       &fe,
    const Quadrature<dim>     &quadrature,
    const Quadrature<dim - 1> &face_quadrature,
    MaterialState<dim>        &materials,
    const MPI_Comm             mpi_communicator)
    : parameters(parameters)
    , owned_cells(owned_cells)
    , fe(fe)
    , quadrature(quadrature)
    , face_quadrature(face_quadrature)
    , materials(materials)
    , mpi_communicator(mpi_communicator)
    , kinematics(
        create_kinematics(parameters.finite_element, mapping, fe, quadrature))
  {
    const auto &bc = parameters.boundary_conditions;
    for (const auto &c : bc.neumann)
      neumann_functions[c.boundary_id] =
        make_vector_function<dim>(c.expressions, "Boundary conditions/Neumann");
    if (!bc.body_force.empty())
      body_force = make_vector_function<dim>(bc.body_force,
                                             "Boundary conditions/Body force");
  }



  template <int dim>
  void
  BulkAssembler<dim>::assemble(const Vector                    &u,
                               const Vector                    &solution,
                               const Vector                    &anchors,
                               const double                     time,
                               const AffineConstraints<double> &constraints,
                               const AffineConstraints<double> &homogeneous,
                               const DynamicsState<dim>        *dynamics,
                               const Targets                   &targets)
  {
    const bool   with_matrix   = targets.matrix != nullptr;
    const double stabilization = parameters.nonlinear_solver.stabilization;
    const bool   dynamic = dynamics != nullptr && dynamics->with_inertia();
    const bool   track_external = targets.external != nullptr;
    if (body_force)
      body_force->set_time(time);
    for (auto &[id, function] : neumann_functions)
      function->set_time(time);

    const unsigned int        dofs_per_cell = fe.n_dofs_per_cell();
    const unsigned int        n_q           = quadrature.size();
    std::vector<unsigned int> component(dofs_per_cell);
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      component[i] = fe.system_to_component_index(i).first;

    using CellIterator       = typename DoFHandler<dim>::active_cell_iterator;
    const auto assemble_cell = [&](const CellIterator   &cell,
                                   AssemblyScratch<dim> &scratch,
                                   AssemblyCopy         &copy)
    {
      add_material_terms<dim>(cell,
                              u,
                              materials,
                              body_force.get(),
                              n_q,
                              with_matrix,
                              track_external,
                              scratch,
                              copy);
      const Kinematics<dim>   &kinematics = *scratch.kinematics;
      const FEValues<dim>     &fe_values  = kinematics.values();
      const types::material_id body       = cell->material_id();

      if (!neumann_functions.empty())
        add_tractions<dim>(cell,
                           neumann_functions,
                           kinematics,
                           component,
                           track_external,
                           scratch,
                           copy);
      if (stabilization > 0)
        add_springs<dim>(cell,
                         fe_values,
                         stabilization,
                         materials.youngs_modulus(body),
                         homogeneous,
                         solution,
                         anchors,
                         with_matrix,
                         copy);

      if (dynamic)
        dynamics->add_inertia(fe_values,
                              copy.dof_indices,
                              component,
                              body,
                              u,
                              with_matrix,
                              copy.cell_rhs,
                              copy.cell_matrix,
                              copy.cell_static,
                              copy.cell_inertia,
                              scratch.inertia);
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
      add_cell<dim>(copy,
                    targets,
                    constraints,
                    homogeneous,
                    dynamic,
                    cell_residual);
    };

    const auto start = std::chrono::steady_clock::now();
    WorkStream::run(
      owned_cells.begin(),
      owned_cells.end(),
      [&](const auto &cell, AssemblyScratch<dim> &scratch, AssemblyCopy &copy)
      { worker(*cell, scratch, copy); },
      copier,
      AssemblyScratch<dim>(*kinematics, face_quadrature),
      AssemblyCopy(dofs_per_cell, stabilization > 0, track_external, dynamic));
    own_seconds += seconds_since(start);
    throw_if_inverted_anywhere(failure, mpi_communicator);
  }



  template <int dim>
  void
  BulkAssembler<dim>::for_each_material_point(const Vector        &u,
                                              const PointFunction &f) const
  {
    const auto points = kinematics->clone();
    for (const auto &cell : owned_cells)
    {
      points->reinit(cell, u);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        f(cell, *points, q, points->material_point(q));
    }
  }



  template <int dim>
  double
  BulkAssembler<dim>::stored_energy(const Vector &u) const
  {
    double energy = 0;
    for_each_material_point(u,
                            [&](const auto               &cell,
                                const Kinematics<dim>    &kinematics,
                                const unsigned int        q,
                                const MaterialPoint<dim> &point)
                            {
                              energy += materials.stored_energy(
                                          cell->material_id(),
                                          point,
                                          materials.old_history(cell, q)) *
                                        kinematics.volume_weight(q);
                            });
    return Utilities::MPI::sum(energy, mpi_communicator);
  }



  template class BulkAssembler<2>;
  template class BulkAssembler<3>;
} // namespace tribos
