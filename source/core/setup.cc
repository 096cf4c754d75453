#include <tribos/base/cells_from_first_process.h>
#include <tribos/base/import_constraints.h>
#include <tribos/base/text.h>
#include <tribos/core/model_checks.h>
#include <tribos/core/problem.h>
#include <tribos/core/vector_function.h>
#include <tribos/scene/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <set>
#include <sstream>
#include <string>

namespace tribos
{
  template <int dim>
  Problem<dim>::Problem(const Parameters::AllParameters &parameters,
                        const MPI_Comm                   mpi_communicator,
                        TimerOutput                     &timer,
                        const std::function<void(const std::string &)> &log,
                        Warnings &warnings)
    : parameters(parameters)
    , mpi_communicator(mpi_communicator)
    , timer(timer)
    , log(log)
    , warnings(warnings)
    , stabilization_springs(parameters,
                            mpi_communicator,
                            locally_owned_dofs,
                            dof_component,
                            dof_body)
    , triangulation_storage(
        make_triangulation<dim>(parameters, mpi_communicator))
    , triangulation(*triangulation_storage)
    , dof_handler(triangulation)
  {
    AssertThrow(parameters.dimension == dim, ExcInternalError());
  }



  template <int dim>
  void
  Problem<dim>::setup(const CellWeights *weights)
  {
    for (const auto &w : parameters.input_warnings)
      warnings.warn(w);
    make_grid(weights);
    setup_system();
    support_warnings<dim>(parameters, triangulation, warnings);
    setup_dynamics();
  }



  template <int dim>
  void
  Problem<dim>::make_grid(const CellWeights *weights)
  {
    TimerOutput::Scope t(timer, "setup");
    create_mesh<dim>(parameters,
                     triangulation,
                     curved_cells,
                     weights,
                     warnings);
  }



  template <int dim>
  void
  Problem<dim>::setup_system()
  {
    TimerOutput::Scope t(timer, "setup");
    // One kind of cell (make_grid() refuses a mixed mesh): Lagrange
    // elements on quadrilaterals and hexahedra (FE_Q) or on triangles and
    // tetrahedra (FE_SimplexP), with the Gauss rules of that kind.
    const ReferenceCell cell_kind = triangulation.get_reference_cells()[0];
    const unsigned int  degree    = parameters.finite_element.degree;
    if (cell_kind.is_hyper_cube())
      fe = std::make_unique<FESystem<dim>>(FE_Q<dim>(degree), dim);
    else
      fe = std::make_unique<FESystem<dim>>(FE_SimplexP<dim>(degree), dim);
    AssertThrow(cell_kind.is_hyper_cube() ||
                  parameters.finite_element.n_quadrature_points <= 4,
                ExcMessage("Parameter <Finite element/Quadrature points> = " +
                           std::to_string(
                             parameters.finite_element.n_quadrature_points) +
                           ": the Gauss rules of triangles and tetrahedra "
                           "have 1 to 4 (points per direction, exact for "
                           "polynomials of degree 2n - 1)."));
    quadrature = cell_kind.template get_gauss_type_quadrature<dim>(
      parameters.finite_element.n_quadrature_points);
    face_quadrature = cell_kind.face_reference_cell(0)
                        .template get_gauss_type_quadrature<dim - 1>(
                          parameters.finite_element.n_quadrature_points);
    dof_handler.distribute_dofs(*fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    owned_per_process =
      Utilities::MPI::all_gather(mpi_communicator, locally_owned_dofs);
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);
    geometry.setup(dof_handler,
                   *fe,
                   quadrature,
                   locally_owned_dofs,
                   locally_relevant_dofs,
                   curved_cells,
                   parameters.finite_element.degree,
                   warnings,
                   mpi_communicator);

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

    material_state = std::make_unique<MaterialState<dim>>(parameters,
                                                          triangulation,
                                                          quadrature.size(),
                                                          mpi_communicator);
    bulk_assembler = std::make_unique<BulkAssembler<dim>>(parameters,
                                                          dof_handler,
                                                          mapping(),
                                                          *fe,
                                                          quadrature,
                                                          face_quadrature,
                                                          *material_state,
                                                          mpi_communicator);

    if (!parameters.contact.pairs.empty())
    {
      contact_handler = std::make_unique<ContactHandler<dim>>(
        parameters.contact,
        dof_handler,
        [this](const types::material_id body)
        { return material_state->youngs_modulus(body); },
        locally_owned_dofs,
        mpi_communicator,
        parameters.finite_element.axisymmetric,
        geometry.curved_mapping());
      // Contact couples this process's slave nodes to master nodes
      // anywhere: the constraints and the pattern know every contact dof.
      // The solution is ghosted on the slave nodes this process reads; the
      // master nodes' positions come with the search (on a shared mesh,
      // whose constraints come from the cells alone, every contact dof is
      // ghosted).
      const auto n_cell_relevant = locally_relevant_dofs.n_elements();
      if (parameters.parallel.mesh == Parameters::Parallel::Mesh::distributed)
        locally_relevant_dofs.add_indices(contact_handler->ghost_dofs());
      else
        locally_relevant_dofs.add_indices(contact_handler->contact_dofs());
      n_contact_ghosts = locally_relevant_dofs.n_elements() - n_cell_relevant;
      for (const auto &w : contact_handler->setup_warnings())
        warnings.warn(w);
    }

    setup_unknowns();
    make_constraints(0, true, homogeneous_constraints);
    make_sparsity();
    setup_vectors();
  }



  template <int dim>
  void
  Problem<dim>::setup_unknowns()
  {
    // The system's unknowns: dofs, then the contact multipliers.
    n_multipliers = contact_handler ? contact_handler->n_unknowns() : 0;
    const types::global_dof_index n_system =
      dof_handler.n_dofs() + n_multipliers;
    system_owned = IndexSet(n_system);
    system_owned.add_indices(locally_owned_dofs);
    coupled_dofs = locally_relevant_dofs;
    if (contact_handler)
      coupled_dofs.add_indices(contact_handler->contact_dofs());
    system_relevant = IndexSet(n_system);
    system_relevant.add_indices(locally_relevant_dofs);
    system_coupled = IndexSet(n_system);
    system_coupled.add_indices(coupled_dofs);
    if (n_multipliers > 0)
    {
      // A node's multipliers belong to the process that owns the node (and
      // evaluates it), the only one that reads them.
      for (const auto &pair : contact_handler->pairs())
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
  }



  template <int dim>
  void
  Problem<dim>::setup_vectors()
  {
    rhs.reinit(system_owned, mpi_communicator);
    free_residual.reinit(system_owned, mpi_communicator);
    full_residual.reinit(system_owned, mpi_communicator);
    contact_force_vector.reinit(system_owned, mpi_communicator);
    owned_solution.reinit(system_owned, mpi_communicator);
    increment_start.reinit(system_owned, mpi_communicator);
    ghosted_solution.reinit(system_owned, system_relevant, mpi_communicator);
    if (n_multipliers > 0)
      ghosted_displacement.reinit(locally_owned_dofs,
                                  locally_relevant_dofs,
                                  mpi_communicator);
    stabilization_springs.reinit(system_owned,
                                 system_relevant,
                                 material_state->n_materials());
    external_forces.reinit(system_owned, mpi_communicator);
    dof_component.assign(dof_handler.n_dofs(), 0);
    dof_body.assign(dof_handler.n_dofs(), 0);
    {
      std::vector<types::global_dof_index> indices(fe->n_dofs_per_cell());
      double                               volume = 0, E_max = 0;
      FEValues<dim>                        fe_values(mapping(),
                              *fe,
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
          std::max(E_max, material_state->youngs_modulus(cell->material_id()));
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
      length_floor =
        1e-14 *
        std::pow(volume,
                 parameters.finite_element.axisymmetric ? 1. / 3. : 1. / dim);
      traction_floor = 1e-12 * E_max;
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
  Problem<dim>::setup_dynamics()
  {
    if (!parameters.time_stepping.dynamic())
      return;
    if (contact_handler && !parameters.time_stepping.contact_mass_removal)
      warnings.warn(
        "dynamics with contact and mass on the contact nodes: each impact "
        "makes the contact force oscillate and creates or destroys "
        "energy (the Signorini bar gains a factor 6-11, doc/dynamics.md); "
        "Time stepping/Mass matrix = lumped with Contact mass removal = "
        "true removes both.");
    typename DynamicsState<dim>::Layout layout;
    layout.dof_handler   = &dof_handler;
    layout.mapping       = &mapping();
    layout.fe            = fe.get();
    layout.quadrature    = &quadrature;
    layout.owned         = locally_owned_dofs;
    layout.relevant      = locally_relevant_dofs;
    layout.system_owned  = system_owned;
    layout.dof_component = &dof_component;
    layout.dof_body      = &dof_body;
    layout.communicator  = mpi_communicator;
    dynamics_state =
      std::make_unique<DynamicsState<dim>>(parameters,
                                           layout,
                                           *material_state,
                                           contact_handler ?
                                             &contact_handler->contact_dofs() :
                                             nullptr,
                                           reaction_dofs,
                                           homogeneous_constraints,
                                           displacement());
    const std::string message = dynamics_state->initial_acceleration(
      [this]() { assemble_system(false, homogeneous_constraints, 0.); },
      free_residual,
      full_residual,
      contact_handler ? &contact_force_vector : nullptr,
      external_forces,
      homogeneous_constraints,
      stagnation_bound);
    if (!message.empty())
      log(message);
    if (contact_handler)
      contact_handler->set_force_weight(
        dynamics_state->integrator().force_weight());
    dynamics_state->start(bulk_assembler->stored_energy(displacement()));
    log(dynamics_state->describe());
  }



  template <int dim>
  const Mapping<dim> &
  Problem<dim>::mapping() const
  {
    if (const Mapping<dim> *curved = geometry.curved_mapping())
      return *curved;
    return fe->reference_cell().template get_default_linear_mapping<dim>();
  }



  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
