#include <tribos/base/cells_from_first_process.h>
#include <tribos/base/import_constraints.h>
#include <tribos/base/interruption.h>
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
                        Model<dim>                      &model,
                        TimerOutput                     &timer,
                        const std::function<void(const std::string &)> &log,
                        Warnings &warnings)
    : AlgebraicSystem(model.layout(),
                      model.homogeneous_constraints(),
                      model.communicator())
    , parameters(parameters)
    , model(model)
    , timer(timer)
    , log(log)
    , warnings(warnings)
    , stabilization_springs(parameters,
                            mpi_communicator,
                            layout.locally_owned_dofs,
                            model.dof_component(),
                            model.dof_body())
  {
    AssertThrow(parameters.dimension == dim, ExcInternalError());
  }



  template <int dim>
  void
  Problem<dim>::setup(const CellWeights *weights)
  {
    for (const auto &w : parameters.input_warnings)
      warnings.warn(w);
    // A signal stops the first setup after the stage it arrived in, before
    // any output exists (the first Newton iteration may be minutes away);
    // the setup of a rebalanced mesh (@p weights), whose run has written
    // its steps, waits for the first Newton iteration and its summary.
    const auto stop_if_signalled = [&]()
    {
      if (weights == nullptr)
        Interruption::check(mpi_communicator, true);
    };
    model.create_mesh(weights);
    stop_if_signalled();
    model.distribute_dofs();
    stop_if_signalled();
    setup_system();
    support_warnings<dim>(parameters, model.triangulation(), warnings);
    setup_dynamics();
    stop_if_signalled();
  }



  template <int dim>
  void
  Problem<dim>::setup_system()
  {
    TimerOutput::Scope t(timer, "setup");
    setup_physics();
  }



  template <int dim>
  void
  Problem<dim>::setup_physics()
  {
    material_state =
      std::make_unique<MaterialState<dim>>(parameters,
                                           model.triangulation(),
                                           model.quadrature().size(),
                                           mpi_communicator);
    bulk_assembler =
      std::make_unique<BulkAssembler<dim>>(parameters,
                                           model.owned_cells(),
                                           model.mapping(),
                                           model.fe(),
                                           model.quadrature(),
                                           model.face_quadrature(),
                                           *material_state,
                                           mpi_communicator);

    if (!parameters.contact.pairs.empty())
    {
      contact_handler = std::make_unique<ContactHandler<dim>>(
        parameters.contact,
        model.dof_handler(),
        [this](const types::material_id body)
        { return material_state->youngs_modulus(body); },
        layout.locally_owned_dofs,
        mpi_communicator,
        parameters.finite_element.axisymmetric,
        model.curved_mapping());
      for (const auto &w : contact_handler->setup_warnings())
        warnings.warn(w);
    }

    if (contact_handler)
    {
      const ContactUnknowns extra = contact_unknowns();
      model.set_unknowns(&extra);
    }
    else
      model.set_unknowns(nullptr);
    make_sparsity();
    setup_vectors();
  }



  template <int dim>
  ContactUnknowns
  Problem<dim>::contact_unknowns() const
  {
    // Contact couples this process's slave nodes to master nodes anywhere:
    // the constraints and the pattern know every contact dof. The solution
    // is ghosted on the slave nodes this process reads; the master nodes'
    // positions come with the search (on a shared mesh, whose constraints
    // come from the cells alone, every contact dof is ghosted).
    const types::global_dof_index n_dofs = model.dof_handler().n_dofs();
    ContactUnknowns               c;
    c.ghost_dofs =
      parameters.parallel.mesh == Parameters::Parallel::Mesh::distributed ?
        contact_handler->ghost_dofs() :
        contact_handler->contact_dofs();
    c.contact_dofs  = contact_handler->contact_dofs();
    c.n_multipliers = contact_handler->n_unknowns();
    // A node's multipliers belong to the process that owns the node (and
    // evaluates it), the only one that reads them.
    c.owned_multipliers = IndexSet(n_dofs + c.n_multipliers);
    for (const auto &pair : contact_handler->pairs())
    {
      const unsigned int n = pair.enforcement->n_node_unknowns();
      for (unsigned int k = 0; k < pair.n_nodes() && n > 0; ++k)
        if (pair.owned[k])
          c.owned_multipliers.add_range(pair.first_unknown + n * k,
                                        pair.first_unknown + n * (k + 1));
    }
    c.owned_multipliers.compress();
    return c;
  }



  template <int dim>
  void
  Problem<dim>::setup_vectors()
  {
    {
      double        volume = 0, E_max = 0, position = 0;
      FEValues<dim> fe_values(model.mapping(),
                              model.fe(),
                              model.quadrature(),
                              update_JxW_values | update_quadrature_points);
      // In the model's order (a sum: an adapted mesh's is a function of its
      // cells alone, so that a restart's floors are the run's).
      for (const auto &cell : model.owned_cells())
      {
        E_max =
          std::max(E_max, material_state->youngs_modulus(cell->material_id()));
        for (const auto v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            position = std::max(position, std::abs(cell->vertex(v)[d]));
        fe_values.reinit(cell);
        for (unsigned int q = 0; q < model.quadrature().size(); ++q)
          volume += fe_values.JxW(q) *
                    (parameters.finite_element.axisymmetric ?
                       2 * numbers::PI * fe_values.quadrature_point(q)[0] :
                       1.);
      }
      volume   = Utilities::MPI::sum(volume, mpi_communicator);
      E_max    = Utilities::MPI::max(E_max, mpi_communicator);
      position = Utilities::MPI::max(position, mpi_communicator);
      const double exponent =
        parameters.finite_element.axisymmetric ? 2. / 3. : (dim - 1.) / dim;
      Scales round_off;
      round_off.stagnation_bound = 1e-10 * E_max * std::pow(volume, exponent);
      round_off.length_floor =
        1e-14 *
        std::pow(volume,
                 parameters.finite_element.axisymmetric ? 1. / 3. : 1. / dim);
      round_off.traction_floor = 1e-12 * E_max;
      round_off.position       = position;
      reinit(round_off);
    }
    stabilization_springs.reinit(layout.system_owned,
                                 layout.system_relevant,
                                 material_state->bodies());
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
    typename DynamicsState<dim>::Layout dynamics_layout;
    dynamics_layout.dof_handler   = &model.dof_handler();
    dynamics_layout.owned_cells   = &model.owned_cells();
    dynamics_layout.mapping       = &model.mapping();
    dynamics_layout.fe            = &model.fe();
    dynamics_layout.quadrature    = &model.quadrature();
    dynamics_layout.owned         = layout.locally_owned_dofs;
    dynamics_layout.relevant      = layout.locally_relevant_dofs;
    dynamics_layout.system_owned  = layout.system_owned;
    dynamics_layout.dof_component = &model.dof_component();
    dynamics_layout.dof_body      = &model.dof_body();
    dynamics_layout.communicator  = mpi_communicator;
    dynamics_state =
      std::make_unique<DynamicsState<dim>>(parameters,
                                           dynamics_layout,
                                           *material_state,
                                           contact_handler ?
                                             &contact_handler->contact_dofs() :
                                             nullptr,
                                           model.reaction_dofs(),
                                           homogeneous_constraints,
                                           displacement());
    const std::string message = dynamics_state->initial_acceleration(
      [this]() { assemble_system(false, homogeneous_constraints, 0.); },
      free_residual,
      full_residual,
      contact_handler ? &contact_force_vector : nullptr,
      external_forces,
      homogeneous_constraints,
      scales.stagnation_bound);
    if (!message.empty())
      log(message);
    if (contact_handler)
      contact_handler->set_force_weight(
        dynamics_state->integrator().force_weight());
    dynamics_state->start(bulk_assembler->stored_energy(displacement()));
    log(dynamics_state->describe());
  }



  template <int dim>
  void
  Problem<dim>::make_sparsity()
  {
    // Contact couples slave nodes with master faces of other cells, often of
    // other bodies: those couplings join the bulk pattern, and the pattern
    // is rebuilt when the search meets a new slave-face pair.
    DynamicSparsityPattern dsp(layout.system_coupled);
    model.bulk_sparsity(dsp);
    if (contact_handler)
      contact_handler->add_couplings(dsp, homogeneous_constraints);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               layout.system_owned,
                                               mpi_communicator,
                                               layout.system_coupled);
    reinit_matrix(dsp);
  }



  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
