#include <tribos/base/import_constraints.h>
#include <tribos/core/problem.h>
#include <tribos/core/vector_function.h>
#include <tribos/scene/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <set>
#include <sstream>
#include <type_traits>

namespace tribos
{
  template <int dim>
  Problem<dim>::Problem(const Parameters::AllParameters &parameters,
                        const MPI_Comm                   mpi_communicator)
    : parameters(parameters)
    , mpi_communicator(mpi_communicator)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , timer(MPI_COMM_SELF, pcout, TimerOutput::never, TimerOutput::wall_times)
    , triangulation_storage(
        parameters.parallel.mesh == Parameters::Parallel::Mesh::shared ?
          std::unique_ptr<parallel::TriangulationBase<dim>>(
            std::make_unique<parallel::shared::Triangulation<dim>>(
              mpi_communicator)) :
          std::make_unique<parallel::fullydistributed::Triangulation<dim>>(
            mpi_communicator))
    , triangulation(*triangulation_storage)
    , dof_handler(triangulation)
    , quadrature(parameters.finite_element.n_quadrature_points)
    , face_quadrature(parameters.finite_element.n_quadrature_points)
  {
    AssertThrow(parameters.dimension == dim, ExcInternalError());
  }



  template <int dim>
  void
  Problem<dim>::make_grid()
  {
    TimerOutput::Scope t(timer, "setup");
    if (parameters.parallel.mesh == Parameters::Parallel::Mesh::shared)
      create_scene(parameters.scene, triangulation);
    else
      create_distributed_scene();

    // Every boundary id named in a condition must exist in the mesh (the
    // faces of own cells: on a distributed mesh the outer faces of the
    // ghost layer are boundary faces with id 0 too).
    std::set<types::boundary_id> existing;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            existing.insert(face->boundary_id());
    existing = Utilities::MPI::compute_set_union(existing, mpi_communicator);
    const auto require = [&](const unsigned int id, const std::string &entry)
    {
      AssertThrow(existing.count(id) == 1,
                  ExcMessage("Parameter <Boundary conditions/" + entry +
                             "> names boundary id " + std::to_string(id) +
                             ", which scene <" + parameters.scene.name +
                             "> does not have. Its boundary ids are listed "
                             "in the README."));
    };
    for (const auto &c : parameters.boundary_conditions.dirichlet)
      require(c.boundary_id, "Dirichlet");
    for (const auto id : parameters.boundary_conditions.symmetry)
      require(id, "Symmetry");
    for (const auto &c : parameters.boundary_conditions.neumann)
      require(c.boundary_id, "Neumann");
  }



  template <int dim>
  void
  Problem<dim>::create_distributed_scene()
  {
    // The scene generators build whole meshes (curved bodies refined on
    // their exact manifolds, then merged flat): the first process builds it,
    // METIS partitions it, and every process keeps its own cells and their
    // ghosts. A bad scene is reported on every process.
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    Triangulation<dim> serial;
    std::string        error;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    {
      try
      {
        create_scene(parameters.scene, serial);
      }
      catch (const ExceptionBase &e)
      {
        std::ostringstream text;
        e.print_info(text);
        error = text.str();
      }
      catch (const std::exception &e)
      {
        error = e.what();
      }
    }
    error = Utilities::MPI::broadcast(mpi_communicator, error, 0);
    AssertThrow(error.empty(), ExcMessage(error));

    const auto description = TriangulationDescription::Utilities::
      create_description_from_triangulation_in_groups<dim, dim>(
        [&serial](Triangulation<dim> &tria)
        {
          tria.copy_triangulation(serial);
          // The mesh is final: no refinement follows, no manifold is
          // needed on the processes.
          for (const auto &cell : tria.cell_iterators())
            cell->set_all_manifold_ids(numbers::flat_manifold_id);
          tria.reset_all_manifolds();
        },
        [this,
         n_ranks](Triangulation<dim> &tria, const MPI_Comm, const unsigned int)
        {
          // A cell that carries slave faces weighs more: its slave nodes'
          // contact elements are evaluated by its process. (No weights at
          // all is METIS' plain partition.)
          const unsigned int weight = parameters.parallel.contact_cell_weight;
          const auto slave_ids      = parameters.contact.slave_boundary_ids();
          std::vector<unsigned int> weights;
          if (weight > 1)
          {
            weights.assign(tria.n_active_cells(), 1);
            for (const auto &cell : tria.active_cell_iterators())
              for (const auto &face : cell->face_iterators())
                if (face->at_boundary() &&
                    slave_ids.count(face->boundary_id()) == 1)
                  weights[cell->active_cell_index()] = weight;
          }
          // After a rebalance: 1 + each cell's measured contact work, in
          // cells' assembly.
          if (last_rebalance.count > 0)
          {
            if (weights.empty())
              weights.assign(tria.n_active_cells(), 1);
            for (const auto &[id, w] : last_rebalance.weights)
            {
              auto &weight_of_cell =
                weights[tria.create_cell_iterator(CellId(id))
                          ->active_cell_index()];
              weight_of_cell = std::max(weight_of_cell, 1 + w);
            }
          }
          GridTools::partition_triangulation(n_ranks, weights, tria);
        },
        mpi_communicator,
        n_ranks);
    triangulation.create_triangulation(description);

    // Cells refined after the merge (local refinement at a contact point)
    // are refined again from the description, and their new vertices would
    // sit on straight lines: every process takes the vertices of its cells
    // from the first process's mesh, where the scene put them (on a sphere,
    // a cylinder, ...).
    const unsigned int n_levels =
      Utilities::MPI::broadcast(mpi_communicator, serial.n_levels(), 0);
    if (n_levels > 1)
    {
      std::vector<CellId::binary_type> mine;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (!cell->is_artificial() && cell->level() > 0)
          mine.push_back(cell->id().template to_binary<dim>());
      const auto requests = Utilities::MPI::gather(mpi_communicator, mine, 0);
      std::map<unsigned int, std::vector<double>> answers;
      for (unsigned int rank = 0; rank < requests.size(); ++rank)
        for (const auto &id : requests[rank])
        {
          const auto cell = serial.create_cell_iterator(CellId(id));
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              answers[rank].push_back(cell->vertex(v)[d]);
        }
      const auto received =
        Utilities::MPI::some_to_some(mpi_communicator, answers);
      if (!mine.empty())
      {
        const auto  &x    = received.at(0);
        unsigned int next = 0;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (!cell->is_artificial() && cell->level() > 0)
            for (const unsigned int v : cell->vertex_indices())
              for (unsigned int d = 0; d < dim; ++d)
                cell->vertex(v)[d] = x[next++];
      }
    }
  }



  template <int dim>
  void
  Problem<dim>::setup_materials()
  {
    const auto &m = parameters.materials;
    body_ids.clear();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (!cell->is_artificial())
        body_ids.insert(cell->material_id());
    body_ids = Utilities::MPI::compute_set_union(body_ids, mpi_communicator);
    const types::material_id max_body = *body_ids.rbegin();
    // The same per-body data builds the dim materials and, for an
    // axisymmetric model, their 3D versions.
    const auto make = [&m](auto dimension, const unsigned int body)
    {
      namespace P = Parameters;
      return create_material<decltype(dimension)::value>(
        P::Materials::for_body(m.models, body, "Model"),
        P::Materials::for_body(m.youngs_moduli, body, "Young's modulus"),
        P::Materials::for_body(m.poissons_ratios, body, "Poisson's ratio"),
        {{P::Materials::for_body(m.yield_stresses, body, "Yield stress"),
          P::Materials::for_body(m.saturation_yield_stresses,
                                 body,
                                 "Saturation yield stress"),
          P::Materials::for_body(m.hardening_exponents,
                                 body,
                                 "Hardening exponent"),
          P::Materials::for_body(m.linear_hardening_moduli,
                                 body,
                                 "Linear hardening modulus")}});
    };
    n_bodies = body_ids.size();
    materials.clear();
    axisymmetric_materials.clear();
    for (unsigned int body = 0; body <= max_body; ++body)
      materials.push_back(make(std::integral_constant<int, dim>(), body));
    if (parameters.finite_element.axisymmetric)
    {
      // The most negative radius, relative to its cell's size, anywhere.
      double worst = 0, worst_x = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto v : cell->vertex_indices())
            if (cell->vertex(v)[0] / cell->diameter() < worst)
            {
              worst   = cell->vertex(v)[0] / cell->diameter();
              worst_x = cell->vertex(v)[0];
            }
      const auto least = Utilities::MPI::min_max_avg(worst, mpi_communicator);
      worst_x =
        Utilities::MPI::broadcast(mpi_communicator, worst_x, least.min_index);
      AssertThrow(least.min >= -1e-10,
                  ExcMessage("Finite element/Axisymmetric = true needs "
                             "the mesh in x = r >= 0; vertex at x = " +
                             std::to_string(worst_x) + "."));
      for (unsigned int body = 0; body <= max_body; ++body)
        axisymmetric_materials.push_back(
          make(std::integral_constant<int, 3>(), body));
    }

    // History only where a material has memory: elastic bodies pay nothing.
    const unsigned int n_q = quadrature.size();
    history_offset.assign(triangulation.n_active_cells(),
                          numbers::invalid_unsigned_int);
    unsigned int n_values = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const unsigned int n = n_history_variables(cell->material_id());
        if (n > 0)
        {
          history_offset[cell->active_cell_index()] = n_values;
          n_values += n * n_q;
        }
      }
    history_old.assign(n_values, 0.);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() &&
          history_offset[cell->active_cell_index()] !=
            numbers::invalid_unsigned_int)
      {
        const unsigned int n = n_history_variables(cell->material_id());
        for (unsigned int q = 0; q < n_q; ++q)
        {
          double *history =
            &history_old[history_offset[cell->active_cell_index()] + q * n];
          if (axisymmetric_materials.empty())
            materials[cell->material_id()]->initialize_history(history);
          else
            axisymmetric_materials[cell->material_id()]->initialize_history(
              history);
        }
      }
    history_new = history_old;
  }



  template <int dim>
  void
  Problem<dim>::setup_system()
  {
    TimerOutput::Scope t(timer, "setup");
    fe = std::make_unique<FESystem<dim>>(FE_Q<dim>(
                                           parameters.finite_element.degree),
                                         dim);
    dof_handler.distribute_dofs(*fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    owned_per_process =
      Utilities::MPI::all_gather(mpi_communicator, locally_owned_dofs);
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    const auto &bc = parameters.boundary_conditions;
    dirichlet_functions.clear();
    reaction_dofs.clear();
    for (const auto &c : bc.dirichlet)
    {
      dirichlet_functions.push_back(
        make_vector_function<dim>(c.expressions,
                                  "Boundary conditions/Dirichlet"));
      std::vector<IndexSet> per_component;
      for (unsigned int d = 0; d < dim; ++d)
      {
        ComponentMask mask(dim, false);
        mask.set(d, true);
        per_component.push_back(DoFTools::extract_boundary_dofs(
          dof_handler,
          mask,
          {static_cast<types::boundary_id>(c.boundary_id)}));
      }
      reaction_dofs.push_back(per_component);
    }
    neumann_functions.clear();
    for (const auto &c : bc.neumann)
      neumann_functions[c.boundary_id] =
        make_vector_function<dim>(c.expressions, "Boundary conditions/Neumann");
    if (!bc.body_force.empty())
      body_force = make_vector_function<dim>(bc.body_force,
                                             "Boundary conditions/Body force");
    if (!parameters.verification.exact_displacement.empty())
      exact_displacement =
        make_vector_function<dim>(parameters.verification.exact_displacement,
                                  "Verification/Exact displacement");

    setup_materials();

    if (!parameters.contact.pairs.empty())
    {
      contact = std::make_unique<ContactHandler<dim>>(
        parameters.contact,
        dof_handler,
        [this](const types::material_id body)
        { return materials[body]->youngs_modulus(); },
        locally_owned_dofs,
        mpi_communicator,
        parameters.finite_element.axisymmetric);
      // Contact couples this process's slave nodes to master nodes
      // anywhere: the constraints and the pattern know every contact dof.
      // The solution is ghosted on the slave nodes this process reads; the
      // master nodes' positions come with the search (on a shared mesh,
      // whose constraints come from the cells alone, every contact dof is
      // ghosted).
      const auto n_cell_relevant = locally_relevant_dofs.n_elements();
      if (parameters.parallel.mesh == Parameters::Parallel::Mesh::distributed)
        locally_relevant_dofs.add_indices(contact->ghost_dofs());
      else
        locally_relevant_dofs.add_indices(contact->contact_dofs());
      n_contact_ghosts = locally_relevant_dofs.n_elements() - n_cell_relevant;
      contact_output   = std::make_unique<ContactOutput<dim>>(*contact);
      for (const auto &w : contact->setup_warnings())
        warn(w);
    }

    // The system's unknowns: dofs, then the contact multipliers.
    n_multipliers = contact ? contact->n_unknowns() : 0;
    const types::global_dof_index n_system =
      dof_handler.n_dofs() + n_multipliers;
    system_owned = IndexSet(n_system);
    system_owned.add_indices(locally_owned_dofs);
    coupled_dofs = locally_relevant_dofs;
    if (contact)
      coupled_dofs.add_indices(contact->contact_dofs());
    system_relevant = IndexSet(n_system);
    system_relevant.add_indices(locally_relevant_dofs);
    system_coupled = IndexSet(n_system);
    system_coupled.add_indices(coupled_dofs);
    if (n_multipliers > 0)
    {
      // A node's multipliers belong to the process that owns the node (and
      // evaluates it), the only one that reads them.
      for (const auto &pair : contact->pairs())
      {
        const unsigned int n = pair.enforcement->n_node_unknowns();
        for (unsigned int k = 0; k < pair.n_nodes() && n > 0; ++k)
          if (pair.owned[k])
          {
            system_owned.add_range(pair.first_unknown + n * k,
                                   pair.first_unknown + n * (k + 1));
            system_relevant.add_range(pair.first_unknown + n * k,
                                      pair.first_unknown + n * (k + 1));
          }
      }
      system_coupled.add_range(dof_handler.n_dofs(), n_system);
    }
    system_owned.compress();
    system_relevant.compress();
    system_coupled.compress();

    make_constraints(0, true, homogeneous_constraints);
    make_sparsity();

    rhs.reinit(system_owned, mpi_communicator);
    free_residual.reinit(system_owned, mpi_communicator);
    full_residual.reinit(system_owned, mpi_communicator);
    contact_forces.reinit(system_owned, mpi_communicator);
    owned_solution.reinit(system_owned, mpi_communicator);
    increment_start.reinit(system_owned, mpi_communicator);
    ghosted_solution.reinit(system_owned, system_relevant, mpi_communicator);
    ghosted_anchors.reinit(system_owned, system_relevant, mpi_communicator);
    if (n_multipliers > 0)
      displacement.reinit(locally_owned_dofs,
                          locally_relevant_dofs,
                          mpi_communicator);
    stabilization_forces.reinit(system_owned, mpi_communicator);
    external_forces.reinit(system_owned, mpi_communicator);
    dof_component.assign(dof_handler.n_dofs(), 0);
    dof_body.assign(dof_handler.n_dofs(), 0);
    {
      std::vector<types::global_dof_index> indices(fe->n_dofs_per_cell());
      double                               volume = 0, E_max = 0;
      FEValues<dim>                        fe_values(*fe,
                              quadrature,
                              update_JxW_values | update_quadrature_points);
      for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        cell->get_dof_indices(indices);
        for (const auto i : indices)
          dof_body[i] = cell->material_id();
        if (!cell->is_locally_owned())
          continue;
        E_max =
          std::max(E_max, materials[cell->material_id()]->youngs_modulus());
        fe_values.reinit(cell);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          volume += fe_values.JxW(q) *
                    (parameters.finite_element.axisymmetric ?
                       2 * numbers::PI * fe_values.quadrature_point(q)[0] :
                       1.);
      }
      volume = Utilities::MPI::sum(volume, mpi_communicator);
      E_max  = Utilities::MPI::max(E_max, mpi_communicator);
      const double exponent =
        parameters.finite_element.axisymmetric ? 2. / 3. : (dim - 1.) / dim;
      stagnation_bound = 1e-10 * E_max * std::pow(volume, exponent);
      traction_floor   = 1e-12 * E_max;
    }
    for (unsigned int d = 0; d < dim; ++d)
    {
      ComponentMask mask(dim, false);
      mask.set(d, true);
      for (const auto i : DoFTools::extract_dofs(dof_handler, mask))
        dof_component[i] = d;
    }
  }



  template <int dim>
  void
  Problem<dim>::make_sparsity()
  {
    // Contact couples slave nodes with master faces of other cells, often of
    // other bodies: those couplings join the bulk pattern, and the pattern
    // is rebuilt when the search meets a new slave-face pair.
    DynamicSparsityPattern dsp(system_coupled);
    if (n_multipliers == 0)
      DoFTools::make_sparsity_pattern(dof_handler,
                                      dsp,
                                      homogeneous_constraints,
                                      false);
    else
    {
      // The bulk pattern on the dofs alone, copied into the system's.
      DynamicSparsityPattern bulk(locally_relevant_dofs);
      DoFTools::make_sparsity_pattern(dof_handler,
                                      bulk,
                                      homogeneous_constraints,
                                      false);
      for (const auto row : locally_relevant_dofs)
        for (auto entry = bulk.begin(row); entry != bulk.end(row); ++entry)
          dsp.add(row, entry->column());
    }
    if (contact)
      contact->add_couplings(dsp, homogeneous_constraints);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               system_owned,
                                               mpi_communicator,
                                               system_coupled);
    // Whatever holds on to the old matrix goes first.
    if (linear_solver)
      linear_solver->release_matrix();
    matrix.reinit(system_owned, system_owned, dsp, mpi_communicator);
    ++sparsity_version;
  }



  template <int dim>
  void
  Problem<dim>::make_constraints(const double               time,
                                 const bool                 homogeneous,
                                 AffineConstraints<double> &constraints) const
  {
    constraints.clear();
    constraints.reinit(system_coupled);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);

    // Dirichlet: du = g(t) - u on the constrained dofs, or du = 0.
    const auto &bc = parameters.boundary_conditions;
    for (unsigned int i = 0; i < bc.dirichlet.size(); ++i)
    {
      const auto &c        = bc.dirichlet[i];
      auto       &function = *dirichlet_functions[i];
      function.set_time(time);
      for (unsigned int k = 0; k < c.components.size(); ++k)
      {
        const unsigned int d = c.components[k];
        ComponentMask      mask(dim, false);
        mask.set(d, true);
        std::map<types::global_dof_index, double> values;
        // Expand the k-th expression to a dim-vector function whose
        // component d is that expression.
        const auto scalar = [&function, k](const Point<dim> &p)
        {
          return function.value(p, k);
        };
        VectorFunctionFromScalarFunctionObject<dim> component(scalar, d, dim);
        VectorTools::interpolate_boundary_values(dof_handler,
                                                 c.boundary_id,
                                                 component,
                                                 values,
                                                 mask);
        for (const auto &[dof, value] : values)
          if (locally_relevant_dofs.is_element(dof) &&
              !constraints.is_constrained(dof))
          {
            constraints.add_line(dof);
            if (!homogeneous)
              constraints.set_inhomogeneity(dof, value - ghosted_solution[dof]);
          }
      }
    }

    if (!bc.symmetry.empty())
    {
      AffineConstraints<double>          symmetry(system_coupled);
      const std::set<types::boundary_id> ids(bc.symmetry.begin(),
                                             bc.symmetry.end());
      VectorTools::compute_no_normal_flux_constraints(dof_handler,
                                                      0,
                                                      ids,
                                                      symmetry);
      symmetry.close();
      // Merging substitutes the symmetry lines into the hanging-node lines
      // that refer to them. On a distributed mesh the outer faces of the
      // ghost layer are boundary faces with id 0 of the local mesh, so a
      // dof there that this process does not own may have a symmetry line
      // it should not have; substituted, it would take a parent's weight
      // out of the line of a hanging node this process owns. Only the own
      // lines are merged: the others come from their owners below, and
      // close() resolves the chains.
      if (parameters.parallel.mesh == Parameters::Parallel::Mesh::distributed)
      {
        AffineConstraints<double> own(system_coupled);
        for (const auto &line : symmetry.get_lines())
          if (locally_owned_dofs.is_element(line.index))
          {
            own.add_line(line.index);
            own.add_entries(line.index, line.entries);
            own.set_inhomogeneity(line.index, line.inhomogeneity);
          }
        symmetry.copy_from(own);
      }
      constraints.merge(
        symmetry,
        AffineConstraints<double>::MergeConflictBehavior::left_object_wins);
    }
    // On a distributed mesh, every dof this process does not own (ghosts,
    // and the master and slave dofs of other processes' cells) as its owner
    // constrains it. A shared mesh has every cell on every process.
    if (parameters.parallel.mesh == Parameters::Parallel::Mesh::distributed)
      import_constraints(constraints,
                         owned_per_process,
                         coupled_dofs,
                         mpi_communicator);
    constraints.close();
  }



  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
