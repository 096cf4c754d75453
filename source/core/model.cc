/**
 * The discretization: mesh, finite element, dofs, who holds which unknowns,
 * the dofs of the Dirichlet conditions and their reaction forces.
 */

#include <tribos/base/import_constraints.h>
#include <tribos/core/model.h>
#include <tribos/core/vector_function.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace tribos
{
  template <int dim>
  Model<dim>::Model(const Parameters::AllParameters &parameters,
                    const MPI_Comm                   mpi_communicator,
                    TimerOutput                     &timer,
                    Warnings                        &warnings)
    : parameters(parameters)
    , mpi_communicator(mpi_communicator)
    , timer(timer)
    , warnings(warnings)
    , triangulation_storage(
        make_triangulation<dim>(parameters, mpi_communicator))
    , dofs(*triangulation_storage)
  {
  }



  template <int dim>
  void
  Model<dim>::create_mesh(const CellWeights *weights)
  {
    TimerOutput::Scope t(timer, "setup");
    tribos::create_mesh<dim>(parameters,
                             *triangulation_storage,
                             curved_cells,
                             weights,
                             warnings);
  }



  template <int dim>
  void
  Model<dim>::distribute_dofs()
  {
    // One kind of cell (create_mesh() refuses a mixed mesh): Lagrange
    // elements on quadrilaterals and hexahedra (FE_Q) or on triangles and
    // tetrahedra (FE_SimplexP), with the Gauss rules of that kind.
    const ReferenceCell cell_kind =
      triangulation_storage->get_reference_cells()[0];
    const unsigned int degree = parameters.finite_element.degree;
    if (cell_kind.is_hyper_cube())
      fe_storage = std::make_unique<FESystem<dim>>(FE_Q<dim>(degree), dim);
    else
      fe_storage =
        std::make_unique<FESystem<dim>>(FE_SimplexP<dim>(degree), dim);
    AssertThrow(cell_kind.is_hyper_cube() ||
                  parameters.finite_element.n_quadrature_points <= 4,
                ExcMessage("Parameter <Finite element/Quadrature points> = " +
                           std::to_string(
                             parameters.finite_element.n_quadrature_points) +
                           ": the Gauss rules of triangles and tetrahedra "
                           "have 1 to 4 (points per direction, exact for "
                           "polynomials of degree 2n - 1)."));
    cell_quadrature = cell_kind.template get_gauss_type_quadrature<dim>(
      parameters.finite_element.n_quadrature_points);
    cell_face_quadrature = cell_kind.face_reference_cell(0)
                             .template get_gauss_type_quadrature<dim - 1>(
                               parameters.finite_element.n_quadrature_points);
    dofs.distribute_dofs(*fe_storage);
    // A mesh adapted during the run: numbered and visited as a function of
    // its cells alone (owned_cells()).
    const bool adapted = parameters.adaptivity.enable;
    if (adapted)
      DoFRenumbering::hierarchical(dofs);
    owned_cells_.clear();
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        owned_cells_.push_back(cell);
    if (adapted)
    {
      // Each id once (it is built from the cell's ancestors).
      std::vector<std::pair<CellId, unsigned int>> order;
      for (unsigned int i = 0; i < owned_cells_.size(); ++i)
        order.emplace_back(owned_cells_[i]->id(), i);
      std::sort(order.begin(), order.end());
      const auto cells = owned_cells_;
      for (unsigned int i = 0; i < order.size(); ++i)
        owned_cells_[i] = cells[order[i].second];
    }
    layout_.locally_owned_dofs = dofs.locally_owned_dofs();
    owned_per_process =
      Utilities::MPI::all_gather(mpi_communicator, layout_.locally_owned_dofs);
    DoFTools::extract_locally_relevant_dofs(dofs,
                                            layout_.locally_relevant_dofs);
    geometry.setup(dofs,
                   *fe_storage,
                   cell_quadrature,
                   layout_.locally_owned_dofs,
                   layout_.locally_relevant_dofs,
                   curved_cells,
                   parameters.finite_element.degree,
                   warnings,
                   parameters.scene.geometry->mesh_source(),
                   mpi_communicator);

    const auto &bc = parameters.boundary_conditions;
    dirichlet_functions.clear();
    dirichlet_dofs.clear();
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
          dofs,
          mask,
          {static_cast<types::boundary_id>(c.boundary_id)}));
      }
      dirichlet_dofs.push_back(per_component);
    }
  }



  template <int dim>
  void
  Model<dim>::set_unknowns(const ContactUnknowns *contact)
  {
    UnknownsLayout &L  = layout_;
    L.n_contact_ghosts = 0;
    if (contact != nullptr)
    {
      const auto n_cell_relevant = L.locally_relevant_dofs.n_elements();
      L.locally_relevant_dofs.add_indices(contact->ghost_dofs);
      L.n_contact_ghosts =
        L.locally_relevant_dofs.n_elements() - n_cell_relevant;
    }

    // The system's unknowns: dofs, then the contact multipliers.
    L.n_multipliers = contact != nullptr ? contact->n_multipliers : 0;
    const types::global_dof_index n_system = dofs.n_dofs() + L.n_multipliers;
    L.system_owned                         = IndexSet(n_system);
    L.system_owned.add_indices(L.locally_owned_dofs);
    L.coupled_dofs = L.locally_relevant_dofs;
    if (contact != nullptr)
      L.coupled_dofs.add_indices(contact->contact_dofs);
    L.system_relevant = IndexSet(n_system);
    L.system_relevant.add_indices(L.locally_relevant_dofs);
    L.system_coupled = IndexSet(n_system);
    L.system_coupled.add_indices(L.coupled_dofs);
    if (L.n_multipliers > 0)
    {
      L.system_owned.add_indices(contact->owned_multipliers);
      L.system_relevant.add_indices(contact->owned_multipliers);
      L.system_coupled.add_range(dofs.n_dofs(), n_system);
    }
    L.system_owned.compress();
    L.system_relevant.compress();
    L.system_coupled.compress();

    make_constraints(0, nullptr, homogeneous);
    hanging     = hanging_node_constraints(dofs,
                                       L.locally_relevant_dofs,
                                       owned_per_process);
    any_hanging = Utilities::MPI::max(hanging.n_constraints() > 0 ? 1 : 0,
                                      mpi_communicator) > 0;

    // Each dof's body (of the own and ghost cells) and component.
    components.assign(dofs.n_dofs(), 0);
    bodies.assign(dofs.n_dofs(), 0);
    std::vector<types::global_dof_index> indices(fe_storage->n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      if (!cell->is_artificial())
      {
        cell->get_dof_indices(indices);
        for (const auto i : indices)
          bodies[i] = cell->material_id();
      }
    for (unsigned int d = 0; d < dim; ++d)
    {
      ComponentMask mask(dim, false);
      mask.set(d, true);
      for (const auto i : DoFTools::extract_dofs(dofs, mask))
        components[i] = d;
    }
  }



  template <int dim>
  const AffineConstraints<double> &
  Model<dim>::homogeneous_constraints() const
  {
    return homogeneous;
  }



  template <int dim>
  const parallel::TriangulationBase<dim> &
  Model<dim>::triangulation() const
  {
    return *triangulation_storage;
  }



  template <int dim>
  const DoFHandler<dim> &
  Model<dim>::dof_handler() const
  {
    return dofs;
  }



  template <int dim>
  const std::vector<typename DoFHandler<dim>::active_cell_iterator> &
  Model<dim>::owned_cells() const
  {
    return owned_cells_;
  }



  template <int dim>
  const FESystem<dim> &
  Model<dim>::fe() const
  {
    return *fe_storage;
  }



  template <int dim>
  const Quadrature<dim> &
  Model<dim>::quadrature() const
  {
    return cell_quadrature;
  }



  template <int dim>
  const Quadrature<dim - 1> &
  Model<dim>::face_quadrature() const
  {
    return cell_face_quadrature;
  }



  template <int dim>
  const Mapping<dim> &
  Model<dim>::mapping() const
  {
    if (const Mapping<dim> *curved = geometry.curved_mapping())
      return *curved;
    return fe_storage->reference_cell()
      .template get_default_linear_mapping<dim>();
  }



  template <int dim>
  const Mapping<dim> *
  Model<dim>::curved_mapping() const
  {
    return geometry.curved_mapping();
  }



  template <int dim>
  const UnknownsLayout &
  Model<dim>::layout() const
  {
    return layout_;
  }



  template <int dim>
  MPI_Comm
  Model<dim>::communicator() const
  {
    return mpi_communicator;
  }



  template <int dim>
  const std::vector<std::vector<IndexSet>> &
  Model<dim>::reaction_dofs() const
  {
    return dirichlet_dofs;
  }



  template <int dim>
  const std::vector<unsigned char> &
  Model<dim>::dof_component() const
  {
    return components;
  }



  template <int dim>
  const std::vector<types::material_id> &
  Model<dim>::dof_body() const
  {
    return bodies;
  }



  template <int dim>
  std::vector<double>
  Model<dim>::reaction_forces(const Vector &residual,
                              const Vector *inertia) const
  {
    const auto force = [&](const types::global_dof_index dof) -> double
    {
      return residual[dof] + (inertia ? (*inertia)[dof] : 0.);
    };
    // Each hanging node's force handed to its parents with the weights of
    // its constraint: the residual condensed onto the parents, zero at
    // every free dof at convergence, so that the reactions balance the
    // loads and the contact forces. The owner of a hanging node sends its
    // shares to the owners of its parents (a parent may lie beyond its
    // ghost layer: Q2's node at a quarter of a coarse edge has a weight on
    // the edge's far vertex); the hanging nodes themselves count no more.
    Vector shares;
    if (any_hanging)
    {
      shares.reinit(layout_.locally_owned_dofs,
                    layout_.locally_relevant_dofs,
                    mpi_communicator,
                    true);
      for (const auto &line : hanging.get_lines())
        if (layout_.locally_owned_dofs.is_element(line.index))
          for (const auto &[parent, weight] : line.entries)
            shares[parent] += weight * force(line.index);
      shares.compress(VectorOperation::add);
    }
    std::vector<double> forces;
    for (const auto &per_component : dirichlet_dofs)
      for (unsigned int d = 0; d < dim; ++d)
      {
        double sum = 0;
        for (const auto dof : per_component[d])
          if (layout_.locally_owned_dofs.is_element(dof) &&
              !hanging.is_constrained(dof))
            sum += force(dof) + (any_hanging ? shares[dof] : 0.);
        forces.push_back(Utilities::MPI::sum(sum, mpi_communicator));
      }
    return forces;
  }



  template class Model<2>;
  template class Model<3>;
} // namespace tribos
